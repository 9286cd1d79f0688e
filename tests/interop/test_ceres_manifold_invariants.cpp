// Ceres's own test of a manifold, EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD
// (ceres/manifold_test_utils.h, GoogleTest): x (+) 0 = x, x (-) x = 0, (x (+) d) (-) x = d, x (+)
// (y (-) x) = y, the Jacobians against Ridders differences, MinusJacobian * PlusJacobian = I, for
// quaternion_manifold and pose_manifold at the identity, seeded random points, 1e-6 below a half
// turn and at a half turn, with steps d from 1e-5 to pi - 1e-6 and random y (about half of them
// with dot(x, y) < 0, where a shortest-path Minus would lead Plus to -y). Ceres's
// QuaternionManifold and EigenQuaternionManifold run over the same rotations as a control of the
// points and the tolerance. Each manifold prints how many of its sets of invariants fail. Needs
// libceres, gtest and gmock: built as its own executable (tests/interop/CMakeLists.txt).
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include <ceres/manifold.h>
#include <ceres/manifold_test_utils.h>
#include <gtest/gtest.h>
#include <quat/interop/ceres.hpp>

#include "support/random.hpp"

namespace {

// The tolerance of Ceres's own manifold tests (manifold_test.cc).
constexpr double tolerance = 1e-9;
constexpr double pi = 3.14159265358979323846;

/// 12 rotations: the identity, 8 seeded random ones, pi - 1e-6 about a random axis, and a half
/// turn about a random axis and about x (w = 0 exactly).
std::vector<quat::quatd> rotations(quat::test::random_rotations& random) {
    std::vector<quat::quatd> x{quat::quatd::identity()};
    for (int i = 0; i < 8; ++i) x.push_back(random.unit_quaternion<double>());
    x.push_back(quat::from_rotation_vector(random.unit_vector<double>() * (pi - 1e-6)));
    x.push_back(quat::from_rotation_vector(random.unit_vector<double>() * pi));
    x.push_back(quat::quatd{0, 1, 0, 0});
    return x;
}

/// 15 step lengths (rotation angles) from 1e-5 to pi - 1e-6.
constexpr std::array<double, 15> step_lengths = {1e-5, 1e-4, 1e-3,      1e-2,      0.1,
                                                 0.5,  1.0,  1.5,       2.0,       2.5,
                                                 3.0,  3.1,  pi - 1e-3, pi - 1e-5, pi - 1e-6};

/// The number of failed expectations of the running test so far.
int failures() {
    const ::testing::TestResult& result =
        *::testing::UnitTest::GetInstance()->current_test_info()->result();
    int count = 0;
    for (int i = 0; i < result.total_part_count(); ++i)
        if (result.GetTestPartResult(i).failed()) ++count;
    return count;
}

/// Runs Ceres's invariants for every rotation and step length (180 sets), x a rotation block or,
/// for pose, a pose block with a random translation; y random; returns the failed sets.
int failed_sets(const ceres::Manifold& manifold, bool pose) {
    using namespace ceres;  // the invariant macro names its matchers and Vector unqualified
    quat::test::random_rotations random;
    int failed = 0;
    for (const quat::quatd& rotation : rotations(random)) {
        for (const double length : step_lengths) {
            const int before = failures();
            Vector x(manifold.AmbientSize()), y(manifold.AmbientSize());
            Vector delta(manifold.TangentSize());
            const quat::vec3<double> angular = random.unit_vector<double>() * length;
            if (pose) {
                quat::write_parameters(quat::to_dual_quaternion(rotation, random.vector<double>()),
                                       x.data());
                quat::write_parameters(random.rigid_motion<double>(), y.data());
                quat::write_parameters(quat::se3::twist<double>{random.vector<double>(), angular},
                                       delta.data());
            } else {
                quat::write_parameters(rotation, x.data());
                quat::write_parameters(random.unit_quaternion<double>(), y.data());
                quat::write_parameters(angular, delta.data());
            }
            SCOPED_TRACE(::testing::Message() << "step length " << length);
            EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD(manifold, x, delta, y, tolerance);
            if (failures() > before) ++failed;
        }
    }
    return failed;
}

void report(const char* name, int failed) {
    std::printf("%s: %d of %d sets of Ceres's manifold invariants fail\n", name, failed,
                static_cast<int>(12 * step_lengths.size()));
}

}  // namespace

TEST(CeresManifoldInvariants, QuaternionManifold) {
    const int failed = failed_sets(quat::quaternion_manifold{}, false);
    report("quat::quaternion_manifold", failed);
    EXPECT_EQ(failed, 0);
}

TEST(CeresManifoldInvariants, PoseManifold) {
    const int failed = failed_sets(quat::pose_manifold{}, true);
    report("quat::pose_manifold", failed);
    EXPECT_EQ(failed, 0);
}

// The control: Ceres's own quaternion manifolds pass at the same points and tolerance (the
// Eigen one stores x, y, z, w, which random rotations fill just as well).
TEST(CeresManifoldInvariants, CeresQuaternionManifolds) {
    const int ceres_failed = failed_sets(ceres::QuaternionManifold{}, false);
    report("ceres::QuaternionManifold", ceres_failed);
    EXPECT_EQ(ceres_failed, 0);
    const int eigen_failed = failed_sets(ceres::EigenQuaternionManifold{}, false);
    report("ceres::EigenQuaternionManifold", eigen_failed);
    EXPECT_EQ(eigen_failed, 0);
}

// y = x with its quaternion negated: the same rotation (and motion), which only a Minus that keeps
// the sign reaches, with an angle of 2 pi.
TEST(CeresManifoldInvariants, YIsXWithItsQuaternionNegated) {
    using namespace ceres;
    quat::test::random_rotations random;
    const quat::quaternion_manifold rotation_manifold;
    const quat::pose_manifold pose_manifold;
    for (const quat::quatd& rotation : rotations(random)) {
        {
            Vector x(4), y(4), delta(3);
            quat::write_parameters(rotation, x.data());
            quat::write_parameters(-rotation, y.data());
            quat::write_parameters(random.unit_vector<double>(), delta.data());
            EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD(rotation_manifold, x, delta, y, tolerance);
        }
        Vector x(7), y(7), delta(6);
        quat::write_parameters(quat::to_dual_quaternion(rotation, random.vector<double>()),
                               x.data());
        y = x;
        y.head(4) = -y.head(4);
        quat::write_parameters(
            quat::se3::twist<double>{random.vector<double>(), random.unit_vector<double>()},
            delta.data());
        EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD(pose_manifold, x, delta, y, tolerance);
    }
}
