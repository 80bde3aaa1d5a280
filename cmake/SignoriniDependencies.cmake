# Third-party dependencies of signorini, wrapped as imported targets under signorini_deps::.
# Used by the build; the installed signorini-config.cmake finds the same packages with
# find_dependency and includes SignoriniTrilinos.cmake and the Find modules.

# MPI: C++ always; the C bindings when the C language is enabled (p4est then links MPI::MPI_C).
set(SIGNORINI_MPI_COMPONENTS CXX)
get_property(_signorini_languages GLOBAL PROPERTY ENABLED_LANGUAGES)
if(C IN_LIST _signorini_languages)
  list(APPEND SIGNORINI_MPI_COMPONENTS C)
endif()
find_package(MPI REQUIRED COMPONENTS ${SIGNORINI_MPI_COMPONENTS})

# Trilinos. A Trilinos_DIR that holds no Trilinos package config is an error (find_package would
# quietly search elsewhere and take, say, /usr); so is a Trilinos without a package signorini needs.
set(SIGNORINI_TRILINOS_COMPONENTS Teuchos Kokkos Tpetra Belos MueLu Ifpack2 Amesos2)
if(Trilinos_DIR AND NOT EXISTS "${Trilinos_DIR}/TrilinosConfig.cmake"
   AND NOT EXISTS "${Trilinos_DIR}/trilinos-config.cmake")
  message(FATAL_ERROR "Trilinos_DIR = ${Trilinos_DIR} holds no TrilinosConfig.cmake. Set it to the "
    "folder <prefix>/lib/cmake/Trilinos of a Trilinos installation, or leave it unset and put <prefix> "
    "into CMAKE_PREFIX_PATH.")
endif()
find_package(Trilinos 13.2 CONFIG COMPONENTS ${SIGNORINI_TRILINOS_COMPONENTS})
if(NOT Trilinos_FOUND)
  set(_signorini_missing "")
  foreach(c IN LISTS SIGNORINI_TRILINOS_COMPONENTS)
    if(DEFINED Trilinos_${c}_FOUND AND NOT Trilinos_${c}_FOUND)
      list(APPEND _signorini_missing ${c})
    endif()
  endforeach()
  if(_signorini_missing)
    string(REPLACE ";" ", " _signorini_missing "${_signorini_missing}")
    string(REPLACE ";" ", " _signorini_all "${SIGNORINI_TRILINOS_COMPONENTS}")
    message(FATAL_ERROR "The Trilinos ${Trilinos_VERSION} in ${Trilinos_DIR} lacks the package(s) "
      "${_signorini_missing}, which signorini needs (all of: ${_signorini_all}). Build "
      "Trilinos with Trilinos_ENABLE_<package>=ON, or point Trilinos_DIR to another installation.")
  endif()
  set(_signorini_considered "")
  if(Trilinos_CONSIDERED_CONFIGS)
    set(_signorini_considered " (found only ${Trilinos_CONSIDERED_CONFIGS}, version(s) ${Trilinos_CONSIDERED_VERSIONS})")
  endif()
  message(FATAL_ERROR "Trilinos 13.2 or newer not found${_signorini_considered}. Set Trilinos_DIR to "
    "<prefix>/lib/cmake/Trilinos or add <prefix> to CMAKE_PREFIX_PATH.")
endif()
include(SignoriniTrilinos)

# One line on the Trilinos found: version, place, Kokkos devices, Tpetra's default node, flags.
set(_signorini_devices "${Kokkos_DEVICES}")
set(_signorini_node "")
foreach(d IN LISTS Trilinos_INCLUDE_DIRS)
  if(NOT _signorini_devices AND EXISTS "${d}/KokkosCore_config.h")
    file(STRINGS "${d}/KokkosCore_config.h" _signorini_lines REGEX "^#define KOKKOS_ENABLE_")
    foreach(l IN LISTS _signorini_lines)
      if(l MATCHES "^#define KOKKOS_ENABLE_(SERIAL|OPENMP|THREADS|CUDA|HIP|SYCL|HPX|OPENMPTARGET)$")
        list(APPEND _signorini_devices ${CMAKE_MATCH_1})
      endif()
    endforeach()
  endif()
  if(NOT _signorini_node AND EXISTS "${d}/KokkosClassic_DefaultNode_config.h")
    file(STRINGS "${d}/KokkosClassic_DefaultNode_config.h" _signorini_lines REGEX "^#define TPETRA_DEFAULTNODE ")
    if(_signorini_lines MATCHES "^#define TPETRA_DEFAULTNODE +([^ ]+)")
      set(_signorini_node "${CMAKE_MATCH_1}")
    endif()
  endif()
endforeach()
if(NOT _signorini_devices)
  set(_signorini_devices "unknown")
endif()
if(NOT _signorini_node)
  set(_signorini_node "unknown")
endif()
string(REPLACE ";" " " _signorini_flags "${SIGNORINI_KOKKOS_FLAGS}")
string(REPLACE "SHELL:" "" _signorini_flags "${_signorini_flags}")
if(NOT _signorini_flags)
  set(_signorini_flags "none")
endif()
string(REPLACE ";" "," _signorini_devices "${_signorini_devices}")
message(STATUS "Trilinos ${Trilinos_VERSION} in ${Trilinos_DIR}: Kokkos devices ${_signorini_devices}, "
  "Tpetra default node ${_signorini_node}, Kokkos flags added: ${_signorini_flags}")

find_package(P4est REQUIRED)
find_package(ExodusII REQUIRED)
find_package(MuParser REQUIRED)
