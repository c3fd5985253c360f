# Backend modules (issue 35): PETSc with MPI (libmagfem_petsc.so) and VTK (libmagfem_vtk.so) are
# loaded by dlopen the first time a command needs them (core/backend_module.hpp), so that the
# executable and the Python module do not list them and every other command starts fast.
#
# Where they live: <prefix>/${MAGFEM_MODULE_DIR}, and the same path under the build tree. The
# executable and the Python module find them through their run path: the build tree's absolute
# directory while built, $ORIGIN-relative once installed (the installed tree can move).
set(MAGFEM_MODULE_DIR ${CMAKE_INSTALL_LIBDIR}/magfem)
set(MAGFEM_MODULE_BUILD_DIR ${PROJECT_BINARY_DIR}/${MAGFEM_MODULE_DIR})
# Every target of the build tree (the tests too) finds the modules there.
list(APPEND CMAKE_BUILD_RPATH ${MAGFEM_MODULE_BUILD_DIR})
# The modules link our static libraries into a shared object: position-independent code.
set(CMAKE_POSITION_INDEPENDENT_CODE ON)

# magfem_backend_module(target): a MODULE library exporting only its extern "C" entry point,
# with our static libraries' symbols kept inside it (--exclude-libs), every symbol resolved at
# link time (--no-undefined: a module missing a source fails the build, not a run), and
# installed beside its siblings.
function(magfem_backend_module target)
  set_target_properties(${target} PROPERTIES
    PREFIX lib
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON
    LIBRARY_OUTPUT_DIRECTORY ${MAGFEM_MODULE_BUILD_DIR})
  target_link_options(${target} PRIVATE -Wl,--exclude-libs,ALL -Wl,--no-undefined)
  magfem_set_warnings(${target})
  install(TARGETS ${target} LIBRARY DESTINATION ${MAGFEM_MODULE_DIR})
endfunction()

# magfem_finds_modules(target dir): the installed `target`, which sits in <prefix>/dir, finds
# the modules relative to itself.
function(magfem_finds_modules target dir)
  file(RELATIVE_PATH to_modules /${dir} /${MAGFEM_MODULE_DIR})
  set_target_properties(${target} PROPERTIES INSTALL_RPATH "$ORIGIN/${to_modules}")
endfunction()
