#!/usr/bin/env python3
"""Writes examples/slope-wedge.json with one more joint across the whole slope: a zigzag of
10,000 vertices 4.2 mm apart, ±4 cm about y = 5 m (a fuzzing find: one step ran for minutes).

    python3 make_zigzag_joint.py EXAMPLES_DIR OUT.json
"""
import json
import random
import sys

model = json.load(open(sys.argv[1] + "/slope-wedge.json"))
draw = random.Random(1)
n = 10000
points = [[-1.0 + 42.0 * k / (n - 1), 5.0 + draw.uniform(-0.04, 0.04)] for k in range(n)]
model["joints"].append({"name": "zigzag", "points": points})
json.dump(model, open(sys.argv[2], "w"))
