# ctest script: installs the build into a scratch prefix, builds and runs the consumer against it, and
# checks the installed paper deck with the installed executable.
# A clean prefix and build each time: a file an earlier version installed must not pass for ours.
file(REMOVE_RECURSE ${WORK}/prefix ${WORK}/build)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${WORK}/prefix RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "install failed")
endif()
# Headers under include/signorini/<package>; the packages' internal headers are not installed.
foreach(header core/Types.hpp dynamics/Simulation.hpp adapt/AdaptiveSimulation.hpp)
  if(NOT EXISTS ${WORK}/prefix/include/signorini/${header})
    message(FATAL_ERROR "include/signorini/${header} was not installed")
  endif()
endforeach()
foreach(header fem/AssemblyTools.hpp fem/Q1Pattern.hpp estimate/EstimatorTools.hpp io/ExodusCalls.hpp)
  if(EXISTS ${WORK}/prefix/include/signorini/${header})
    message(FATAL_ERROR "the internal header include/signorini/${header} was installed")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${WORK}/build -DCMAKE_PREFIX_PATH=${WORK}/prefix
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK}/build RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer failed")
endif()
execute_process(COMMAND ${WORK}/build/consumer RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the consumer failed")
endif()
# The installed executable checks the installed paper deck from another folder (its libraries
# through the RUNPATH, the deck from share/signorini/inputs).
execute_process(COMMAND ${WORK}/prefix/bin/signorini --check --output-dir ${WORK}/out
                        ${WORK}/prefix/share/signorini/inputs/membrane.xml
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc OR NOT out MATCHES "membrane[.]xml is valid")
  message(FATAL_ERROR "the installed signorini does not check the installed membrane.xml:\n${out}")
endif()
