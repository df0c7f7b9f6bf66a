"""The results of a run with ground water: every element wholly below the piezometric line has
the pore pressure gamma_w * (level - y) at its centroid, the total stress is the effective one
less the pore pressure, and the contacts report the water pressure of their place.
Usage: check_water.py RESULT.vtu CONTACTS.vtp "x1,y1;x2,y2;..." [PICTURE.png]
With a picture (a render of --field pore_pressure): it holds the colour scale's many colours."""
import re
import struct
import sys
import zlib

GAMMA_W = 9810.0
line = [tuple(float(v) for v in p.split(",")) for p in sys.argv[3].split(";")]


def level(x):
    if x <= line[0][0]:
        return line[0][1]
    for (xa, ya), (xb, yb) in zip(line, line[1:]):
        if x <= xb:
            return ya + (yb - ya) * (x - xa) / (xb - xa)
    return line[-1][1]


def arrays(path):
    text = open(path).read()
    found = {}
    for m in re.finditer(r'<DataArray[^>]*Name="([^"]+)"[^>]*>(.*?)</DataArray>', text, re.S):
        found[m.group(1)] = [float(v) for v in m.group(2).split()]
    points = re.search(r"<Points>\s*<DataArray[^>]*>(.*?)</DataArray>", text, re.S)
    found["Points"] = [float(v) for v in points.group(1).split()]
    return found


grid = arrays(sys.argv[1])
for name in ("pore_pressure", "effective_stress", "stress"):
    assert name in grid, "no cell array " + name
xyz, connectivity, offsets = grid["Points"], [int(v) for v in grid["connectivity"]], [int(v) for v in grid["offsets"]]
u, total, effective = grid["pore_pressure"], grid["stress"], grid["effective_stress"]
checked = 0
for c, end in enumerate(offsets):
    start = offsets[c - 1] if c > 0 else 0
    corners = connectivity[start:start + 3]
    if any(xyz[3 * i + 1] >= level(xyz[3 * i]) for i in corners):
        continue  # the water line crosses it (or runs above it): the mean is not the centroid's
    cx = sum(xyz[3 * i] for i in corners) / 3
    cy = sum(xyz[3 * i + 1] for i in corners) / 3
    expected = GAMMA_W * (level(cx) - cy)
    assert abs(u[c] - expected) <= 1e-6 * max(1.0, expected), (c, u[c], expected)
    for k in range(3):  # xx, yy, zz: total = effective - u; xy unchanged
        assert abs(total[6 * c + k] - (effective[6 * c + k] - u[c])) <= 1e-6 * max(1.0, abs(total[6 * c + k])), c
    assert total[6 * c + 3] == effective[6 * c + 3]
    checked += 1
assert checked > 10, "too few elements below the water line: %d" % checked
print("pore pressure and total stress of %d elements below the line as expected" % checked)

contacts = arrays(sys.argv[2])
assert "water_pressure" in contacts and "effective_normal_force" in contacts
wet = 0
pts = contacts["Points"]
for i, p in enumerate(contacts["water_pressure"]):
    if i >= len(contacts["normal_force"]) or contacts["state"][i] < 0:
        break
    x, y = pts[3 * i], pts[3 * i + 1]
    expected = GAMMA_W * max(0.0, level(x) - y)
    assert abs(p - expected) <= 1e-3 * GAMMA_W + 1e-6 * expected, (i, p, expected)
    assert contacts["effective_normal_force"][i] == contacts["normal_force"][i]
    wet += p > 0
assert wet > 0, "no contact under water"
print("%d contacts under water report their water pressure" % wet)

if len(sys.argv) > 4:
    data = open(sys.argv[4], "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, chunks, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            chunks.append(body)
        pos += 12 + length
    width, height, depth, colour = header[0], header[1], header[2], header[3]
    assert depth == 8 and colour in (2, 6), header
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(b"".join(chunks))
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for r in range(height):
        kind, line_bytes = raw[r * (stride + 1)], bytearray(raw[r * (stride + 1) + 1:(r + 1) * (stride + 1)])
        for i in range(stride):
            a = line_bytes[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line_bytes[i] = (line_bytes[i] + a) & 255
            elif kind == 2:
                line_bytes[i] = (line_bytes[i] + b) & 255
            elif kind == 3:
                line_bytes[i] = (line_bytes[i] + (a + b) // 2) & 255
            elif kind == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                line_bytes[i] = (line_bytes[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line_bytes))
        previous = line_bytes
    colours = set()
    for row in rows:
        for i in range(0, stride, channels * 4):
            r, g, b = row[i], row[i + 1], row[i + 2]
            if max(r, g, b) - min(r, g, b) > 60:  # saturated: the colour scale, not text or grey
                colours.add((r // 16, g // 16, b // 16))
    assert len(colours) >= 12, "the picture holds only %d saturated colours" % len(colours)
    print("the pore pressure picture holds %d saturated colours" % len(colours))
