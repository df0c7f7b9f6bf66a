"""Checks the files of `mcdda run examples/newmark-sliding-block.json`: history.csv's motion
columns against the record and against each other, summary.json's permanent displacement.

Usage: check_earthquake.py RUN_DIR
"""
import csv
import json
import math
import sys

folder = sys.argv[1]
rows = list(csv.DictReader(open(f"{folder}/history.csv")))
summary = json.load(open(f"{folder}/summary.json"))
problems = []

for column in ("block:ux", "block:vx", "block:ax", "base:ax", "base:vx", "base:ux"):
    if column not in rows[0]:
        problems.append(f"history.csv has no column {column}")
if not problems:
    # The base's acceleration is the record's: 0.3 g × sin(2π·2·(t − 0.2)) between 0.2 and 1.7 s.
    for r in rows:
        t = float(r["time"])
        expected = 0.3 * 9.81 * math.sin(2 * math.pi * 2 * (t - 0.2)) if 0.2 <= t <= 1.7 else 0.0
        if abs(float(r["base:ax"]) - expected) > 1e-3:
            problems.append(f"base:ax at t = {t} is {r['base:ax']}, the record {expected}")
            break
    # The base's velocity is the record's integral (trapezoidal between rows).
    v = 0.0
    for a, b in zip(rows, rows[1:]):
        v += 0.5 * (float(b["time"]) - float(a["time"])) * (float(a["base:ax"]) + float(b["base:ax"]))
    if abs(v - float(rows[-1]["base:vx"])) > 1e-3:
        problems.append(f"base:vx at the end {rows[-1]['base:vx']} is not the record's integral {v}")
    # The block, relative to the base, ends down the joint (towards -x), at rest.
    last = rows[-1]
    if not float(last["block:ux"]) < -0.03:
        problems.append(f"block:ux at the end is {last['block:ux']}: the block did not slide")
    if abs(float(last["block:vx"])) > 1e-3:
        problems.append(f"block:vx at the end is {last['block:vx']}: not at rest")
    # Once the block has stopped, its absolute acceleration is the base's.
    if abs(float(last["block:ax"]) - float(last["base:ax"])) > 0.05:
        problems.append("block:ax differs from base:ax at rest")

permanent = summary.get("permanent_displacement")
if permanent is None:
    problems.append("summary.json has no permanent_displacement")
else:
    ux, uy = permanent["points"]["block"]
    if abs(ux - float(rows[-1]["block:ux"])) > 1e-9 or abs(uy - float(rows[-1]["block:uy"])) > 1e-9:
        problems.append(f"permanent_displacement.points.block {ux, uy} is not history.csv's last row")
    if not permanent["largest"] >= math.hypot(ux, uy) - 1e-12 or permanent["relative_to"] != "base":
        problems.append(f"permanent_displacement {permanent}")

for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
