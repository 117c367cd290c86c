# dispkin_find_dependency(<Package> WHAT <description> DEBIAN <debian-package> [ARGS <find_package args>...])
# find_package(<Package> <args> QUIET), and if it is missing, stop with a message that names the
# Debian package to install.
function(dispkin_find_dependency name)
  cmake_parse_arguments(PARSE_ARGV 1 dep "" "DEBIAN;WHAT" "ARGS")
  find_package(${name} ${dep_ARGS} QUIET)
  if(NOT ${name}_FOUND)
    message(FATAL_ERROR "dispkin needs ${dep_WHAT} (CMake package ${name}), which was not found.\n"
                        "On Debian or Ubuntu: apt-get install ${dep_DEBIAN} (scripts/install-deps.sh installs them all).\n"
                        "If it is installed elsewhere, add its prefix to CMAKE_PREFIX_PATH.")
  endif()
  # find_package() inside a function: hand the imported targets' variables the callers use up.
  foreach(var ${name}_FOUND ${name}_VERSION ${name}_DIR ${name}_INCLUDE_DIRS ${name}_LIBRARIES)
    if(DEFINED ${var})
      set(${var} "${${var}}" PARENT_SCOPE)
    endif()
  endforeach()
endfunction()
