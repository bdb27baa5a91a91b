# SPDX-License-Identifier: GPL-2.0-or-later
# Installed programs find the shared library through an RPATH relative to their own location
# ($ORIGIN/../lib, $ORIGIN/../lib64, $ORIGIN/../lib/x86_64-linux-gnu, ... as GNUInstallDirs
# says), so an installed tree starts from any prefix and still does after it is moved. No RPATH
# is written when the library is installed into a directory the linker searches anyway (a
# system prefix), nor for a static build, nor when CMAKE_SKIP_RPATH or CMAKE_SKIP_INSTALL_RPATH
# asks for none.
#
# ASPERITY_PROGRAMS_RELOCATABLE tells whether installed programs start without help from the
# environment from wherever the tree lies.

if(APPLE)
  set(_asperity_origin "@loader_path")
else()
  set(_asperity_origin "$ORIGIN")
endif()

if(NOT BUILD_SHARED_LIBS)
  set(ASPERITY_INSTALL_RPATH_NEEDED FALSE)
  set(ASPERITY_PROGRAMS_RELOCATABLE TRUE)
elseif(CMAKE_SKIP_RPATH OR CMAKE_SKIP_INSTALL_RPATH
       OR "${CMAKE_INSTALL_FULL_LIBDIR}" IN_LIST CMAKE_C_IMPLICIT_LINK_DIRECTORIES)
  set(ASPERITY_INSTALL_RPATH_NEEDED FALSE)
  set(ASPERITY_PROGRAMS_RELOCATABLE FALSE)
else()
  set(ASPERITY_INSTALL_RPATH_NEEDED TRUE)
  set(ASPERITY_PROGRAMS_RELOCATABLE TRUE)
endif()

# asperity_install_rpath(<dir> <target>...): the targets are installed into the GNUInstallDirs
# directory <dir> (BINDIR, LIBEXECDIR, ...) and link libasperity.
function(asperity_install_rpath dir)
  if(NOT ASPERITY_INSTALL_RPATH_NEEDED)
    return()
  endif()
  file(RELATIVE_PATH _to_libdir "${CMAKE_INSTALL_FULL_${dir}}" "${CMAKE_INSTALL_FULL_LIBDIR}")
  if(_to_libdir)
    set(_rpath "${_asperity_origin}/${_to_libdir}")
  else()
    set(_rpath "${_asperity_origin}")
  endif()
  set_target_properties(${ARGN} PROPERTIES INSTALL_RPATH "${_rpath}")
endfunction()
