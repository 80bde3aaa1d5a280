# The MPI launcher of the tests, from FindMPI's cache variables: MPIEXEC_EXECUTABLE,
# MPIEXEC_NUMPROC_FLAG (-n) and MPIEXEC_PREFLAGS (before the program). With Open MPI,
# MPIEXEC_PREFLAGS defaults to --oversubscribe --allow-run-as-root: tests run 3 ranks on fewer
# cores, and containers run as root. Other MPIs (MPICH) get no flags; -DMPIEXEC_PREFLAGS=...
# replaces them.
if(NOT MPIEXEC_EXECUTABLE)
  message(FATAL_ERROR "No MPI launcher found (MPIEXEC_EXECUTABLE): set -DMPIEXEC_EXECUTABLE=/path/to/mpiexec, "
    "or -DSIGNORINI_ENABLE_TESTS=OFF.")
endif()
# Decided once per launcher: a user's MPIEXEC_PREFLAGS (even empty) is kept afterwards; on the first
# configure an empty one counts as unset (FindMPI leaves it empty), so with Open MPI it gets the flags.
if(NOT "${SIGNORINI_MPIEXEC_CHECKED}" STREQUAL "${MPIEXEC_EXECUTABLE}")
  execute_process(COMMAND ${MPIEXEC_EXECUTABLE} --version OUTPUT_VARIABLE _signorini_version
    ERROR_VARIABLE _signorini_version RESULT_VARIABLE _signorini_rc TIMEOUT 20)
  if(NOT _signorini_rc EQUAL 0)
    set(_signorini_version "${MPI_CXX_LIBRARY_VERSION_STRING}")
  endif()
  set(_signorini_openmpi_flags --oversubscribe --allow-run-as-root)
  if(_signorini_version MATCHES "Open MPI|OpenRTE")
    if(MPIEXEC_PREFLAGS STREQUAL "")
      set_property(CACHE MPIEXEC_PREFLAGS PROPERTY VALUE "${_signorini_openmpi_flags}")
    endif()
    message(STATUS "Tests: ${MPIEXEC_EXECUTABLE} is Open MPI's")
  elseif(MPIEXEC_PREFLAGS STREQUAL "${_signorini_openmpi_flags}")
    set_property(CACHE MPIEXEC_PREFLAGS PROPERTY VALUE "")  # the Open MPI default of an earlier launcher
  endif()
  set(SIGNORINI_MPIEXEC_CHECKED "${MPIEXEC_EXECUTABLE}" CACHE INTERNAL "launcher whose flags were chosen")
endif()
# MPIEXEC_PREFLAGS as a list (also when given as one string with spaces).
string(REPLACE ";" " " _signorini_preflags "${MPIEXEC_PREFLAGS}")
separate_arguments(SIGNORINI_MPIEXEC_PREFLAGS UNIX_COMMAND "${_signorini_preflags}")
string(JOIN " " _signorini_shown ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} <n> ${SIGNORINI_MPIEXEC_PREFLAGS} <program>)
message(STATUS "Tests run MPI as: ${_signorini_shown}")
# The launcher for the test scripts (tests/driver/*.sh and run_bad_deck.cmake, tests/adapt/*.sh),
# one argument: executable|numproc flag|preflags..., separated by "|".
unset(SIGNORINI_MPIEXEC CACHE)  # the find_program result of earlier versions
string(JOIN "|" SIGNORINI_MPIEXEC "${MPIEXEC_EXECUTABLE}" "${MPIEXEC_NUMPROC_FLAG}" ${SIGNORINI_MPIEXEC_PREFLAGS})

# signorini_add_gtest(NAME SOURCES ... LIBS ... [NP n] [LABELS ...]): a GoogleTest executable
# registered with ctest, run on n MPI ranks (default 1).
function(signorini_add_gtest name)
  cmake_parse_arguments(T "" "NP;TIMEOUT" "SOURCES;LIBS;LABELS;NPS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE signorini_test_main ${T_LIBS})
  # The libraries' warnings; aggregates that rely on default member initialisers are fine.
  target_compile_options(${name} PRIVATE -Wall -Wextra -Wno-unused-parameter -Wno-missing-field-initializers)
  target_compile_definitions(${name} PRIVATE
    SIGNORINI_SOURCE_DIR="${PROJECT_SOURCE_DIR}" SIGNORINI_BINARY_DIR="${PROJECT_BINARY_DIR}")
  if(NOT T_NPS)
    set(T_NPS 1)
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 600)
  endif()
  foreach(np ${T_NPS})
    set(test_name ${name}_np${np})
    add_test(NAME ${test_name}
      COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${np} ${SIGNORINI_MPIEXEC_PREFLAGS} $<TARGET_FILE:${name}>)
    # Every GoogleTest executable is also labelled "unit" (ctest -L unit: the library tests alone).
    set_tests_properties(${test_name} PROPERTIES TIMEOUT ${T_TIMEOUT} PROCESSORS ${np} LABELS "unit;${T_LABELS}")
  endforeach()
endfunction()
