# SuiteSparse 5.12 on Debian 12 ships neither a CMake config nor a .pc file (docs/design.md):
# locate the headers and libraries and wrap them in one INTERFACE IMPORTED target.
find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(UMFPACK_LIBRARY umfpack REQUIRED)
find_library(KLU_LIBRARY klu REQUIRED)
find_library(BTF_LIBRARY btf REQUIRED)
find_library(AMD_LIBRARY amd REQUIRED)
find_library(COLAMD_LIBRARY colamd REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
find_package(BLAS REQUIRED)
find_package(LAPACK REQUIRED)
if(NOT TARGET SuiteSparse::SuiteSparse)
  add_library(SuiteSparse::SuiteSparse INTERFACE IMPORTED)
  set_target_properties(SuiteSparse::SuiteSparse PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${SUITESPARSE_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${CHOLMOD_LIBRARY};${KLU_LIBRARY};${BTF_LIBRARY};${UMFPACK_LIBRARY};${AMD_LIBRARY};${COLAMD_LIBRARY};${SUITESPARSECONFIG_LIBRARY};${LAPACK_LIBRARIES};${BLAS_LIBRARIES}")
endif()
