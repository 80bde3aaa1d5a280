# run_bad_deck.cmake: runs the signorini driver on NP MPI ranks and checks how it ends.
#   cmake -DSIGNORINI=... -DMPIEXEC='mpiexec|-n|--oversubscribe' -DNP=2 -DWORK_DIR=... -DWRAPPER=.../rank_status.sh
#         -DARGS='--output-dir|{OUT}|deck.xml' -DEXPECT_EXIT=1 -DEXPECT_REGEX='re1<AND>re2' [-DABSENT_REGEX='re3']
#         [-DEXPECT_FILES='a.steps.csv|a.e'] [-DBLOCK='a.e|a.cycles.csv'] [-DSEED='a.e|a.e-s.0003']
#         [-DUNCHANGED='a.e'] [-DTIMEOUT=50] -P run_bad_deck.cmake
#
# 1. Makes a fresh, empty output directory WORK_DIR/out ("{OUT}" in ARGS; also the working
#    directory of the run, so that output written to "." is caught too).
#    BLOCK names directories made in it first, to take output names (they are not outputs).
#    SEED names files made in it first, as an earlier run would have left them (each holds
#    "seeded <name>"); UNCHANGED names those of them that must still hold exactly that afterwards;
#    the others that EXPECT_FILES lists must have been replaced by the run's own.
# 2. Runs `EXECUTABLE NUMPROC_FLAG NP PREFLAGS... rank_status.sh STATUS_DIR SIGNORINI ARGS`, MPIEXEC
#    being "EXECUTABLE|NUMPROC_FLAG|PREFLAGS..." (FindMPI's MPIEXEC_EXECUTABLE, MPIEXEC_NUMPROC_FLAG,
#    MPIEXEC_PREFLAGS; a bare executable gets -n) and ARGS separated by "|"; rank_status.sh
#    records the exit status of every rank.
# 3. Checks that EVERY rank exited with EXPECT_EXIT (a crash gives 134/139, a killed or hung
#    rank gives no status at all), that stdout + stderr match each regular expression in
#    EXPECT_REGEX (separated by "<AND>"), none in ABSENT_REGEX, and show no crash, and that the output directory then
#    holds exactly EXPECT_FILES (non-empty) -- by default nothing at all, not even a .part file.
cmake_minimum_required(VERSION 3.16)  # policies for -P scripts (IN_LIST)
foreach(v SIGNORINI MPIEXEC WORK_DIR WRAPPER EXPECT_EXIT)
  if(NOT DEFINED ${v} OR "${${v}}" STREQUAL "")
    message(FATAL_ERROR "run_bad_deck.cmake: -D${v}=... is required")
  endif()
endforeach()
if(NOT NP)
  set(NP 2)
endif()
if(NOT TIMEOUT)
  set(TIMEOUT 50)
endif()

set(out_dir "${WORK_DIR}/out")
set(status_dir "${WORK_DIR}/status")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${out_dir}" "${status_dir}")
set(blocked "")
if(NOT "${BLOCK}" STREQUAL "")
  string(REPLACE "|" ";" blocked "${BLOCK}")
  foreach(b IN LISTS blocked)
    file(MAKE_DIRECTORY "${out_dir}/${b}")
  endforeach()
endif()

set(seeded "")
if(NOT "${SEED}" STREQUAL "")
  string(REPLACE "|" ";" seeded "${SEED}")
  foreach(f IN LISTS seeded)
    get_filename_component(d "${out_dir}/${f}" DIRECTORY)
    file(MAKE_DIRECTORY "${d}")
    file(WRITE "${out_dir}/${f}" "seeded ${f}\n")
  endforeach()
endif()

set(args "")
if(NOT "${ARGS}" STREQUAL "")
  string(REPLACE "{OUT}" "${out_dir}" args "${ARGS}")
  string(REPLACE "|" ";" args "${args}")
endif()

string(REPLACE "|" ";" launcher "${MPIEXEC}")
list(POP_FRONT launcher mpiexec_executable)
list(POP_FRONT launcher numproc_flag)
if("${numproc_flag}" STREQUAL "")
  set(numproc_flag -n)
endif()
set(command ${mpiexec_executable} ${numproc_flag} ${NP} ${launcher} /bin/sh ${WRAPPER} ${status_dir} ${SIGNORINI} ${args})
string(REPLACE ";" "' '" shown "'${command}'")
message(STATUS "running: ${shown}")
message(STATUS "in: ${out_dir}")
execute_process(
  COMMAND ${command}
  WORKING_DIRECTORY "${out_dir}"
  RESULT_VARIABLE mpi_result
  OUTPUT_VARIABLE stdout
  ERROR_VARIABLE stderr
  TIMEOUT ${TIMEOUT})
message(STATUS "mpiexec result: ${mpi_result}")
message("---- stdout ----\n${stdout}---- stderr ----\n${stderr}----------------")
set(all "${stdout}\n${stderr}")

