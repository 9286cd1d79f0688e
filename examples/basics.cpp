// basics: compose rotations, rotate vectors, and convert between every representation quat has.
// Run: example_basics (prints to stdout; exits non-zero if a stated property fails).
#include <cmath>
#include <cstdio>

#include <quat/quat.hpp>

#include "check.hpp"

using namespace quat;

namespace {

constexpr double degree = numbers::pi / 180;

void print(const char* name, const quatd& q) {
    std::printf("%-34s (w %+.6f, x %+.6f, y %+.6f, z %+.6f)\n", name, q.w, q.x, q.y, q.z);
}
void print(const char* name, const vec3<double>& v) {
    std::printf("%-34s (%+.6f, %+.6f, %+.6f)\n", name, v.x, v.y, v.z);
}
void print(const char* name, const rotation_matrix<double>& m) {
    for (int i = 0; i < 3; ++i)
        std::printf("%-34s [%+.6f %+.6f %+.6f]\n", i == 0 ? name : "", m(i, 0), m(i, 1), m(i, 2));
}
void print(const char* name, const axis_angle<double>& a) {
    std::printf("%-34s axis (%+.6f, %+.6f, %+.6f), angle %.4f deg\n", name, a.axis.x, a.axis.y,
                a.axis.z, a.angle / degree);
}
template <sequence S, frame F>
void print(const char* name, const euler<double, S, F>& e) {
    std::printf("%-34s (%+.4f, %+.4f, %+.4f) deg\n", name, e[0] / degree, e[1] / degree,
                e[2] / degree);
}

bool same_rotation(const quatd& a, const quatd& b) { return angle_between(a, b) < 1e-12; }
bool near(const vec3<double>& a, const vec3<double>& b) { return norm(a - b) < 1e-12; }

}  // namespace

int main() {
    using example::expect;
    std::printf("quat %d.%d.%d basics\n\n", QUAT_VERSION_MAJOR, QUAT_VERSION_MINOR,
                QUAT_VERSION_PATCH);

    // 1. Build rotations: axis-angle with the half angle, q = (cos(a/2), sin(a/2) axis).
    const quatd about_x = to_quaternion(axis_angle<double>{{1, 0, 0}, 90 * degree});
    const quatd about_z = to_quaternion(axis_angle<double>{{0, 0, 1}, 90 * degree});
    print("90 deg about x", about_x);
    print("90 deg about z", about_z);

    // 2. Rotate: counter-clockwise seen from the axis tip, so x-turn takes y to z, z-turn takes x
    //    to y.
    const vec3<double> ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
    print("rotate(about_x, y)", rotate(about_x, ey));
    expect(near(rotate(about_x, ey), ez), "90 deg about x takes y to z (counter-clockwise)");
    expect(near(rotate(about_z, ex), ey), "90 deg about z takes x to y");

    // 3. Compose: a * b applies b first.
    const quatd x_then_z = about_z * about_x;
    print("about_z * about_x (x first)", x_then_z);
    print("rotate(about_z * about_x, y)", rotate(x_then_z, ey));
    expect(near(rotate(x_then_z, ey), rotate(about_z, rotate(about_x, ey))),
           "a * b applies b first");
    expect(!same_rotation(about_z * about_x, about_x * about_z), "the product does not commute");

    // 4. Convert between all representations and back.
    const quatd q = normalize(quatd{0.8, 0.2, -0.4, 0.4});
    print("\nq", q);
    const rotation_matrix<double> m = to_matrix(q);
    print("to_matrix(q)", m);
    print("to_quaternion(m)", to_quaternion(m));
    expect(same_rotation(to_quaternion(m), q), "quaternion -> matrix -> quaternion");
    expect(near(rotate(m, ex), rotate(q, ex)), "the matrix and the quaternion rotate alike");

    const axis_angle<double> aa = to_axis_angle(q);
    print("to_axis_angle(q)", aa);
    expect(same_rotation(to_quaternion(aa), q), "quaternion -> axis-angle -> quaternion");
    print("to_matrix(axis_angle)", to_matrix(aa));

    const vec3<double> rv = to_rotation_vector(q);
    print("to_rotation_vector(q) (log map)", rv);
    expect(same_rotation(from_rotation_vector(rv), q), "log map then exp map");

    // Euler angles: the default is intrinsic z-y-x, yaw-pitch-roll, R = Rz(yaw) Ry(pitch) Rx(roll).
    const euler<double> ypr = to_euler<sequence::zyx>(q);
    print("to_euler<zyx> (yaw, pitch, roll)", ypr);
    expect(same_rotation(to_quaternion(ypr), q), "quaternion -> intrinsic zyx -> quaternion");
    // The same rotation as extrinsic x-y-z has the same three angles in reverse order.
    const euler<double, sequence::xyz, frame::extrinsic> rpy =
        to_euler<sequence::xyz, frame::extrinsic>(q);
    print("to_euler<xyz, extrinsic> (r, p, y)", rpy);
    expect(std::abs(rpy[0] - ypr[2]) < 1e-12 && std::abs(rpy[2] - ypr[0]) < 1e-12,
           "intrinsic z-y-x angles = extrinsic x-y-z angles reversed");
    const euler<double, sequence::zxz> proper = to_euler<sequence::zxz>(m);
    print("to_euler<zxz>(m) (proper Euler)", proper);
    expect(same_rotation(to_quaternion(proper), q), "matrix -> intrinsic zxz -> quaternion");
    print("to_matrix(euler zxz)", to_matrix(proper));

    // 5. Inverse, angle between, interpolation.
    print("\nconjugate(q) (inverse of unit q)", conjugate(q));
    expect(same_rotation(q * conjugate(q), quatd::identity()), "q q* = identity for unit q");
    std::printf("%-34s %.4f deg\n", "angle from about_x to q",
                to_axis_angle(q * conjugate(about_x)).angle / degree);
    expect(std::abs(angle_between(q, -q)) < 1e-12, "q and -q are the same rotation");
    print("slerp(identity, q, 0.5)", slerp(quatd::identity(), q, 0.5));
    expect(std::abs(to_axis_angle(slerp(quatd::identity(), q, 0.5)).angle - aa.angle / 2) < 1e-12,
           "slerp halfway turns half the angle");

    // 6. Untrusted input goes through try_ functions.
    const auto bad = try_to_quaternion(axis_angle<double>{{0, 0, 0}, 1.0});
    expect(!bad.has_value(), "try_to_quaternion rejects a zero axis");
    const auto scaled =
        try_to_quaternion(rotation_matrix<double>{{{2, 0, 0}, {0, 2, 0}, {0, 0, 2}}});
    expect(!scaled.has_value(), "try_to_quaternion rejects a matrix that is not a rotation");

    std::printf("\n%s\n",
                example::failures() == 0 ? "all properties hold" : "SOME PROPERTIES FAILED");
    return example::failures() == 0 ? 0 : 1;
}
