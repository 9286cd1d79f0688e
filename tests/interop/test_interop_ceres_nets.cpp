// quat/interop/ceres.hpp inside the nets the rest of quat is held by: NaN, +Inf and -Inf in each
// component of each parameter block give a non-finite result (docs/api.md's promise; the manifolds
// still return true, as Ceres's own do), and evaluating the manifolds and the parameter readers
// and writers allocates nothing (constructing Ceres's objects does, by Ceres's design, and is left
// out of the count).
#include <cmath>
#include <limits>
#include <string>

#include <quat/interop/ceres.hpp>
#include <quat/quat.hpp>

#include "support/allocation_counter.hpp"
#include "support/catch.hpp"
#include "support/random.hpp"

namespace {

bool any_nonfinite(const double* values, int count) {
    for (int i = 0; i < count; ++i)
        if (!std::isfinite(values[i])) return true;
    return false;
}

constexpr double bad_values[] = {std::numeric_limits<double>::quiet_NaN(),
                                 std::numeric_limits<double>::infinity(),
                                 -std::numeric_limits<double>::infinity()};

/// Calls check(x, y, delta, "where") with one bad component in x, then in y, then in delta.
template <class Check>
void for_each_bad_parameter(const double* x, const double* y, const double* delta, int ambient,
                            int tangent, Check check) {
    for (const double value : bad_values)
        for (int block = 0; block < 3; ++block)
            for (int i = 0; i < (block == 2 ? tangent : ambient); ++i) {
                double bx[7], by[7], bd[6];
                for (int k = 0; k < ambient; ++k) {
                    bx[k] = x[k];
                    by[k] = y[k];
                }
                for (int k = 0; k < tangent; ++k) bd[k] = delta[k];
                double* target = block == 0 ? bx : (block == 1 ? by : bd);
                target[i] = value;
                check(bx, by, bd,
                      std::string(block == 0 ? "x[" : (block == 1 ? "y[" : "delta[")) +
                          std::to_string(i) + "]=" + std::to_string(value));
            }
}

template <class Manifold>
void check_manifold(const Manifold& manifold, const double* x, const double* y,
                    const double* delta) {
    const int ambient = manifold.AmbientSize(), tangent = manifold.TangentSize();
    for_each_bad_parameter(
        x, y, delta, ambient, tangent,
        [&](const double* bx, const double* by, const double* bd, const std::string& where) {
            INFO(where);
            double out[7], jacobian[42];
            const bool x_bad = any_nonfinite(bx, ambient);
            CHECK(manifold.Plus(bx, bd, out));
            if (x_bad || any_nonfinite(bd, tangent)) CHECK(any_nonfinite(out, ambient));
            CHECK(manifold.Minus(by, bx, out));
            if (x_bad || any_nonfinite(by, ambient)) CHECK(any_nonfinite(out, tangent));
            // Both manifolds' Jacobians at x depend on its rotation alone.
            const bool rotation_bad = any_nonfinite(bx, 4);
            CHECK(manifold.PlusJacobian(bx, jacobian));
            if (rotation_bad) CHECK(any_nonfinite(jacobian, ambient * tangent));
            CHECK(manifold.MinusJacobian(bx, jacobian));
            if (rotation_bad) CHECK(any_nonfinite(jacobian, ambient * tangent));
        });
}

}  // namespace

TEST_CASE("ceres manifolds give a non-finite result for a NaN or infinite parameter",
          "[interop][ceres][hostile]") {
    quat::test::random_rotations random;
    double x[7], y[7];
    quat::write_parameters(random.rigid_motion<double>(), x);
    quat::write_parameters(random.rigid_motion<double>(), y);
    const double delta[6] = {0.1, -0.2, 0.3, 0.4, -0.1, 0.2};
    check_manifold(quat::quaternion_manifold{}, x, y, delta);
    check_manifold(quat::pose_manifold{}, x, y, delta);

    for (const double value : bad_values)
        for (int i = 0; i < 7; ++i) {
            double p[7] = {x[0], x[1], x[2], x[3], x[4], x[5], x[6]};
            p[i] = value;
            INFO("p[" << i << "]=" << value);
            double read[8];
            quat::write_parameters(quat::pose_from_parameters(p), read);
            CHECK(any_nonfinite(read, 7));
            if (i < 6) {
                quat::write_parameters(quat::twist_from_parameters(p), read);
                CHECK(any_nonfinite(read, 6));
            }
        }
}

TEST_CASE("evaluating the ceres manifolds and parameter blocks allocates nothing",
          "[interop][ceres][allocation]") {
    quat::test::random_rotations random;
    double x[7], y[7], out[7], jacobian[42];
    quat::write_parameters(random.rigid_motion<double>(), x);
    quat::write_parameters(random.rigid_motion<double>(), y);
    const double delta[6] = {0.1, -0.2, 0.3, 0.4, -0.1, 0.2};
    const quat::quaternion_manifold rotation;
    const quat::pose_manifold pose;

    const long before = allocations.load();
    double sink = 0;
    for (const ceres::Manifold* manifold : {static_cast<const ceres::Manifold*>(&rotation),
                                            static_cast<const ceres::Manifold*>(&pose)}) {
        manifold->Plus(x, delta, out);
        sink += out[0];
        manifold->Minus(y, x, out);
        sink += out[1];
        manifold->PlusJacobian(x, jacobian);
        sink += jacobian[2];
        manifold->MinusJacobian(x, jacobian);
        sink += jacobian[3];
    }
    const quat::dual_quaternion<double> motion = quat::pose_from_parameters(x);
    quat::write_parameters(motion, out);
    quat::write_parameters(quat::twist_from_parameters(delta), out);
    sink += out[4] + quat::quaternion_from_parameters(y).w + quat::vec3_from_parameters(y + 4).z;
    const long after = allocations.load();

    CHECK(after == before);
    CHECK(std::isfinite(sink));
}
