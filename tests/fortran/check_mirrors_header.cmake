# SPDX-License-Identifier: GPL-2.0-or-later
# Checks that the Fortran module mirrors the C headers: every integer constant of the headers
# (#define ASP_... and enumerators named ASP_...) is a public integer(c_int) parameter of the
# module with the same value; every ASP_EXPORT function has a bind(c, name='...') interface,
# and the C name is a public Fortran name that calls it: either that interface itself is named
# like the C function, or it sits inside a generic interface block named like the C function;
# and the module has no ASP_ constant, asp_ binding or asp_ generic interface that the headers
# lack.
#
# A function with an MPI_Comm parameter (asperity_mpi.h's asp_grid_create_mpi) is the one
# exception: a C MPI_Comm is not a handle Fortran can hold, so it has no bind(c) interface.
# The header has a twin taking MPI's Fortran handle (asp_grid_create_mpi_f), which is bound
# like any other function; the C name must be a public generic interface of the module (its
# procedures take the Fortran handle and call the twin).
#
#   cmake -DHEADER="include/asperity/asperity.h;include/asperity/asperity_mpi.h"
#         -DMODULE=bindings/fortran/asperity.f90 [-DDROP=NAME[,NAME...]]
#         -P check_mirrors_header.cmake
#
# DROP takes constants or functions out of the module text before the check, to show that the
# check notices a missing entry (the test fortran.mirrors_header_notices_drift).
cmake_minimum_required(VERSION 3.16)

if(NOT DEFINED MODULE OR NOT EXISTS "${MODULE}")
  message(FATAL_ERROR "pass -DMODULE=<existing file> (got '${MODULE}')")
endif()
if(NOT DEFINED HEADER OR HEADER STREQUAL "")
  message(FATAL_ERROR "pass -DHEADER=<existing file>[;<existing file>...]")
endif()
set(header "")
foreach(file IN LISTS HEADER)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "pass -DHEADER=<existing file>[;<existing file>...] (got '${file}')")
  endif()
  file(READ "${file}" text)
  string(APPEND header "${text}\n")
endforeach()
string(REPLACE ";" ", " HEADER "${HEADER}")

# ---- the C headers ---------------------------------------------------------------------------
# Block comments out, one at a time (CMake's regular expressions have no lazy match).
while(TRUE)
  string(FIND "${header}" "/*" open)
  if(open EQUAL -1)
    break()
  endif()
  string(SUBSTRING "${header}" 0 ${open} before)
  math(EXPR after_open "${open} + 2")
  string(SUBSTRING "${header}" ${after_open} -1 rest)
  string(FIND "${rest}" "*/" close)
  if(close EQUAL -1)
    message(FATAL_ERROR "${HEADER}: unterminated comment")
  endif()
  math(EXPR after_close "${close} + 2")
  string(SUBSTRING "${rest}" ${after_close} -1 rest)
  set(header "${before} ${rest}")
endwhile()
string(REGEX REPLACE "//[^\n]*" "" header "${header}")
# CMake lists split on ';': C statements end in one, so mark them with something else.
string(REPLACE ";" "@" header "${header}")

# name -> value of every integer constant, as variables c_<name>; the names in c_names.
set(c_names "")
set(problems "")

function(to_integer text out)
  string(STRIP "${text}" text)
  string(REGEX REPLACE "^\\((.*)\\)$" "\\1" text "${text}")
  string(STRIP "${text}" text)
  if(text MATCHES "^-?[0-9]+$")
    math(EXPR value "${text}")
  elseif(text MATCHES "^-?0[xX][0-9a-fA-F]+$")
    math(EXPR value "${text}" OUTPUT_FORMAT DECIMAL)
  else()
    set(value "")
  endif()
  set(${out} "${value}" PARENT_SCOPE)
endfunction()

string(REGEX MATCHALL "#[ \t]*define[ \t]+ASP_[A-Za-z0-9_]*[^\n]*" defines "${header}")
foreach(line IN LISTS defines)
  string(REGEX MATCH "#[ \t]*define[ \t]+(ASP_[A-Za-z0-9_]*)(.*)" _ "${line}")
  set(name "${CMAKE_MATCH_1}")
  set(body "${CMAKE_MATCH_2}")
  if(body MATCHES "^\\(")
    string(APPEND problems "header: ${name} is a function-like macro; extend this check\n")
    continue()
  endif()
  to_integer("${body}" value)
  if(value STREQUAL "")
    string(APPEND problems
      "header: ${name} has the value '${body}', not an integer; extend this check\n")
    continue()
  endif()
  list(APPEND c_names ${name})
  set(c_${name} ${value})
endforeach()

