#!/usr/bin/env bash
# The Debian package from the outside: `cpack -G DEB` in the build tree, then its files, its
# desktop entry and AppStream metadata (validated), its dependencies (VTK's run-time library,
# never the -dev packages that Debian's ParaView conflicts with), and the unpacked programs and
# Python module run on a shipped example.
#
# deb-package.sh BUILD_DIR WORK_DIR APP_ID [PYTHON_MODULE_FILE PYTHON]
# (the last two when the package holds the Python module: its file name and the Python to import it with)
set -euo pipefail
build=$1 work=$2 app_id=$3 module=${4:-} python=${5:-}

for tool in cpack dpkg-deb dpkg-shlibdeps desktop-file-validate appstreamcli; do
  command -v "$tool" >/dev/null || { echo "$tool is missing: run scripts/install-dependencies.sh"; exit 1; }
done
failed=0
fail() { echo "FAILED: $*"; failed=1; }

rm -rf "$work"
mkdir -p "$work"
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/cpack" > "$work/cpack.log" 2>&1 \
  || { cat "$work/cpack.log"; exit 1; }
deb=$(echo "$work"/cpack/mcdda_*_"$(dpkg --print-architecture)".deb)
test -f "$deb" || { cat "$work/cpack.log"; echo "no package in $work/cpack"; exit 1; }
echo "package: $(basename "$deb"), $(stat -c %s "$deb") bytes"

# Contents.
dpkg-deb -c "$deb" | awk '{print $6}' | sed 's|^\./|/|' > "$work/contents.txt"
expected=(
  /usr/bin/mcdda /usr/bin/mcdda-gui
  "/usr/share/applications/$app_id.desktop"
  "/usr/share/icons/hicolor/scalable/apps/$app_id.svg"
  "/usr/share/metainfo/$app_id.metainfo.xml"
  /usr/share/man/man1/mcdda.1.gz /usr/share/man/man1/mcdda-gui.1.gz
  /usr/share/mcdda/examples/kirsch.json /usr/share/mcdda/examples/jointed-tunnel.json
  /usr/share/mcdda/examples/records/synthetic-0.3g.AT2 /usr/share/mcdda/examples/studies/wedge-friction.json
  /usr/share/doc/mcdda/README.md /usr/share/doc/mcdda/docs/running.md
)
if [ -n "$module" ]; then expected+=("/usr/lib/python3/dist-packages/$module"); fi
for f in "${expected[@]}"; do
  grep -qxF "$f" "$work/contents.txt" || fail "the package lacks $f"
done
# The library for programs of one's own (docs/api.md) and examples/api stay out.
if grep -E '^/usr/include/|\.a$|/cmake/|/examples/api/' "$work/contents.txt"; then
  fail "the package holds the files above, which belong to the library component"
fi

# Dependencies: computed by dpkg-shlibdeps; VTK's run-time library only.
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
grep -Eq '(^|, )libvtk9\.1( |,|$)' <<< "$depends" || fail "Depends lacks libvtk9.1"
grep -Eq '(^|, )libqt6widgets6( |,|$)' <<< "$depends" || fail "Depends lacks libqt6widgets6"
if grep -Eq -- '-dev( |,|$)|python3-vtk9|(^|, )vtk9( |,|$)' <<< "$depends"; then
  fail "Depends names a development package, python3-vtk9 or vtk9"
fi

root=$work/root
dpkg-deb -x "$deb" "$root"

# Desktop entry, metadata, manual pages.
desktop-file-validate "$root/usr/share/applications/$app_id.desktop" || fail "desktop-file-validate"
appstreamcli validate --no-net --strict "$root/usr/share/metainfo/$app_id.metainfo.xml" || fail "appstreamcli validate"
grep -qxF "Icon=$app_id" "$root/usr/share/applications/$app_id.desktop" || fail "the desktop entry names another icon"
for page in mcdda mcdda-gui; do
  gzip -t "$root/usr/share/man/man1/$page.1.gz" || fail "$page.1.gz is not gzip"
  if command -v groff >/dev/null; then
    warnings=$(zcat "$root/usr/share/man/man1/$page.1.gz" | LC_ALL=C.UTF-8 groff -man -Tutf8 -ww -z 2>&1)
    [ -z "$warnings" ] || fail "groff on $page.1: $warnings"
  fi
done

# The unpacked programs: no run path into the build tree, the package's version, a run.
for program in mcdda mcdda-gui; do
  if readelf -d "$root/usr/bin/$program" | grep -Eq 'R(UN)?PATH'; then fail "$program has a run path"; fi
done
version=$(dpkg-deb -f "$deb" Version)
"$root/usr/bin/mcdda" --version | tee "$work/version.txt"
grep -q "^mcdda $version " "$work/version.txt" || fail "mcdda --version is not the package's $version"
"$root/usr/bin/mcdda-gui" --version | grep -qxF "mcdda-gui $version" || fail "mcdda-gui --version"
"$root/usr/bin/mcdda" run "$root/usr/share/mcdda/examples/kirsch.json" --out "$work/run" --quiet \
  --set /analysis/steps=1 || fail "mcdda run exited with $?"
grep -q '"status": *"completed"' "$work/run/summary.json" || fail "the run did not complete"
test -f "$work/run/kirsch_000001.vtu" || fail "the run wrote no step 1"

if [ -n "$module" ]; then
  PYTHONPATH="$root/usr/lib/python3/dist-packages" "$python" -c "
import mcdda, sys
assert mcdda.__file__.startswith('$root/'), mcdda.__file__
a = mcdda.Analysis.from_file('$root/usr/share/mcdda/examples/kirsch.json', ['/analysis/steps=1'])
r = a.run()
print('python: mcdda', mcdda.__version__, r['status'])
sys.exit(r['exit_code'])" || fail "the packaged Python module"
fi

[ $failed -eq 0 ] && echo "package ok"
exit $failed
