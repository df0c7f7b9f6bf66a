#!/usr/bin/env python3
"""Fuzzes every command of the `mcdda` command line with mutated inputs.

    python3 scripts/fuzz-commands.py --mcdda build/app/mcdda --examples examples \\
        --mutants 2000 --seed 1 --out /tmp/fuzz [--jobs 2] [--timeout 20] \\
        [--commands check,mesh,run,render,import-dxf,study] [--weights check=4,run=1,...]

Mutants (each from its own random generator seeded by --seed and its number, so one mutant can
be made again with --only N):

- check, mesh, run: the example models mutated structurally (members deleted, replaced by values
  of the wrong type, duplicated; huge, tiny and not-quite-numbers), as text (cut short, bytes
  changed, NaN, 1e400, invalid UTF-8) and geometrically (joints with many vertices, fanned at
  tiny angles, crossing at tiny angles, through one point, very fine joint sets, joints a hair from
  a vertex, self-intersecting regions); `run` adds `--set /analysis/steps=1` and only uses the
  examples that run one step quickly;
- render: the result file of `mcdda run` of examples/kirsch.json damaged (counts, connectivity,
  offsets and cell types out of range, NaN/Inf, types and attributes, truncation, byte flips, huge
  declared counts, XML breakage) through `render MODEL --results FILE --out X.png`;
- import-dxf: small drawings (made here, plus tests/cli/bad-input/*.dxf) with group codes,
  counts, numbers, encodings and structure damaged;
- study: study files with bad versions, outputs, parameters, designs, model paths, malformed
  JSON and huge numbers.

Every call is classified: ok (exit 0), refused (another exit status below 128, or 130, with a
message), CRASH (a signal, an exit status of 128 or more other than 130, or a sanitizer report),
HANG (still running after --timeout seconds; a study whose runs have started is "slow" instead:
running many runs is not a hang), UNCLEAR (a library's text in the output: json.exception,
std::, what(), terminate called, unexpected failure, bad_alloc, VTK or CGAL messages; or an error
exit with no message). The counts go to stdout and OUT/summary.json — also when the run is
stopped early by Ctrl-C or SIGTERM (kill, a batch system's time limit, or SIGINT to a run started
in the background, where the shell ignores it otherwise); every CRASH, HANG and UNCLEAR input is
kept in OUT/findings/<name>/ with repro.sh (the command line) and output.txt. With --emit-only
nothing is run: every mutant is written to OUT/mutants/<number>-<command>/ with its repro.sh
(with --only N, one finding's input made again without waiting for it to hang).
The exit status is 1 when there is any finding, 0 otherwise, 2 on a usage or set-up problem.

Sanitized builds (scripts/sanitize.sh, or a CLI built with -fsanitize=address,undefined) work
the same: pass --mcdda pointing at them; ASAN_OPTIONS, UBSAN_OPTIONS and LSAN_OPTIONS get
defaults (with scripts/sanitize-suppressions.txt) when not set, and a sanitizer report in the
output, or in a study's run logs, is a CRASH.
"""

import argparse
import collections
import concurrent.futures
import copy
import json
import math
import os
import random
import re
import resource
import shlex
import shutil
import signal
import subprocess
import sys
import threading
import time

ALL_COMMANDS = ["check", "mesh", "run", "render", "import-dxf", "study"]
DEFAULT_WEIGHTS = {"check": 6, "mesh": 2, "run": 1, "render": 3, "import-dxf": 6, "study": 3}
# Examples that run one step within a few seconds (measured on 2 busy cores: kirsch 0.15 s,
# griffith-crack 1.1 s, salencon-tunnel 2.4 s, jointed-tunnel 2.5 s, the others 0.3 s); the others
# (hoek-brown-tunnel 20 s, jennings-direct-shear 4.3 s, ...) are checked and meshed, not run.
DEFAULT_RUN_EXAMPLES = ["kirsch", "griffith-crack", "incline-sliding", "incline-stable", "lavarak-cavern",
                        "salencon-tunnel", "slope-wedge", "prandtl-flexible-footing", "jointed-tunnel"]
# Examples used as the base of geometric mutants (simple outlines, a few joints).
GEOMETRY_EXAMPLES = ["kirsch", "slope-wedge", "jointed-tunnel", "lavarak-cavern", "griffith-crack",
                     "incline-stable", "salencon-tunnel", "rock-bridge-slope"]

# A library's words in the output: the message is not the program's own.
UNCLEAR_PATTERNS = [
    (re.compile(r"json\.exception|nlohmann"), "json library text"),
    (re.compile(r"std::"), "std:: in message"),
    (re.compile(r"what\(\)"), "what()"),
    (re.compile(r"terminate called"), "terminate called"),
    (re.compile(r"unexpected failure"), "unexpected failure"),
    (re.compile(r"internal failure"), "internal failure"),
    (re.compile(r"bad_alloc|bad_array_new_length|length_error|out_of_range|invalid_argument|"
                r"\b_M_\w+|vector::|basic_string::|stoi|stod|bad array new length"), "std exception text"),
    (re.compile(r"\bvtk[A-Z]\w+|ERR\||Generic Warning|vtkOutputWindow|In /build/vtk|\(0x[0-9a-f]+\): "), "VTK log text"),
    (re.compile(r"CGAL ERROR|CGAL::|[Pp]recondition violation|[Aa]ssertion violation|Expr: |Expression : "),
     "CGAL text"),
    (re.compile(r"Assertion `|assertion failed|Eigen::"), "assertion"),
    (re.compile(r"XML parse error|XML_ERROR|expat", re.I), "XML parser text"),
    (re.compile(r"Segmentation fault|core dumped|Aborted"), "signal text"),
]
SANITIZER = re.compile(r"ERROR: AddressSanitizer|ERROR: LeakSanitizer|runtime error: |"
                       r"SUMMARY: (Address|UndefinedBehavior|Leak)Sanitizer|AddressSanitizer:DEADLYSIGNAL|"
                       r"==\d+==ERROR:")
CHILD_SIGNAL = re.compile(r"killed by signal (\d+)")


def log(msg):
    sys.stderr.write(msg + "\n")
    sys.stderr.flush()


# ----------------------------------------------------------------------------------------------
# JSON helpers


def dump(doc, rng=None, allow_nan=False):
    indent = None if rng is None else rng.choice([None, 1, 2])
    return json.dumps(doc, indent=indent, allow_nan=allow_nan, ensure_ascii=False)


def all_paths(node, path=()):
    """Every path (tuple of keys/indices) into the document, the root included."""
    out = [path]
    if isinstance(node, dict):
        for k, v in node.items():
            out.extend(all_paths(v, path + (k,)))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            out.extend(all_paths(v, path + (i,)))
    return out


def get_at(doc, path):
    for k in path:
        doc = doc[k]
    return doc


def set_at(doc, path, value):
    if not path:
        return value
    get_at(doc, path[:-1])[path[-1]] = value
    return doc


WEIRD_VALUES = [None, True, False, 0, -1, 1, 0.5, -0.0, 90, 360, 1e308, -1e308, 1e-300, 5e-324, 1.7976931348623157e308,
                2 ** 31, 2 ** 31 - 1, -(2 ** 31), 2 ** 53 + 1, 2 ** 63, 2 ** 63 - 1, -(2 ** 63), 2 ** 64, 2 ** 64 + 1,
                10 ** 30, -(10 ** 30), 3.7e12, 1e9, 1e-9, "", "rock", "x", "1.0", "NaN", "inf", "\u0000",
                "\u00ff\u00fe", "\U0001F600", "a" * 5000, [], {}, [1], [0, 0], [[0, 0]], [[0, 0], [1, 0], [0, 1]],
                [[0, 0], [1e-300, 0], [0, 1e-300]], [None, None], [1e308, 1e308], {"circle": {"center": [0, 0], "radius": 1}},
                {"arc": {"radius": -1}}, {"arc": {"center": [0, 0], "radius": 1, "start": 0, "end": 360, "segments": 100000}},
                {"circle": {"center": [0, 0], "radius": 1e-300, "segments": 3}}, [[1, 2, 3]], [["a", "b"]]]
NUMBER_FACTORS = [-1.0, 0.0, 1e6, 1e-6, 1.0000001, 0.9999999, 1e12, 1e-12, 1e300, 1e-300, 1e308, 2.0, 0.5]
NUMBER_NUDGES = [1e-9, -1e-9, 1e-15, -1e-15, 5e-324, 1e-300]


def random_number_replacement(rng, value):
    k = rng.randrange(4)
    if k == 0:
        return value * rng.choice(NUMBER_FACTORS)
    if k == 1:
        return value + rng.choice(NUMBER_NUDGES) * (1 if value == 0 else abs(value))
    if k == 2:
        return rng.choice([0, -0.0, 1e308, -1e308, 5e-324, 2 ** 63, 2 ** 64, 10 ** 25, -(10 ** 25), 1e-320, 4.9e-324])
    return -value


