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

# pkg-config: the prefix is written as the normalized absolute path quat is installed to, found at
# install time (so `cmake --install build --prefix P` writes P; under DESTDIR, the final prefix).
# A prefix relative to ${pcfiledir} would survive a move of the tree but print
# -I<prefix>/share/pkgconfig/../../include, since pkg-config cannot normalize a path; a moved tree
# is found instead by `pkg-config --define-prefix` (pkgconf, pkg-config >= 0.29), which derives the
# prefix from where quat.pc lies (two directories up) and prints it normalized. includedir is given
# through ${prefix} for that reason, unless CMAKE_INSTALL_INCLUDEDIR is absolute.
if(IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
    get_filename_component(_quat_pc_includedir "${CMAKE_INSTALL_INCLUDEDIR}" ABSOLUTE)
else()
    set(_quat_pc_includedir "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
install(CODE "
    get_filename_component(QUAT_PC_PREFIX \"\${CMAKE_INSTALL_PREFIX}\" ABSOLUTE)
    set(QUAT_PC_INCLUDEDIR [[${_quat_pc_includedir}]])
    set(PROJECT_DESCRIPTION [[${PROJECT_DESCRIPTION}]])
    set(PROJECT_VERSION [[${PROJECT_VERSION}]])
    configure_file([[${PROJECT_SOURCE_DIR}/cmake/quat.pc.in]] [[${PROJECT_BINARY_DIR}/quat.pc]]
                   @ONLY)
    " COMPONENT quat_Development)
install(FILES "${PROJECT_BINARY_DIR}/quat.pc"
        DESTINATION "${QUAT_INSTALL_PKGCONFIGDIR}"
        COMPONENT quat_Development)

install(FILES "${PROJECT_SOURCE_DIR}/LICENSE"
        DESTINATION "${CMAKE_INSTALL_DATADIR}/doc/quat"
        COMPONENT quat_Development)
