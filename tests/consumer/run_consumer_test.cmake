# The find_package(dispkin) and pkg-config promises, checked end to end on an installed package.
#   VARIANT=static (default): installs the build tree DISPKIN_BUILD_DIR into a scratch prefix;
#     builds the consumer and the README's C++ quick start against the whole package, a consumer
#     that asks only for COMPONENTS core hexapod and one with `pkg-config --static`, and checks
#     that a missing component is named.
#   VARIANT=shared: configures and builds dispkin's libraries from DISPKIN_SOURCE_DIR with
#     BUILD_SHARED_LIBS=ON (unoptimised: this checks packaging, not speed; the build directory
#     SHARED_BUILD_DIR is kept between runs), installs them, moves the prefix elsewhere, checks
#     that the libraries find each other through their RUNPATH ($ORIGIN), then builds and runs the
#     consumer there through CMake (COMPONENTS core hexapod serial) and through pkg-config.
# Both check that the installed CMake files name no absolute path.
#   VARIANT=missing_dependency: configuring dispkin without Qhull, KDL or TinyXML names the
#     Debian package to install.
if(NOT VARIANT)
  set(VARIANT static)
endif()
file(REMOVE_RECURSE ${WORK_DIR})

function(run)
  cmake_parse_arguments(PARSE_ARGV 0 run "" "WHAT" "COMMAND")
  execute_process(COMMAND ${run_COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${run_WHAT} failed (${rc}):\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

# No absolute path in the installed package files: every dependency is an imported target found
# again by find_dependency (so a prefix can move and a consumer's system can differ).
function(check_no_absolute_paths prefix)
  file(GLOB_RECURSE files ${prefix}/lib*/cmake/dispkin/dispkin*.cmake ${prefix}/lib*/pkgconfig/dispkin.pc)
  list(LENGTH files count)
  if(count LESS 6)
    message(FATAL_ERROR "the installed package files are missing: ${files}")
  endif()
  foreach(file ${files})
    file(READ ${file} text)
    foreach(forbidden "/usr/" "/opt/" "${prefix}" "${DISPKIN_SOURCE_DIR}" "${DISPKIN_BUILD_DIR}" "${SHARED_BUILD_DIR}")
      if(forbidden AND text MATCHES "${forbidden}")
        message(FATAL_ERROR "${file} names the absolute path ${forbidden}")
      endif()
    endforeach()
  endforeach()
endfunction()

function(build_consumer name prefix)
  run(WHAT "configuring the consumer ${name}" COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/${name}
      -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O0 ${ARGN})
  run(WHAT "building the consumer ${name}" COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/${name})
  run(WHAT "the consumer ${name}" COMMAND ${WORK_DIR}/${name}/consumer)
  message(STATUS "${name}: ${out}")
endfunction()

# A Makefile user: the compiler and linker flags from pkg-config (with ARGN, e.g. --static),
# nothing else.
function(build_pkgconfig_consumer libdir)
  find_program(PKG_CONFIG pkg-config REQUIRED)
  set(ENV{PKG_CONFIG_PATH} ${libdir}/pkgconfig)
  run(WHAT "pkg-config" COMMAND ${PKG_CONFIG} ${ARGN} --cflags --libs dispkin)
  string(STRIP "${out}" flags)
  separate_arguments(flags UNIX_COMMAND "${flags}")
  find_program(CXX NAMES c++ g++ clang++ REQUIRED)
  run(WHAT "compiling the consumer with pkg-config's flags" COMMAND ${CXX} -std=c++17 ${CONSUMER_SOURCE_DIR}/main.cpp
      ${flags} -Wl,-rpath,${libdir} -o ${WORK_DIR}/consumer_pkgconfig)
  run(WHAT "the pkg-config consumer" COMMAND ${WORK_DIR}/consumer_pkgconfig)
  message(STATUS "pkg-config ${ARGN}: ${out}")
endfunction()

if(VARIANT STREQUAL "static")
  # The README's C++ quick start, wrapped in main(), is built as a second consumer program.
  file(READ ${DISPKIN_SOURCE_DIR}/README.md readme)
  string(FIND "${readme}" "```cpp\n" begin)
  if(begin EQUAL -1)
    message(FATAL_ERROR "README.md has no ```cpp block")
  endif()
  math(EXPR begin "${begin} + 7")
  string(SUBSTRING "${readme}" ${begin} -1 rest)
  string(FIND "${rest}" "```" end)
  string(SUBSTRING "${rest}" 0 ${end} quickstart)
  string(REPLACE "#include <dispkin/dispkin.hpp>" "#include <dispkin/dispkin.hpp>\nint main() {" quickstart "${quickstart}")
  file(WRITE ${WORK_DIR}/readme/readme_quickstart.cpp "${quickstart}  return 0;\n}\n")

  set(prefix ${WORK_DIR}/prefix)
  run(WHAT "install" COMMAND ${CMAKE_COMMAND} --install ${DISPKIN_BUILD_DIR} --prefix ${prefix})
  check_no_absolute_paths(${prefix})
  if(NOT EXISTS ${prefix}/share/dispkin/package.xml)
    message(FATAL_ERROR "package.xml is not installed to share/dispkin (where ROS 2 tools look)")
  endif()
  build_consumer(whole ${prefix} -DREADME_QUICKSTART=${WORK_DIR}/readme/readme_quickstart.cpp)
  run(WHAT "the README quick start" COMMAND ${WORK_DIR}/whole/readme_quickstart)
  build_consumer(components ${prefix} -DDISPKIN_COMPONENTS=core,hexapod)
  file(GLOB libdirs LIST_DIRECTORIES true ${prefix}/lib*)
  list(GET libdirs 0 libdir)
  build_pkgconfig_consumer(${libdir} --static)

  # A component that does not exist is named in the error (configure only).
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/missing
                          -DCMAKE_PREFIX_PATH=${prefix} -DDISPKIN_COMPONENTS=core,gripper
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0 OR NOT err MATCHES "dispkin component \"gripper\" is missing: there is no such component")
    message(FATAL_ERROR "asking for a component that does not exist: exit ${rc}, and the error does not name it:\n${err}")
  endif()
elseif(VARIANT STREQUAL "shared")
  run(WHAT "configuring the shared build" COMMAND ${CMAKE_COMMAND} -S ${DISPKIN_SOURCE_DIR} -B ${SHARED_BUILD_DIR} -G Ninja
      -DBUILD_SHARED_LIBS=ON -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O0
      -DDISPKIN_BUILD_TESTS=OFF -DDISPKIN_BUILD_EXAMPLES=OFF -DDISPKIN_BUILD_BENCHMARKS=OFF -DDISPKIN_BUILD_PYTHON=OFF)
  run(WHAT "building the shared libraries" COMMAND ${CMAKE_COMMAND} --build ${SHARED_BUILD_DIR})
  set(staging ${WORK_DIR}/staging)
  run(WHAT "install" COMMAND ${CMAKE_COMMAND} --install ${SHARED_BUILD_DIR} --prefix ${staging})
  # Moved after installing: nothing may still point at the staging prefix or the build tree.
  set(prefix ${WORK_DIR}/moved/prefix)
  file(MAKE_DIRECTORY ${WORK_DIR}/moved)
  file(RENAME ${staging} ${prefix})
  check_no_absolute_paths(${prefix})
  file(GLOB libdirs LIST_DIRECTORIES true ${prefix}/lib*)
  list(GET libdirs 0 libdir)
  foreach(component core hexapod serial)
    set(library ${libdir}/libdispkin_${component}.so)
    if(NOT EXISTS ${library})
      message(FATAL_ERROR "${library} was not installed")
    endif()
    run(WHAT "readelf -d ${library}" COMMAND readelf -d ${library})
    if(NOT out MATCHES "\\(RUNPATH\\)[^\n]*\\[\\$ORIGIN\\]")
      message(FATAL_ERROR "${library} has no RUNPATH [$ORIGIN]:\n${out}")
    endif()
    # ldd of the library alone: its own RUNPATH must find its siblings in the moved prefix.
    run(WHAT "ldd ${library}" COMMAND ldd ${library})
    if(out MATCHES "not found" OR (NOT component STREQUAL "core" AND NOT out MATCHES "libdispkin_core[^\n]*=> ${libdir}/libdispkin_core"))
      message(FATAL_ERROR "${library} does not find its dependencies from the moved prefix:\n${out}")
    endif()
  endforeach()
  build_consumer(shared ${prefix} -DDISPKIN_COMPONENTS=core,hexapod,serial -DDISPKIN_EXPECT_UMBRELLA=ON)

  build_pkgconfig_consumer(${libdir})
elseif(VARIANT STREQUAL "missing_dependency")
  # Configuring dispkin where a dependency cannot be found stops with the Debian package to
  # install (configure only: stops at the first missing package).
  foreach(case "Qhull;libqhull-dev" "OrocosKDL;liborocos-kdl-dev" "TinyXML;libtinyxml-dev")
    list(GET case 0 package)
    list(GET case 1 debian)
    execute_process(COMMAND ${CMAKE_COMMAND} -S ${DISPKIN_SOURCE_DIR} -B ${WORK_DIR}/${package}
                            -DCMAKE_DISABLE_FIND_PACKAGE_${package}=ON -DDISPKIN_BUILD_TESTS=OFF
                            -DDISPKIN_BUILD_EXAMPLES=OFF -DDISPKIN_BUILD_BENCHMARKS=OFF
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(rc EQUAL 0 OR NOT err MATCHES "apt-get install ${debian}")
      message(FATAL_ERROR "without ${package}: exit ${rc}, and the error does not say `apt-get install ${debian}`:\n${err}")
    endif()
  endforeach()
else()
  message(FATAL_ERROR "VARIANT must be static, shared or missing_dependency, not ${VARIANT}")
endif()
