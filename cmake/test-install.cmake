# CTest fixture: install the build tree into a fresh prefix for the package consumer test.
# Usage: cmake -DBUILD_DIR=<quat build> -DPREFIX=<prefix> -P test-install.cmake
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "cmake --install failed: ${result}")
endif()
foreach(file include/quat/quat.hpp share/cmake/quat/quatConfig.cmake
             share/cmake/quat/quatConfigVersion.cmake share/pkgconfig/quat.pc)
    if(NOT EXISTS "${PREFIX}/${file}")
        message(FATAL_ERROR "install did not produce ${file}")
    endif()
endforeach()

# quat.pc names the prefix as a normalized absolute path (no `..`, no `.`), the one installed to,
# and `pkg-config --define-prefix` finds a copy of the tree moved elsewhere
# (cmake/install-rules.cmake says why). The package consumer test (tests/package) compiles with these flags.
find_program(PKG_CONFIG_EXECUTABLE NAMES pkgconf pkg-config REQUIRED)
get_filename_component(prefix_normalized "${PREFIX}" ABSOLUTE)
set(moved "${PREFIX}-moved")
file(REMOVE_RECURSE "${moved}")
file(COPY "${PREFIX}/" DESTINATION "${moved}")
foreach(case installed moved)
    if(case STREQUAL "installed")
        set(pc_dir "${PREFIX}/share/pkgconfig")
        set(options "")
        set(expected "-I${prefix_normalized}/include")
    else()
        set(pc_dir "${moved}/share/pkgconfig")
        set(options --define-prefix)
        get_filename_component(expected "${moved}/include" ABSOLUTE)
        set(expected "-I${expected}")
    endif()
    execute_process(COMMAND "${CMAKE_COMMAND}" -E env "PKG_CONFIG_PATH=${pc_dir}"
                            "${PKG_CONFIG_EXECUTABLE}" ${options} --cflags quat
                    OUTPUT_VARIABLE cflags OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE result)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "pkg-config ${options} --cflags quat failed (${case}): ${result}")
    endif()
    if(cflags MATCHES "(^|/)\\.\\.?(/|$| )")
        message(FATAL_ERROR "pkg-config ${options} --cflags quat has a component . or .. "
                            "(${case}): ${cflags}")
    endif()
    if(NOT cflags STREQUAL expected)
        message(FATAL_ERROR "pkg-config ${options} --cflags quat (${case}) says '${cflags}', "
                            "expected '${expected}'")
    endif()
endforeach()
file(REMOVE_RECURSE "${moved}")
