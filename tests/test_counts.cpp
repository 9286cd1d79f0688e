// Operation counts of the core operations, counted with quat::counted<double> (bench/counted.hpp).
// The numbers are written here on purpose: a change that makes an operation cost more fails.
// `quat_bench --counts` prints the same cases beside the thesis's Table 3.1.
#include "../bench/count_cases.hpp"
#include "support/catch.hpp"

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
    // Thesis (MATLAB): matrix 10/25/0/6 and 16/30/0/2; quaternion 25/42/0/6 and 21/31/0/2 (add/mul/div/trig).
    check(matrix_from_euler(), {18, 33, 0, 0, 6});
    check(quaternion_from_euler(), {27, 41, 0, 0, 6});
    check(matrix_from_axis_angle(), {16, 21, 0, 0, 2});
    check(quaternion_from_axis_angle(), {23, 29, 0, 0, 2});
}
