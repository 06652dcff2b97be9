# Stage a LAMMPS source tree with the GRFLOW package added, without writing
# into the original tree.
#
# The staged tree lives in the build directory.  Its src/ is a real directory
# of symbolic links to the original entries; its src/GRFLOW is a real
# directory of links to our LAMMPS adapters (src/GRFLOW) and to the
# host-free sources shared with LIGGGHTS (src/shared); its
# src/OPENMP is a real directory too, of links to the original OPENMP entries
# plus our accelerator variants (src/OPENMP/*_omp.*, found there by the OPENMP
# package's RegisterStylesExt as for any other package); src/KOKKOS likewise,
# with our KOKKOS variants (src/KOKKOS/*_kokkos*); its cmake/ is a copy
# whose package list names GRFLOW.  bench/ and potentials/
# are staged empty so "install" does not copy data GRFLOW never uses.
#
# GRFLOW_KOKKOS_STAGE_STYLES (optional): a list of the LAMMPS KOKKOS styles to
# stage, by the name of the plain style's header without .h (e.g.
# fix_nve_sphere); the KOKKOS package's own files (kokkos.cpp, atom_kokkos,
# comm_kokkos, npair_kokkos, ...) and GRFLOW's are always staged.  A style
# not staged is not compiled, and runs as its plain host version.  Empty
# (the default): every style, as a LAMMPS tree has them.
#
# In:  LAMMPS_SOURCE_DIR (original tree), GRFLOW_PACKAGE_DIR (our src/GRFLOW),
#      GRFLOW_SHARED_DIR (our src/shared), GRFLOW_OPENMP_DIR (our src/OPENMP),
#      GRFLOW_KOKKOS_DIR (our src/KOKKOS), GRFLOW_KOKKOS_STAGE_STYLES
# Out: GRFLOW_STAGED_LAMMPS (staged tree root)

# A LAMMPS source tree of a version GRFLOW supports, or a fatal error.  The
# one place that lists the supported versions.
function(grflow_check_lammps_tree orig)
  if(NOT EXISTS ${orig}/src/version.h OR NOT EXISTS ${orig}/cmake/CMakeLists.txt)
    message(FATAL_ERROR "${orig} is not a LAMMPS source tree "
      "(no src/version.h or cmake/CMakeLists.txt)")
  endif()
  file(STRINGS ${orig}/src/version.h lmp_version REGEX "LAMMPS_VERSION")
  if(NOT lmp_version MATCHES "4 Feb 2025|4 Jul 2026")
    message(FATAL_ERROR "GRFLOW supports LAMMPS 4Feb2025 and 4Jul2026; ${orig} has: ${lmp_version}")
  endif()
endfunction()

# The text of a LAMMPS cmake/CMakeLists.txt with GRFLOW in its list of
# standard packages (so that -D PKG_GRFLOW=on exists); unchanged if it is
# there already.
function(grflow_register_cmake_package cml out)
  if(cml MATCHES "set\\(STANDARD_PACKAGES\n[^)]*  GRFLOW\n")
    set(${out} "${cml}" PARENT_SCOPE)
    return()
  endif()
  string(REPLACE "set(STANDARD_PACKAGES\n" "set(STANDARD_PACKAGES\n  GRFLOW\n" patched "${cml}")
  if(patched STREQUAL cml)
    message(FATAL_ERROR "could not find the list STANDARD_PACKAGES in a LAMMPS cmake/CMakeLists.txt")
  endif()
  set(${out} "${patched}" PARENT_SCOPE)
endfunction()

