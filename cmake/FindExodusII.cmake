# FindExodusII: the ExodusII C library (Debian: libexodusii-dev, library exoIIv2c) on netCDF.
# Defines ExodusII_FOUND and the imported target signorini_deps::exodusii.
find_path(ExodusII_INCLUDE_DIR exodusII.h)
find_library(ExodusII_LIBRARY NAMES exoIIv2c exodus)
find_library(ExodusII_NETCDF_LIBRARY NAMES netcdf)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(ExodusII REQUIRED_VARS ExodusII_LIBRARY ExodusII_NETCDF_LIBRARY ExodusII_INCLUDE_DIR)
if(ExodusII_FOUND AND NOT TARGET signorini_deps::exodusii)
  add_library(signorini_deps::exodusii UNKNOWN IMPORTED)
  set_target_properties(signorini_deps::exodusii PROPERTIES
    IMPORTED_LOCATION "${ExodusII_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${ExodusII_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${ExodusII_NETCDF_LIBRARY}")
endif()
mark_as_advanced(ExodusII_INCLUDE_DIR ExodusII_LIBRARY ExodusII_NETCDF_LIBRARY)
