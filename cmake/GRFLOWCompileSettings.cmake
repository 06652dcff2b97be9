# Compile options and definitions of the GRFLOW sources, for every build of
# them (the package inside LAMMPS, the plugin in CMakeLists.txt, and the
# plugin alone in plugin/CMakeLists.txt), in one place.
#
#   grflow_compile_settings(TREE OPTIONS_VAR DEFINITIONS_VAR)
#
# TREE: the LAMMPS source tree the sources are compiled against.
# - -ffp-contract=off (GCC, Clang): no fused multiply-adds, so that the
#   contact law gives the same numbers to the bit on every x86-64 target
#   and in both hosts (GCC fuses a*b+c by default when the target has FMA,
#   e.g. -march=native; the default x86-64 target has none): LIGGGHTS's
#   build uses the same flag (scripts/build-liggghts.sh), and the tests
#   that compare the hosts or builds byte for byte rely on it.
# - GRFLOW_PAIR_HAS_ATOM2CUT (src/GRFLOW/pair_granular_grflow.h): 1 if the
#   tree's Pair still has the virtual atom2cut() (4Feb2025), 0 if not
#   (4Jul2026).

function(grflow_compile_settings tree opts_var defs_var)
  set(opts "")
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    set(opts -ffp-contract=off)
  endif()
  file(STRINGS ${tree}/src/pair.h atom2cut REGEX "virtual double atom2cut")
  if(atom2cut)
    set(defs GRFLOW_PAIR_HAS_ATOM2CUT=1)
  else()
    set(defs GRFLOW_PAIR_HAS_ATOM2CUT=0)
  endif()
  set(${opts_var} "${opts}" PARENT_SCOPE)
  set(${defs_var} "${defs}" PARENT_SCOPE)
endfunction()
