// Proves every GLM and Eigen statement of docs/conventions.md by compiling against GLM 0.9.9 and
// Eigen 3.4 and comparing numerically with quat. Each TEST_CASE name is the statement it proves.
#include <cmath>

#include <Eigen/Geometry>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <quat/interop/eigen.hpp>
#include <quat/interop/glm.hpp>
#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_conventions {

using quat::euler;
using quat::frame;
using quat::quatd;
using quat::sequence;
using quat::test::max_difference;
using tol = quat::test::tolerance<double>;

namespace {

constexpr double pi = quat::numbers::pi;

/// Random rotations whose yaw-pitch-roll pitch stays 0.1 rad away from gimbal lock.
quatd away_from_lock(quat::test::random_rotations& random) {
    for (;;) {
        const quatd q = random.unit_quaternion<double>();
        if (std::abs(quat::to_euler<sequence::zyx>(q)[1]) < pi / 2 - 0.1) return q;
    }
}

}  // namespace

// ---- Quaternion layout ------------------------------------------------------------------------

TEST_CASE("GLM: glm::quat(w, x, y, z) takes the scalar first but stores x, y, z, w",
          "[conventions][glm]") {
    const glm::dquat g(1.0, 2.0, 3.0, 4.0);
    CHECK(g.w == 1.0);
    CHECK(g.x == 2.0);
    CHECK(glm::value_ptr(g)[0] == 2.0);  // memory: x first
    CHECK(glm::value_ptr(g)[3] == 1.0);  // ... and w last
    CHECK(g[3] == 1.0);                  // operator[] follows memory
}

TEST_CASE("Eigen: Quaternion(w, x, y, z) takes the scalar first but coeffs() is x, y, z, w",
          "[conventions][eigen]") {
    const Eigen::Quaterniond e(1.0, 2.0, 3.0, 4.0);
    CHECK(e.w() == 1.0);
    CHECK(e.x() == 2.0);
    CHECK(e.coeffs()(0) == 2.0);
    CHECK(e.coeffs()(3) == 1.0);
    // Constructing from a 4-vector reads it in coeffs() order, scalar last.
    const Eigen::Quaterniond from_vector(Eigen::Vector4d(2.0, 3.0, 4.0, 1.0));
    CHECK(from_vector.w() == 1.0);
}

// ---- Product, rotation, matrices
// -----------------------------------------------------------------

TEST_CASE("GLM and Eigen: Hamilton product, a * b applies b first, v -> q v q*",
          "[conventions][glm][eigen]") {
    quat::test::random_rotations random;
    for (int n = 0; n < 500; ++n) {
        const quatd a = random.unit_quaternion<double>(), b = random.unit_quaternion<double>();
        const quat::vec3<double> v = random.vector<double>();
        CHECK(max_difference(quat::from_glm(quat::to_glm(a) * quat::to_glm(b)), a * b) <= tol::glm);
        CHECK(max_difference(
                  quat::from_eigen(Eigen::Quaterniond(quat::to_eigen(a) * quat::to_eigen(b))),
                  a * b) <= tol::glm);
        CHECK(max_difference(quat::from_glm(quat::to_glm(a) * quat::to_glm(v)),
                             quat::rotate(a, v)) <= tol::glm * (1 + quat::norm(v)));
        CHECK(
            max_difference(quat::from_eigen(Eigen::Vector3d(quat::to_eigen(a) * quat::to_eigen(v))),
                           quat::rotate(a, v)) <= tol::glm * (1 + quat::norm(v)));
    }
    // ij = k in both.
    const glm::dquat gi(0, 1, 0, 0), gj(0, 0, 1, 0);
    CHECK((gi * gj).z == 1.0);
    CHECK((Eigen::Quaterniond(0, 1, 0, 0) * Eigen::Quaterniond(0, 0, 1, 0)).z() == 1.0);
}

TEST_CASE("GLM: mat3_cast is column-major, m[col][row] == to_matrix(q)(row, col)",
          "[conventions][glm]") {
    const quatd q = quat::normalize(quatd{0.8, 0.2, -0.4, 0.4});
    const glm::dmat3 g = glm::mat3_cast(quat::to_glm(q));
    const quat::rotation_matrix<double> m = quat::to_matrix(q);
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) CHECK(std::abs(g[col][row] - m(row, col)) <= tol::glm);
    CHECK(std::abs(g[0][1] - m(0, 1)) > 0.5);  // indexing the other way round would be wrong
}

TEST_CASE("Eigen: toRotationMatrix() == to_matrix(q), indexed (row, col)", "[conventions][eigen]") {
    const quatd q = quat::normalize(quatd{0.8, 0.2, -0.4, 0.4});
    const Eigen::Matrix3d e = quat::to_eigen(q).toRotationMatrix();
    const quat::rotation_matrix<double> m = quat::to_matrix(q);
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) CHECK(std::abs(e(row, col) - m(row, col)) <= tol::glm);
}