set(failures "")
function(fail msg)
  set(failures "${failures}  - ${msg}\n" PARENT_SCOPE)
endfunction()

if(NOT "${mpi_result}" MATCHES "^[0-9]+$")
  fail("mpiexec did not finish normally: ${mpi_result} (a hang or a timeout after ${TIMEOUT} s?)")
endif()

# Exit status of every rank.
math(EXPR last_rank "${NP} - 1")
foreach(rank RANGE 0 ${last_rank})
  set(f "${status_dir}/rank-${rank}.status")
  if(NOT EXISTS "${f}")
    fail("rank ${rank} reported no exit status (killed, crashed or hung)")
    continue()
  endif()
  file(READ "${f}" status)
  string(STRIP "${status}" status)
  if(EXPECT_EXIT STREQUAL "nonzero")
    if(status EQUAL 0)
      fail("rank ${rank} exited with 0, expected a non-zero status")
    endif()
  elseif(NOT status EQUAL EXPECT_EXIT)
    fail("rank ${rank} exited with ${status}, expected ${EXPECT_EXIT}")
  endif()
endforeach()

# The messages.
if(NOT "${EXPECT_REGEX}" STREQUAL "")
  string(REPLACE "<AND>" ";" regexes "${EXPECT_REGEX}")
  foreach(re IN LISTS regexes)
    string(REPLACE "<SEMICOLON>" ";" re "${re}")  # a ";" of the message (tests.cmake)
    if(NOT "${all}" MATCHES "${re}")
      fail("the output does not match the regular expression: ${re}")
    endif()
  endforeach()
endif()
if(NOT "${ABSENT_REGEX}" STREQUAL "")
  string(REPLACE "<AND>" ";" regexes "${ABSENT_REGEX}")
  foreach(re IN LISTS regexes)
    if("${all}" MATCHES "${re}")
      fail("the output matches the regular expression it must not: ${re}")
    endif()
  endforeach()
endif()
foreach(re "terminate called" "Process received signal" "Segmentation fault" "MPI_ABORT" "[Ii]nternal error")
  if("${all}" MATCHES "${re}")
    fail("the output shows a crash or an internal error (matches '${re}')")
  endif()
endforeach()

# Files of an earlier run that must be left as they were.
if(NOT "${UNCHANGED}" STREQUAL "")
  string(REPLACE "|" ";" unchanged "${UNCHANGED}")
  foreach(f IN LISTS unchanged)
    if(NOT EXISTS "${out_dir}/${f}")
      fail("the earlier run's file '${f}' is gone")
    else()
      file(READ "${out_dir}/${f}" content)
      if(NOT content STREQUAL "seeded ${f}\n")
        fail("the earlier run's file '${f}' was overwritten")
      endif()
    endif()
  endforeach()
endif()

# The output directory: exactly the expected files, nothing else.
set(expected "")
if(NOT "${EXPECT_FILES}" STREQUAL "")
  string(REPLACE "|" ";" expected "${EXPECT_FILES}")
endif()
# A seeded file that the run writes again (expected, not UNCHANGED) must hold this run's output.
foreach(f IN LISTS seeded)
  if(f IN_LIST expected AND NOT f IN_LIST unchanged AND EXISTS "${out_dir}/${f}")
    file(READ "${out_dir}/${f}" content)
    if(content STREQUAL "seeded ${f}\n")
      fail("the earlier run's file '${f}' was kept instead of replaced by this run's")
    endif()
  endif()
endforeach()
file(GLOB_RECURSE found LIST_DIRECTORIES true RELATIVE "${out_dir}" "${out_dir}/*")
list(SORT found)
foreach(f IN LISTS expected)
  if(NOT EXISTS "${out_dir}/${f}")
    fail("expected output file '${f}' is missing")
  else()
    file(SIZE "${out_dir}/${f}" size)
    if(size EQUAL 0)
      fail("output file '${f}' is empty")
    endif()
  endif()
endforeach()
set(folders "")  # the folders of expected files are expected too
foreach(f IN LISTS expected)
  get_filename_component(d "${f}" DIRECTORY)
  while(NOT "${d}" STREQUAL "")
    list(APPEND folders "${d}")
    get_filename_component(d "${d}" DIRECTORY)
  endwhile()
endforeach()
set(unexpected "")
foreach(f IN LISTS found)
  if(NOT f IN_LIST expected AND NOT f IN_LIST blocked AND NOT f IN_LIST folders)
    list(APPEND unexpected "${f}")
  endif()
endforeach()
if(unexpected)
  string(REPLACE ";" ", " unexpected "${unexpected}")
  fail("the output directory holds unexpected files: ${unexpected}")
endif()

if(failures)
  message(FATAL_ERROR "FAILED:\n${failures}")
endif()
message(STATUS "PASSED")