# Enumerations: enum [tag] { A = 1, B, C = 5 }, values counted on from the last given one.
string(REGEX MATCHALL "enum[^{@]*{[^}]*}" enums "${header}")
foreach(enum IN LISTS enums)
  string(REGEX REPLACE "^enum[^{]*{(.*)}$" "\\1" body "${enum}")
  string(REPLACE "," ";" entries "${body}")
  set(next 0)
  foreach(entry IN LISTS entries)
    string(STRIP "${entry}" entry)
    if(entry STREQUAL "")
      continue()
    endif()
    if(entry MATCHES "^([A-Za-z_][A-Za-z0-9_]*)[ \t\r\n]*=(.*)$")
      set(name "${CMAKE_MATCH_1}")
      to_integer("${CMAKE_MATCH_2}" value)
      if(value STREQUAL "")
        string(APPEND problems
          "header: enumerator ${name} = '${CMAKE_MATCH_2}' is not an integer; extend this check\n")
        break()
      endif()
    elseif(entry MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
      set(name "${entry}")
      set(value ${next})
    else()
      string(APPEND problems "header: cannot read the enumerator '${entry}'\n")
      break()
    endif()
    math(EXPR next "${value} + 1")
    if(name MATCHES "^ASP_")
      list(APPEND c_names ${name})
      set(c_${name} ${value})
    endif()
  endforeach()
endforeach()

# Exported functions: the identifier right before the first '(' of each ASP_EXPORT declaration;
# those with an MPI_Comm parameter in c_comm_functions too.
set(c_functions "")
set(c_comm_functions "")
string(REGEX MATCHALL "ASP_EXPORT[^(@]*\\([^@]*" exports "${header}")
foreach(declaration IN LISTS exports)
  if(declaration MATCHES "([A-Za-z_][A-Za-z0-9_]*)[ \t\r\n]*\\((.*)$")
    set(name "${CMAKE_MATCH_1}")
    list(APPEND c_functions ${name})
    if(CMAKE_MATCH_2 MATCHES "(^|[^A-Za-z0-9_])MPI_Comm([^A-Za-z0-9_]|$)")
      list(APPEND c_comm_functions ${name})
    endif()
  endif()
endforeach()

list(LENGTH c_names n_constants)
list(LENGTH c_functions n_functions)
if(n_constants EQUAL 0 OR n_functions EQUAL 0)
  message(FATAL_ERROR "${HEADER}: found ${n_constants} constants and ${n_functions} "
                      "functions; the header was not read as expected")
endif()

# ---- the Fortran module ----------------------------------------------------------------------
file(READ "${MODULE}" module)
string(REPLACE "," ";" drop "${DROP}")
foreach(name IN LISTS drop)
  string(REGEX REPLACE "${name}[ \t]*=[ \t]*-?[0-9]+(_c_int)?" "" module "${module}")
  string(REGEX REPLACE "name[ \t]*=[ \t]*['\"]${name}['\"]" "name='dropped'" module "${module}")
  string(REGEX REPLACE "interface[ \t]+${name}([ \t]*\n)" "interface dropped\\1" module
         "${module}")
endforeach()
string(REPLACE ";" "@" module "${module}")
# Comments out (a '!' after a quote on the same line is left alone: it may be in a string),
# continuation lines joined, and everything in lower case but the names bound to C.
string(REGEX REPLACE "(^|\n)([^'\"!\n]*)![^\n]*" "\\1\\2" module "${module}")
string(REGEX REPLACE "&[ \t]*\n[ \t]*&?" " " module "${module}")
string(REGEX MATCHALL "[Bb][Ii][Nn][Dd][ \t]*\\([ \t]*[Cc][ \t]*,[ \t]*[Nn][Aa][Mm][Ee][ \t]*=[ \t]*['\"][^'\"]*['\"]"
       binds "${module}")
string(TOLOWER "${module}" module)
string(REPLACE "\n" ";" statements "${module}")

set(f_names "")
set(f_public "")
foreach(statement IN LISTS statements)
  if(statement MATCHES "^[ \t]*public[ \t]*::(.*)$")
    string(REGEX MATCHALL "[a-z_][a-z0-9_]*" names "${CMAKE_MATCH_1}")
    list(APPEND f_public ${names})
  elseif(statement MATCHES "^[ \t]*integer[ \t]*\\(([^)]*)\\)([^:]*)::(.*)$")
    set(kind "${CMAKE_MATCH_1}")
    set(attributes "${CMAKE_MATCH_2}")
    set(entities "${CMAKE_MATCH_3}")
    if(NOT attributes MATCHES "parameter")
      continue()
    endif()
    string(REGEX MATCHALL "[a-z_][a-z0-9_]*[ \t]*=[ \t]*-?[0-9]+(_[a-z0-9_]+)?" pairs
           "${entities}")
    foreach(pair IN LISTS pairs)
      string(REGEX MATCH "([a-z_][a-z0-9_]*)[ \t]*=[ \t]*(-?[0-9]+)" _ "${pair}")
      set(name "${CMAKE_MATCH_1}")
      set(value "${CMAKE_MATCH_2}")
      if(NOT name MATCHES "^asp_")
        continue()
      endif()
      string(REGEX REPLACE "[ \t]" "" kind_compact "${kind}")
      if(NOT kind_compact STREQUAL "c_int" AND NOT kind_compact STREQUAL "kind=c_int")
        string(TOUPPER "${name}" upper)
        string(APPEND problems "module: ${upper} is integer(${kind}), not integer(c_int)\n")
      endif()
      list(APPEND f_names ${name})
      set(f_${name} ${value})
      if(attributes MATCHES "public")
        list(APPEND f_public ${name})
      endif()
    endforeach()
  endif()
endforeach()

# C name -> Fortran procedure name of its binding (f_procedure_<C name>) and the generic
# interface block that holds the binding, if any (f_generic_<C name>); the C names in f_bound,
# the names of the generic interfaces in f_generics.
set(f_bound "")
set(f_generics "")
set(generic "")
foreach(statement IN LISTS statements)
  if(statement MATCHES "^[ \t]*interface[ \t]+([a-z_][a-z0-9_]*)[ \t]*$")
    set(generic "${CMAKE_MATCH_1}")
    list(APPEND f_generics "${generic}")
  elseif(statement MATCHES "^[ \t]*end[ \t]*interface")
    set(generic "")
  endif()
  if(statement MATCHES "(function|subroutine)[ \t]+([a-z_][a-z0-9_]*)[ \t]*\\([^)]*\\).*bind[ \t]*\\([ \t]*c[ \t]*,[ \t]*name[ \t]*=[ \t]*['\"]([^'\"]*)['\"]")
    set(f_procedure_${CMAKE_MATCH_3} ${CMAKE_MATCH_2})
    set(f_generic_${CMAKE_MATCH_3} "${generic}")
  endif()
endforeach()
foreach(bind IN LISTS binds)
  string(REGEX MATCH "['\"]([^'\"]*)['\"]" _ "${bind}")
  list(APPEND f_bound "${CMAKE_MATCH_1}")
endforeach()

# ---- compare ---------------------------------------------------------------------------------
foreach(name IN LISTS c_names)
  string(TOLOWER "${name}" lower)
  if(NOT lower IN_LIST f_names)
    string(APPEND problems "${name} = ${c_${name}} is missing from the module\n")
  elseif(NOT f_${lower} EQUAL c_${name})
    string(APPEND problems
      "${name} is ${c_${name}} in the header but ${f_${lower}} in the module\n")
  elseif(NOT lower IN_LIST f_public)
    string(APPEND problems "${name} is in the module but not public\n")
  endif()
endforeach()
foreach(lower IN LISTS f_names)
  string(TOUPPER "${lower}" name)
  if(NOT name IN_LIST c_names)
    string(APPEND problems "${name} = ${f_${lower}} is in the module but not in the header\n")
  endif()
endforeach()

foreach(function IN LISTS c_functions)
  string(TOLOWER "${function}" lower)
  if(function IN_LIST c_comm_functions)
    if(function IN_LIST f_bound)
      string(APPEND problems "${function} takes a C MPI_Comm, which Fortran cannot pass, but "
                             "the module binds it\n")
    elseif(NOT lower IN_LIST f_generics)
      string(APPEND problems "${function} (C MPI_Comm) has no generic interface ${lower} in "
                             "the module taking MPI's Fortran handle\n")
    elseif(NOT lower IN_LIST f_public)
      string(APPEND problems "${function} has a generic interface in the module but is not "
                             "public\n")
    endif()
    continue()
  endif()
  if(NOT function IN_LIST f_bound)
    string(APPEND problems
      "${function} has no interface with bind(c, name='${function}') in the module\n")
  elseif(NOT DEFINED f_procedure_${function})
    string(APPEND problems "${function}: could not read the Fortran name of its interface\n")
  elseif(NOT f_procedure_${function} STREQUAL lower AND
         NOT f_generic_${function} STREQUAL lower)
    string(APPEND problems
      "${function} is bound to the Fortran name ${f_procedure_${function}}, which is neither "
      "${lower} nor inside a generic interface ${lower}\n")
  elseif(NOT lower IN_LIST f_public)
    string(APPEND problems "${function} has an interface in the module but is not public\n")
  endif()
endforeach()
foreach(function IN LISTS f_bound)
  if(function MATCHES "^asp_" AND NOT function IN_LIST c_functions)
    string(APPEND problems
      "the module binds ${function}, which the header does not export\n")
  endif()
endforeach()
string(TOLOWER "${c_functions}" c_functions_lower)
foreach(generic IN LISTS f_generics)
  if(generic MATCHES "^asp_" AND NOT generic IN_LIST c_functions_lower)
    string(APPEND problems
      "the module has a generic interface ${generic}, which the header does not export\n")
  endif()
endforeach()

if(NOT problems STREQUAL "")
  message(FATAL_ERROR "${MODULE} does not mirror ${HEADER}:\n${problems}")
endif()
list(LENGTH f_bound n_bound)
message(STATUS "the module mirrors the header: ${n_constants} constants, "
               "${n_functions} functions")
