# signorini_add_package(NAME SOURCES ... DEPENDS ... [INTERNAL_HEADERS ...]): one library per folder
# in packages/, exported as signorini::NAME. Its headers are included as "signorini/NAME/X.hpp" (a
# consumer's own X.hpp cannot take their place) and installed under include/signorini/NAME, all but
# the INTERNAL_HEADERS, which only the package's sources and tests include.
function(signorini_add_package name)
  cmake_parse_arguments(P "" "" "SOURCES;DEPENDS;INTERNAL_HEADERS" ${ARGN})
  add_library(signorini_${name} ${P_SOURCES})
  add_library(signorini::${name} ALIAS signorini_${name})
  # Shared libraries: libsignorini_NAME.so.0.1 (ABI kept within a minor version, as the package
  # config's SameMinorVersion compatibility says).
  set_target_properties(signorini_${name} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME signorini_${name}
    VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  # The public headers use C++17 (std::is_same_v, ...): so must every target that includes them.
  target_compile_features(signorini_${name} PUBLIC cxx_std_17)
  # In the build tree each package has an include root of its own, holding signorini/NAME as a link
  # to its folder: a package sees only the headers of the packages it depends on.
  set(root ${PROJECT_BINARY_DIR}/include/${name})
  file(MAKE_DIRECTORY ${root}/signorini)
  file(CREATE_LINK ${CMAKE_CURRENT_SOURCE_DIR} ${root}/signorini/${name} SYMBOLIC)
  target_include_directories(signorini_${name} PUBLIC
    $<BUILD_INTERFACE:${root}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(signorini_${name} PUBLIC ${P_DEPENDS})
  # No FMA contraction: reproducible arithmetic needs the host and kernel copies of the element
  # matrices to round alike (docs/reproducibility.md); on x86-64 without -march it changes nothing.
  target_compile_options(signorini_${name} PRIVATE -Wall -Wextra -Wno-unused-parameter -ffp-contract=off)
  install(TARGETS signorini_${name} EXPORT signoriniTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  file(GLOB headers ${CMAKE_CURRENT_SOURCE_DIR}/*.hpp)
  foreach(internal ${P_INTERNAL_HEADERS})
    list(REMOVE_ITEM headers ${CMAKE_CURRENT_SOURCE_DIR}/${internal})
  endforeach()
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/signorini/${name})
endfunction()
