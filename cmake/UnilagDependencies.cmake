# Dependencies of unilag. Trilinos 13.2 is the project's own build (scripts/setup.sh), found through
# Trilinos_DIR or CMAKE_PREFIX_PATH; TriBITS 13.2 exports no per-package targets, so we wrap its variables.
find_package(MPI REQUIRED COMPONENTS C CXX)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(Trilinos 13.2 REQUIRED COMPONENTS Kokkos Teuchos Tpetra Zoltan2)

if(NOT "${Trilinos_PACKAGE_LIST}" MATCHES "Zoltan2")
  message(FATAL_ERROR "Trilinos at ${Trilinos_DIR} lacks Zoltan2: run scripts/setup.sh")
endif()

add_library(unilag_trilinos INTERFACE)
target_include_directories(unilag_trilinos SYSTEM INTERFACE ${Trilinos_INCLUDE_DIRS} ${Trilinos_TPL_INCLUDE_DIRS})
target_link_libraries(unilag_trilinos INTERFACE ${Trilinos_LIBRARIES} MPI::MPI_CXX OpenMP::OpenMP_CXX)
add_library(unilag::trilinos ALIAS unilag_trilinos)

# Kokkos alone (what kernels/ may use). Kokkos headers come from the same Trilinos install.
add_library(unilag_kokkos INTERFACE)
target_include_directories(unilag_kokkos SYSTEM INTERFACE ${Trilinos_INCLUDE_DIRS})
if(TARGET Kokkos::kokkos)
  target_link_libraries(unilag_kokkos INTERFACE Kokkos::kokkos OpenMP::OpenMP_CXX)
else()
  target_link_libraries(unilag_kokkos INTERFACE kokkoscore OpenMP::OpenMP_CXX)
endif()
add_library(unilag::kokkos ALIAS unilag_kokkos)

# LAPACK (Debian liblapack-dev) for the tube's dense eigenproblems, called through extern "C" (src/tube/Lapack.cpp).
find_package(LAPACK REQUIRED)

set(HDF5_PREFER_PARALLEL ON)
find_package(HDF5 REQUIRED COMPONENTS C)
if(NOT HDF5_IS_PARALLEL)
  message(FATAL_ERROR "unilag needs parallel HDF5 (Debian libhdf5-openmpi-dev)")
endif()
add_library(unilag_hdf5 INTERFACE)
target_include_directories(unilag_hdf5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS} ${HDF5_INCLUDE_DIRS})
target_link_libraries(unilag_hdf5 INTERFACE ${HDF5_C_LIBRARIES} MPI::MPI_C)
add_library(unilag::hdf5 ALIAS unilag_hdf5)

# gmsh and muparser ship no CMake config on Debian.
find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
find_library(GMSH_LIBRARY gmsh REQUIRED)
find_path(MUPARSER_INCLUDE_DIR muParser.h PATH_SUFFIXES muParser REQUIRED)
find_library(MUPARSER_LIBRARY muparser REQUIRED)
add_library(unilag_gmsh INTERFACE)
target_include_directories(unilag_gmsh SYSTEM INTERFACE ${GMSH_INCLUDE_DIR})
target_link_libraries(unilag_gmsh INTERFACE ${GMSH_LIBRARY})
add_library(unilag_muparser INTERFACE)
target_include_directories(unilag_muparser SYSTEM INTERFACE ${MUPARSER_INCLUDE_DIR})
target_link_libraries(unilag_muparser INTERFACE ${MUPARSER_LIBRARY})

include(FeatureSummary)
feature_summary(WHAT ALL)
