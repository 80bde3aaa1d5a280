# FindP4est: p4est and its companion library libsc.
# Defines P4est_FOUND and the imported target signorini_deps::p4est.
find_path(P4est_INCLUDE_DIR p4est.h PATH_SUFFIXES p4est)
find_library(P4est_LIBRARY NAMES p4est)
find_library(P4est_SC_LIBRARY NAMES sc)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(P4est REQUIRED_VARS P4est_LIBRARY P4est_SC_LIBRARY P4est_INCLUDE_DIR)
if(P4est_FOUND AND NOT TARGET signorini_deps::p4est)
  # p4est is C on MPI: MPI::MPI_C when the project found MPI's C bindings (its C language enabled),
  # else MPI::MPI_CXX, which brings the same mpi.h and MPI library.
  if(TARGET MPI::MPI_C)
    set(_p4est_mpi MPI::MPI_C)
  else()
    set(_p4est_mpi MPI::MPI_CXX)
  endif()
  add_library(signorini_deps::p4est UNKNOWN IMPORTED)
  set_target_properties(signorini_deps::p4est PROPERTIES
    IMPORTED_LOCATION "${P4est_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${P4est_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${P4est_SC_LIBRARY};${_p4est_mpi}")
  unset(_p4est_mpi)
endif()
mark_as_advanced(P4est_INCLUDE_DIR P4est_LIBRARY P4est_SC_LIBRARY)
