# The Debian package: `cpack -G DEB` in the build directory, or `cmake --build <dir> --target
# package`, makes mcdda_<version>_amd64.deb of the programs, the Python module, the manual
# pages, the desktop files, the examples and the documentation. Not the static library and its
# headers (the `library` component, docs/api.md): nothing in the package needs them.
#
# The package depends on the shared libraries the programs load, as dpkg-shlibdeps (dpkg-dev)
# finds them: VTK's run-time libvtk9.1, never libvtk9-dev or python3-vtk9, which Debian's ParaView
# (python3-paraview) conflicts with.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME mcdda)
set(CPACK_PACKAGE_VENDOR mcdda)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "elastic-plastic discontinuous deformation analysis of jointed rock")
set(CPACK_PACKAGE_DESCRIPTION "\
mcdda models jointed rock and stiff soil as blocks that slide and open along
joints (DDA contacts with Coulomb friction), each block meshed into finite
elements that yield by Mohr-Coulomb or generalised Hoek-Brown plasticity, with
construction stages, ground water, strength reduction and earthquakes.

This package holds the desktop program mcdda-gui, the command line program
mcdda (check, mesh, render, run, parameter studies, DXF import), the Python
module mcdda, the example models and the documentation.")
set(MCDDA_PACKAGE_CONTACT "mcdda maintainers <mcdda@localhost>" CACHE STRING
  "The Maintainer field of the Debian package")
set(CPACK_PACKAGE_CONTACT ${MCDDA_PACKAGE_CONTACT})
set(CPACK_STRIP_FILES ON)
# Values reach the package as written (no second round of CMake escapes).
set(CPACK_VERBATIM_VARIABLES ON)

# Only the programs' components; the Python module only when built for Debian's python3 (a
# module for another interpreter has no place in /usr/lib/python3/dist-packages).
set(CPACK_COMPONENTS_ALL runtime)
if(MCDDA_PYTHON_DIR AND MCDDA_PYTHON_DEBIAN)
  list(APPEND CPACK_COMPONENTS_ALL python)
elseif(MCDDA_PYTHON_DIR)
  message(STATUS "mcdda package: without the Python module (built for ${MCDDA_PYTHON_EXECUTABLE}, not Debian's python3)")
endif()
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_GROUPING ALL_COMPONENTS_IN_ONE)

set(CPACK_DEBIAN_PACKAGE_NAME mcdda)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)
# Loaded as plug-ins, so dpkg-shlibdeps cannot see them: Qt's SVG support draws the icons.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6svg6")
# `mcdda render` without a display runs under xvfb-run; the desktop program's German dialogs
# come from Qt's translations; the Python module is built for one Python version and needs NumPy.
set(recommends "xvfb, xauth, qt6-translations-l10n")
if(MCDDA_PYTHON_DIR AND MCDDA_PYTHON_DEBIAN)
  string(REPLACE "." ";" python_version "${MCDDA_PYTHON_VERSION}")
  list(GET python_version 1 python_minor)
  math(EXPR python_next "${python_minor} + 1")
  string(APPEND recommends ", python3 (>= ${MCDDA_PYTHON_VERSION}), python3 (<< 3.${python_next}), python3-numpy")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "${recommends}")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "paraview, openmpi-bin")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

# `cmake --build <dir> --target package_source`: the sources without build trees and results.
set(CPACK_SOURCE_GENERATOR TGZ)
set(CPACK_SOURCE_IGNORE_FILES "^${PROJECT_SOURCE_DIR}/(\\.git|\\.cache|build[^/]*|out)/")

include(CPack)