function(grflow_stage_lammps)
  set(orig ${LAMMPS_SOURCE_DIR})
  set(stage ${CMAKE_BINARY_DIR}/lammps-staged)
  grflow_check_lammps_tree(${orig})
  if(EXISTS ${orig}/src/GRFLOW)
    message(FATAL_ERROR "${orig}/src already has a GRFLOW folder; pass a clean LAMMPS tree")
  endif()
  file(GLOB omp_files RELATIVE ${GRFLOW_OPENMP_DIR} ${GRFLOW_OPENMP_DIR}/*)
  foreach(e ${omp_files})
    if(EXISTS ${orig}/src/OPENMP/${e})
      message(FATAL_ERROR "${orig}/src/OPENMP already has ${e}; pass a clean LAMMPS tree")
    endif()
  endforeach()
  file(GLOB kk_files RELATIVE ${GRFLOW_KOKKOS_DIR} ${GRFLOW_KOKKOS_DIR}/*)
  foreach(e ${kk_files})
    if(EXISTS ${orig}/src/KOKKOS/${e})
      message(FATAL_ERROR "${orig}/src/KOKKOS already has ${e}; pass a clean LAMMPS tree")
    endif()
  endforeach()

  # rebuild the link farm when the original tree changes location or the
  # set of our files changes
  file(GLOB pkg_files RELATIVE ${GRFLOW_PACKAGE_DIR} ${GRFLOW_PACKAGE_DIR}/*)
  file(GLOB shared_files RELATIVE ${GRFLOW_SHARED_DIR} ${GRFLOW_SHARED_DIR}/*)
  set(stamp ${stage}/.grflow-staged-from)
  set(stamp_text "${orig}\nOPENMP: ${omp_files}\nKOKKOS: ${kk_files}\nGRFLOW: ${pkg_files}\nshared: ${shared_files}\nKOKKOS styles: ${GRFLOW_KOKKOS_STAGE_STYLES}")
  set(restage TRUE)
  if(EXISTS ${stamp})
    file(READ ${stamp} previous)
    if(previous STREQUAL "${stamp_text}")
      set(restage FALSE)
    endif()
  endif()
  if(restage)
    file(REMOVE_RECURSE ${stage})
    file(MAKE_DIRECTORY ${stage}/src ${stage}/bench ${stage}/potentials ${stage}/doc)
    foreach(top lib python tools unittest examples fortran)
      if(EXISTS ${orig}/${top})
        file(CREATE_LINK ${orig}/${top} ${stage}/${top} SYMBOLIC)
      endif()
    endforeach()
    file(CREATE_LINK ${orig}/doc/lammps.1 ${stage}/doc/lammps.1 SYMBOLIC)
    file(GLOB entries RELATIVE ${orig}/src ${orig}/src/*)
    list(REMOVE_ITEM entries OPENMP KOKKOS)
    foreach(e ${entries})
      file(CREATE_LINK ${orig}/src/${e} ${stage}/src/${e} SYMBOLIC)
    endforeach()
    file(MAKE_DIRECTORY ${stage}/src/GRFLOW)
    foreach(e ${pkg_files})
      file(CREATE_LINK ${GRFLOW_PACKAGE_DIR}/${e} ${stage}/src/GRFLOW/${e} SYMBOLIC)
    endforeach()
    foreach(e ${shared_files})
      file(CREATE_LINK ${GRFLOW_SHARED_DIR}/${e} ${stage}/src/GRFLOW/${e} SYMBOLIC)
    endforeach()
    file(MAKE_DIRECTORY ${stage}/src/OPENMP)
    file(GLOB entries RELATIVE ${orig}/src/OPENMP ${orig}/src/OPENMP/*)
    foreach(e ${entries})
      file(CREATE_LINK ${orig}/src/OPENMP/${e} ${stage}/src/OPENMP/${e} SYMBOLIC)
    endforeach()
    foreach(e ${omp_files})
      file(CREATE_LINK ${GRFLOW_OPENMP_DIR}/${e} ${stage}/src/OPENMP/${e} SYMBOLIC)
    endforeach()
    file(MAKE_DIRECTORY ${stage}/src/KOKKOS)
    file(GLOB entries RELATIVE ${orig}/src/KOKKOS ${orig}/src/KOKKOS/*)
    foreach(e ${entries})
      if(GRFLOW_KOKKOS_STAGE_STYLES AND e MATCHES "^(.*)_kokkos\\.h$")
        # a style header of a style not asked for is left out (its .cpp is
        # then never registered, so never compiled)
        set(base ${CMAKE_MATCH_1})
        file(STRINGS ${orig}/src/KOKKOS/${e} is_style REGEX "Style\\(" LIMIT_COUNT 1)
        if(is_style AND NOT base IN_LIST GRFLOW_KOKKOS_STAGE_STYLES)
          continue()
        endif()
      endif()
      file(CREATE_LINK ${orig}/src/KOKKOS/${e} ${stage}/src/KOKKOS/${e} SYMBOLIC)
    endforeach()
    foreach(e ${kk_files})
      file(CREATE_LINK ${GRFLOW_KOKKOS_DIR}/${e} ${stage}/src/KOKKOS/${e} SYMBOLIC)
    endforeach()
    file(WRITE ${stamp} "${stamp_text}")
  endif()

  # copy cmake/ and register GRFLOW as a standard package (idempotent)
  file(COPY ${orig}/cmake DESTINATION ${stage} REGEX "/cmake/CMakeLists\\.txt$" EXCLUDE)
  file(READ ${orig}/cmake/CMakeLists.txt cml)
  grflow_register_cmake_package("${cml}" cml_patched)
  file(WRITE ${stage}/cmake/CMakeLists.txt.new "${cml_patched}")
  file(COPY_FILE ${stage}/cmake/CMakeLists.txt.new ${stage}/cmake/CMakeLists.txt ONLY_IF_DIFFERENT)
  file(REMOVE ${stage}/cmake/CMakeLists.txt.new)
  set(GRFLOW_STAGED_LAMMPS ${stage} PARENT_SCOPE)
endfunction()
