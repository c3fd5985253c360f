# Every dependency is a Debian 12 package; a missing one stops configuration with the
# package name to install (scripts/install_deps.sh installs them all).
function(magfem_require found package)
  if(NOT ${found})
    message(FATAL_ERROR "magfem: missing dependency. Install it with: apt-get install ${package}")
  endif()
endfunction()

find_package(Eigen3 3.4 QUIET NO_MODULE)
magfem_require(Eigen3_FOUND libeigen3-dev)

find_package(yaml-cpp QUIET)
magfem_require(yaml-cpp_FOUND libyaml-cpp-dev)

find_package(CGAL QUIET)
magfem_require(CGAL_FOUND libcgal-dev)

find_package(VTK 9 QUIET COMPONENTS CommonCore CommonDataModel IOXML)
magfem_require(VTK_FOUND libvtk9-dev)

find_package(NLopt QUIET)
magfem_require(NLopt_FOUND libnlopt-cxx-dev)

find_package(Threads REQUIRED)

# PETSc (with hypre's BoomerAMG and Open MPI) for algebraic multigrid in 3D and the
# distributed solve under mpirun; only the module magfem_petsc (solver/petsc_backend.hpp)
# includes and links them.
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(PETSC QUIET IMPORTED_TARGET PETSc)
endif()
magfem_require(PETSC_FOUND libpetsc-real-dev)
find_package(MPI QUIET COMPONENTS CXX)
magfem_require(MPI_CXX_FOUND libopenmpi-dev)
# Scotch itself (PETSc's partitioner): its random seed is set directly (pmg_partition.cpp).
# libscotch-dev comes with PETSc's development package.
find_path(SCOTCH_INCLUDE_DIR scotch/scotch.h)
find_library(SCOTCH_LIBRARY scotch)
magfem_require(SCOTCH_INCLUDE_DIR libscotch-dev)
magfem_require(SCOTCH_LIBRARY libscotch-dev)
add_library(magfem_petsc_libs INTERFACE)
target_link_libraries(magfem_petsc_libs INTERFACE PkgConfig::PETSC MPI::MPI_CXX ${SCOTCH_LIBRARY})

# SuiteSparse ships no CMake config in Debian 12: locate CHOLMOD directly.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY cholmod)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig)
if(CHOLMOD_INCLUDE_DIR AND CHOLMOD_LIBRARY AND SUITESPARSECONFIG_LIBRARY)
  set(CHOLMOD_FOUND TRUE)
endif()
magfem_require(CHOLMOD_FOUND libsuitesparse-dev)
add_library(magfem_cholmod INTERFACE)
target_include_directories(magfem_cholmod SYSTEM INTERFACE ${CHOLMOD_INCLUDE_DIR})
target_link_libraries(magfem_cholmod INTERFACE ${CHOLMOD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY})

# TetGen (AGPL-3.0) is fenced into the 3D mesher's translation unit only.
find_path(TETGEN_INCLUDE_DIR tetgen.h)
find_library(TETGEN_LIBRARY tet)
if(TETGEN_INCLUDE_DIR AND TETGEN_LIBRARY)
  set(TETGEN_FOUND TRUE)
endif()
magfem_require(TETGEN_FOUND libtet1.5-dev)
add_library(magfem_tetgen INTERFACE)
target_include_directories(magfem_tetgen SYSTEM INTERFACE ${TETGEN_INCLUDE_DIR})
target_compile_definitions(magfem_tetgen INTERFACE TETLIBRARY)
target_link_libraries(magfem_tetgen INTERFACE ${TETGEN_LIBRARY})

if(MAGFEM_BUILD_TESTS)
  find_package(GTest QUIET)
  magfem_require(GTest_FOUND libgtest-dev)
endif()
