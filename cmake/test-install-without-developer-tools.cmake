# CTest test install_without_developer_tools: on a machine with nothing but a compiler and cmake,
# `cmake -S <src> -B <build> && cmake --install <build> --prefix <prefix>` must work with no quat
# option. GLM, Eigen, Catch2, Google Benchmark, Doxygen and Python are made unfindable (their
# prefixes and directories are ignored), the source tree is configured in a fresh directory without
# any -D of quat's, nothing is built, and the install is checked.
# Usage: cmake -DSOURCE_DIR=<quat> -DWORK_DIR=<scratch> -DGENERATOR=<gen> -DMAKE_PROGRAM=<make>
#              -DCXX_COMPILER=<c++> -P test-install-without-developer-tools.cmake
cmake_minimum_required(VERSION 3.21)
set(build "${WORK_DIR}/build")
set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# Simulate the bare machine: the system prefixes hold the packages ("/" too: with a merged /usr,
# /lib/cmake is /usr/lib/cmake), the bin directories and those of any python3 or doxygen on PATH
# (pyenv shims, say) hold the programs.
set(ignore_prefixes / /usr /usr/local)
set(ignore_paths /bin /usr/bin /usr/local/bin /usr/include /usr/local/include)
foreach(tool python3 python doxygen)
    find_program(tool_path ${tool} NO_CACHE)
    if(tool_path)
        get_filename_component(tool_dir "${tool_path}" DIRECTORY)
        list(APPEND ignore_paths "${tool_dir}")
    endif()
    unset(tool_path)
endforeach()
list(REMOVE_DUPLICATES ignore_paths)

# The compiler and make program are named in full, since their directories are ignored; the rest
# are not quat options but what hides the packages. The trace records every command run.
execute_process(
    COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${build}" -G "${GENERATOR}"
            "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
            "-DCMAKE_IGNORE_PREFIX_PATH=${ignore_prefixes}" "-DCMAKE_IGNORE_PATH=${ignore_paths}"
            --trace-redirect=${WORK_DIR}/configure-trace.txt
    RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "configure with no option failed (${result}): did a developer-only part "
                        "look for GLM, Eigen, Catch2, Google Benchmark, Doxygen or Python?")
endif()

# No developer part is on by default, and none looked for anything: no find_* command ran from
# quat's own CMake files, and the cache holds none of the lookups the developer build makes.
file(STRINGS "${build}/CMakeCache.txt" cache)
foreach(line IN LISTS cache)
    if(line MATCHES "^(QUAT_DEVELOPER_MODE|QUAT_BUILD_[A-Z]+):BOOL=ON$")
        message(FATAL_ERROR "${CMAKE_MATCH_1} defaults to ON; it must default OFF")
    endif()
    if(line MATCHES "^(Catch2_DIR|Eigen3_DIR|benchmark_DIR|QUAT_[A-Z_]*GLM[A-Z_]*|DOXYGEN_EXECUTABLE|_?Python3_EXECUTABLE)[:=]")
        message(FATAL_ERROR "configure looked for a developer dependency: ${line}")
    endif()
endforeach()
if(NOT "QUAT_INSTALL:BOOL=ON" IN_LIST cache)
    message(FATAL_ERROR "QUAT_INSTALL is not ON for the top-level project")
endif()
string(LENGTH "${SOURCE_DIR}/" source_length)
file(STRINGS "${WORK_DIR}/configure-trace.txt" trace REGEX "^[^(]+\\([0-9]+\\): +find_[a-z]+\\(")
foreach(line IN LISTS trace)
    string(SUBSTRING "${line}" 0 ${source_length} head)
    if(head STREQUAL "${SOURCE_DIR}/")
        message(FATAL_ERROR "configure with no option ran a lookup: ${line}")
    endif()
endforeach()
if(EXISTS "${build}/CTestTestfile.cmake")
    message(FATAL_ERROR "configure with no option enabled testing (some developer part is on)")
endif()

execute_process(COMMAND "${CMAKE_COMMAND}" --install "${build}" --prefix "${prefix}"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "cmake --install failed: ${result}")
endif()
foreach(file include/quat/quat.hpp include/quat/config.hpp share/cmake/quat/quatConfig.cmake
             share/cmake/quat/quatConfigVersion.cmake share/cmake/quat/quatTargets.cmake
             share/pkgconfig/quat.pc)
    if(NOT EXISTS "${prefix}/${file}")
        message(FATAL_ERROR "install did not produce ${file}")
    endif()
endforeach()
message(STATUS "configured with no option and installed into ${prefix} without GLM, Eigen, Catch2, "
               "Google Benchmark, Doxygen or Python")
