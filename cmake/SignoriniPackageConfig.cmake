# Installs signorini's libraries, headers and a CMake package config so that another
# Trilinos application can find_package(signorini) and link signorini::<package>.
include(CMakePackageConfigHelpers)
install(EXPORT signoriniTargets NAMESPACE signorini:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/signorini)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/signorini-config.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/signorini-config.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/signorini)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/signorini-config-version.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${CMAKE_CURRENT_BINARY_DIR}/signorini-config.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/signorini-config-version.cmake
  ${CMAKE_CURRENT_LIST_DIR}/SignoriniTrilinos.cmake
  ${CMAKE_CURRENT_LIST_DIR}/FindP4est.cmake
  ${CMAKE_CURRENT_LIST_DIR}/FindExodusII.cmake
  ${CMAKE_CURRENT_LIST_DIR}/FindMuParser.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/signorini)
