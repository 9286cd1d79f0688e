# Ceres::ceres for the opt-in quat/interop/ceres.hpp's test and the Ceres examples (pose_graph,
# camera_imu_spline) (Debian's libceres-dev), or no target when Ceres is missing. Debian 12's
# CeresConfig.cmake gives up when glog's config cannot find libunwind-dev, which conflicts with
# LLVM's libunwind-19-dev (installed with libc++-19-dev): then the target is made from the shared
# library, glog and Eigen directly.
if(TARGET Ceres::ceres)
    return()
endif()
find_package(Ceres CONFIG QUIET)
if(TARGET Ceres::ceres)
    return()
endif()
find_package(Eigen3 3.3 QUIET NO_MODULE)
find_path(QUAT_CERES_HEADER_DIR ceres/ceres.h)
find_library(QUAT_CERES_LIBRARY ceres)
find_library(QUAT_GLOG_LIBRARY glog)
if(TARGET Eigen3::Eigen AND QUAT_CERES_HEADER_DIR AND QUAT_CERES_LIBRARY AND QUAT_GLOG_LIBRARY)
    add_library(Ceres::ceres UNKNOWN IMPORTED)
    set_target_properties(Ceres::ceres PROPERTIES
        IMPORTED_LOCATION "${QUAT_CERES_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${QUAT_CERES_HEADER_DIR}"
        INTERFACE_LINK_LIBRARIES "${QUAT_GLOG_LIBRARY};Eigen3::Eigen")
endif()
