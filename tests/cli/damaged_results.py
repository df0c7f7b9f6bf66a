"""`mcdda render --results` treats a result file as hostile input.

Usage: damaged_results.py MCDDA EXAMPLES WORKDIR

Runs one step of the Kirsch example, then renders copies of its result file damaged the way a
fuzzer found crashing the renderer (a connectivity index out of range or negative, a point count of
10⁹ in the header, a file cut short, a NaN in the field drawn; a field-data array of type IdType or
"Bogus", cell offsets shuffled, a cell-data array given twice or renamed onto another, a
NumberOfComponents of -1 or 10⁹, ...). Then one step of the slope-wedge example (it has contacts)
and copies of its contacts file damaged likewise (cut short, an XML entity-expansion bomb, an
unknown type, a point count of 10¹²). Each must end with a clear message naming the file and the
problem, the exit status of a refused input file (1), no signal, no
VTK log text or C++ library text and no picture; the undamaged files must still render.
"""
import os
import random
import re
import shutil
import subprocess
import sys

mcdda, examples, work = sys.argv[1:4]
model = os.path.join(examples, "kirsch.json")
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
run_dir = os.path.join(work, "run")
subprocess.run([mcdda, "run", model, "--out", run_dir, "--quiet", "--set", "/analysis/steps=1"], check=True)
good_path = os.path.join(run_dir, "kirsch_000001.vtu")
good = open(good_path).read()


def data_array(text, name):
    """The span of the values of DataArray `name`."""
    m = re.search(r'<DataArray[^>]*Name="%s"[^>]*>' % name, text)
    end = text.index("</DataArray>", m.end())
    return m.end(), end


def replace_first_value(text, name, value):
    start, end = data_array(text, name)
    values = text[start:end].split()
    values[0] = value
    return text[:start] + "\n" + " ".join(values) + "\n" + text[end:]


