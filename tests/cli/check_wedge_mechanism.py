"""The mechanism of the planar wedge's strength reduction (examples/slope-wedge.json): the last
saved step's displacement_increment is the wedge sliding as one body down its joint (from
(12, 3) to (32.8, 15), dipping 30 degrees), the ground below it still, and the same however
many steps each trial takes. Usage: check_wedge_mechanism.py RESULT.vtu [OTHER_RESULT.vtu]"""
import math
import re
import sys


def mechanism(path):
    text = open(path).read()
    m = re.search(r"<Points>\s*<DataArray[^>]*>(.*?)</DataArray>", text, re.S)
    xyz = [float(v) for v in m.group(1).split()]
    m = re.search(r'<DataArray[^>]*Name="displacement_increment"[^>]*>(.*?)</DataArray>', text, re.S)
    assert m, path + ": no displacement_increment"
    u = [float(v) for v in m.group(1).split()]
    return [(xyz[3 * i], xyz[3 * i + 1], u[3 * i], u[3 * i + 1]) for i in range(len(xyz) // 3)]


def joint_y(x):
    return 3.0 + (x - 12.0) * math.tan(math.radians(30.0))


nodes = mechanism(sys.argv[1])
# (The wedge lies above the joint between its ends; the ground is below it and left of the toe.)
wedge = [(ux, uy) for x, y, ux, uy in nodes if 12.0 < x < 32.8 and y > joint_y(x) + 0.3]
ground = [(ux, uy) for x, y, ux, uy in nodes if y < joint_y(x) - 0.3 or x < 11.5]
largest = max(math.hypot(ux, uy) for _, _, ux, uy in nodes)
print("%d wedge nodes, %d ground nodes, largest increment %.6g m" % (len(wedge), len(ground), largest))
assert len(wedge) > 20 and len(ground) > 100
assert largest > 0.0
# One body: every wedge node moves by the largest increment, down the joint (towards the face).
for ux, uy in wedge:
    assert abs(math.hypot(ux, uy) - largest) <= 1e-3 * largest, ("the wedge does not move as one body", ux, uy)
    dip = math.degrees(math.atan2(-uy, -ux))
    assert abs(dip - 30.0) < 0.5, ("the wedge does not slide down its joint", dip)
# The ground stays.
assert max(math.hypot(ux, uy) for ux, uy in ground) <= 1e-3 * largest, "the ground below the joint moves"
if len(sys.argv) > 2:
    other = mechanism(sys.argv[2])
    assert len(other) == len(nodes)
    differs = max(math.hypot(a[2] - b[2], a[3] - b[3]) for a, b in zip(nodes, other))
    print("largest difference from %s: %.3g m" % (sys.argv[2], differs))
    assert differs <= 1e-6 * largest, "the mechanism depends on the number of steps of a trial"
