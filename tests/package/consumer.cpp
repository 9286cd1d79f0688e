// A user program: a quarter turn about z, checked three ways, plus the version macros.
#include <quat/quat.hpp>

#include <cmath>
#include <cstdio>

int main() {
    static_assert(QUAT_VERSION_MAJOR >= 1, "version macros come from quat/config.hpp");
    constexpr double quarter_turn = 1.5707963267948966;
    const auto q = quat::to_quaternion(quat::axis_angle<double>{{0.0, 0.0, 1.0}, quarter_turn});
    const quat::vec3<double> x{1.0, 0.0, 0.0};

    // Counter-clockwise seen from +z: x goes to y, by the quaternion and by its matrix.
    const auto by_quaternion = quat::rotate(q, x);
    const auto by_matrix = quat::rotate(quat::to_matrix(q), x);
    const auto back = quat::to_euler<quat::sequence::zyx, quat::frame::intrinsic>(q);

    const bool ok = std::abs(by_quaternion.y - 1.0) < 1e-12 &&
                    std::abs(by_matrix.y - 1.0) < 1e-12 &&
                    std::abs(back[0] - quarter_turn) < 1e-12 &&
                    std::abs(quat::to_axis_angle(q).angle - quarter_turn) < 1e-12;
    std::printf("quat %d.%d.%d: %s\n", QUAT_VERSION_MAJOR, QUAT_VERSION_MINOR, QUAT_VERSION_PATCH,
                ok ? "ok" : "WRONG");
    return ok ? 0 : 1;
}
