"""Checks a study.csv of examples/studies/prandtl-cohesion.json: `count` runs collapsed, each
at a pressure within 3 % of Prandtl's (2 + π) cu, the same for every E (within 0.1 %), and a
settlement at the last step carried that shrinks as E grows. Prints the largest error."""

import csv
import math
import sys

path, count = sys.argv[1], int(sys.argv[2])
rows = [r for r in csv.DictReader(open(path)) if r["status"] == "collapsed"]
if len(rows) != count:
    sys.exit(f"{path}: {len(rows)} collapsed runs, expected {count}")
worst = 0.0
by_cu = {}
for r in rows:
    cu, q = float(r["cu"]), float(r["collapse_pressure"])
    error = q / ((2 + math.pi) * cu) - 1
    worst = max(worst, abs(error))
    by_cu.setdefault(cu, []).append(q)
    if abs(error) > 0.03:
        sys.exit(f"run {r['run']}: collapse pressure {q} is {100 * error:.2f} % off (2 + π) cu = {(2 + math.pi) * cu}")
for cu, qs in by_cu.items():
    if max(qs) > 1.001 * min(qs):
        sys.exit(f"cu = {cu}: the collapse pressure depends on E: {qs}")
print(f"{len(rows)} collapses, largest error against (2 + π) cu: {100 * worst:.2f} %")
