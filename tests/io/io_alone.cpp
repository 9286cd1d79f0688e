// quat/io.hpp alone: it prints the core value types and brings none of the families, so printing a
// vec3 compiles no solver (the layout only declares the families' results; they print where their
// own headers are included, tests/test_io.cpp). Built and run as CTest test io_alone.
#include <quat/io.hpp>
#include <sstream>

// Each family's include guards, its solvers' (fitting/detail/) among them.
#if defined(QUAT_FITTING_ALIGN_VECTORS_HPP_INCLUDED) || defined(QUAT_FITTING_MEAN_HPP_INCLUDED) || \
    defined(QUAT_FITTING_NEAREST_ROTATION_HPP_INCLUDED) ||                                         \
    defined(QUAT_FITTING_DETAIL_WAHBA_HPP_INCLUDED) ||                                             \
    defined(QUAT_FITTING_DETAIL_SYMMETRIC_EIGEN_HPP_INCLUDED)
#error "quat/io.hpp includes a fitting/ header"
#endif
#if defined(QUAT_RIGID_DUAL_QUATERNION_HPP_INCLUDED) ||                                  \
    defined(QUAT_RIGID_HOMOGENEOUS_MATRIX_HPP_INCLUDED) ||                               \
    defined(QUAT_RIGID_SCREW_HPP_INCLUDED) || defined(QUAT_RIGID_SCLERP_HPP_INCLUDED) || \
    defined(QUAT_RIGID_BLEND_HPP_INCLUDED)
#error "quat/io.hpp includes a rigid/ header"
#endif
#if defined(QUAT_REGISTRATION_ALIGN_POINTS_HPP_INCLUDED) || \
    defined(QUAT_REGISTRATION_HAND_EYE_HPP_INCLUDED)
#error "quat/io.hpp includes a registration/ header"
#endif
#if defined(QUAT_LIE_SO3_HPP_INCLUDED) || defined(QUAT_LIE_SE3_HPP_INCLUDED) || \
    defined(QUAT_LIE_GEODESIC_MEAN_HPP_INCLUDED)
#error "quat/io.hpp includes a lie/ header"
#endif
#if defined(QUAT_PATHS_INTERPOLATION_HPP_INCLUDED) || defined(QUAT_PATHS_SQUAD_HPP_INCLUDED) || \
    defined(QUAT_BATCH_ROTATIONS_HPP_INCLUDED) || defined(QUAT_BATCH_RIGID_MOTIONS_HPP_INCLUDED)
#error "quat/io.hpp includes a paths/ or batch/ header"
#endif

int main() {
    std::ostringstream out;
    out << quat::vec3<double>{1, -2, 0.5} << ' ' << quat::quaternion<float>{1, 0, 0, 0.25f};
    return out.str() == "vec3{1, -2, 0.5} quaternion{1, 0, 0, 0.25}" ? 0 : 1;
}
