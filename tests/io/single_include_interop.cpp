// A single-header user's program: only single_include/ on the include path for quat, GLM, Eigen
// and (when CMake finds it, QUAT_TEST_FMT=1) {fmt} through the generated interop headers, io.hpp
// beside them, each included before the single quat.hpp (they include it themselves). The same
// rotation and rigid motion go to each library and back, and each library applies them as quat
// does; fmt::format prints what operator<< prints. Exit status 0 when all agree.
#ifndef QUAT_TEST_FMT
#define QUAT_TEST_FMT 0
#endif
#if __has_include(<quat/rigid/homogeneous_matrix.hpp>)
#error "include/ is on the include path: this test must see single_include/ alone"
#endif

#include <quat/interop/eigen.hpp>
#include <quat/interop/glm.hpp>
#include <quat/io.hpp>
#if QUAT_TEST_FMT
#include <quat/interop/fmt.hpp>
#endif
#include <quat/quat.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace {

int failures = 0;

void check(bool ok, const char* what) {
    if (!ok) {
        std::printf("FAILED: %s\n", what);
        ++failures;
    }
}

// GLM and Eigen round differently from quat; a few ulps of 1 is agreement.
bool near(double a, double b) { return std::fabs(a - b) <= 1e-14; }

bool near(const quat::vec3<double>& a, const quat::vec3<double>& b) {
    return near(a.x, b.x) && near(a.y, b.y) && near(a.z, b.z);
}

}  // namespace

int main() {
    const quat::vec3<double> axis = quat::normalize(quat::vec3<double>{1, -2, 3});
    const quat::quatd q = quat::to_quaternion(quat::axis_angle<double>{axis, 0.7});
    const quat::vec3<double> v{0.25, 1.5, -2.0};
    const quat::vec3<double> rotated = quat::rotate(q, v);
    const quat::vec3<double> shift{1, 2, 3};
    const quat::homogeneous_matrix<double> motion =
        quat::to_homogeneous(quat::to_dual_quaternion(q, shift));

    // GLM: the same four numbers, the same rotation; the matrices column-major on GLM's side.
    const glm::dquat g = quat::to_glm(q);
    check(quat::from_glm(g) == q, "from_glm(to_glm(q)) == q");
    check(near(quat::from_glm(g * quat::to_glm(v)), rotated), "glm::dquat * v rotates as quat");
    check(near(quat::from_glm(quat::to_glm(quat::to_matrix(q)) * quat::to_glm(v)), rotated),
          "glm::dmat3 * v rotates as quat");
    const glm::dvec4 moved_by_glm = quat::to_glm(motion) * glm::dvec4(v.x, v.y, v.z, 1);
    check(near(quat::vec3<double>{moved_by_glm.x, moved_by_glm.y, moved_by_glm.z}, rotated + shift),
          "glm::dmat4 moves a point as quat's homogeneous matrix does");
    check(quat::from_glm(quat::to_glm(motion)) == motion,
          "homogeneous matrix through GLM and back");

    // Eigen: likewise, with Eigen's own types.
    const Eigen::Quaterniond e = quat::to_eigen(q);
    check(quat::from_eigen(e) == q, "from_eigen(to_eigen(q)) == q");
    check(near(quat::from_eigen(Eigen::Vector3d(e * quat::to_eigen(v))), rotated),
          "Eigen::Quaterniond * v rotates as quat");
    const Eigen::Matrix4d m4 = quat::to_eigen(motion);
    const Eigen::Vector4d moved_by_eigen = m4 * Eigen::Vector4d(v.x, v.y, v.z, 1);
    check(near(quat::vec3<double>{moved_by_eigen.x(), moved_by_eigen.y(), moved_by_eigen.z()},
               rotated + shift),
          "Eigen::Matrix4d moves a point as quat's homogeneous matrix does");
    check(quat::from_eigen(m4) == motion, "homogeneous matrix through Eigen and back");

    // io.hpp and interop/fmt.hpp together: one format. A half turn about z and a unit lift, whose
    // components print alike at any precision.
    const quat::dual_quaternion<double> half_turn{{0, 0, 0, 1}, {-0.5, 0, 0, 0}};
    std::ostringstream printed;
    printed << half_turn.real << ' ' << quat::to_homogeneous(half_turn);
    check(printed.str() ==
              "quaternion{0, 0, 0, 1} "
              "homogeneous_matrix{{-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, 1, 1}, {0, 0, 0, 1}}",
          "operator<< from single_include/quat/io.hpp");
#if QUAT_TEST_FMT
    check(fmt::format("{} {}", half_turn.real, quat::to_homogeneous(half_turn)) == printed.str(),
          "fmt::format prints what operator<< prints");
#endif

    std::printf("single_include interop (GLM, Eigen%s): %s\n", QUAT_TEST_FMT ? ", {fmt}" : "",
                failures == 0 ? "ok" : "FAILED");
    return failures == 0 ? 0 : 1;
}
