// Operation counts of the core operations, counted with quat::counted<double> (bench/counted.hpp).
// The numbers are written here on purpose: a change that makes an operation cost more fails.
// `quat_bench --counts` prints the same cases beside the thesis's Table 3.1.
#include "../bench/count_cases.hpp"
#include "support/catch.hpp"

namespace test_counts {

namespace {

struct expected {
    long add, mul, div, sqrt, trig;
};

void check(const quat::operation_counts& got, expected e) {
    CHECK(got.add <= e.add);
    CHECK(got.mul <= e.mul);
    CHECK(got.div <= e.div);
    CHECK(got.sqrt <= e.sqrt);
    CHECK(got.trig <= e.trig);
}

}  // namespace

TEST_CASE("counted<T> counts each kind of operation", "[counts]") {
    using C = quat::counted<double>;
    quat::reset_counts();
    const C a(2.0), b(3.0);
    const C r = sqrt(a * b + a / b - a) + cos(b);
    const quat::operation_counts n = quat::counts();
    CHECK(n.add == 3);
    CHECK(n.mul == 1);
    CHECK(n.div == 1);
    CHECK(n.sqrt == 1);
    CHECK(n.trig == 1);
    CHECK(r.value == Approx(std::sqrt(6.0 + 2.0 / 3.0 - 2.0) + std::cos(3.0)));
}

TEST_CASE("rotating a point: quaternion cheaper than q p q*, matrix cheapest", "[counts]") {
    using namespace bench::count_cases;
    check(rotate_naive(), {24, 32, 0, 0, 0});
    // M v with M built from q and s = 2 (2 - |q|^2): |v| kept to 4 eps after normalize (18/12
    // for v + w t + u x t, which reaches 5.4 eps); see quaternion.hpp.
    check(rotate_quaternion(), {23, 25, 0, 0, 0});
    check(rotate_matrix(), {6, 9, 0, 0, 0});
    check(rotate_batch_per_point(1024), {6, 9, 0, 0, 0});
}

TEST_CASE("composing: the quaternion product is cheaper than the matrix product", "[counts]") {
    using namespace bench::count_cases;
    check(compose_quaternions(), {12, 16, 0, 0, 0});
    check(compose_matrices(), {18, 27, 0, 0, 0});
    check(quaternion_to_matrix(), {15, 9, 0, 0, 0});
}

TEST_CASE("Table 3.1: build the rotation from Euler angles or axis-angle, rotate one point",
          "[counts]") {
    using namespace bench::count_cases;
    // Thesis (MATLAB): matrix 10/25/0/6 and 16/30/0/2; quaternion 25/42/0/6 and 21/31/0/2
    // (add/mul/div/trig).
    check(matrix_from_euler(), {18, 33, 0, 0, 6});
    check(quaternion_from_euler(), {27, 41, 0, 0, 6});
    check(matrix_from_axis_angle(), {16, 21, 0, 0, 2});
    check(quaternion_from_axis_angle(), {23, 29, 0, 0, 2});
}

namespace {
quat::operation_counts plus(const quat::operation_counts& a, const quat::operation_counts& b) {
    return {a.add + b.add, a.mul + b.mul, a.div + b.div, a.sqrt + b.sqrt, a.trig + b.trig};
}
}  // namespace

TEST_CASE("rigid motion: build from rotation + translation, move one point", "[counts]") {
    using namespace bench::count_cases;
    // 4x4: to_matrix(q) (9 mul, 15 add); t and the last row (0, 0, 0, 1) are copies.
    check(rigid_build_matrix(), {15, 9, 0, 0, 0});
    // Dual quaternion: t/2 (3 mul), then the Hamilton product (0, t/2) q (16 mul, 12 add).
    check(rigid_build_dual(), {12, 19, 0, 0, 0});
    // Pair: q and t are stored as given.
    check(rigid_build_pair(), {0, 0, 0, 0, 0});
    // Full 4x4 x (x, y, z, 1): 4 rows of 4 mul, 3 add, the known last row and the * 1 included.
    check(rigid_point_matrix_full(), {12, 16, 0, 0, 0});
    // transform(m, p): R p (9 mul, 6 add) + t (3 add); the last row is not read.
    check(rigid_point_matrix(), {9, 9, 0, 0, 0});
    // R p / 2 (rotate(q, p)'s 25 mul, 22 add: s / 2 = 2 - |q|^2 is one addition, not two) + t / 2
    // (dual real*'s vector part: 12 mul, 9 add) + 3 add, doubled (3 add); t rebuilt per call.
    check(rigid_point_dual(), {37, 37, 0, 0, 0});
    // rotate(q, p) (25 mul, 23 add) + t (3 add).
    check(rigid_point_pair(), {26, 25, 0, 0, 0});
    // to_homogeneous(dq) once (25 mul, 30 add, < 1 per point over 1024), then R p + t per point.
    check(rigid_batch_dual_per_point(1024), {9, 9, 0, 0, 0});
    // Build and one point counted together: exactly the two parts.
    CHECK(rigid_once_matrix_full() == plus(rigid_build_matrix(), rigid_point_matrix_full()));
    CHECK(rigid_once_matrix() == plus(rigid_build_matrix(), rigid_point_matrix()));
    CHECK(rigid_once_dual() == plus(rigid_build_dual(), rigid_point_dual()));
    CHECK(rigid_once_pair() == plus(rigid_build_pair(), rigid_point_pair()));
    check(rigid_once_matrix_full(), {27, 25, 0, 0, 0});
    check(rigid_once_matrix(), {24, 18, 0, 0, 0});
    check(rigid_once_dual(), {49, 56, 0, 0, 0});
    check(rigid_once_pair(), {26, 25, 0, 0, 0});
}

TEST_CASE("rigid motion: composing two; the 3x4 affine product is cheapest", "[counts]") {
    using namespace bench::count_cases;
    // 16 entries, each a length-4 dot product (4 mul, 3 add).
    check(rigid_compose_matrix_full(), {48, 64, 0, 0, 0});
    // Last rows known: R_a R_b (27 mul, 18 add) + R_a t_b (9 mul, 6 add) + t_a (3 add).
    check(rigid_compose_affine(), {27, 36, 0, 0, 0});
    // real: a.r b.r; dual: a.r b.d + a.d b.r; three Hamilton products (16/12) and a sum (4 add).
    check(rigid_compose_dual(), {40, 48, 0, 0, 0});
    // q_a q_b (16 mul, 12 add) + rotate(q_a, t_b) (25 mul, 23 add) + t_a (3 add).
    check(rigid_compose_pair(), {38, 41, 0, 0, 0});
    // to_matrix(real) (9 mul, 15 add) + translation_of (12 mul, 12 add).
    check(dual_to_homogeneous(), {27, 21, 0, 0, 0});
}

TEST_CASE("Table 3.2 for rigid motions: the types store their scalars and nothing else",
          "[counts]") {
    // 4x4 matrix 16, dual quaternion 8, quaternion + translation 4 + 3 (no 3x4 type in quat).
    CHECK(sizeof(quat::homogeneous_matrix<double>) == 16 * sizeof(double));
    CHECK(sizeof(quat::homogeneous_matrix<float>) == 16 * sizeof(float));
    CHECK(sizeof(quat::dual_quaternion<double>) == 8 * sizeof(double));
    CHECK(sizeof(quat::dual_quaternion<float>) == 8 * sizeof(float));
    CHECK(sizeof(quat::quaternion<double>) + sizeof(quat::vec3<double>) == 7 * sizeof(double));
}

}  // namespace test_counts
