# SPDX-License-Identifier: GPL-2.0-or-later
# Debian packages through CPack, one per install component:
#   libasperity<ABI>   runtime     the shared library
#   libasperity-dev    development headers, CMake package, pkg-config file, Fortran module source
#   asperity           cli         the command
#   python3-asperity   python      the Python package (ctypes; loads libasperity<ABI>)
# Build them from a tree configured for /usr (so that the library goes to Debian's multiarch
# directory): tools/make-packages.sh does it, and tests/package checks the result.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME asperity)
set(CPACK_PACKAGE_VENDOR "the asperity developers")
set(CPACK_PACKAGE_CONTACT "asperity developers <asperity@localhost>")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX})
set(CPACK_DEB_COMPONENT_INSTALL ON)
# The C API's debug information serves the ABI check in the build tree, not the packages.
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://example.invalid/asperity")
# dpkg-shlibdeps writes the Depends of what links: libc, libstdc++, FFTW, libzip, ...
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The private libraries of the build tree are no package's business.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${PROJECT_BINARY_DIR}/src)

set(_runtime libasperity${ASPERITY_ABI_VERSION})
set(_exact "(= ${PROJECT_VERSION})")
set(CPACK_COMPONENTS_ALL runtime development)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME ${_runtime})
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION libs)
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION
  "contact mechanics of rough surfaces by FFT-based boundary elements (library)\n The shared library of asperity: the normal contact of an elastic half-space and a rigid\n rough surface, with or without adhesion, by the optimisation algorithms of contact\n mechanics (Polonsky-Keer, Bugnicourt, L-BFGS-B, L-BFGS, FIRE, GFMD).")

set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME libasperity-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
# pkg-config needs fftw3.pc (asperity.pc lists it as Requires.private).
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "${_runtime} ${_exact}, libfftw3-dev")
set(CPACK_COMPONENT_DEVELOPMENT_DESCRIPTION
  "contact mechanics of rough surfaces (development files)\n Headers, CMake package, pkg-config file and the Fortran 2003 module's source of\n asperity.")

if(TARGET asperity_cli)
  list(APPEND CPACK_COMPONENTS_ALL cli)
  set(CPACK_DEBIAN_CLI_PACKAGE_NAME asperity)
  set(CPACK_DEBIAN_CLI_PACKAGE_DEPENDS "${_runtime} ${_exact}")
  set(CPACK_DEBIAN_CLI_PACKAGE_RECOMMENDS "gnuplot-nox | gnuplot")
  set(CPACK_COMPONENT_CLI_DESCRIPTION
    "contact mechanics of rough surfaces (command)\n The asperity command: scenes from TOML files solved, compared (error against\n time), swept and described; measured surfaces from text, .npy and .x3p files.")
endif()

if(TARGET asperity_python)
  list(APPEND CPACK_COMPONENTS_ALL python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-asperity)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_ARCHITECTURE all)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "python3, python3-numpy, ${_runtime} ${_exact}")
  set(CPACK_COMPONENT_PYTHON_DESCRIPTION
    "contact mechanics of rough surfaces (Python 3)\n The Python package of asperity, through ctypes and NumPy.")
endif()

# Each package carries the licence as Debian wants it, /usr/share/doc/<package>/copyright.
foreach(_component IN LISTS CPACK_COMPONENTS_ALL)
  string(TOUPPER ${_component} _upper)
  install(FILES ${PROJECT_SOURCE_DIR}/LICENSE
    DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/${CPACK_DEBIAN_${_upper}_PACKAGE_NAME}
    RENAME copyright COMPONENT ${_component})
endforeach()

include(CPack)