def mutate_structure(doc, rng, log_kinds):
    """One structural mutation of a parsed JSON document; returns the (possibly new) root."""
    paths = all_paths(doc)
    path = rng.choice(paths)
    node = get_at(doc, path)
    kind = rng.choice(["replace", "delete", "duplicate", "number", "unknown-key", "swap", "type", "empty",
                       "huge-array", "number", "delete"])
    if kind == "replace":
        log_kinds.append("replace")
        return set_at(doc, path, copy.deepcopy(rng.choice(WEIRD_VALUES)))
    if kind == "delete" and path:
        parent = get_at(doc, path[:-1])
        log_kinds.append("delete")
        if isinstance(parent, list):
            del parent[path[-1]]
        else:
            del parent[path[-1]]
        return doc
    if kind == "duplicate" and isinstance(node, list) and node:
        log_kinds.append("duplicate")
        n = rng.choice([1, 1, 2, 10, 100])
        item = rng.choice(node)
        for _ in range(n):
            node.insert(rng.randrange(len(node) + 1), copy.deepcopy(item))
        return doc
    if kind == "duplicate" and isinstance(node, dict) and node:
        log_kinds.append("duplicate-key-text")
        return doc  # duplicate keys are made at text level (see mutate_text)
    if kind == "number" and isinstance(node, (int, float)) and not isinstance(node, bool):
        log_kinds.append("number")
        return set_at(doc, path, random_number_replacement(rng, node))
    if kind == "unknown-key" and isinstance(node, dict):
        log_kinds.append("unknown-key")
        node[rng.choice(["unexpected_key", "Name", "materials ", "", "\u00e9"])] = rng.choice(WEIRD_VALUES)
        return doc
    if kind == "swap" and isinstance(node, list) and len(node) >= 2:
        log_kinds.append("swap")
        i, j = rng.sample(range(len(node)), 2)
        node[i], node[j] = node[j], node[i]
        return doc
    if kind == "type":
        log_kinds.append("type")
        if isinstance(node, (int, float)) and not isinstance(node, bool):
            return set_at(doc, path, rng.choice([str(node), [node], {"value": node}, bool(node)]))
        if isinstance(node, str):
            return set_at(doc, path, rng.choice([1, [node], {node: node}, node.upper(), node + "\u0000", node * 3]))
        if isinstance(node, list):
            return set_at(doc, path, rng.choice([{str(i): v for i, v in enumerate(node)}, len(node), node[:1]]))
        if isinstance(node, dict):
            return set_at(doc, path, rng.choice([list(node.values()), list(node.keys()), None]))
        return set_at(doc, path, "null")
    if kind == "empty":
        log_kinds.append("empty")
        if isinstance(node, (list, dict)):
            node.clear()
            return doc
        return set_at(doc, path, rng.choice(["", [], {}]))
    if kind == "huge-array" and isinstance(node, list) and node:
        log_kinds.append("huge-array")
        n = rng.choice([1000, 10000, 100000])
        n = max(10, min(n, 4000000 // max(len(json.dumps(node[-1], allow_nan=True)), 1)))  # at most a few MB
        node.extend(copy.deepcopy(node[-1]) for _ in range(n))
        return doc
    # fall back: replace
    log_kinds.append("replace")
    return set_at(doc, path, copy.deepcopy(rng.choice(WEIRD_VALUES)))


NOISE = "{}[],:\"0-.e9 \\n\t"
BAD_NUMBERS = ["NaN", "-NaN", "Infinity", "-Infinity", "inf", "1e400", "-1e400", "1e-400", "0x10", "01", "+1", ".5",
               "1.", "1e", "-", "1e99999999999", "123456789012345678901234567890", "-0", "1E+308", "9" * 400,
               "0.000000000000000000000000000000000000000000000000000000000000000000000000000000001"]


def mutate_text(text, rng, log_kinds):
    """One mutation of JSON text: truncation, bytes, NaN and friends, encodings. Returns bytes."""
    data = text.encode("utf-8")
    kind = rng.choice(["truncate", "delete", "insert", "bad-number", "bad-number", "invalid-utf8", "nul", "bom",
                       "utf16", "deep", "dup-key", "comment", "trailing-comma", "long-string", "empty", "flip"])
    log_kinds.append("text-" + kind)
    at = rng.randrange(len(data) + 1) if data else 0
    if kind == "truncate":
        return data[:at]
    if kind == "delete":
        return data[:at] + data[at + rng.choice([1, 1, 2, 10]):]
    if kind == "insert":
        return data[:at] + rng.choice(NOISE).encode() + data[at:]
    if kind == "bad-number":
        numbers = [m for m in re.finditer(rb"-?\d+(\.\d+)?([eE][-+]?\d+)?", data)]
        if numbers:
            m = rng.choice(numbers)
            return data[:m.start()] + rng.choice(BAD_NUMBERS).encode() + data[m.end():]
        return data + b" NaN"
    if kind == "invalid-utf8":
        strings = [m for m in re.finditer(rb'"[^"\\]*"', data)]
        bad = rng.choice([b"\xff", b"\xc3", b"\xed\xa0\x80", b"\xf4\x90\x80\x80", b"\xc0\xaf", b"\x80", b"\\ud800",
                          b"\\u0000", b"\\uDFFF\\uD800"])
        if strings:
            m = rng.choice(strings)
            return data[:m.start() + 1] + bad + data[m.start() + 1:]
        return bad + data
    if kind == "nul":
        return data[:at] + b"\x00" + data[at:]
    if kind == "bom":
        return rng.choice([b"\xef\xbb\xbf", b"\xff\xfe", b"\xfe\xff", b"\xef\xbb\xbf\xef\xbb\xbf"]) + data
    if kind == "utf16":
        return text.encode(rng.choice(["utf-16", "utf-16-le", "utf-16-be", "utf-32"]))
    if kind == "deep":
        n = rng.choice([1000, 100000, 1000000])
        value = (b"[" * n + b"]" * n) if rng.random() < 0.5 else (b'{"a":' * n + b"1" + b"}" * n)
        m = re.search(rb":\s*", data)
        if m:
            return data[:m.end()] + value + b"," + data[m.end():]
        return value
    if kind == "dup-key":
        m = re.search(rb'\{\s*("[^"]*"\s*:\s*("[^"]*"|[-\d.eE+]+|true|false|null)\s*,)', data)
        if m:
            return data[:m.end()] + m.group(1) + data[m.end():]
        return data
    if kind == "comment":
        return data[:at] + rng.choice([b"// c\n", b"/* c */", b"/*", b"#"]) + data[at:]
    if kind == "trailing-comma":
        i = data.rfind(b"}")
        return data[:i] + b"," + data[i:] if i > 0 else data
    if kind == "long-string":
        strings = [m for m in re.finditer(rb'"[^"\\]*"', data)]
        if strings:
            m = rng.choice(strings)
            return data[:m.start() + 1] + b"x" * rng.choice([10 ** 4, 10 ** 6]) + data[m.start() + 1:]
        return data
    if kind == "empty":
        return rng.choice([b"", b" ", b"\n", b"null", b"[]", b"{}", b"0", b'"mcdda-model"'])
    # flip
    data = bytearray(data)
    for _ in range(rng.choice([1, 1, 3, 10])):
        if data:
            i = rng.randrange(len(data))
            data[i] ^= 1 << rng.randrange(8)
    return bytes(data)


# ----------------------------------------------------------------------------------------------
# Geometry mutations of models


def ring_points(ring):
    pts = []
    if isinstance(ring, dict) and "circle" in ring:
        c = ring["circle"].get("center", [0, 0])
        r = ring["circle"].get("radius", 1)
        return [[c[0] - r, c[1] - r], [c[0] + r, c[1] + r]]
    if not isinstance(ring, list):
        return pts
    for p in ring:
        if isinstance(p, list) and len(p) == 2 and all(isinstance(v, (int, float)) for v in p):
            pts.append([float(p[0]), float(p[1])])
        elif isinstance(p, dict) and "arc" in p:
            a = p["arc"]
            c, r = a.get("center", [0, 0]), a.get("radius", 1)
            for ang in (a.get("start", 0), a.get("end", 0)):
                pts.append([c[0] + r * math.cos(math.radians(ang)), c[1] + r * math.sin(math.radians(ang))])
    return pts


def model_vertices(doc):
    """(outline vertices, hole vertices) of the model's regions."""
    verts, holes = [], []
    for reg in doc.get("regions", []) if isinstance(doc.get("regions"), list) else []:
        if not isinstance(reg, dict):
            continue
        verts.extend(ring_points(reg.get("boundary")))
        for h in reg.get("holes", []) or []:
            holes.extend(ring_points(h))
    return verts, holes


def bbox(points):
    if not points:
        return 0.0, 0.0, 10.0, 10.0
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    return min(xs), min(ys), max(xs), max(ys)


def joints_list(doc):
    if not isinstance(doc.get("joints"), list):
        doc["joints"] = []
    return doc["joints"]


def add_joint(doc, points, name):
    j = {"name": name, "points": [[float(x), float(y)] for x, y in points]}
    mats = doc.get("joint_materials")
    if isinstance(mats, list) and mats and isinstance(mats[0], dict) and "name" in mats[0]:
        j["joint_material"] = mats[0]["name"]
    joints_list(doc).append(j)


def mutate_geometry(doc, rng, log_kinds):
    verts, holes = model_vertices(doc)
    x0, y0, x1, y1 = bbox(verts)
    w, h = max(x1 - x0, 1e-3), max(y1 - y0, 1e-3)
    diag = math.hypot(w, h)
    inside = lambda: (x0 + w * rng.uniform(0.15, 0.85), y0 + h * rng.uniform(0.15, 0.85))
    kind = rng.choice(["many-vertices", "fan", "fan", "crossing", "crossing", "one-point", "fine-set", "near-vertex",
                       "near-vertex", "self-intersecting", "near-parallel", "crack-tips", "tiny-joint"])
    log_kinds.append("geom-" + kind)
    L = diag
    if kind == "many-vertices":
        n = rng.choice([20, 100, 500, 2000, 10000])
        cx, cy = inside()
        ang = rng.uniform(0, math.pi)
        amp = diag * rng.choice([1e-9, 1e-6, 1e-3, 1e-2, 0.05])
        pts = []
        for i in range(n):
            t = -0.6 + 1.2 * i / (n - 1)
            off = amp * (1 if i % 2 else -1) if rng.random() < 0.7 else amp * rng.uniform(-1, 1)
            pts.append((cx + t * L * math.cos(ang) - off * math.sin(ang), cy + t * L * math.sin(ang) + off * math.cos(ang)))
        add_joint(doc, pts, "many vertices")
    elif kind == "fan":
        cx, cy = inside() if rng.random() < 0.7 else rng.choice(verts or [(0, 0)])
        k = rng.choice([2, 3, 5, 10, 30])
        delta = math.radians(rng.choice([1e-1, 1e-2, 1e-4, 1e-6, 1e-9, 1e-12]))
        a0 = rng.uniform(0, math.pi)
        for i in range(k):
            a = a0 + i * delta
            add_joint(doc, [(cx, cy), (cx + L * math.cos(a), cy + L * math.sin(a))], "fan %d" % i)
    elif kind == "crossing":
        cx, cy = inside()
        delta = math.radians(rng.choice([1e-1, 1e-3, 1e-5, 1e-7, 1e-9, 1e-12]))
        a0 = rng.uniform(0, math.pi)
        gap = rng.choice([0.0, 0.0, 1e-12, 1e-9, 1e-6]) * diag
        for i, a in enumerate([a0, a0 + delta]):
            ox, oy = -gap * i * math.sin(a0), gap * i * math.cos(a0)
            add_joint(doc, [(cx + ox - L * math.cos(a), cy + oy - L * math.sin(a)),
                            (cx + ox + L * math.cos(a), cy + oy + L * math.sin(a))], "crossing %d" % i)
    elif kind == "one-point":
        cx, cy = inside() if rng.random() < 0.6 else rng.choice(verts + holes or [(0, 0)])
        k = rng.choice([2, 3, 5, 10, 20, 50])
        for i in range(k):
            a = rng.uniform(0, math.pi)
            add_joint(doc, [(cx - L * math.cos(a), cy - L * math.sin(a)), (cx + L * math.cos(a), cy + L * math.sin(a))],
                      "through one point %d" % i)
    elif kind == "fine-set":
        n = rng.choice([50, 200, 1000, 5000, 6000, 100000])
        s = {"name": "fine", "angle": rng.choice([0, 30, 45, 89.999999, rng.uniform(0, 180)]), "spacing": diag / n,
             "origin": list(inside())}
        if rng.random() < 0.5:
            s["persistence"] = rng.choice([0.5, 0.9, 0.999999, 1e-6])
            s["trace_length"] = diag / rng.choice([5, 50, 1000])
        mats = doc.get("joint_materials")
        if isinstance(mats, list) and mats and isinstance(mats[0], dict) and "name" in mats[0]:
            s["joint_material"] = mats[0]["name"]
        if not isinstance(doc.get("joint_sets"), list):
            doc["joint_sets"] = []
        doc["joint_sets"].append(s)
    elif kind == "near-vertex":
        vx, vy = rng.choice(verts + holes or [(0, 0)])
        d = diag * rng.choice([0.0, 1e-15, 1e-12, 1e-9, 1e-7, 1e-6, 1.1e-6, 0.9e-6, 1e-5])
        a = rng.uniform(0, math.pi)
        nx, ny = -math.sin(a), math.cos(a)
        px, py = vx + d * nx, vy + d * ny
        if rng.random() < 0.5:  # passing by the vertex
            add_joint(doc, [(px - L * math.cos(a), py - L * math.sin(a)), (px + L * math.cos(a), py + L * math.sin(a))],
                      "near vertex")
        else:  # ending a hair from it
            add_joint(doc, [(px, py), (px + L * math.cos(a), py + L * math.sin(a))], "ends near vertex")
    elif kind == "self-intersecting":
        regs = [r for r in doc.get("regions", []) if isinstance(r, dict) and isinstance(r.get("boundary"), list)] \
            if isinstance(doc.get("regions"), list) else []
        if regs:
            reg = rng.choice(regs)
            ring = reg["boundary"]
            pts = [i for i, p in enumerate(ring) if isinstance(p, list)]
            how = rng.choice(["bowtie", "repeat", "spike", "collinear", "loop", "zero-area", "overlap-region", "hole-out"])
            log_kinds.append("ring-" + how)
            if how == "bowtie" and len(pts) >= 2:
                i, j = rng.sample(pts, 2)
                ring[i], ring[j] = ring[j], ring[i]
            elif how == "repeat" and pts:
                i = rng.choice(pts)
                ring.insert(i, list(ring[i]))
            elif how == "spike" and pts:
                i = rng.choice(pts)
                p = ring[i]
                ring.insert(i + 1, [p[0] + w * 0.3, p[1] + h * 1e-12])
                ring.insert(i + 2, list(p))
            elif how == "collinear":
                reg["boundary"] = [[x0, y0], [x0 + w / 2, y0], [x1, y0]]
            elif how == "loop" and pts:
                i = rng.choice(pts)
                p = ring[i]
                e = diag * rng.choice([1e-12, 1e-6, 1e-3])
                ring[i + 1:i + 1] = [[p[0] + e, p[1] + e], [p[0] + e, p[1] - e], [p[0] - e, p[1] + e]]
            elif how == "zero-area":
                reg["boundary"] = [[x0, y0], [x1, y1], [x0, y0 + 1e-300]]
            elif how == "overlap-region":
                new = copy.deepcopy(reg)
                new["name"] = "overlap"
                new["boundary"] = [[x0 + w * 0.3, y0 + h * 0.3], [x1 + w, y0 + h * 0.3], [x1 + w, y1 + h], [x0 + w * 0.3, y1 + h]]
                new.pop("holes", None)
                doc["regions"].append(new)
            else:  # a hole that crosses the outline
                if not isinstance(reg.get("holes"), list):
                    reg["holes"] = []
                if True:
                    reg["holes"].append([[x0 - w * 0.1, y0 + h * 0.4], [x0 + w * 0.2, y0 + h * 0.4], [x0 + w * 0.2, y0 + h * 0.6]])
        else:
            doc["regions"] = [{"material": "x", "boundary": [[0, 0], [1, 1], [1, 0], [0, 1]]}]
    elif kind == "near-parallel":
        cx, cy = inside()
        a = rng.uniform(0, math.pi)
        for i in range(rng.choice([2, 3, 10])):
            off = i * diag * rng.choice([0.0, 1e-12, 1e-9, 1e-6, 1e-4])
            add_joint(doc, [(cx - L * math.cos(a) - off * math.sin(a), cy - L * math.sin(a) + off * math.cos(a)),
                            (cx + L * math.cos(a) - off * math.sin(a), cy + L * math.sin(a) + off * math.cos(a))],
                      "parallel %d" % i)
    elif kind == "crack-tips":
        # cracks ending in the rock, a hair from each other
        cx, cy = inside()
        for i in range(rng.choice([2, 4, 8])):
            a = rng.uniform(0, 2 * math.pi)
            e = diag * rng.choice([0.0, 1e-12, 1e-9, 1e-6])
            l = diag * rng.choice([1e-6, 1e-3, 0.05, 0.2])
            add_joint(doc, [(cx + e * math.cos(a), cy + e * math.sin(a)), (cx + l * math.cos(a), cy + l * math.sin(a))],
                      "crack %d" % i)
    else:  # tiny joint
        cx, cy = inside()
        l = diag * rng.choice([1e-15, 1e-12, 1e-9, 1e-6])
        a = rng.uniform(0, math.pi)
        add_joint(doc, [(cx, cy), (cx + l * math.cos(a), cy + l * math.sin(a))], "tiny")
    return doc


# ----------------------------------------------------------------------------------------------
# Result-file (.vtu/.vtp) mutations


def vtk_arrays(text):
    """(start of values, end of values, opening tag) of every DataArray."""
    out = []
    for m in re.finditer(r"<DataArray[^>]*>", text):
        end = text.find("</DataArray>", m.end())
        if end > 0:
            out.append((m.end(), end, m.group(0)))
    return out


COUNT_VALUES = ["0", "-1", "1", "2", "999999999", "1000000000000", "99999999999999999999", "9223372036854775807",
                "18446744073709551616", "-9223372036854775808", "1e9", "abc", "", "3.5", "0x10", " 12", "nan"]
INDEX_VALUES = ["-1", "-5", "99999999", "2147483647", "2147483648", "-2147483648", "9223372036854775807",
                "99999999999999999999", "abc", "1.5", "nan", "", "1e3", "-0"]
FIELD_VALUES = ["nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e308", "-1e308", "1e400", "1e-320", "abc", "",
                "0x1p3", "1,5", "--1", "9" * 400]
CELL_TYPES = ["0", "1", "3", "5", "9", "22", "42", "255", "-1", "256", "70", "7", "abc"]


def replace_values(text, start, end, rng, values, count=None):
    vals = text[start:end].split()
    if not vals:
        return text[:start] + " " + rng.choice(values) + " " + text[end:]
    for _ in range(count or rng.choice([1, 1, 2, 5])):
        vals[rng.randrange(len(vals))] = rng.choice(values)
    return text[:start] + "\n" + " ".join(vals) + "\n" + text[end:]


def mutate_vtk(text, rng, log_kinds, n_points):
    arrays = vtk_arrays(text)
    by_name = {}
    for a in arrays:
        m = re.search(r'Name="([^"]*)"', a[2])
        if m:
            by_name.setdefault(m.group(1), a)
    kind = rng.choice(["count", "count", "connectivity", "connectivity", "offsets", "types", "field", "field", "points",
                       "truncate", "flip", "attr-type", "attr-components", "attr-format", "delete-array",
                       "dup-array", "array-short", "array-long", "xml-break", "entities", "encoding", "empty",
                       "rename-array", "shuffle-offsets"])
    log_kinds.append("vtu-" + kind)
    if kind == "count":
        attr = rng.choice(["NumberOfPoints", "NumberOfCells", "NumberOfVerts", "NumberOfLines", "NumberOfPolys",
                           "NumberOfTuples"])
        return re.sub(r'%s="[^"]*"' % attr, '%s="%s"' % (attr, rng.choice(COUNT_VALUES)), text, count=1)
    if kind == "connectivity" and "connectivity" in by_name:
        s, e, _ = by_name["connectivity"]
        return replace_values(text, s, e, rng, INDEX_VALUES + [str(n_points), str(n_points + 1)])
    if kind == "offsets" and "offsets" in by_name:
        s, e, _ = by_name["offsets"]
        return replace_values(text, s, e, rng, INDEX_VALUES + ["0", "3"])
    if kind == "shuffle-offsets" and "offsets" in by_name:
        s, e, _ = by_name["offsets"]
        vals = text[s:e].split()
        vals.reverse() if rng.random() < 0.5 else rng.shuffle(vals)
        return text[:s] + "\n" + " ".join(vals) + "\n" + text[e:]
    if kind == "types" and "types" in by_name:
        s, e, _ = by_name["types"]
        return replace_values(text, s, e, rng, CELL_TYPES, rng.choice([1, 1, 1000000]))
    if kind in ("field", "points") and arrays:
        if kind == "points" and "Points" in by_name:
            s, e, _ = by_name["Points"]
        else:
            s, e, _ = rng.choice(arrays)
        return replace_values(text, s, e, rng, FIELD_VALUES)
    if kind == "truncate":
        return text[:rng.randrange(len(text) + 1)]
    if kind == "flip":
        data = bytearray(text.encode("utf-8"))
        for _ in range(rng.choice([1, 1, 5, 50])):
            i = rng.randrange(len(data))
            data[i] ^= 1 << rng.randrange(8)
        return bytes(data)
    if kind == "attr-type" and arrays:
        _, _, tag = rng.choice(arrays)
        new = re.sub(r'type="[^"]*"', 'type="%s"' % rng.choice(["Int8", "UInt8", "Int64", "UInt64", "Float32", "String",
                                                                 "Bit", "IdType", "Bogus", ""]), tag)
        return text.replace(tag, new, 1)
    if kind == "attr-components" and arrays:
        _, _, tag = rng.choice(arrays)
        val = rng.choice(["0", "-1", "2", "4", "7", "9", "1000000000", "abc"])
        new = re.sub(r'NumberOfComponents="[^"]*"', 'NumberOfComponents="%s"' % val, tag) \
            if "NumberOfComponents" in tag else tag.replace("<DataArray", '<DataArray NumberOfComponents="%s"' % val)
        return text.replace(tag, new, 1)
    if kind == "attr-format" and arrays:
        _, _, tag = rng.choice(arrays)
        new = re.sub(r'format="[^"]*"', 'format="%s"' % rng.choice(["binary", "appended", "Ascii", "", "raw"]), tag)
        if rng.random() < 0.3:
            new = new.replace(">", ' offset="99999999999">', 1)
        return text.replace(tag, new, 1)
    if kind == "delete-array" and arrays:
        s, e, tag = rng.choice(arrays)
        return text[:s - len(tag)] + text[e + len("</DataArray>"):]
    if kind == "dup-array" and arrays:
        s, e, tag = rng.choice(arrays)
        block = text[s - len(tag):e + len("</DataArray>")]
        return text[:e + len("</DataArray>")] + block + text[e + len("</DataArray>"):]
    if kind == "array-short" and arrays:
        s, e, _ = rng.choice(arrays)
        vals = text[s:e].split()
        return text[:s] + " ".join(vals[:rng.randrange(len(vals) + 1)]) + text[e:]
    if kind == "array-long" and arrays:
        s, e, _ = rng.choice(arrays)
        vals = text[s:e].split()
        return text[:s] + " ".join(vals + vals[:rng.choice([1, 3, 1000])]) + text[e:]
    if kind == "rename-array" and arrays:
        _, _, tag = rng.choice(arrays)
        new = re.sub(r'Name="[^"]*"', 'Name="%s"' % rng.choice(["", "stress", "displacement", "\xff", "x" * 1000]), tag)
        return text.replace(tag, new, 1)
    if kind == "xml-break":
        tags = list(re.finditer(r"</?\w+[^>]*>", text))
        if not tags:
            return text + "<"
        m = rng.choice(tags)
        how = rng.randrange(4)
        if how == 0:
            return text[:m.start()] + text[m.end():]
        if how == 1:
            return text[:m.end()] + m.group(0) + text[m.end():]
        if how == 2:
            return text[:m.start()] + "<" + text[m.start():]
        return text[:m.start()] + "<Piece NumberOfPoints=\"1\" NumberOfCells=\"1\">" + text[m.start():]
    if kind == "entities":
        doctype = ('<?xml version="1.0"?>\n<!DOCTYPE VTKFile [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;'
                   '&a;&a;&a;"><!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;"><!ENTITY d "&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;">'
                   '<!ENTITY e "&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;"><!ENTITY f "&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;">'
                   '<!ENTITY g "&f;&f;&f;&f;&f;&f;&f;&f;&f;&f;"><!ENTITY h "&g;&g;&g;&g;&g;&g;&g;&g;&g;&g;">]>\n')
        body = re.sub(r"^<\?xml[^>]*>\s*", "", text)
        body = body.replace('Name="stress"', 'Name="&h;"', 1) if rng.random() < 0.5 else \
            body.replace('<VTKFile', '<!-- &h; -->\n<VTKFile', 1).replace('</VTKFile>', '&h;</VTKFile>', 1)
        return doctype + body
    if kind == "encoding":
        how = rng.randrange(3)
        if how == 0:
            return text.encode("utf-16")
        if how == 1:
            return b"\xef\xbb\xbf" + text.encode("utf-8")
        return text.replace('<?xml version="1.0"?>', '<?xml version="1.0" encoding="EBCDIC"?>').encode("utf-8")
    if kind == "empty":
        return rng.choice(["", "<", "<VTKFile/>", "<?xml version=\"1.0\"?>", "\x00" * 1000,
                           '<VTKFile type="UnstructuredGrid"><UnstructuredGrid><Piece NumberOfPoints="999999999" '
                           'NumberOfCells="999999999"></Piece></UnstructuredGrid></VTKFile>'])
    log_kinds.append("vtu-fallback-truncate")
    return text[:rng.randrange(len(text) + 1)]


# ----------------------------------------------------------------------------------------------
# DXF drawings and their mutations


def dxf_pairs_test_drawing():
    """The drawing of tests/cli/write_test_dxf.sh."""
    p = [(0, "SECTION"), (2, "HEADER"), (9, "$INSUNITS"), (70, "4"), (0, "ENDSEC"), (0, "SECTION"), (2, "ENTITIES"),
         (0, "LWPOLYLINE"), (8, "rock"), (90, "4"), (70, "1")]
    for x, y in [(0, 0), (20000, 0), (20000, 20000), (0, 20000)]:
        p += [(10, str(x)), (20, str(y))]
    p += [(0, "POLYLINE"), (8, "holes"), (66, "1"), (70, "1")]
    for x, y in [(8000, 8000), (8000, 12000), (12000, 12000), (12000, 8000)]:
        p += [(0, "VERTEX"), (8, "holes"), (10, str(x)), (20, str(y)), (30, "0")]
    p += [(0, "SEQEND"), (0, "LINE"), (8, "joints"), (10, "0"), (20, "15000"), (11, "20000"), (21, "16000"),
          (0, "LWPOLYLINE"), (8, "faults"), (90, "3"), (70, "0")]
    for x, y in [(0, 4000), (6000, 5000), (20000, 3000)]:
        p += [(10, str(x)), (20, str(y))]
    p += [(0, "POINT"), (8, "monitor"), (10, "10000"), (20, "18000"), (0, "CIRCLE"), (8, "0"), (10, "3000"),
          (20, "3000"), (40, "500"), (0, "ENDSEC"), (0, "EOF")]
    return p


def fmt_num(rng, v):
    return rng.choice(["%g", "%.1f", "%.12f", "%r"]) % v if rng.random() < 0.9 else repr(v)


def dxf_pairs_random(rng):
    """A small random drawing: a few closed polylines (some inside others), lines, points."""
    p = []
    if rng.random() < 0.7:
        p += [(0, "SECTION"), (2, "HEADER"), (9, "$INSUNITS"), (70, str(rng.choice([0, 1, 2, 4, 5, 6, 14])))]
        if rng.random() < 0.3:
            p += [(9, "$DWGCODEPAGE"), (3, rng.choice(["ANSI_1252", "ANSI_932", "UTF8"]))]
        p += [(0, "ENDSEC")]
    p += [(0, "SECTION"), (2, "ENTITIES")]
    size = rng.choice([1.0, 20.0, 1000.0, 20000.0])
    for k in range(rng.choice([1, 1, 2, 3])):
        n = rng.choice([3, 4, 5, 8, 50])
        cx, cy = rng.uniform(0, size), rng.uniform(0, size)
        r = size * rng.uniform(0.1, 1.0) / (k + 1)
        pts = [(cx + r * math.cos(2 * math.pi * i / n), cy + r * math.sin(2 * math.pi * i / n)) for i in range(n)]
        layer = rng.choice(["rock", "soil", "holes", "Openings", "0", "rock %d" % k])
        if rng.random() < 0.6:
            p += [(0, "LWPOLYLINE"), (8, layer), (90, str(n)), (70, "1")]
            for x, y in pts:
                p += [(10, fmt_num(rng, x)), (20, fmt_num(rng, y))]
                if rng.random() < 0.05:
                    p += [(42, fmt_num(rng, rng.uniform(-1, 1)))]
        else:
            p += [(0, "POLYLINE"), (8, layer), (66, "1"), (70, "1")]
            for x, y in pts:
                p += [(0, "VERTEX"), (8, layer), (10, fmt_num(rng, x)), (20, fmt_num(rng, y)), (30, "0")]
            p += [(0, "SEQEND")]
    for k in range(rng.choice([0, 1, 2, 5])):
        x0, y0, x1, y1 = (rng.uniform(-0.2, 1.2) * size for _ in range(4))
        p += [(0, "LINE"), (8, rng.choice(["joints", "faults", "0"])), (10, fmt_num(rng, x0)), (20, fmt_num(rng, y0)),
              (11, fmt_num(rng, x1)), (21, fmt_num(rng, y1))]
    for k in range(rng.choice([0, 1, 3])):
        p += [(0, "POINT"), (8, "monitor"), (10, fmt_num(rng, rng.uniform(0, size))), (20, fmt_num(rng, rng.uniform(0, size)))]
    if rng.random() < 0.3:
        p += [(0, rng.choice(["CIRCLE", "ARC", "TEXT", "SPLINE", "INSERT", "HATCH"])), (8, "0"), (10, "1"), (20, "1"),
              (40, "1")]
    p += [(0, "ENDSEC"), (0, "EOF")]
    return p


def parse_dxf_pairs(data):
    """Group code / value pairs of a text DXF (for the bad-input drawings)."""
    lines = data.decode("utf-8", "surrogateescape").splitlines()
    pairs = []
    for i in range(0, len(lines) - 1, 2):
        try:
            pairs.append((int(lines[i].strip()), lines[i + 1]))
        except ValueError:
            pairs.append((lines[i], lines[i + 1]))
    return pairs


DXF_BAD_NUMBERS = ["abc", "", " ", "1e400", "-1e400", "nan", "NaN", "inf", "-inf", "1,5", "0x10", "1e-320", "1e308",
                   "-1e308", "99999999999999999999999", "1.2.3", "--1", "+", "1e", "\x00", "5e-324", "1d3", "١٢٣"]
DXF_BAD_COUNTS = ["0", "-1", "1", "2", "1000000000", "2147483647", "2147483648", "-2147483648", "99999999999999999999",
                  "abc", "", "1e9", "3.5"]
DXF_BAD_CODES = ["x", "", "-1", "999999", "1e3", " 10 ", "0x0A", "10.0", "99999999999999999999", "\x00", "9", "1000",
                 "1071", "330", "100"]


def serialize_dxf(pairs, rng, crlf=False, pad_codes=False):
    nl = "\r\n" if crlf else "\n"
    out = []
    for code, value in pairs:
        c = str(code)
        if pad_codes and isinstance(code, int):
            c = c.rjust(3)
        out.append(c + nl + str(value) + nl)
    return "".join(out)


def mutate_dxf(pairs, rng, log_kinds):
    """Returns the drawing as bytes."""
    pairs = list(pairs)
    n_mut = rng.choice([1, 1, 1, 2, 3])
    byte_kind = None
    for _ in range(n_mut):
        kind = rng.choice(["code", "count", "count", "number", "number", "delete-pair", "delete-line", "dup-pair",
                           "dup-entity", "layer", "insunits", "entity-name", "remove-end", "many-vertices",
                           "zero-length", "self-intersecting", "huge-coords", "bulge", "vertex-outside", "nested",
                           "bytes", "bytes"])
        log_kinds.append("dxf-" + kind)
        idx = rng.randrange(len(pairs)) if pairs else 0
        if kind == "code" and pairs:
            c, v = pairs[idx]
            pairs[idx] = (rng.choice(DXF_BAD_CODES + [str(rng.randrange(-10, 2000))]), v)
        elif kind == "count":
            cands = [i for i, (c, _) in enumerate(pairs) if c in (90, 70, 66, 71, 72, 73, 74)]
            if cands:
                i = rng.choice(cands)
                pairs[i] = (pairs[i][0], rng.choice(DXF_BAD_COUNTS))
        elif kind == "number":
            cands = [i for i, (c, _) in enumerate(pairs) if c in (10, 20, 30, 11, 21, 31, 40, 42, 70)]
            if cands:
                for _ in range(rng.choice([1, 1, 3])):
                    i = rng.choice(cands)
                    pairs[i] = (pairs[i][0], rng.choice(DXF_BAD_NUMBERS))
        elif kind == "delete-pair" and pairs:
            del pairs[idx]
        elif kind == "delete-line" and pairs:
            # drop only the code or only the value: everything after is misaligned
            c, v = pairs[idx]
            flat = [x for cv in pairs for x in cv]
            del flat[2 * idx + rng.randrange(2)]
            pairs = [(flat[i], flat[i + 1]) for i in range(0, len(flat) - 1, 2)] + ([(flat[-1], "")] if len(flat) % 2 else [])
        elif kind == "dup-pair" and pairs:
            pairs.insert(idx, pairs[idx])
        elif kind == "dup-entity":
            starts = [i for i, (c, v) in enumerate(pairs) if c == 0 and v not in ("SECTION", "ENDSEC", "EOF", "SEQEND")]
            if starts:
                s = rng.choice(starts)
                e = next((i for i in range(s + 1, len(pairs)) if pairs[i][0] == 0), len(pairs))
                ent = pairs[s:e]
                # At most about two million groups (tens of MB): a thousand copies of a
                # 100,000-vertex polyline made a 4.5 GB drawing, whose reading is no finding.
                times = min(rng.choice([1, 10, 1000]), max(1, 2000000 // max(1, len(ent))))
                pairs[e:e] = ent * times
        elif kind == "layer":
            cands = [i for i, (c, _) in enumerate(pairs) if c == 8]
            if cands:
                i = rng.choice(cands)
                pairs[i] = (8, rng.choice(["", " ", "ro\xffck", "ro\udcffck", "\udcc3",  "holes", "HOLES", "openings", "x" * 5000, "a\"b", "\\",
                                           "\u00e9", "\u0000", "rock\trock", "%%c", "\\U+00E9", "joints"]))
        elif kind == "insunits":
            cands = [i for i, (c, v) in enumerate(pairs) if c == 9 and v == "$INSUNITS"]
            if cands and cands[0] + 1 < len(pairs):
                pairs[cands[0] + 1] = (70, rng.choice(["-1", "99", "abc", "", "21", "2147483648", "3", "7"]))
            else:
                pairs[0:0] = [(0, "SECTION"), (2, "HEADER"), (9, "$INSUNITS"), (70, rng.choice(["-1", "99", "abc"])),
                              (0, "ENDSEC")]
        elif kind == "entity-name":
            cands = [i for i, (c, _) in enumerate(pairs) if c == 0]
            if cands:
                i = rng.choice(cands)
                pairs[i] = (0, rng.choice(["lwpolyline", "LWPOLYLINE ", "POLYLINE", "VERTEX", "SEQEND", "LINE", "POINT",
                                           "SECTION", "ENDSEC", "EOF", "BLOCK", "ENDBLK", "", "3DFACE", "ENTITIES"]))
        elif kind == "remove-end":
            pairs = [cv for cv in pairs if cv[1] not in rng.choice([("EOF",), ("ENDSEC",), ("EOF", "ENDSEC"), ("SEQEND",)])]
        elif kind == "many-vertices":
            n = rng.choice([1000, 10000, 100000])
            ent = [(0, "LWPOLYLINE"), (8, "rock"), (90, str(n)), (70, "1")]
            for i in range(n):
                a = 2 * math.pi * i / n
                r = 10 + (rng.choice([0, 1e-9, 1e-3]) * (i % 2))
                ent += [(10, "%.17g" % (r * math.cos(a))), (20, "%.17g" % (r * math.sin(a)))]
            pos = next((i for i, (c, v) in enumerate(pairs) if c == 2 and v == "ENTITIES"), len(pairs) - 1)
            pairs[pos + 1:pos + 1] = ent
        elif kind == "zero-length":
            pos = next((i for i, (c, v) in enumerate(pairs) if c == 2 and v == "ENTITIES"), len(pairs) - 1)
            pairs[pos + 1:pos + 1] = [(0, "LINE"), (8, "joints"), (10, "5"), (20, "5"), (11, "5"), (21, "5")]
        elif kind == "self-intersecting":
            pos = next((i for i, (c, v) in enumerate(pairs) if c == 2 and v == "ENTITIES"), len(pairs) - 1)
            pts = rng.choice([[(0, 0), (10, 10), (10, 0), (0, 10)], [(0, 0), (10, 0), (0, 0), (0, 10)],
                              [(0, 0), (1, 0), (2, 0)], [(0, 0), (0, 0), (0, 0)], [(0, 0)], [(0, 0), (1e-300, 0), (0, 1e-300)],
                              [(0, 0), (10, 0), (10, 10), (5, -1e-12), (0, 10)]])
            ent = [(0, "LWPOLYLINE"), (8, rng.choice(["rock", "holes"])), (90, str(len(pts))), (70, "1")]
            for x, y in pts:
                ent += [(10, repr(float(x))), (20, repr(float(y)))]
            pairs[pos + 1:pos + 1] = ent
        elif kind == "huge-coords":
            cands = [i for i, (c, _) in enumerate(pairs) if c in (10, 20, 11, 21)]
            for i in cands[:rng.choice([1, 2, len(cands)])]:
                pairs[i] = (pairs[i][0], rng.choice(["1e300", "-1e300", "1.7976931348623157e308", "1e-300", "1e15",
                                                     "123456789.123456789"]))
        elif kind == "bulge":
            cands = [i for i, (c, _) in enumerate(pairs) if c in (10,)]
            if cands:
                i = rng.choice(cands)
                pairs.insert(i, (42, rng.choice(["1", "-1", "1e300", "nan", "abc", "0.0001", "1e-300"])))
        elif kind == "vertex-outside":
            pos = next((i for i, (c, v) in enumerate(pairs) if c == 2 and v == "ENTITIES"), len(pairs) - 1)
            pairs[pos + 1:pos + 1] = rng.choice([[(0, "VERTEX"), (8, "rock"), (10, "1"), (20, "1")], [(0, "SEQEND")],
                                                 [(0, "POLYLINE"), (8, "rock"), (66, "1"), (70, "1")]])
        elif kind == "nested":
            pairs[idx:idx] = rng.choice([[(0, "SECTION"), (2, "ENTITIES")], [(0, "SECTION")], [(2, "HEADER")],
                                         [(0, "SECTION"), (2, "BLOCKS"), (0, "BLOCK"), (8, "0"), (2, "b")]])
        elif kind == "bytes":
            byte_kind = rng.choice(["truncate", "flip", "nul", "latin1", "invalid-utf8", "utf16", "bom", "cr", "binary",
                                    "empty", "long-line", "crlf-mixed"])
            log_kinds.append("dxf-bytes-" + byte_kind)
    text = serialize_dxf(pairs, rng, crlf=rng.random() < 0.2, pad_codes=rng.random() < 0.3)
    data = text.encode("utf-8", "surrogateescape") if byte_kind != "latin1" else text.encode("latin-1", "replace")
    if byte_kind == "truncate":
        data = data[:rng.randrange(len(data) + 1)]
    elif byte_kind == "flip":
        data = bytearray(data)
        for _ in range(rng.choice([1, 1, 5, 30])):
            if data:
                i = rng.randrange(len(data))
                data[i] ^= 1 << rng.randrange(8)
        data = bytes(data)
    elif byte_kind == "nul" and data:
        i = rng.randrange(len(data))
        data = data[:i] + b"\x00" + data[i:]
    elif byte_kind == "invalid-utf8" and data:
        i = rng.randrange(len(data))
        data = data[:i] + rng.choice([b"\xff", b"\xc3", b"\xed\xa0\x80", b"\x80\x80"]) + data[i:]
    elif byte_kind == "utf16":
        data = text.encode(rng.choice(["utf-16", "utf-16-le", "utf-16-be"]), "replace")
    elif byte_kind == "bom":
        data = rng.choice([b"\xef\xbb\xbf", b"\xff\xfe", b"\xfe\xff"]) + data
    elif byte_kind == "cr":
        data = data.replace(b"\r\n", b"\n").replace(b"\n", b"\r")
    elif byte_kind == "binary":
        data = b"AutoCAD Binary DXF\r\n\x1a\x00" + data[rng.randrange(len(data) + 1):]
    elif byte_kind == "empty":
        data = rng.choice([b"", b"\n", b"0\n", b"0\nEOF\n", b"0\nSECTION\n", b"999\ncomment\n"])
    elif byte_kind == "long-line" and data:
        i = rng.randrange(len(data))
        data = data[:i] + b"1" * rng.choice([10000, 1000000]) + data[i:]
    elif byte_kind == "crlf-mixed":
        data = data.replace(b"\n", b"\r\n", rng.randrange(1, 50))
    return data


# ----------------------------------------------------------------------------------------------
# Studies


def study_base_kirsch(examples):
    return {"format": "mcdda-study", "version": 1,
            "model": os.path.join(examples, "kirsch.json"),
            "set": ["/analysis/steps=1", "/analysis/output_every=1", "/mesh/local/0/size=0.3"],
            "design": {"type": "grid"},
            "parameters": [{"name": "E", "path": "/materials/0/young_modulus", "values": [1e10]}],
            "outputs": [{"name": "crown", "history": "crown:uy"}, {"name": "steps", "summary": "/steps"}],
            "threads_per_run": 1}


def mutate_study(doc, rng, log_kinds, case_files, examples):
    kind = rng.choice(["version", "format", "outputs", "outputs", "parameters", "parameters", "parameters", "model",
                       "model", "design", "set", "threads", "structure", "structure", "model-mutant"])
    log_kinds.append("study-" + kind)
    if not isinstance(doc, dict):
        return doc
    if kind == "version":
        doc["version"] = rng.choice([0, 2, "1", 1.5, None, -1, 1e308, True, [], 1.0000000001, 2 ** 64, "", {}])
    elif kind == "format":
        doc["format"] = rng.choice(["", "mcdda-model", "MCDDA-STUDY", None, 1, "mcdda-study\u0000", "mcdda-study "])
    elif kind == "outputs":
        outs = doc.get("outputs") if isinstance(doc.get("outputs"), list) else []
        how = rng.randrange(8)
        if how == 0:
            doc["outputs"] = rng.choice([[], None, {}, "x", [None], [[]]])
        elif how == 1:
            outs.append({"name": "o", "summary": rng.choice(["/status", "", "/", "/nonexistent", "/steps/0", "~",
                                                               "/factor_of_safety/value", "/timing/total", "/bolts/99/force",
                                                               "/collapse/carried/loads/nope", "no-slash", "/\u00ff"])})
        elif how == 2:
            outs.append({"name": "h", "history": rng.choice(["", "nope:ux", "crown:ux", "step", ",", "\"", "crown:uy,x"])})
        elif how == 3:
            outs.append({"name": "both", "summary": "/steps", "history": "crown:uy"})
        elif how == 4:
            outs.append({"name": rng.choice(["", "=cmd|' /C calc'!A0", "+1", "@x", "\t", "a" * 10000, "steps", None, 5]),
                         "summary": "/steps"})
        elif how == 5:
            outs.extend({"name": "o%d" % i, "summary": "/steps"} for i in range(rng.choice([100, 10000])))
        elif how == 6:
            outs.append({"summary": "/steps"})
        else:
            outs.append(rng.choice([1, "x", [], {"name": "n"}]))
        if how != 0:
            doc["outputs"] = outs
    elif kind == "parameters":
        params = doc.get("parameters") if isinstance(doc.get("parameters"), list) else []
        how = rng.randrange(10)
        p = {"name": "p", "path": rng.choice(["/materials/0/young_modulus", "/materials/0/poisson_ratio",
                                               "/materials/0/cohesion", "/mesh/size", "/analysis/steps",
                                               "/analysis/time_step", "/regions/0/boundary/0/0", "/joint_sets/0/spacing",
                                               "", "/", "/nonexistent/x", "/materials/99/x", "/materials/-",
                                               "materials/0/x", "/materials/0/young_modulus/0", "/~2", "/mesh/size~"])}
        if how == 0:
            doc["parameters"] = rng.choice([[], None, {}, "x"])
            return doc
        if how == 1:
            p["values"] = rng.choice([[], [None], ["x"], [[1]], [{}], [1e308], [-1e308], [5e-324], [0], [-1], [True],
                                      [2 ** 64], [1e10, "1e10"], list(range(rng.choice([21, 1000, 100000])))])
        elif how == 2:
            p["range"] = rng.choice([[0, 1, 0], [0, 1, -1], [0, 1, 1e9], [0, 1, 1e18], [1, 0, 2], [0, 1, 2.5], [0, 1],
                                     [0, 1, 2, 3], [1e308, -1e308, 3], [0, 1, 2 ** 64], [0, 1, 1], ["a", "b", 2],
                                     [1e10, 1e10, 1], [1e10, 2e10, 1000000]])
        elif how == 3:
            p["uniform"] = rng.choice([[0, 1], [1, 0], [1e308, -1e308], [0], "x", [5e9, 1e10]])
        elif how == 4:
            p["values"] = [1e10]
            p["range"] = [1, 2, 2]
        elif how == 5:
            p = {"values": [1e10]}
        elif how == 6:
            p["values"] = [1e10, 2e10]
            params.extend(copy.deepcopy(p) for _ in range(rng.choice([2, 10, 30])))  # grid of 2^n runs
        elif how == 7:
            p["path"] = "/materials/0/young_modulus"
            p["name"] = rng.choice(["", "=1+1", "a,b", "a\nb", "\u00ff", None, 7, "E"])
            p["values"] = [1e10]
        elif how == 8:
            p["values"] = [rng.choice(["1e10", "NaN", "abc", {"circle": 1}, [1, 2]])]
        else:
            p["values"] = [1e10] * rng.choice([1, 20, 21, 5000])
        params.append(p)
        doc["parameters"] = params
    elif kind == "model":
        doc["model"] = rng.choice(["", "/", "/dev/zero", "/dev/null", "/dev/urandom", "/proc/self/status", "nonexistent.json",
                                   "../../../../../../../../etc/passwd", "a\u0000b", "x" * 5000, "/tmp", None, 1, [],
                                   os.path.join(examples, "studies"), os.path.join(examples, "records", "sine-2hz-3-cycles.csv"),
                                   "study.json", ".", "~/model.json", "file:///etc/passwd"])
    elif kind == "model-mutant":
        # the study's model is itself a damaged model
        base = json.loads(open(os.path.join(examples, "kirsch.json")).read())
        kinds = []
        for _ in range(rng.choice([1, 2])):
            base = mutate_structure(base, rng, kinds)
        log_kinds.extend("model-" + k for k in kinds)
        case_files["model.json"] = dump(base, allow_nan=True).encode("utf-8", "surrogatepass")
        doc["model"] = "model.json"
    elif kind == "design":
        doc["design"] = rng.choice([{"type": "latin_hypercube", "samples": rng.choice([0, -1, 1e9, 1e18, 2.5, "x", 1, 2 ** 64]),
                                     "seed": rng.choice([0, -1, 1e30, "x", 2 ** 64])},
                                    {"type": "monte_carlo", "samples": rng.choice([0, 1, -5, 1e12, None]), "seed": 1},
                                    {"type": "latin_hypercube"}, {"type": "nope"}, {"type": None}, [], "grid", None,
                                    {"type": "grid", "samples": 5}])
        if rng.random() < 0.5 and isinstance(doc.get("parameters"), list):
            doc["parameters"].append({"name": "u", "path": "/materials/0/young_modulus", "uniform": [5e9, 1e10]})
    elif kind == "set":
        doc["set"] = rng.choice([None, "x", [1], ["garbage"], ["/analysis/steps=1e9"], ["/analysis/steps=-1"],
                                 ["=1"], ["/=1"], ["/format=\"x\""], ["/mesh/size=1e-9"], ["/materials=[]"],
                                 ["/analysis/steps=1", "/analysis/steps=\"\\u0000\""], ["/a\u00ffb=1"], [""],
                                 ["/analysis/time_step=NaN"], ["/analysis/time_step=1e400"]])
    elif kind == "threads":
        doc["threads_per_run"] = rng.choice([-1, 1e9, 257, 256, "x", 0.5, None, 2 ** 64, 1e308])
    else:
        kinds = []
        doc = mutate_structure(doc, rng, kinds)
        log_kinds.extend("struct-" + k for k in kinds)
    return doc


# ----------------------------------------------------------------------------------------------
# The corpus and the cases


class Corpus:
    def __init__(self, args, mcdda, out):
        self.examples = os.path.abspath(args.examples)
        self.repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        self.models = {}
        for name in sorted(os.listdir(self.examples)):
            if name.endswith(".json"):
                path = os.path.join(self.examples, name)
                try:
                    doc = json.loads(open(path, encoding="utf-8").read())
                except (OSError, ValueError):
                    continue
                self.absolutize(doc)
                self.models[name[:-5]] = doc
        if not self.models:
            raise SystemExit("no example models in %s" % self.examples)
        wanted = args.run_examples.split(",") if args.run_examples else DEFAULT_RUN_EXAMPLES
        self.run_models = [n for n in wanted if n in self.models] or sorted(self.models)
        self.geometry_models = [n for n in GEOMETRY_EXAMPLES if n in self.models] or sorted(self.models)
        # DXF drawings
        self.dxf_bases = [("test-drawing", dxf_pairs_test_drawing())]
        bad = os.path.join(self.repo, "tests", "cli", "bad-input")
        if os.path.isdir(bad):
            for name in sorted(os.listdir(bad)):
                if name.endswith(".dxf"):
                    self.dxf_bases.append((name, parse_dxf_pairs(open(os.path.join(bad, name), "rb").read())))
        # studies
        self.study_bases = [("kirsch-study", study_base_kirsch(self.examples))]
        sdir = os.path.join(self.examples, "studies")
        if os.path.isdir(sdir):
            for name in sorted(os.listdir(sdir)):
                if name.endswith(".json"):
                    try:
                        doc = json.loads(open(os.path.join(sdir, name), encoding="utf-8").read())
                    except ValueError:
                        continue
                    if isinstance(doc.get("model"), str):
                        doc["model"] = os.path.normpath(os.path.join(sdir, doc["model"]))
                    # keep them quick should they pass: one step, one value per parameter
                    doc["set"] = list(doc.get("set", [])) + ["/analysis/steps=1", "/analysis/max_trials=3"]
                    for p in doc.get("parameters", []):
                        if "values" in p:
                            p["values"] = p["values"][:1]
                        if "range" in p:
                            p["range"] = [p["range"][0], p["range"][1], 1]
                    self.study_bases.append((name, doc))
        self.bad_study_texts = []
        if os.path.isdir(bad):
            for name in sorted(os.listdir(bad)):
                if name.startswith("study-") and name.endswith(".json"):
                    text = open(os.path.join(bad, name), encoding="utf-8", errors="replace").read()
                    text = text.replace("../../../examples/", self.examples + "/").replace(
                        "../models/", os.path.join(self.repo, "tests", "cli", "models") + "/")
                    self.bad_study_texts.append((name, text))
        self.results = None  # (model path, vtu text, vtp text or None, point count)

    def absolutize(self, doc):
        """Record files named relative to the examples folder, made absolute."""
        for gm in doc.get("ground_motions", []) or []:
            if isinstance(gm, dict) and isinstance(gm.get("file"), str) and not os.path.isabs(gm["file"]):
                gm["file"] = os.path.join(self.examples, gm["file"])

    def prepare_results(self, mcdda, out, env, timeout):
        run_dir = os.path.join(out, "base", "kirsch-run")
        shutil.rmtree(run_dir, ignore_errors=True)
        model = os.path.join(self.examples, "kirsch.json")
        cmd = [mcdda, "run", model, "--out", run_dir, "--quiet", "--set", "/analysis/steps=1", "--threads", "1"]
        try:
            p = subprocess.run(cmd, capture_output=True, timeout=max(timeout * 6, 120), env=env)
        except subprocess.TimeoutExpired:
            log("warning: the base run of kirsch.json timed out: render mutants left out")
            return False
        vtu = os.path.join(run_dir, "kirsch_000001.vtu")
        if p.returncode != 0 or not os.path.exists(vtu):
            log("warning: the base run of kirsch.json failed (exit %d): render mutants left out\n%s"
                % (p.returncode, (p.stdout + p.stderr).decode(errors="replace")[-2000:]))
            return False
        text = open(vtu, encoding="utf-8").read()
        vtp_path = os.path.join(run_dir, "kirsch_contacts_000001.vtp")
        vtp = open(vtp_path, encoding="utf-8").read() if os.path.exists(vtp_path) else None
        m = re.search(r'NumberOfPoints="(\d+)"', text)
        self.results = (model, text, vtp, int(m.group(1)) if m else 0)
        # render itself must work, or every render mutant would only say so
        png = os.path.join(out, "base", "good.png")
        try:
            p = subprocess.run([mcdda, "render", model, "--results", vtu, "--out", png], capture_output=True,
                               timeout=max(timeout * 3, 60), env=env)
        except subprocess.TimeoutExpired:
            log("warning: rendering the undamaged results timed out: render mutants left out")
            return False
        if p.returncode != 0:
            log("warning: `mcdda render` of the undamaged results failed (exit %d): render mutants left out\n%s"
                % (p.returncode, (p.stdout + p.stderr).decode(errors="replace")[-1000:]))
            return False
        return True


class Case:
    def __init__(self, index, command):
        self.index = index
        self.command = command
        self.files = {}  # name -> bytes
        self.args = []  # after the program; file names relative to the case folder
        self.family = ""
        self.kinds = []
        self.base = ""


def make_case(index, command, corpus, seed):
    """Mutant `index` for `command`; a mutation that trips over its own input is drawn again."""
    for attempt in range(10):
        try:
            return make_case_once(index, command, corpus, seed if attempt == 0 else "%s/retry%d" % (seed, attempt))
        except Exception as e:  # noqa: BLE001 - a generator fault, not a finding
            last = e
    raise RuntimeError("cannot make mutant %d for %s: %r" % (index, command, last))


def make_case_once(index, command, corpus, seed):
    rng = random.Random("%s:%d:%s" % (seed, index, command))
    c = Case(index, command)
    if command in ("check", "mesh", "run"):
        make_model_case(c, rng, corpus)
    elif command == "render":
        make_render_case(c, rng, corpus)
    elif command == "import-dxf":
        make_dxf_case(c, rng, corpus)
    else:
        make_study_case(c, rng, corpus)
    return c


SET_POINTERS = ["/materials/0/young_modulus", "/materials/0", "/materials/-", "/materials/99999999999999999999", "",
                "/", "//", "/~2", "/~", "/a~1b", "/mesh/size", "/analysis/steps", "/regions/0/boundary/0",
                "/joints/-", "/format", "/version", "/analysis", "/\u00ff", "/materials/0/name", "/materials/01"]
SET_VALUES = ["1", "-1", "1e400", "NaN", "", "null", "[]", "{}", "\"x\"", "x", "{\"a\":", "1e308", "0", "[[0,0],[1,1]]",
              "\"\\u0000\"", "true", "9" * 400, "\udcff"]


def make_model_case(c, rng, corpus):
    names = corpus.run_models if c.command == "run" else sorted(corpus.models)
    geometric = rng.random() < 0.35
    if geometric:
        names = [n for n in names if n in corpus.geometry_models] or names
    base_name = rng.choice(names)
    doc = copy.deepcopy(corpus.models[base_name])
    c.base = base_name
    # bounded work: the mesher refuses a size field that asks for more, one step per run
    cap = 20000 if c.command == "run" else 200000
    if isinstance(doc.get("mesh"), dict):
        doc["mesh"].setdefault("max_elements", cap)
        doc["mesh"]["max_elements"] = min(doc["mesh"]["max_elements"], cap)
    if c.command == "run":
        if isinstance(doc.get("analysis"), dict):
            doc["analysis"]["steps"] = 1
            doc["analysis"]["max_trials"] = 3
        for st in doc.get("stages", []) or []:
            if isinstance(st, dict) and "steps" in st:
                st["steps"] = 1
    text_level = False
    if geometric:
        c.family = "geometry"
        doc = mutate_geometry(doc, rng, c.kinds)
        if rng.random() < 0.2:
            doc = mutate_structure(doc, rng, c.kinds)
    else:
        r = rng.random()
        if r < 0.3:
            c.family = "text"
            text_level = True
        else:
            c.family = "structure"
            for _ in range(rng.choice([1, 1, 2, 3])):
                doc = mutate_structure(doc, rng, c.kinds)
    try:
        text = dump(doc, rng, allow_nan=False)
    except ValueError:
        text = dump(doc, rng, allow_nan=True)
    data = mutate_text(text, rng, c.kinds) if text_level else text.encode("utf-8", "surrogatepass")
    c.files["model.json"] = data
    extra = []
    if c.command == "check" and rng.random() < 0.12:
        c.family += "+set"
        c.kinds.append("set")
        for _ in range(rng.choice([1, 2])):
            extra += ["--set", rng.choice(SET_POINTERS) + "=" + rng.choice(SET_VALUES)]
    if c.command == "check":
        c.args = ["check", "model.json"] + extra
    elif c.command == "mesh":
        c.args = ["mesh", "model.json", "--out", "mesh"]
    else:
        c.args = ["run", "model.json", "--out", "run", "--quiet", "--threads", "1", "--set", "/analysis/steps=1"]


def make_render_case(c, rng, corpus):
    model, vtu, vtp, n_points = corpus.results
    c.base = "kirsch_000001.vtu"
    c.family = "results"
    extra = []
    if vtp and rng.random() < 0.15:
        c.family = "contacts"
        c.files["r.vtu"] = vtu.encode()
        data = mutate_vtk(vtp, rng, c.kinds, n_points)
        c.files["c.vtp"] = data if isinstance(data, bytes) else data.encode("utf-8", "surrogateescape")
        extra += ["--contacts", "c.vtp"]
    else:
        text = vtu
        for _ in range(rng.choice([1, 1, 1, 2, 3])):
            text = mutate_vtk(text, rng, c.kinds, n_points)
            if isinstance(text, bytes):
                break
        c.files["r.vtu"] = text if isinstance(text, bytes) else text.encode("utf-8", "surrogateescape")
    if rng.random() < 0.3:
        extra += ["--field", rng.choice(["stress_xx", "stress_1", "displacement", "plastic_state", "block", "material",
                                         "velocity", "stress", "displacement_x", "nope", "", "stress_9"])]
    if rng.random() < 0.15:
        extra += ["--deform", rng.choice(["auto", "1e300", "0", "-1", "nan", "1000"])]
    if rng.random() < 0.05:
        extra += ["--size", rng.choice(["1x1", "0x0", "64x64", "2x100000", "abc", "-5x5"])]
    if rng.random() < 0.05:
        extra += ["--bands", rng.choice(["0", "1", "1000000", "-3", "x"])]
    c.args = ["render", model, "--results", "r.vtu", "--out", "x.png"] + extra


def make_dxf_case(c, rng, corpus):
    c.family = "dxf"
    if rng.random() < 0.5:
        base_name, pairs = "random", dxf_pairs_random(rng)
    else:
        base_name, pairs = rng.choice(corpus.dxf_bases)
    c.base = base_name
    c.files["d.dxf"] = mutate_dxf(pairs, rng, c.kinds) if rng.random() < 0.95 else \
        serialize_dxf(pairs, rng).encode("utf-8", "surrogateescape")
    extra = []
    if rng.random() < 0.2:
        extra = ["--units", rng.choice(["m", "mm", "cm", "km", "in", "ft", "", "furlongs", "MM"])]
    c.args = ["import-dxf", "d.dxf", "--out", "m.json"] + extra


def make_study_case(c, rng, corpus):
    r = rng.random()
    if r < 0.1 and corpus.bad_study_texts:
        c.base, text = rng.choice(corpus.bad_study_texts)
        c.family = "study-text"
        c.files["study.json"] = mutate_text(text, rng, c.kinds)
    else:
        c.base, doc = rng.choice(corpus.study_bases)
        doc = copy.deepcopy(doc)
        if r < 0.35:
            c.family = "study-text"
            c.files["study.json"] = mutate_text(dump(doc, rng), rng, c.kinds)
        else:
            c.family = "study"
            for _ in range(rng.choice([1, 1, 2])):
                doc = mutate_study(doc, rng, c.kinds, c.files, corpus.examples)
            try:
                text = dump(doc, rng)
            except ValueError:
                text = dump(doc, rng, allow_nan=True)
            c.files["study.json"] = text.encode("utf-8", "surrogatepass")
    c.args = ["study", "study.json", "--out", "out", "--quiet", "--threads", "1"]


# ----------------------------------------------------------------------------------------------
# Running and classifying


def limit_process(pid, mb):
    """No core files; at most `mb` MB of address space (set from outside: preexec_fn is unsafe with threads)."""
    try:
        resource.prlimit(pid, resource.RLIMIT_CORE, (0, 0))
        if mb > 0:
            resource.prlimit(pid, resource.RLIMIT_AS, (mb << 20, mb << 20))
    except (ValueError, OSError):
        pass


def kill_group(proc):
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def first_message_line(out):
    for line in out.splitlines():
        line = line.strip()
        if line:
            return line
    return ""


def signature(case, outcome, out, reason):
    """A finding's kind: the command, the outcome and its message with numbers and paths blurred; for a
    hang, the mutations; for VTK's log, the file damaged (results or contacts)."""
    command = case.command
    if outcome == "HANG" or (outcome == "CRASH" and not out.strip()):
        kinds = sorted(set(k for k in case.kinds if not k.startswith("ring-")))
        return "%s %s (%s) after %s" % (command, outcome, reason, "+".join(kinds) or case.family)
    if reason == "VTK log text":
        m = re.search(r"ERR\| (vtk\w+)", out)
        return "%s %s: VTK log text (%s file damaged; %s)" % (command, outcome, case.family, m.group(1) if m else "")
    text = re.sub(r"\x1b\[[0-9;]*m", "", out)
    # VTK's log prefix: date, time, seconds since start, thread
    text = re.sub(r"\d{4}-\d\d-\d\d [\d:.]+ \(\s*[\d.]+s\) \[\s*\w+\]\s*", "", text)
    text = re.sub(r"0x[0-9a-fA-F]+", "0x…", text)
    line = reason + ": " + first_message_line(text) if reason else first_message_line(text)
    line = re.sub(r"/[^\s:\"']*/", "…/", line)
    line = re.sub(r"\d+(\.\d+)?([eE][-+]?\d+)?", "N", line)
    line = re.sub(r'"[^"]{20,}"', '"…"', line)
    return "%s %s: %s" % (command, outcome, line[:160])


def classify(case, rc, out, timed_out, case_dir, sanitized):
    """(outcome, reason) of one call."""
    if timed_out:
        if case.command == "study" and os.path.isdir(os.path.join(case_dir, "out", "runs")):
            return "slow", "runs started; stopped at the timeout"
        return "HANG", "timeout"
    m = SANITIZER.search(out)
    if m:
        return "CRASH", "sanitizer: " + m.group(0)
    if rc < 0:
        return "CRASH", "signal %d (%s)" % (-rc, signal.Signals(-rc).name if -rc in signal.Signals._value2member_map_ else "?")
    if rc >= 128 and rc != 130:
        return "CRASH", "exit status %d" % rc
    if case.command == "study":
        for root, _, files in os.walk(os.path.join(case_dir, "out")):
            for f in files:
                if f == "log.txt":
                    try:
                        text = open(os.path.join(root, f), errors="replace").read()
                    except OSError:
                        continue
                    m = SANITIZER.search(text)
                    if m:
                        return "CRASH", "sanitizer in a run: " + m.group(0)
        m = CHILD_SIGNAL.search(out)
        if m and int(m.group(1)) not in (signal.SIGKILL, signal.SIGTERM, signal.SIGINT):
            return "CRASH", "a run was killed by signal %s" % m.group(1)
    for pattern, name in UNCLEAR_PATTERNS:
        if pattern.search(out):
            return "UNCLEAR", name
    if rc != 0 and not out.strip():
        return "UNCLEAR", "error exit %d with no message" % rc
    if rc == 0 or (case.command == "run" and rc in (3, 4, 5)):
        return "ok", ""  # a run's result: completed, unbalanced, failed or collapsed (docs/running.md)
    return "refused", ""


class Harness:
    def __init__(self, args):
        self.args = args
        self.mcdda = os.path.abspath(args.mcdda)
        self.out = os.path.abspath(args.out)
        self.cases_dir = os.path.join(self.out, "cases")
        self.findings_dir = os.path.join(self.out, "findings")
        self.lock = threading.Lock()
        self.counts = collections.defaultdict(collections.Counter)  # command -> outcome -> n
        self.exit_codes = collections.defaultdict(collections.Counter)
        self.families = collections.defaultdict(collections.Counter)
        self.kinds = collections.OrderedDict()  # signature -> {count, first finding folder}
        self.seconds = collections.Counter()
        self.done = 0
        self.findings = 0
        self.stop = False
        self.env = dict(os.environ)
        supp = os.path.join(os.path.dirname(os.path.abspath(__file__)), "sanitize-suppressions.txt")
        asan = "detect_leaks=1:abort_on_error=0:allocator_may_return_null=1"
        if args.memory_mb > 0:
            asan += ":hard_rss_limit_mb=%d" % args.memory_mb
        self.env.setdefault("ASAN_OPTIONS", asan)
        self.env.setdefault("UBSAN_OPTIONS", "print_stacktrace=1:halt_on_error=1")
        if os.path.exists(supp):
            self.env.setdefault("LSAN_OPTIONS", "suppressions=%s:print_suppressions=0" % supp)
        self.env.setdefault("MCDDA_THREADS", "1")
        self.env.setdefault("OMP_NUM_THREADS", "1")
        self.env.setdefault("OPENBLAS_NUM_THREADS", "1")
        self.sanitized = self.detect_sanitizer()
        self.render_env = dict(self.env)
        self.xvfb = None

    def detect_sanitizer(self):
        try:
            data = open(self.mcdda, "rb").read()
        except OSError:
            return False
        return b"__asan_init" in data or b"__ubsan_handle" in data

    def start_display(self):
        """One Xvfb for every render call (xvfb-run per call costs a server start each)."""
        if self.args.display != "own" or os.environ.get("DISPLAY") or not shutil.which("Xvfb"):
            self.render_env.pop("DISPLAY", None) if self.args.display == "xvfb-run" else None
            return
        for n in range(97, 140):
            if os.path.exists("/tmp/.X%d-lock" % n) or os.path.exists("/tmp/.X11-unix/X%d" % n):
                continue
            proc = subprocess.Popen(["Xvfb", ":%d" % n, "-screen", "0", "1920x1200x24", "-nolisten", "tcp"],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
            for _ in range(50):
                if os.path.exists("/tmp/.X11-unix/X%d" % n):
                    break
                if proc.poll() is not None:
                    break
                time.sleep(0.1)
            if proc.poll() is None:
                self.xvfb = proc
                self.render_env["DISPLAY"] = ":%d" % n
                return
        log("warning: could not start Xvfb; render calls start xvfb-run each")

    def stop_display(self):
        if self.xvfb:
            kill_group(self.xvfb)
            self.xvfb.wait()

    def run_case(self, case):
        case_dir = os.path.join(self.cases_dir, "%06d-%s" % (case.index, case.command))
        shutil.rmtree(case_dir, ignore_errors=True)
        os.makedirs(case_dir)
        for name, data in case.files.items():
            with open(os.path.join(case_dir, name), "wb") as f:
                f.write(data)
        argv = [self.mcdda] + case.args
        env = self.render_env if case.command == "render" else self.env
        mem = 0 if self.sanitized else self.args.memory_mb
        start = time.monotonic()
        timed_out = False
        for attempt in range(121):
            try:
                proc = subprocess.Popen(argv, cwd=case_dir, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, env=env, start_new_session=True)
                break
            except OSError as e:  # the program being relinked under us: wait for it
                if attempt == 120:
                    log("cannot run %s: %s; stopping" % (self.mcdda, e))
                    self.stop = True
                    shutil.rmtree(case_dir, ignore_errors=True)
                    return
                time.sleep(1)
        start = time.monotonic()
        # A sanitized program sets its own core-dump limit at start-up: lowering the hard limit
        # from outside while it does made ASan abort ("setrlimit() failed"), a race of the harness
        # (ASan writes no core dumps on 64-bit Linux by default anyway).
        if not self.sanitized:
            limit_process(proc.pid, mem)
        try:
            raw, _ = proc.communicate(timeout=self.args.timeout)
        except subprocess.TimeoutExpired:
            timed_out = True
            kill_group(proc)
            raw, _ = proc.communicate()
        kill_group(proc)  # anything the call left behind (xvfb-run's server, a study's runs)
        seconds = time.monotonic() - start
        rc = proc.returncode
        out = raw.decode("utf-8", errors="replace")
        outcome, reason = classify(case, rc, out, timed_out, case_dir, self.sanitized)
        keep = outcome in ("CRASH", "HANG", "UNCLEAR")
        folder = None
        if keep:
            folder = os.path.join(self.findings_dir, "%06d-%s-%s" % (case.index, case.command, outcome))
            shutil.rmtree(folder, ignore_errors=True)
            for sub in ("mesh", "run", "x.png", "m.json") + (() if case.command == "study" and outcome == "CRASH" else ("out",)):
                p = os.path.join(case_dir, sub)
                if os.path.isdir(p):
                    shutil.rmtree(p, ignore_errors=True)
                elif os.path.exists(p):
                    os.remove(p)
            os.makedirs(self.findings_dir, exist_ok=True)
            shutil.move(case_dir, folder)
            self.write_repro(folder, case, rc, out, outcome, reason, seconds, timed_out)
        else:
            shutil.rmtree(case_dir, ignore_errors=True)
        if self.args.verbose:
            log("%06d %-10s %-8s exit %-7s %5.1fs %s [%s] %s" % (
                case.index, case.command, outcome, "timeout" if timed_out else rc, seconds, case.base,
                ",".join(case.kinds), first_message_line(out)[:200]))
        sig = signature(case, outcome, out, reason) if keep else None
        with self.lock:
            self.done += 1
            self.counts[case.command][outcome] += 1
            self.exit_codes[case.command]["timeout" if timed_out else str(rc)] += 1
            self.families["%s/%s" % (case.command, case.family)][outcome] += 1
            self.seconds[case.command] += seconds
            if keep:
                self.findings += 1
                entry = self.kinds.get(sig)
                if entry is None:
                    entry = self.kinds[sig] = {"count": 0, "first": folder, "examples": []}
                    self.report_new_kind(sig, folder, case, out, reason)
                entry["count"] += 1
                if len(entry["examples"]) < 5:
                    entry["examples"].append(folder)
                if self.args.stop_on_finding:
                    self.stop = True

    def emit_case(self, case):
        """Writes the mutant's files and its command line to OUT/mutants/, without running it."""
        folder = os.path.join(self.out, "mutants", "%06d-%s" % (case.index, case.command))
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        for name, data in case.files.items():
            with open(os.path.join(folder, name), "wb") as f:
                f.write(data)
        cmd = " ".join(shlex.quote(a) for a in [self.mcdda] + case.args)
        with open(os.path.join(folder, "repro.sh"), "w") as f:
            f.write("#!/bin/sh\n# %s - mutant %d of seed %s, base %s, mutations: %s\n"
                    % (case.command, case.index, self.args.seed, case.base, ", ".join(case.kinds)))
            f.write('cd "$(dirname "$0")" && %s\n' % cmd)
        os.chmod(os.path.join(folder, "repro.sh"), 0o755)
        with self.lock:
            self.done += 1
            self.counts[case.command]["emitted"] += 1

    def write_repro(self, folder, case, rc, out, outcome, reason, seconds, timed_out):
        cmd = " ".join(shlex.quote(a) for a in [self.mcdda] + case.args)
        with open(os.path.join(folder, "repro.sh"), "w") as f:
            f.write("#!/bin/sh\n# %s %s (%s) - mutant %d of seed %s, base %s, mutations: %s\n"
                    % (case.command, outcome, reason, case.index, self.args.seed, case.base, ", ".join(case.kinds)))
            f.write('cd "$(dirname "$0")" && %s%s\n' % ("timeout %d " % (self.args.timeout * 3) if timed_out else "", cmd))
        os.chmod(os.path.join(folder, "repro.sh"), 0o755)
        with open(os.path.join(folder, "output.txt"), "w") as f:
            f.write("command: %s\nexit: %s\nseconds: %.1f\noutcome: %s (%s)\nbase: %s\nmutations: %s\n\n"
                    % (cmd, "timeout" if timed_out else rc, seconds, outcome, reason, case.base, ", ".join(case.kinds)))
            f.write(out[-20000:])

    def report_new_kind(self, sig, folder, case, out, reason):
        log("NEW FINDING: %s\n  %s/repro.sh" % (sig, folder))
        if self.args.findings_log:
            with open(self.args.findings_log, "a") as f:
                f.write("\n### %s\n\n- when: %s, mutant %d of seed %s (base %s; mutations: %s)\n- reason: %s\n"
                        "- reproduce: `sh %s/repro.sh` (input in that folder)\n- command: `%s`\n"
                        "- output (last lines):\n\n```\n%s\n```\n"
                        % (sig, time.strftime("%H:%M:%S"), case.index, self.args.seed, case.base,
                           ", ".join(case.kinds), reason, folder,
                           " ".join(shlex.quote(a) for a in [self.mcdda] + case.args),
                           "\n".join(out.strip().splitlines()[-12:])[:3000]))

    def summary(self, wall, planned):
        commands = [c for c in ALL_COMMANDS if c in self.counts]
        outcomes = ["ok", "refused", "slow", "CRASH", "HANG", "UNCLEAR"]
        lines = ["%-11s %8s %8s %6s %6s %6s %8s %8s %10s" % ("command", "ok", "refused", "slow", "CRASH", "HANG",
                                                              "UNCLEAR", "total", "s/call")]
        total = collections.Counter()
        for c in commands:
            n = sum(self.counts[c].values())
            total.update(self.counts[c])
            lines.append("%-11s %8d %8d %6d %6d %6d %8d %8d %10.2f" % (
                c, *(self.counts[c][o] for o in outcomes), n, self.seconds[c] / max(n, 1)))
        n = sum(total.values())
        lines.append("%-11s %8d %8d %6d %6d %6d %8d %8d" % ("all", *(total[o] for o in outcomes), n))
        lines.append("%d mutants (of %d planned) in %.0f s wall (%.1f calls/s), %d findings of %d kinds"
                     % (n, planned, wall, n / max(wall, 1e-9), self.findings, len(self.kinds)))
        for sig, e in self.kinds.items():
            lines.append("  [%d] %s\n       %s/repro.sh" % (e["count"], sig, e["first"]))
        text = "\n".join(lines)
        data = {"mcdda": self.mcdda, "sanitized": self.sanitized, "seed": self.args.seed, "first": self.args.first,
                "planned": planned,
                "mutants": n, "wall_seconds": round(wall, 1), "timeout": self.args.timeout, "jobs": self.args.jobs,
                "counts": {c: dict(self.counts[c]) for c in commands},
                "exit_codes": {c: dict(self.exit_codes[c]) for c in commands},
                "families": {k: dict(v) for k, v in sorted(self.families.items())},
                "seconds_per_call": {c: round(self.seconds[c] / max(sum(self.counts[c].values()), 1), 3) for c in commands},
                "findings": self.findings,
                "finding_kinds": [{"signature": s, **e} for s, e in self.kinds.items()]}
        with open(os.path.join(self.out, "summary.json"), "w") as f:
            json.dump(data, f, indent=2)
        return text


def parse_weights(text, commands):
    weights = {c: DEFAULT_WEIGHTS[c] for c in commands}
    if text:
        for item in text.split(","):
            name, _, value = item.partition("=")
            if name not in ALL_COMMANDS:
                raise SystemExit("--weights: unknown command %r" % name)
            if name in weights:
                weights[name] = float(value)
    return weights


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mcdda", required=True, help="the mcdda program (a sanitized build too)")
    ap.add_argument("--examples", required=True, help="the examples folder (models, studies/)")
    ap.add_argument("--mutants", type=int, default=200, help="number of calls (default 200)")
    ap.add_argument("--seed", default="1", help="random seed (default 1)")
    ap.add_argument("--out", required=True, help="work folder: summary.json, findings/")
    ap.add_argument("--timeout", type=float, default=20, help="seconds per call before it is a HANG (default 20)")
    ap.add_argument("--commands", default=",".join(ALL_COMMANDS), help="commands to fuzz (default all)")
    ap.add_argument("--weights", default="", help="share of the mutants per command, e.g. check=6,run=1 (defaults: %s)"
                    % ",".join("%s=%g" % kv for kv in DEFAULT_WEIGHTS.items()))
    ap.add_argument("--jobs", type=int, default=2, help="calls in parallel (default 2)")
    ap.add_argument("--max-seconds", type=float, default=0, help="stop starting calls after this long (0: no limit)")
    ap.add_argument("--memory-mb", type=int, default=4000,
                    help="address-space limit per call, MB (default 4000; 0: none; not applied to sanitized builds, "
                         "which get ASan's hard_rss_limit_mb instead)")
    ap.add_argument("--run-examples", default="", help="examples `run` mutants start from (comma-separated names)")
    ap.add_argument("--display", choices=["own", "xvfb-run"], default="own",
                    help="render: one Xvfb started here for all calls (default), or each call's own xvfb-run")
    ap.add_argument("--findings-log", default="", help="append each new kind of finding to this Markdown file")
    ap.add_argument("--only", default="", help="make and run only these mutant numbers (comma-separated)")
    ap.add_argument("--first", type=int, default=0,
                    help="start at this mutant number: continues a long run that was stopped (its summary "
                         "gave the count done) with the same seed, commands and weights")
    ap.add_argument("--stop-on-finding", action="store_true")
    ap.add_argument("--verbose", action="store_true", help="one line per call")
    ap.add_argument("--keep-going", action="store_true", help="exit 0 even with findings")
    ap.add_argument("--emit-only", action="store_true",
                    help="write each mutant and its command line to OUT/mutants/NNNNNN-COMMAND/ without running it "
                         "(with --only: to make one finding's input again)")
    args = ap.parse_args()

    commands = [c.strip() for c in args.commands.split(",") if c.strip()]
    for c in commands:
        if c not in ALL_COMMANDS:
            ap.error("--commands: unknown command %r (known: %s)" % (c, ", ".join(ALL_COMMANDS)))
    if not os.access(args.mcdda, os.X_OK):
        ap.error("--mcdda %s is not an executable" % args.mcdda)
    h = Harness(args)
    os.makedirs(h.out, exist_ok=True)
    shutil.rmtree(h.cases_dir, ignore_errors=True)
    shutil.rmtree(h.findings_dir, ignore_errors=True)
    if args.emit_only:
        shutil.rmtree(os.path.join(h.out, "mutants"), ignore_errors=True)
    os.makedirs(h.cases_dir)
    corpus = Corpus(args, h.mcdda, h.out)
    if "render" in commands:
        h.start_display()
        if not corpus.prepare_results(h.mcdda, h.out, h.render_env, args.timeout):
            commands.remove("render")
    if not commands:
        h.stop_display()
        raise SystemExit("no command left to fuzz")
    weights = parse_weights(args.weights, commands)
    order_rng = random.Random("order:%s" % args.seed)
    names = list(weights)
    cum = [weights[n] for n in names]

    def command_of(i):
        return random.Random("cmd:%s:%d" % (args.seed, i)).choices(names, weights=cum)[0]

    if not 0 <= args.first <= args.mutants:
        ap.error("--first %d: not between 0 and --mutants %d" % (args.first, args.mutants))
    indices = [int(x) for x in args.only.split(",")] if args.only else range(args.first, args.mutants)
    planned = len(indices)
    log("fuzzing %s (%s) with %d mutants, seed %s, %d jobs, timeout %g s; weights %s"
        % (h.mcdda, "sanitized" if h.sanitized else "not sanitized", planned, args.seed, args.jobs, args.timeout,
           ", ".join("%s=%g" % kv for kv in weights.items())))
    start = time.monotonic()
    last_report = start
    interrupted = False
    harness_error = False

    def stop_with_summary(signum, frame):
        raise KeyboardInterrupt

    # A background job inherits SIGINT ignored, and kill sends SIGTERM: both end with the summary.
    signal.signal(signal.SIGINT, stop_with_summary)
    signal.signal(signal.SIGTERM, stop_with_summary)
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            pending = set()
            it = iter(indices)
            exhausted = False
            while True:
                while not exhausted and len(pending) < args.jobs * 2 and not h.stop:
                    if args.max_seconds and time.monotonic() - start > args.max_seconds:
                        exhausted = True
                        break
                    i = next(it, None)
                    if i is None:
                        exhausted = True
                        break
                    case = make_case(i, command_of(i), corpus, args.seed)
                    pending.add(pool.submit(h.emit_case if args.emit_only else h.run_case, case))
                if not pending:
                    break
                done, pending = concurrent.futures.wait(pending, return_when=concurrent.futures.FIRST_COMPLETED)
                for f in done:
                    f.result()
                now = time.monotonic()
                if now - last_report > 30:
                    last_report = now
                    log("%d/%d done, %.1f calls/s, %d findings" % (h.done, planned, h.done / (now - start), h.findings))
                if h.stop:
                    exhausted = True
    except KeyboardInterrupt:
        interrupted = True
        log("interrupted: summary of the calls done")
    except Exception:  # a fault of the harness itself: say so, and still give the summary
        import traceback
        traceback.print_exc()
        harness_error = True
    finally:
        h.stop_display()
    wall = time.monotonic() - start
    if args.emit_only:
        print("%d mutants written to %s (not run)" % (h.done, os.path.join(h.out, "mutants")))
        shutil.rmtree(h.cases_dir, ignore_errors=True)
        sys.exit(130 if interrupted else 2 if harness_error else 0)
    print(h.summary(wall, planned))
    shutil.rmtree(h.cases_dir, ignore_errors=True)
    if interrupted:
        sys.exit(130)
    if harness_error:
        sys.exit(2)
    sys.exit(1 if h.findings and not args.keep_going else 0)


if __name__ == "__main__":
    main()
