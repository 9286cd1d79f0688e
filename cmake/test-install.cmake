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
