# signorini_add_package(NAME SOURCES ... DEPENDS ...): one library per folder in packages/,
# exported as signorini::NAME, headers installed under include/signorini/NAME.
function(signorini_add_package name)
  cmake_parse_arguments(P "" "" "SOURCES;DEPENDS" ${ARGN})
  add_library(signorini_${name} ${P_SOURCES})
  add_library(signorini::${name} ALIAS signorini_${name})
  # Shared libraries: libsignorini_NAME.so.0.1 (ABI kept within a minor version, as the package
  # config's SameMinorVersion compatibility says).
  set_target_properties(signorini_${name} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME signorini_${name}
    VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  # The public headers use C++17 (std::is_same_v, ...): so must every target that includes them.
  target_compile_features(signorini_${name} PUBLIC cxx_std_17)
  target_include_directories(signorini_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/signorini/${name}>)
  target_link_libraries(signorini_${name} PUBLIC ${P_DEPENDS})
  # No FMA contraction: reproducible arithmetic needs the host and kernel copies of the element
  # matrices to round alike (docs/reproducibility.md); on x86-64 without -march it changes nothing.
  target_compile_options(signorini_${name} PRIVATE -Wall -Wextra -Wno-unused-parameter -ffp-contract=off)
  install(TARGETS signorini_${name} EXPORT signoriniTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  file(GLOB headers ${CMAKE_CURRENT_SOURCE_DIR}/*.hpp)
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/signorini/${name})
endfunction()
