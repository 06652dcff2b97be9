# Add the GRFLOW package to a LAMMPS source tree, the way a package is added
# to one's own LAMMPS: src/GRFLOW (GRFLOW's LAMMPS classes and the host-free
# sources it shares with LIGGGHTS, src/shared), its OPENMP variants in src/OPENMP,
# its KOKKOS variants in src/KOKKOS (built with -D PKG_KOKKOS=on by CMake;
# the make build's KOKKOS/Install.sh lists its files by name and does not
# install them), and GRFLOW in the package lists of cmake/CMakeLists.txt (for
# -D PKG_GRFLOW=on) and src/Makefile (for make package-status and friends;
# make yes-grflow works without it).  Unlike GRFLOW's own build, this writes
# into the tree it is given.  Run again after updating GRFLOW, it replaces
# GRFLOW's files and changes nothing else.
#
#   cmake -D LAMMPS_TREE=/path/to/lammps -P cmake/GRFLOWAddToLAMMPS.cmake
#
# (scripts/add-to-lammps.sh runs this.)

cmake_minimum_required(VERSION 3.20)
if(NOT LAMMPS_TREE)
  message(FATAL_ERROR "usage: cmake -D LAMMPS_TREE=/path/to/lammps -P ${CMAKE_CURRENT_LIST_FILE}")
endif()
get_filename_component(tree ${LAMMPS_TREE} ABSOLUTE)
get_filename_component(top ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
include(${CMAKE_CURRENT_LIST_DIR}/GRFLOWStageLAMMPS.cmake)
grflow_check_lammps_tree(${tree})
if(NOT EXISTS ${tree}/src/Makefile OR NOT IS_DIRECTORY ${tree}/src/OPENMP)
  message(FATAL_ERROR "${tree} has no src/Makefile or src/OPENMP: not a whole LAMMPS source tree")
endif()

# src/GRFLOW: replaced as a whole, so that files GRFLOW dropped go too; a
# GRFLOW folder that is not this package's is left alone
if(EXISTS ${tree}/src/GRFLOW AND NOT EXISTS ${tree}/src/GRFLOW/grflow_contact.h)
  message(FATAL_ERROR "${tree}/src/GRFLOW exists and is not this GRFLOW package; "
    "move it away first")
endif()
file(REMOVE_RECURSE ${tree}/src/GRFLOW)
file(COPY ${top}/src/GRFLOW DESTINATION ${tree}/src)
file(GLOB shared_files ${top}/src/shared/*)
file(COPY ${shared_files} DESTINATION ${tree}/src/GRFLOW)
file(GLOB omp_files ${top}/src/OPENMP/*)
file(COPY ${omp_files} DESTINATION ${tree}/src/OPENMP)
if(IS_DIRECTORY ${tree}/src/KOKKOS)
  file(GLOB kk_files ${top}/src/KOKKOS/*)
  file(COPY ${kk_files} DESTINATION ${tree}/src/KOKKOS)
endif()

# cmake/CMakeLists.txt: GRFLOW among the standard packages
file(READ ${tree}/cmake/CMakeLists.txt cml)
grflow_register_cmake_package("${cml}" cml_new)
if(NOT cml_new STREQUAL cml)
  file(WRITE ${tree}/cmake/CMakeLists.txt "${cml_new}")
endif()

# src/Makefile: grflow in the list PACKAGE
file(READ ${tree}/src/Makefile mk)
if(NOT mk MATCHES "\nPACKAGE = \\\\\n([^\n]*\\\\\n)*\tgrflow \\\\\n")
  string(REPLACE "\nPACKAGE = \\\n" "\nPACKAGE = \\\n\tgrflow \\\n" mk_new "${mk}")
  if(mk_new STREQUAL mk)
    message(FATAL_ERROR "could not find the list PACKAGE in ${tree}/src/Makefile")
  endif()
  file(WRITE ${tree}/src/Makefile "${mk_new}")
endif()

message(STATUS "GRFLOW added to ${tree}:
  CMake:  cmake -S ${tree}/cmake -B build -D PKG_GRFLOW=on [-D PKG_OPENMP=on]
          [-D PKG_KOKKOS=on and your Kokkos settings: granular/grflow/kk]
  make:   cd ${tree}/src && make yes-grflow [yes-openmp] && make mpi
          (yes-openmp after yes-grflow, so that OPENMP installs granular/grflow/omp;
           after updating GRFLOW: run this again, then make package-update)")
