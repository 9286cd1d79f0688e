// quat/interop/glm.hpp and quat/interop/eigen.hpp: conversions keep every value, and the converted
// objects rotate, multiply and convert to matrices exactly as quat's do.
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <quat/interop/eigen.hpp>
#include <quat/interop/glm.hpp>
#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_interop {

using quat::quaternion;
using quat::rotation_matrix;
using quat::vec3;
using quat::test::max_difference;
using quat::test::tolerance;

TEMPLATE_TEST_CASE("GLM round trips are exact and keep the meaning of w, x, y, z", "[interop][glm]",
                   float, double) {
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const quaternion<TestType> q = random.unit_quaternion<TestType>();
        const vec3<TestType> v = random.vector<TestType>();
        const rotation_matrix<TestType> m = quat::to_matrix(q);
        CHECK(quat::from_glm(quat::to_glm(q)) == q);
        CHECK(quat::from_glm(quat::to_glm(m)) == m);
        CHECK(quat::from_glm(quat::to_glm(v)) == v);
        const glm::qua<TestType> g = quat::to_glm(q);
        CHECK(g.w == q.w);
        CHECK(g.x == q.x);
        // The converted objects act alike.
        CHECK(max_difference(quat::from_glm(g * quat::to_glm(v)), quat::rotate(q, v)) <=
              tolerance<TestType>::glm * (1 + quat::norm(v)));
        CHECK(max_difference(quat::from_glm(quat::to_glm(m) * quat::to_glm(v)),
                             quat::rotate(m, v)) <= tolerance<TestType>::glm * (1 + quat::norm(v)));
        CHECK(max_difference(quat::from_glm(glm::mat3_cast(g)), m) <= tolerance<TestType>::glm);
        const quaternion<TestType> p = random.unit_quaternion<TestType>();
        CHECK(max_difference(quat::from_glm(g * quat::to_glm(p)), q * p) <=
              tolerance<TestType>::glm);
    }
}

TEMPLATE_TEST_CASE("Eigen round trips are exact and keep the meaning of w, x, y, z",
                   "[interop][eigen]", float, double) {
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const quaternion<TestType> q = random.unit_quaternion<TestType>();
        const vec3<TestType> v = random.vector<TestType>();
        const rotation_matrix<TestType> m = quat::to_matrix(q);
        CHECK(quat::from_eigen(quat::to_eigen(q)) == q);
        CHECK(quat::from_eigen(quat::to_eigen(m)) == m);
        CHECK(quat::from_eigen(quat::to_eigen(v)) == v);
        const Eigen::Quaternion<TestType> e = quat::to_eigen(q);
        CHECK(e.coeffs()(3) == q.w);  // Eigen stores w last
        CHECK(e.coeffs()(0) == q.x);
        CHECK(max_difference(quat::from_eigen(Eigen::Matrix<TestType, 3, 1>(e * quat::to_eigen(v))),
                             quat::rotate(q, v)) <= tolerance<TestType>::glm * (1 + quat::norm(v)));
        CHECK(max_difference(quat::from_eigen(Eigen::Matrix<TestType, 3, 1>(quat::to_eigen(m) *
                                                                            quat::to_eigen(v))),
                             quat::rotate(m, v)) <= tolerance<TestType>::glm * (1 + quat::norm(v)));
        CHECK(max_difference(quat::from_eigen(Eigen::Matrix<TestType, 3, 3>(e.toRotationMatrix())),
                             m) <= tolerance<TestType>::glm);
        const quaternion<TestType> p = random.unit_quaternion<TestType>();
        CHECK(max_difference(quat::from_eigen(Eigen::Quaternion<TestType>(e * quat::to_eigen(p))),
                             q * p) <= tolerance<TestType>::glm);
    }
}

