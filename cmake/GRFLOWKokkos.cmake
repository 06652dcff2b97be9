# The KOKKOS build of GRFLOW (CMakeLists.txt with -D GRFLOW_KOKKOS=ON;
# scripts/setup-kokkos.sh runs it): LAMMPS with GRFLOW, GRANULAR (for
# comparisons with gran/hooke/history/kk) and KOKKOS, against an installed
# Kokkos 4.5.01 (-D Kokkos_ROOT=PREFIX, e.g. made by scripts/build-kokkos.sh),
# through LAMMPS's EXTERNAL_KOKKOS route (find_package(Kokkos 4.5.01)).
#
# GRFLOW_KOKKOS_STYLES: which of LAMMPS's own KOKKOS styles are built.
#   ""        all of them (those whose plain style is in the build), as in
#             any LAMMPS tree: the default
#   minimal   the KOKKOS package's core and the styles a GRFLOW run on a
#             device uses (atom styles atomic and sphere, fix nve/sphere,
#             fix deform, verlet, neighbor lists, compute temp, and
#             gran/hooke/history with its history fix for comparisons):
#             a build of a third of the time (CI, scripts/gpu-check.sh).
#             Other styles then run as their plain versions on the host.
#   a list    of plain style header names (e.g. "fix_nve_sphere;fix_deform")
# GRFLOW's own KOKKOS styles (src/KOKKOS) are always built.

set(GRFLOW_KOKKOS_STYLES "" CACHE STRING
  "LAMMPS KOKKOS styles to build: empty for all, 'minimal', or a list of style header names")

set(GRFLOW_KOKKOS_MINIMAL_STYLES
  # the KOKKOS package's own classes that carry style macros, and those its
  # core files include (min_kokkos.cpp: fix_minimize; comm_kokkos.cpp:
  # fix_property_atom)
  verlet nbin npair npair_copy npair_halffull npair_skip npair_trim fix_minimize
  fix_property_atom
  # what a GRFLOW run uses
  atom_vec_atomic atom_vec_sphere fix_nve_sphere fix_deform compute_temp
  # stock granular styles, for comparisons
  pair_gran_hooke_history fix_neigh_history)

# GRFLOW_KOKKOS_STAGE_STYLES: the list cmake/GRFLOWStageLAMMPS.cmake stages
function(grflow_kokkos_styles)
  if(NOT GRFLOW_KOKKOS)
    set(GRFLOW_KOKKOS_STAGE_STYLES "" PARENT_SCOPE)
  elseif(GRFLOW_KOKKOS_STYLES STREQUAL "minimal")
    set(GRFLOW_KOKKOS_STAGE_STYLES "${GRFLOW_KOKKOS_MINIMAL_STYLES}" PARENT_SCOPE)
  else()
    set(GRFLOW_KOKKOS_STAGE_STYLES "${GRFLOW_KOKKOS_STYLES}" PARENT_SCOPE)
  endif()
endfunction()

# the packages and the Kokkos of the KOKKOS build (a macro: it sets cache
# variables for the LAMMPS configure)
macro(grflow_kokkos_packages)
  if(NOT Kokkos_ROOT AND NOT Kokkos_DIR AND NOT DEFINED ENV{Kokkos_ROOT})
    message(FATAL_ERROR "GRFLOW_KOKKOS=ON needs an installed Kokkos 4.5.01: "
      "-D Kokkos_ROOT=/path/to/prefix (scripts/build-kokkos.sh makes one)")
  endif()
  # found here too, so that LAMMPS's configure sees its devices from the
  # start (Kokkos_ENABLE_CUDA, Kokkos_ENABLE_OPENMP: compiler flags, checks)
  # (LAMMPS sets C++17 without extensions, as an installed Kokkos wants)
  set(CMAKE_CXX_EXTENSIONS OFF CACHE BOOL "Use compiler extensions")
  find_package(Kokkos 4.5.01 REQUIRED CONFIG)
  foreach(pkg GRANULAR GRFLOW KOKKOS)
    set(PKG_${pkg} ON CACHE BOOL "Build the ${pkg} package")
  endforeach()
  set(EXTERNAL_KOKKOS ON CACHE BOOL "Build against an external Kokkos library" FORCE)
endmacro()

function(grflow_kokkos_summary)
  string(REPLACE ";" "+" devices "${Kokkos_DEVICES}")
  if(GRFLOW_KOKKOS_STAGE_STYLES)
    set(styles "${GRFLOW_KOKKOS_STYLES}")
  else()
    set(styles "all")
  endif()
  message(STATUS "GRFLOW: KOKKOS build, Kokkos ${Kokkos_VERSION} (${Kokkos_DIR}), devices "
    "${devices}; LAMMPS KOKKOS styles: ${styles}; lmp in ${CMAKE_BINARY_DIR}")
endfunction()