cases = {
    "connectivity-out-of-range": (replace_first_value(good, "connectivity", "99999999"),
                                  r"cell 0 names point 99999999, but the file has \d+ points \(connectivity damaged\)"),
    "connectivity-negative": (replace_first_value(good, "connectivity", "-5"),
                              r"cell 0 names point -5, but the file has \d+ points"),
    "point-count-huge": (re.sub(r'NumberOfPoints="\d+"', 'NumberOfPoints="999999999"', good, count=1),
                         r"declare 999999999 points and \d+ cells but the model's mesh has \d+ nodes"),
    "point-count-not-a-number": (re.sub(r'NumberOfPoints="\d+"', 'NumberOfPoints="1e9"', good, count=1),
                                 r'NumberOfPoints "1e9" is not a count'),
    "cut-short": (good[: len(good) // 2], r"the file is damaged \("),
    "nan-in-field": (replace_first_value(good, "stress", "nan"),
                     r'"stress" holds values that are not finite numbers \(NaN or infinity\) at 1 entries', 1),
}


def data_array_block(text, name):
    """The whole <DataArray Name="name" ...> ... </DataArray> element, with its indentation."""
    m = re.search(r'[ ]*<DataArray[^>]*Name="%s"[^>]*>' % name, text)
    end = text.index("</DataArray>", m.end()) + len("</DataArray>\n")
    return m.start(), end


def shuffled_values(text, name, seed):
    start, end = data_array(text, name)
    values = text[start:end].split()
    random.Random(seed).shuffle(values)
    return text[:start] + "\n" + " ".join(values) + "\n" + text[end:]


def duplicated(text, name):
    start, end = data_array_block(text, name)
    return text[:end] + text[start:end] + text[end:]


# An XML entity-expansion bomb ("billion laughs") put before the root element.
bomb = '<!DOCTYPE VTKFile [\n  <!ENTITY a "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa">\n' + "".join(
    '  <!ENTITY %s "%s">\n' % (chr(ord("b") + k), ("&%s;" % chr(ord("a") + k)) * 10) for k in range(8)) + "]>\n"


def with_bomb(text):
    head, rest = text.split("\n", 1)
    return head + "\n" + bomb + rest.replace('Name="step"', 'Name="&i;"', 1)


# Found by scripts/fuzz-commands.py (/tmp/fuzz-findings.md): VTK's own reader crashed (SIGSEGV),
# threw std::length_error or std::bad_alloc, or printed its log on each of these.
cases.update({
    "fielddata-idtype": (good.replace('type="Float64" Name="time"', 'type="IdType" Name="time"', 1),
                         r'\.vtu:\d+: the FieldData array "time" has type "IdType", not the Float64'),
    "fielddata-unknown-type": (good.replace('type="Float64" Name="stage"', 'type="Bogus" Name="stage"', 1),
                               r'\.vtu:\d+: the FieldData array "stage" has type "Bogus"'),
    "offsets-shuffled": (shuffled_values(good, "offsets", 20261126),
                         r"\.vtu:\d+: cell offsets must increase \(offset \d+ follows \d+\)"),
    "offsets-first-zero": (replace_first_value(good, "offsets", "0"),
                           r"\.vtu:\d+: the first cell offset is 0"),
    "cell-array-twice": (duplicated(good, "plastic_state"),
                         r'\.vtu:\d+: a second CellData array named "plastic_state" \(the first is on line \d+\)'),
    "cell-array-renamed": (good.replace('Name="material"', 'Name="stress"', 1),
                           r'\.vtu:\d+: the CellData array "stress" has type "Int32", not the Float64'),
    "cell-array-renamed-onto-another": (good.replace('Name="plastic_strain"', 'Name="stress"', 1),
                                        r'a second CellData array named "stress"'),
    "components-negative": (good.replace('Name="velocity" NumberOfComponents="3"',
                                         'Name="velocity" NumberOfComponents="-1"', 1),
                            r'\.vtu:\d+: the PointData array "velocity" has NumberOfComponents "-1", not the 3'),
    "points-components-huge": (good.replace('<DataArray type="Float64" NumberOfComponents="3" format="ascii">',
                                            '<DataArray type="Float64" NumberOfComponents="1000000000" format="ascii">', 1),
                               r'\.vtu:\d+: the Points array has NumberOfComponents "1000000000", not the 3'),
    "cell-type-wrong": (replace_first_value(good, "types", "7"),
                        r"\.vtu:\d+: cell 0 is of type 7, not the three-node triangle \(type 5\)"),
    "format-binary": (good.replace('Name="stress" NumberOfComponents="6" format="ascii"',
                                   'Name="stress" NumberOfComponents="6" format="binary"', 1),
                      r'\.vtu:\d+: the CellData array "stress" is stored as format="binary"'),
    "values-missing": (replace_first_value(good, "plastic_strain", ""),
                       r'\.vtu:\d+: the CellData array "plastic_strain" holds \d+ values instead of 3625'),
    "point-not-finite": (re.sub(r'(<Points>\s*<DataArray[^>]*>\s*)\S+', r'\g<1>-inf', good, count=1),
                         r"\.vtu:\d+: point 0 has a coordinate that is not a finite number"),
    "entity-bomb": (with_bomb(good), r"\.vtu:2: a <!DOCTYPE> declaration"),
    "stage-not-whole": (re.sub(r'(Name="stage"[^>]*>\s*)\S+', r'\g<1>1e300', good, count=1),
                        r'\.vtu:\d+: the FieldData array "stage" holds "1e300", not a whole number'),
})

# Contacts files: one step of a model with contacts, its contacts file damaged.
wedge = os.path.join(examples, "slope-wedge.json")
wedge_dir = os.path.join(work, "wedge")
w = subprocess.run([mcdda, "run", wedge, "--out", wedge_dir, "--quiet", "--set", "/analysis/steps=1"])
if w.returncode not in (0, 3):  # 3: not yet in equilibrium after one step
    sys.exit("the slope-wedge run failed: exit %d" % w.returncode)
wedge_results = os.path.join(wedge_dir, "slope-wedge_000001.vtu")
good_contacts_path = os.path.join(wedge_dir, "slope-wedge_contacts_000001.vtp")
good_contacts = open(good_contacts_path).read()
contact_cases = {
    "contacts-cut-short": (good_contacts[:300], r"\.vtp:\d+: the file is damaged \(it ends inside"),
    "contacts-entity-bomb": (with_bomb(good_contacts), r"\.vtp:2: a <!DOCTYPE> declaration"),
    "contacts-unknown-type": (good_contacts.replace('type="Float64" Name="stage"', 'type="Bogus" Name="stage"', 1),
                              r'\.vtp:\d+: the FieldData array "stage" has type "Bogus"'),
    "contacts-point-count-huge": (re.sub(r'NumberOfPoints="\d+"', 'NumberOfPoints="1000000000000"', good_contacts,
                                         count=1),
                                  r"\.vtp:\d+: NumberOfPoints 1000000000000 is more than a contacts file can hold"),
    "contacts-point-count-short": (re.sub(r'NumberOfPoints="\d+"', 'NumberOfPoints="3"', good_contacts, count=1),
                                   r"\.vtp:\d+: the Points array holds more than the 9 values it should"),
    "contacts-offsets-shuffled": (shuffled_values(good_contacts, "offsets", 7),
                                  r"\.vtp:\d+: cell offsets must increase \(offset \d+ follows \d+\)"),
    "contacts-vertex-out-of-range": (replace_first_value(good_contacts, "connectivity", "99999"),
                                     r"\.vtp:\d+: cell 0 names point 99999, but the file has \d+ points"),
    "contacts-components-negative": (good_contacts.replace('Name="force" NumberOfComponents="3"',
                                                           'Name="force" NumberOfComponents="-1"', 1),
                                     r'\.vtp:\d+: the PointData array "force" has NumberOfComponents "-1"'),
    "contacts-array-twice": (duplicated(good_contacts, "slip"), r'a second PointData array named "slip"'),
    "contacts-not-a-number": (replace_first_value(good_contacts, "normal", "0x1p3"),
                              r'\.vtp:\d+: "0x1p3" in the PointData array "normal" is not a number'),
}

failures = []


def check(name, args, path, expected, status, kind):
    png = os.path.join(work, name + ".png")
    p = subprocess.run([mcdda, "render"] + args + ["--out", png], capture_output=True, text=True,
                       env={k: v for k, v in os.environ.items() if k != "DISPLAY"})
    out = p.stdout + p.stderr
    print("%s: exit %d: %s" % (name, p.returncode, out.strip()))
    if p.returncode < 0 or p.returncode >= 128:
        failures.append("%s: ended by a signal (exit status %d)" % (name, p.returncode))
    elif p.returncode != status:
        failures.append("%s: exit status %d instead of %d" % (name, p.returncode, status))
    if not re.search(expected, out):
        failures.append("%s: message does not match %r" % (name, expected))
    if path not in out:
        failures.append("%s: message does not name the %s file" % (name, kind))
    if "ERR|" in out or "vtk" in out.lower().replace(".vtu", ""):
        failures.append("%s: VTK's own log reached the terminal" % name)
    if "std::" in out or "vector::" in out or "bad_alloc" in out:
        failures.append("%s: C++ library text reached the terminal" % name)
    if len(out.strip().splitlines()) != 1:
        failures.append("%s: not a one-line message" % name)
    if os.path.exists(png):
        failures.append("%s: a picture was written" % name)


for name, case in cases.items():
    text, expected = case[0], case[1]
    status = case[2] if len(case) > 2 else 1
    path = os.path.join(work, name + ".vtu")
    with open(path, "w") as f:
        f.write(text)
    check(name, [model, "--results", path, "--field", "stress_xx"], path, expected, status, "result")

for name, (text, expected) in contact_cases.items():
    path = os.path.join(work, name + ".vtp")
    with open(path, "w") as f:
        f.write(text)
    check(name, [wedge, "--results", wedge_results, "--contacts", path], path, expected, 1, "contacts")

png = os.path.join(work, "good.png")
p = subprocess.run([mcdda, "render", model, "--results", good_path, "--field", "stress_xx", "--out", png],
                   capture_output=True, text=True, env={k: v for k, v in os.environ.items() if k != "DISPLAY"})
if p.returncode != 0 or not os.path.getsize(png) > 1000:
    failures.append("the undamaged file no longer renders: " + p.stdout + p.stderr)
png = os.path.join(work, "good-contacts.png")
p = subprocess.run([mcdda, "render", wedge, "--results", wedge_results, "--contacts", good_contacts_path, "--out", png],
                   capture_output=True, text=True, env={k: v for k, v in os.environ.items() if k != "DISPLAY"})
if p.returncode != 0 or not os.path.getsize(png) > 1000:
    failures.append("the undamaged contacts file no longer renders: " + p.stdout + p.stderr)

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("all %d damaged result files and %d damaged contacts files refused clearly; the undamaged ones render" %
      (len(cases), len(contact_cases)))
