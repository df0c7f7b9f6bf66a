"""`mcdda render --results` treats a result file as hostile input.

Usage: damaged_results.py MCDDA EXAMPLES WORKDIR

Runs one step of the Kirsch example, then renders copies of its result file damaged the way a
fuzzer found crashing the renderer (a connectivity index out of range or negative, a point count of
10⁹ in the header, a file cut short, a NaN in the field drawn). Each must end with a clear message
naming the file and the problem, a normal exit status (no signal), no VTK log dump and no picture;
the undamaged file must still render.
"""
import os
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
                     r'"stress" holds values that are not finite numbers \(NaN or infinity\) at 1 entries'),
}

failures = []
for name, (text, expected) in cases.items():
    path = os.path.join(work, name + ".vtu")
    with open(path, "w") as f:
        f.write(text)
    png = os.path.join(work, name + ".png")
    p = subprocess.run([mcdda, "render", model, "--results", path, "--field", "stress_xx", "--out", png],
                       capture_output=True, text=True, env={k: v for k, v in os.environ.items() if k != "DISPLAY"})
    out = p.stdout + p.stderr
    print("%s: exit %d: %s" % (name, p.returncode, out.strip()))
    if p.returncode <= 0 or p.returncode >= 128:
        failures.append("%s: exit status %d (a signal or success)" % (name, p.returncode))
    if not re.search(expected, out):
        failures.append("%s: message does not match %r" % (name, expected))
    if path not in out:
        failures.append("%s: message does not name the file" % name)
    if "ERR|" in out or "vtk" in out.lower().replace(".vtu", ""):
        failures.append("%s: VTK's own log reached the terminal" % name)
    if os.path.exists(png):
        failures.append("%s: a picture was written" % name)

png = os.path.join(work, "good.png")
p = subprocess.run([mcdda, "render", model, "--results", good_path, "--field", "stress_xx", "--out", png],
                   capture_output=True, text=True, env={k: v for k, v in os.environ.items() if k != "DISPLAY"})
if p.returncode != 0 or not os.path.getsize(png) > 1000:
    failures.append("the undamaged file no longer renders: " + p.stdout + p.stderr)

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("all %d damaged result files refused clearly; the undamaged one renders" % len(cases))