TEMPLATE_TEST_CASE("rigid motions convert to glm::mat4 and Eigen::Isometry3 and act alike",
                   "[interop][glm][eigen]", float, double) {
    quat::test::random_rotations random;
    for (int n = 0; n < 200; ++n) {
        const auto motion = random.rigid_motion<TestType>();
        const vec3<TestType> p = random.vector<TestType>();
        const quat::homogeneous_matrix<TestType> m = quat::to_homogeneous(motion);
        CHECK(quat::from_eigen(quat::to_eigen(m)) == m);
        CHECK(quat::from_glm(quat::to_glm(m)) == m);
        const vec3<TestType> moved = quat::transform(m, p);
        const Eigen::Transform<TestType, 3, Eigen::Isometry> iso(quat::to_eigen(m));
        CHECK(quat::from_eigen(iso) == m);
        CHECK(
            max_difference(quat::from_eigen(Eigen::Matrix<TestType, 3, 1>(iso * quat::to_eigen(p))),
                           moved) <= tolerance<TestType>::glm * (1 + quat::norm(p)));
        const auto g = quat::to_glm(m) * glm::vec<4, TestType>(p.x, p.y, p.z, 1);
        CHECK(max_difference(vec3<TestType>{g.x, g.y, g.z}, moved) <=
              tolerance<TestType>::glm * (1 + quat::norm(p)));
        // Eigen's own construction from a rotation and a translation gives the same motion.
        const auto t = quat::translation_of(motion);
        const Eigen::Transform<TestType, 3, Eigen::Isometry> built =
            Eigen::Translation<TestType, 3>(t.x, t.y, t.z) * quat::to_eigen(motion.real);
        const quat::homogeneous_matrix<TestType> from_built = quat::from_eigen(built);
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                CHECK(std::abs(from_built(r, c) - m(r, c)) <= tolerance<TestType>::glm);
    }
    // An AffineCompact3 has no stored last row: from_eigen writes (0, 0, 0, 1).
    Eigen::Transform<double, 3, Eigen::AffineCompact> compact =
        Eigen::Transform<double, 3, Eigen::AffineCompact>::Identity();
    compact.translation() = Eigen::Vector3d(1, 2, 3);
    const quat::homogeneous_matrix<double> from_compact = quat::from_eigen(compact);
    CHECK(from_compact(0, 3) == 1);
    CHECK(from_compact(3, 3) == 1);
    CHECK(from_compact(3, 0) == 0);
}

TEST_CASE("from_eigen reads row-major Eigen matrices by element, not by memory",
          "[interop][eigen]") {
    Eigen::Matrix<double, 3, 3, Eigen::RowMajor> row_major;
    row_major << 1, 2, 3, 4, 5, 6, 7, 8, 9;
    const rotation_matrix<double> m = quat::from_eigen(row_major);
    CHECK(m(0, 1) == 2);
    CHECK(m(1, 0) == 4);
    CHECK(m(2, 2) == 9);
}

TEST_CASE("to_glm puts element (row, col) into GLM's column-major m[col][row]", "[interop][glm]") {
    const rotation_matrix<double> m{{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}}};
    const glm::dmat3 g = quat::to_glm(m);
    CHECK(g[0][1] == 4);  // column 0, row 1
    CHECK(g[1][0] == 2);
    CHECK(g[2][2] == 9);
}

TEST_CASE("matrix<T, R, C> converts to and from Eigen by element", "[interop][eigen]") {
    quat::matrix<double, 6, 3> m{};
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = 10 * i + j;
    const Eigen::Matrix<double, 6, 3> e = quat::to_eigen(m);
    CHECK(e(4, 2) == 42);
    CHECK(e(0, 1) == 1);
    CHECK(quat::from_eigen(e) == m);
    Eigen::Matrix<float, 2, 6, Eigen::RowMajor> row_major;
    row_major << 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12;
    const quat::matrix<float, 2, 6> back = quat::from_eigen(row_major);
    CHECK(back(1, 0) == 7);
    CHECK(back(0, 5) == 6);
    // A 3x3 Eigen matrix reads as a rotation_matrix; to_matrix3 makes it a Jacobian.
    const Eigen::Matrix3d square = Eigen::Matrix3d::Identity() * 2;
    const quat::matrix3<double> jacobian = quat::to_matrix3(quat::from_eigen(square));
    CHECK(jacobian == quat::matrix3<double>::identity() * 2.0);
}

}  // namespace test_interop
