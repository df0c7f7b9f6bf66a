"""Importing mcdda where NumPy cannot be imported raises an ImportError that says so and how to
fix it (a virtual environment made without --system-site-packages does not see Debian's NumPy);
likewise with a NumPy 2 when the module's pybind11 predates it.

Run as `python3 check_no_numpy.py MODULE_DIR`: a child Python imports mcdda from MODULE_DIR with a
stand-in `numpy` first on its path."""
import os
import subprocess
import sys
import tempfile

module_dir = sys.argv[1]


def import_with(numpy_init):
    """What `import mcdda` says with a numpy package whose __init__.py is `numpy_init`."""
    with tempfile.TemporaryDirectory() as stand_in:
        os.mkdir(os.path.join(stand_in, "numpy"))
        with open(os.path.join(stand_in, "numpy", "__init__.py"), "w") as f:
            f.write(numpy_init)
        child = subprocess.run(
            [sys.executable, "-c", """
try:
    import mcdda
except ImportError as e:
    print(type(e).__name__ + ": " + str(e))
else:
    print("imported")
"""],
            env=dict(os.environ, PYTHONPATH=os.pathsep.join([stand_in, module_dir])),
            capture_output=True, text=True)
    print(child.stdout + child.stderr, end="")
    if child.returncode != 0:
        sys.exit(f"the child Python failed (exit status {child.returncode})")
    return child.stdout


problems = []
said = import_with('raise ImportError("No module named \'numpy\' (hidden by the test)")\n')
for text in ["ImportError: mcdda needs NumPy", sys.executable, "hidden by the test", "pip install",
             "--system-site-packages"]:
    if text not in said:
        problems.append(f"without NumPy the message lacks {text!r}")

# NumPy 2 is refused only by a module built with a pybind11 that cannot read its arrays.
said = import_with('__version__ = "2.0.0"\n')
if not said.startswith("imported"):
    for text in ["ImportError: mcdda needs NumPy 1", "NumPy 2.0.0", "pip install 'numpy<2'"]:
        if text not in said:
            problems.append(f"with NumPy 2 the message lacks {text!r}")

if problems:
    sys.exit("\n".join(problems))
