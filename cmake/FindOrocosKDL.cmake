# Finds the Orocos Kinematics and Dynamics Library and defines the imported target
# OrocosKDL::OrocosKDL (KDL's own CMake file gives only a bare library name and Eigen's include
# directory). Debian/Ubuntu: apt-get install liborocos-kdl-dev (KDL has no PyPI package that
# installs its C++ library). Installed with dispkin's CMake package: a static dispkin::serial
# hands KDL on to its consumers as a link-only dependency, found again here.
find_package(orocos_kdl CONFIG QUIET)
if(orocos_kdl_FOUND)
  set(_dispkin_kdl_hint "${orocos_kdl_DIR}/../..")   # <prefix>/lib[/<arch>]/cmake/orocos_kdl
endif()
find_path(OrocosKDL_INCLUDE_DIR kdl/chain.hpp HINTS "${_dispkin_kdl_hint}/../include" "${_dispkin_kdl_hint}/../../include")
find_library(OrocosKDL_LIBRARY NAMES orocos-kdl HINTS "${_dispkin_kdl_hint}")
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OrocosKDL REQUIRED_VARS OrocosKDL_LIBRARY OrocosKDL_INCLUDE_DIR
  VERSION_VAR orocos_kdl_VERSION)
mark_as_advanced(OrocosKDL_INCLUDE_DIR OrocosKDL_LIBRARY)
if(OrocosKDL_FOUND AND NOT TARGET OrocosKDL::OrocosKDL)
  if(NOT TARGET Eigen3::Eigen)
    find_package(Eigen3 3.3 QUIET NO_MODULE)
  endif()
  add_library(OrocosKDL::OrocosKDL UNKNOWN IMPORTED)
  set_target_properties(OrocosKDL::OrocosKDL PROPERTIES
    IMPORTED_LOCATION "${OrocosKDL_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${OrocosKDL_INCLUDE_DIR}")
  if(TARGET Eigen3::Eigen)
    set_target_properties(OrocosKDL::OrocosKDL PROPERTIES INTERFACE_LINK_LIBRARIES Eigen3::Eigen)
  endif()
endif()
unset(_dispkin_kdl_hint)