TEST_CASE("GLM angleAxis(angle, axis) and Eigen AngleAxis(angle, axis) take the angle first",
          "[conventions][glm][eigen]") {
    const quat::vec3<double> axis = quat::normalize(quat::vec3<double>{1, -2, 2});
    const double angle = 1.2;
    const quatd q = quat::to_quaternion(quat::axis_angle<double>{axis, angle});
    CHECK(max_difference(quat::from_glm(glm::angleAxis(angle, quat::to_glm(axis))), q) <= tol::glm);
    CHECK(max_difference(
              quat::from_eigen(Eigen::Quaterniond(Eigen::AngleAxisd(angle, quat::to_eigen(axis)))),
              q) <= tol::glm);
}

// ---- Euler angles
// --------------------------------------------------------------------------------

TEST_CASE(
    "GLM: eulerAngles(q) = (pitch, yaw, roll) about x, y, z with R = Rz(roll) Ry(yaw) Rx(pitch)",
    "[conventions][glm]") {
    quat::test::random_rotations random;
    for (int n = 0; n < 500; ++n) {
        const quatd q = away_from_lock(random);
        const glm::dvec3 g = glm::eulerAngles(quat::to_glm(q));
        // quat's default euler<T> is intrinsic z-y-x: {angle about z, about y, about x}.
        const euler<double> zyx = quat::to_euler<sequence::zyx>(q);
        CHECK(std::abs(g.x - zyx[2]) <= tol::glm);  // pitch = about x
        CHECK(std::abs(g.y - zyx[1]) <= tol::glm);  // yaw = about y
        CHECK(std::abs(g.z - zyx[0]) <= tol::glm);  // roll = about z
        // The free functions say the same, and glm::quat(vec3) builds the rotation back.
        CHECK(std::abs(glm::pitch(quat::to_glm(q)) - zyx[2]) <= tol::glm);
        CHECK(std::abs(glm::yaw(quat::to_glm(q)) - zyx[1]) <= tol::glm);
        CHECK(std::abs(glm::roll(quat::to_glm(q)) - zyx[0]) <= tol::glm);
        CHECK(quat::angle_between(quat::from_glm(glm::dquat(g)), q) <= 1e-7);
    }
}

TEST_CASE("GLM's yaw is about y (y-up graphics), not about z as in aerospace yaw",
          "[conventions][glm]") {
    const quatd about_z = quat::to_quaternion(quat::axis_angle<double>{{0, 0, 1}, 0.5});
    CHECK(std::abs(glm::yaw(quat::to_glm(about_z))) <= tol::glm);
    CHECK(std::abs(glm::roll(quat::to_glm(about_z)) - 0.5) <= tol::glm);
    // quat's euler<T> (aerospace yaw-pitch-roll) puts it into yaw.
    CHECK(std::abs(quat::to_euler<sequence::zyx>(about_z)[0] - 0.5) <= tol::glm);
}

TEST_CASE(
    "Eigen: eulerAngles(a0, a1, a2) is intrinsic a0-a1-a2 with e0 in [0, pi], e1 and e2 in [-pi, "
    "pi]",
    "[conventions][eigen]") {
    quat::test::random_rotations random;
    int different_branch = 0;
    for (int n = 0; n < 500; ++n) {
        const quatd q = away_from_lock(random);
        const Eigen::Matrix3d m = quat::to_eigen(quat::to_matrix(q));
        const Eigen::Vector3d e = m.eulerAngles(2, 1, 0);  // z, y, x
        CHECK(e(0) >= 0.0);
        CHECK(e(0) <= pi);
        CHECK(std::abs(e(1)) <= pi);
        CHECK(std::abs(e(2)) <= pi);
        // Same rotation as quat's intrinsic z-y-x with these angles ...
        const euler<double> from_eigen{{e(0), e(1), e(2)}};
        CHECK(quat::angle_between(quat::to_quaternion(from_eigen), q) <= 1e-7);
        // ... but the range differs: quat keeps pitch in [-pi/2, pi/2] and yaw in [-pi, pi].
        const euler<double> ours = quat::to_euler<sequence::zyx>(q);
        if (std::abs(ours[0] - e(0)) > 1e-6) {
            ++different_branch;
            CHECK(std::abs(std::abs(e(1)) - (pi - std::abs(ours[1]))) <=
                  1e-7);  // pitch -> pi - pitch
        }
    }
    CHECK(different_branch > 100);  // about half of all rotations have yaw < 0
}

TEST_CASE(
    "extrinsic x-y-z (ROS setRPY, scipy 'xyz') equals intrinsic z-y-x with the angles reversed",
    "[conventions]") {
    quat::test::random_rotations random;
    for (int n = 0; n < 200; ++n) {
        const double roll = random.uniform<double>(-pi, pi),
                     pitch = random.uniform<double>(-1.5, 1.5),
                     yaw = random.uniform<double>(-pi, pi);
        const euler<double, sequence::xyz, frame::extrinsic> rpy{{roll, pitch, yaw}};
        const euler<double, sequence::zyx, frame::intrinsic> ypr{{yaw, pitch, roll}};
        CHECK(quat::angle_between(quat::to_quaternion(rpy), quat::to_quaternion(ypr)) <=
              tol::round_trip);
        // Eigen's AngleAxis product spelling of the same rotation.
        const Eigen::Quaterniond e = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                                     Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                                     Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
        CHECK(quat::angle_between(quat::from_eigen(e), quat::to_quaternion(ypr)) <= 1e-7);
    }
}

}  // namespace test_conventions
