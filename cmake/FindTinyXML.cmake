# Finds TinyXML 2.6 (the XML parser urdfdom 1–3 is built on) and defines the imported target
# TinyXML::TinyXML. Debian/Ubuntu: apt-get install libtinyxml-dev; PyPI: cmeel-tinyxml.
# Installed with dispkin's CMake package: a static dispkin::serial hands TinyXML on to its
# consumers as a link-only dependency, found again here instead of an absolute path.
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(PC_TinyXML QUIET tinyxml)
endif()
find_path(TinyXML_INCLUDE_DIR tinyxml.h HINTS ${PC_TinyXML_INCLUDE_DIRS})
find_library(TinyXML_LIBRARY NAMES tinyxml HINTS ${PC_TinyXML_LIBRARY_DIRS})
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(TinyXML REQUIRED_VARS TinyXML_LIBRARY TinyXML_INCLUDE_DIR
  VERSION_VAR PC_TinyXML_VERSION)
mark_as_advanced(TinyXML_INCLUDE_DIR TinyXML_LIBRARY)
if(TinyXML_FOUND AND NOT TARGET TinyXML::TinyXML)
  add_library(TinyXML::TinyXML UNKNOWN IMPORTED)
  set_target_properties(TinyXML::TinyXML PROPERTIES
    IMPORTED_LOCATION "${TinyXML_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${TinyXML_INCLUDE_DIR}")
endif()
