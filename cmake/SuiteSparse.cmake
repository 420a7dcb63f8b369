# SuiteSparse 5.x (Debian 12) ships no CMake config: find headers and libraries and make
# imported targets with the names SuiteSparse 7 uses, so a newer system works unchanged.
find_package(UMFPACK CONFIG QUIET)
find_package(KLU CONFIG QUIET)
if(NOT TARGET SuiteSparse::UMFPACK OR NOT TARGET SuiteSparse::KLU)
  find_path(SUITESPARSE_INCLUDE_DIR umfpack.h PATH_SUFFIXES suitesparse REQUIRED)
  foreach(lib umfpack klu amd colamd btf suitesparseconfig)
    string(TOUPPER ${lib} LIBU)
    find_library(SUITESPARSE_${LIBU}_LIBRARY ${lib} REQUIRED)
  endforeach()
  add_library(SuiteSparse::Config UNKNOWN IMPORTED)
  set_target_properties(SuiteSparse::Config PROPERTIES
    IMPORTED_LOCATION "${SUITESPARSE_SUITESPARSECONFIG_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${SUITESPARSE_INCLUDE_DIR}")
  foreach(lib AMD COLAMD BTF)
    add_library(SuiteSparse::${lib} UNKNOWN IMPORTED)
    set_target_properties(SuiteSparse::${lib} PROPERTIES
      IMPORTED_LOCATION "${SUITESPARSE_${lib}_LIBRARY}"
      INTERFACE_LINK_LIBRARIES SuiteSparse::Config)
  endforeach()
  add_library(SuiteSparse::UMFPACK UNKNOWN IMPORTED)
  set_target_properties(SuiteSparse::UMFPACK PROPERTIES
    IMPORTED_LOCATION "${SUITESPARSE_UMFPACK_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${SUITESPARSE_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "SuiteSparse::AMD;SuiteSparse::Config")
  add_library(SuiteSparse::KLU UNKNOWN IMPORTED)
  set_target_properties(SuiteSparse::KLU PROPERTIES
    IMPORTED_LOCATION "${SUITESPARSE_KLU_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${SUITESPARSE_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "SuiteSparse::AMD;SuiteSparse::COLAMD;SuiteSparse::BTF;SuiteSparse::Config")
elseif(NOT TARGET SuiteSparse::Config)
  find_package(SuiteSparse_config CONFIG REQUIRED)
  if(TARGET SuiteSparse::SuiteSparseConfig)
    add_library(SuiteSparse::Config ALIAS SuiteSparse::SuiteSparseConfig)
  endif()
endif()
