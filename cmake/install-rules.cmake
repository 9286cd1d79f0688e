# Install rules: headers, the exported quat::quat target, the CMake package files and quat.pc.
# Included from the top-level CMakeLists.txt when QUAT_INSTALL is ON.
include(CMakePackageConfigHelpers)

set(QUAT_INSTALL_CMAKEDIR "${CMAKE_INSTALL_DATADIR}/cmake/quat"
    CACHE STRING "Where quatConfig.cmake is installed, relative to the prefix")
set(QUAT_INSTALL_PKGCONFIGDIR "${CMAKE_INSTALL_DATADIR}/pkgconfig"
    CACHE STRING "Where quat.pc is installed, relative to the prefix")

install(DIRECTORY "${PROJECT_SOURCE_DIR}/include/quat"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
        COMPONENT quat_Development
        FILES_MATCHING PATTERN "*.hpp" PATTERN "*.inc")

install(TARGETS quat EXPORT quatTargets)
install(EXPORT quatTargets
        NAMESPACE quat::
        DESTINATION "${QUAT_INSTALL_CMAKEDIR}"
        COMPONENT quat_Development)

configure_package_config_file(
    "${PROJECT_SOURCE_DIR}/cmake/quatConfig.cmake.in"
    "${PROJECT_BINARY_DIR}/quatConfig.cmake"
    INSTALL_DESTINATION "${QUAT_INSTALL_CMAKEDIR}")
# Header-only: the package fits any architecture; a 1.x request accepts any 1.y >= x.
write_basic_package_version_file(
    "${PROJECT_BINARY_DIR}/quatConfigVersion.cmake"
    COMPATIBILITY SameMajorVersion
    ARCH_INDEPENDENT)
install(FILES "${PROJECT_BINARY_DIR}/quatConfig.cmake" "${PROJECT_BINARY_DIR}/quatConfigVersion.cmake"
        DESTINATION "${QUAT_INSTALL_CMAKEDIR}"
        COMPONENT quat_Development)

# pkg-config: computed relative to the .pc file so the install prefix can be moved.
file(RELATIVE_PATH _quat_pc_to_prefix
     "/prefix/${QUAT_INSTALL_PKGCONFIGDIR}" "/prefix")
string(REGEX REPLACE "/$" "" _quat_pc_to_prefix "${_quat_pc_to_prefix}")
configure_file("${PROJECT_SOURCE_DIR}/cmake/quat.pc.in" "${PROJECT_BINARY_DIR}/quat.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/quat.pc"
        DESTINATION "${QUAT_INSTALL_PKGCONFIGDIR}"
        COMPONENT quat_Development)

install(FILES "${PROJECT_SOURCE_DIR}/LICENSE"
        DESTINATION "${CMAKE_INSTALL_DATADIR}/doc/quat"
        COMPONENT quat_Development)
