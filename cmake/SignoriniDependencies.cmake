# Third-party dependencies of signorini, wrapped as imported targets under signorini_deps::.
# Used by the build and (through signorini-config.cmake) by downstream projects.
find_package(MPI REQUIRED COMPONENTS C CXX)

find_package(Trilinos 13.2 REQUIRED
  COMPONENTS Teuchos Kokkos Tpetra Belos MueLu Ifpack2 Amesos2)
if(NOT TARGET signorini_deps::trilinos)
  add_library(signorini_deps::trilinos INTERFACE IMPORTED)
  set_target_properties(signorini_deps::trilinos PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${Trilinos_INCLUDE_DIRS};${Trilinos_TPL_INCLUDE_DIRS}"
    INTERFACE_LINK_LIBRARIES "${Trilinos_LIBRARIES};${Trilinos_TPL_LIBRARIES};MPI::MPI_CXX")
endif()

find_package(P4est REQUIRED)
find_package(ExodusII REQUIRED)
find_package(MuParser REQUIRED)
