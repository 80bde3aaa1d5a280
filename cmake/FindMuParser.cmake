# FindMuParser: the muParser expression library.
# Defines MuParser_FOUND and the imported target signorini_deps::muparser.
find_path(MuParser_INCLUDE_DIR muParser.h PATH_SUFFIXES muParser)
find_library(MuParser_LIBRARY NAMES muparser)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MuParser REQUIRED_VARS MuParser_LIBRARY MuParser_INCLUDE_DIR)
if(MuParser_FOUND AND NOT TARGET signorini_deps::muparser)
  add_library(signorini_deps::muparser UNKNOWN IMPORTED)
  set_target_properties(signorini_deps::muparser PROPERTIES
    IMPORTED_LOCATION "${MuParser_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${MuParser_INCLUDE_DIR}")
endif()
mark_as_advanced(MuParser_INCLUDE_DIR MuParser_LIBRARY)
