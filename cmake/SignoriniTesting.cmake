# signorini_add_gtest(NAME SOURCES ... LIBS ... [NP n] [LABELS ...]): a GoogleTest executable
# registered with ctest, run on n MPI ranks (default 1).
function(signorini_add_gtest name)
  cmake_parse_arguments(T "" "NP;TIMEOUT" "SOURCES;LIBS;LABELS;NPS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE signorini_test_main ${T_LIBS})
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
      COMMAND ${SIGNORINI_MPIEXEC} --oversubscribe --allow-run-as-root -np ${np} $<TARGET_FILE:${name}>)
    set_tests_properties(${test_name} PROPERTIES TIMEOUT ${T_TIMEOUT} PROCESSORS ${np} LABELS "${T_LABELS}")
  endforeach()
endfunction()
