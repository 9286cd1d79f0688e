// SE(3) as a Lie group (quat/lie/se3.hpp): exp against the matrix exponential of the 4x4 twist (its
// series in long double), log against to_screw and sclerp, and every analytic Jacobian against
// central differences of the same function in long double through the right plus and minus
// (J = d (f(X exp(d)) (-) f(X)) / d d at d = 0), at fixed-seed random points, the identity, zero
// and tiny rotations (pure and nearly pure translations), both sides of the coefficients' switches
// (|omega| = 2 and 3), around 1/4, and near half turns (pi - 1e-8); ceres::Jet derivatives of
// exp, log, plus and minus, finite at zero and tiny tangents and equal to the analytic Jacobians;
// the identities between the Jacobians; NaN in, NaN out.
//
// The reference differences are those of tests/test_so3.cpp: Richardson-extrapolated twice, errors
// relative to the largest entry; near a half turn (log, minus) the step stays below the distance
// 1e-8 to it, and long double's rounding limits the reference to 2e-9 there.
// QUAT_LIE_REPORT=1 in the environment prints the worst error of every Jacobian.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include <ceres/jet.h>
#include <quat/lie/se3.hpp>
#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/jacobian_check.hpp"
#include "support/random.hpp"

namespace test_se3 {

namespace {

using namespace quat;
using ld = long double;
template <class T>
using twist = se3::twist<T>;
template <class T>
using dq = dual_quaternion<T>;

constexpr double pi = 3.14159265358979323846;
constexpr double near_half_turn = pi - 1e-8;

quat::test::worst_errors worst("se3");

void check(const std::string& name, double error, double tolerance = 1e-12) {
    worst.check(name, error, tolerance);
}
using quat::test::central_differences;
using quat::test::relative_error;

using arr6 = std::array<ld, 6>;
arr6 arr(const twist<ld>& t) {
    return {t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z};
}
std::array<ld, 3> arr(const vec3<ld>& v) { return {v.x, v.y, v.z}; }
twist<ld> tw(const arr6& a) { return {{a[0], a[1], a[2]}, {a[3], a[4], a[5]}}; }
vec3<ld> vec(const std::array<ld, 3>& a) { return {a[0], a[1], a[2]}; }
twist<ld> wide(const twist<double>& t) { return {vec3<ld>(t.linear), vec3<ld>(t.angular)}; }
dq<ld> wide(const dq<double>& x) { return dq<ld>(x); }
vec3<ld> wide(const vec3<double>& v) { return vec3<ld>(v); }

dq<ld> oplus(const dq<ld>& x, const arr6& d) { return x * se3::exp(tw(d)); }
arr6 ominus(const dq<ld>& y, const dq<ld>& x) { return arr(se3::log(se3::inverse(x) * y)); }
arr6 difference(const twist<ld>& a, const twist<ld>& b) { return arr(a - b); }

/// The twists' rotation angles the Jacobians are checked at: both sides of each switch, as in
/// tests/test_so3.cpp.
std::array<double, 12> angles() {
    return {0.0,       1e-12,     1e-6, 0.2499999, 0.2500001, 0.3,
            1.9999999, 2.0000001, 2.5,  2.9999999, 3.0000001, near_half_turn};
}
ld step_for(double a) { return a > 3.1 ? 4e-9L : 1e-3L; }
double tolerance_for(double a) { return a > 3.1 ? 2e-9 : 1e-12; }

/// exp of the 4x4 matrix m by its Taylor series, in long double (|m| of a few units).
matrix<ld, 4, 4> matrix_exponential(const matrix<ld, 4, 4>& m) {
    matrix<ld, 4, 4> sum = matrix<ld, 4, 4>::identity(), term = sum;
    for (int k = 1; k < 80; ++k) {
        term = term * m * (1.0L / k);
        sum += term;
    }
    return sum;
}

/// The largest difference of rotation (radians) and translation between two motions.
double motion_difference(const dq<double>& a, const dq<double>& b) {
    const vec3<double> dt = translation_of(a) - translation_of(b);
    return std::max(angle_between(a.real, b.real), norm(dt));
}

}  // namespace

TEST_CASE("se3 hat and vee invert each other, and to_vector puts the linear part first") {
    const twist<double> t{{1, 2, 3}, {4, 5, 6}};
    const matrix<double, 4, 4> h = se3::hat(t);
    CHECK(h(0, 3) == 1);
    CHECK(h(2, 1) == 4);
    CHECK(h(3, 3) == 0);
    const twist<double> back = se3::vee(h);
    CHECK(arr(wide(back)) == arr(wide(t)));
    const matrix<double, 6, 1> v = se3::to_vector(t);
    CHECK(v(0, 0) == 1);
    CHECK(v(5, 0) == 6);
    CHECK(arr(wide(se3::to_twist(v))) == arr(wide(t)));
    CHECK(arr(wide(2.0 * t - t)) == arr(wide(t)));
    CHECK(arr(wide(-t + t)) == arr6{});
}

TEST_CASE("se3 exp is the matrix exponential of the twist, and log inverts it") {
    test::random_rotations random;
    for (const double a : angles()) {
        const twist<double> t{random.vector<double>(2.0), random.unit_vector<double>() * a};
        INFO("angle " << a);
        const dq<double> x = se3::exp(t);
        const matrix<ld, 4, 4> m = matrix_exponential(se3::hat(wide(t)));
        const rotation_matrix<double> r = to_matrix(x.real);
        const vec3<double> translation = translation_of(x);
        double error = 0;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j)
                error = std::max(error, static_cast<double>(std::abs(r(i, j) - m(i, j))));
            error = std::max(error, static_cast<double>(std::abs(translation[i] - m(i, 3))));
        }
        INFO("error " << error);
        CHECK(error <= 2e-15 * (1 + norm(translation)));
        // log(exp(t)) = t
        const twist<double> back = se3::log(x);
        const arr6 d = difference(wide(back), wide(t));
        for (const ld e : d) CHECK(std::abs(e) <= 4e-15);
    }
}

TEST_CASE(
    "se3 log agrees with to_screw, exp(log X) = X, and sclerp(a, b, t) = a exp(t log(a^-1 b))") {
    test::random_rotations random;
    for (int k = 0; k < 50; ++k) {
        const dq<double> a = random.rigid_motion<double>(), b = random.rigid_motion<double>();
        const dq<double> x = k % 2 == 0 ? b : -b;  // either sign
        const twist<double> t = se3::log(x);
        const screw<double> s = to_screw(x);
        const vec3<double> angular = s.direction * s.angle;
        const vec3<double> linear = s.moment * s.angle + s.direction * s.displacement;
        CHECK(norm(t.angular - angular) <= 4e-15);
        CHECK(norm(t.linear - linear) <= 1e-14);
        CHECK(norm(t.angular) <= pi);
        CHECK(motion_difference(se3::exp(t), x) <= 1e-14);
        const twist<double> from_matrix = se3::log(to_homogeneous(x));
        CHECK(norm(from_matrix.angular - t.angular) <= 4e-15);
        CHECK(norm(from_matrix.linear - t.linear) <= 1e-14);
        const twist<double> relative = se3::log(se3::between(a, b));
        for (const double u : {0.0, 0.25, 0.5, 0.9, 1.0, 1.5}) {
            INFO("t = " << u);
            CHECK(motion_difference(sclerp(a, b, u), a * se3::exp(u * relative)) <= 2e-14);
        }
    }
}

TEST_CASE(
    "se3 Jacobians satisfy Jr(t) = Jl(-t), Jl = Ad(exp t) Jr, J^-1 J = I and the adjoint "
    "identity") {
    test::random_rotations random;
    const auto largest_difference = [](const matrix6<double>& a, const matrix6<double>& b) {
        double error = 0;
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) error = std::max(error, std::abs(a(i, j) - b(i, j)));
        return error;
    };
    for (const double a : angles()) {
        const twist<double> t{random.vector<double>(2.0), random.unit_vector<double>() * a};
        INFO("angle " << a);
        CHECK(se3::right_jacobian(t) == se3::left_jacobian(-t));
        CHECK(largest_difference(se3::left_jacobian(t),
                                 se3::adjoint(se3::exp(t)) * se3::right_jacobian(t)) <= 1e-14);
        const auto identity = matrix6<double>::identity();
        CHECK(largest_difference(se3::right_jacobian_inverse(t) * se3::right_jacobian(t),
                                 identity) <= 1e-14);
        CHECK(largest_difference(se3::left_jacobian_inverse(t) * se3::left_jacobian(t), identity) <=
              1e-14);
        // X exp(v) = exp(Ad(X) v) X
        const dq<double> x = random.rigid_motion<double>();
        const twist<double> v{random.vector<double>(), random.vector<double>()};
        const twist<double> moved = se3::to_twist(se3::adjoint(x) * se3::to_vector(v));
        CHECK(motion_difference(x * se3::exp(v), se3::exp(moved) * x) <= 1e-14);
    }
}

TEST_CASE("se3 Jacobians equal central differences through the right plus and minus") {
    test::random_rotations random;
    for (int sample = 0; sample < 3; ++sample) {
        for (const double a : angles()) {
            const twist<double> t{random.vector<double>(2.0), random.unit_vector<double>() * a};
            const dq<double> drawn = random.rigid_motion<double>();
            const dq<double> x =
                sample == 0 ? dq<double>::identity() : drawn;  // the identity first
            const dq<double> y = x * se3::exp(t);              // y (-) x = t
            const vec3<double> p = random.vector<double>(3.0);
            const ld h = step_for(a);
            const double tolerance = tolerance_for(a);
            const std::string at = a > 3.1 ? " at pi - 1e-8" : "";
            INFO("angle " << a << ", sample " << sample);
            matrix6<double> d1{}, d2{};

            const dq<double> e = se3::exp(t, &d1);
            check("exp", relative_error(d1, central_differences<6, 6>(
                                                [&](const arr6& d) {
                                                    return ominus(se3::exp(wide(t) + tw(d)),
                                                                  wide(e));
                                                },
                                                1e-3L)));
            const twist<double> l = se3::log(e, &d1);
            check("log" + at,
                  relative_error(d1, central_differences<6, 6>(
                                         [&](const arr6& d) {
                                             return difference(se3::log(oplus(wide(e), d)),
                                                               wide(l));
                                         },
                                         h)),
                  tolerance);
            check("left_jacobian",
                  relative_error(se3::left_jacobian(t),
                                 central_differences<6, 6>(
                                     [&](const arr6& d) {
                                         return arr(se3::log(se3::exp(wide(t) + tw(d)) *
                                                             se3::inverse(se3::exp(wide(t)))));
                                     },
                                     1e-3L)));

            const dq<double> c = se3::compose(x, y, &d1, &d2);
            check("compose d_a",
                  relative_error(d1, central_differences<6, 6>(
                                         [&](const arr6& d) {
                                             return ominus(oplus(wide(x), d) * wide(y), wide(c));
                                         },
                                         1e-3L)));
            check("compose d_b",
                  relative_error(d2, central_differences<6, 6>(
                                         [&](const arr6& d) {
                                             return ominus(wide(x) * oplus(wide(y), d), wide(c));
                                         },
                                         1e-3L)));
            const dq<double> i = se3::inverse(x, &d1);
            check("inverse", relative_error(d1, central_differences<6, 6>(
                                                    [&](const arr6& d) {
                                                        return ominus(
                                                            se3::inverse(oplus(wide(x), d)),
                                                            wide(i));
                                                    },
                                                    1e-3L)));
            matrix<double, 3, 6> dp_x{};
            matrix3<double> dp_p{};
            const vec3<double> moved = se3::act(x, p, &dp_x, &dp_p);
            check("act d_x",
                  relative_error(dp_x, central_differences<3, 6>(
                                           [&](const arr6& d) {
                                               return arr(transform(oplus(wide(x), d), wide(p)) -
                                                          wide(moved));
                                           },
                                           1e-3L)));
            check("act d_p",
                  relative_error(dp_p, central_differences<3, 3>(
                                           [&](const std::array<ld, 3>& d) {
                                               return arr(transform(wide(x), wide(p) + vec(d)) -
                                                          wide(moved));
                                           },
                                           1e-3L)));
            const dq<double> b = se3::between(x, y, &d1, &d2);
            check("between d_x",
                  relative_error(
                      d1, central_differences<6, 6>(
                              [&](const arr6& d) {
                                  return ominus(se3::inverse(oplus(wide(x), d)) * wide(y), wide(b));
                              },
                              1e-3L)));
            check("between d_y", relative_error(d2, central_differences<6, 6>(
                                                        [&](const arr6& d) {
                                                            return ominus(se3::inverse(wide(x)) *
                                                                              oplus(wide(y), d),
                                                                          wide(b));
                                                        },
                                                        1e-3L)));
            const dq<double> pl = se3::plus(x, t, &d1, &d2);
            check("plus d_x", relative_error(d1, central_differences<6, 6>(
                                                     [&](const arr6& d) {
                                                         return ominus(
                                                             oplus(oplus(wide(x), d), arr(wide(t))),
                                                             wide(pl));
                                                     },
                                                     1e-3L)));
            check("plus d_t", relative_error(d2, central_differences<6, 6>(
                                                     [&](const arr6& d) {
                                                         return ominus(
                                                             wide(x) * se3::exp(wide(t) + tw(d)),
                                                             wide(pl));
                                                     },
                                                     1e-3L)));
            const twist<double> m = se3::minus(y, x, &d1, &d2);
            check("minus d_y" + at,
                  relative_error(d1, central_differences<6, 6>(
                                         [&](const arr6& d) {
                                             return difference(
                                                 tw(ominus(oplus(wide(y), d), wide(x))), wide(m));
                                         },
                                         h)),
                  tolerance);
            check("minus d_x" + at,
                  relative_error(d2, central_differences<6, 6>(
                                         [&](const arr6& d) {
                                             return difference(
                                                 tw(ominus(wide(y), oplus(wide(x), d))), wide(m));
                                         },
                                         h)),
                  tolerance);
            const dq<double> ql = se3::plus_left(x, t, &d2, &d1);
            check("plus_left d_t",
                  relative_error(d1, central_differences<6, 6>(
                                         [&](const arr6& d) {
                                             return ominus(se3::exp(wide(t) + tw(d)) * wide(x),
                                                           wide(ql));
                                         },
                                         1e-3L)));
            check("plus_left d_x",
                  relative_error(d2, central_differences<6, 6>(
                                         [&](const arr6& d) {
                                             return ominus(se3::exp(wide(t)) * oplus(wide(x), d),
                                                           wide(ql));
                                         },
                                         1e-3L)));
            const dq<double> yl = se3::exp(t) * x;  // y x^-1 = exp(t)
            const twist<double> ml = se3::minus_left(yl, x, &d1, &d2);
            check("minus_left d_y" + at,
                  relative_error(d1, central_differences<6, 6>(
                                         [&](const arr6& d) {
                                             return difference(se3::log(oplus(wide(yl), d) *
                                                                        se3::inverse(wide(x))),
                                                               wide(ml));
                                         },
                                         h)),
                  tolerance);
            check(
                "minus_left d_x" + at,
                relative_error(d2, central_differences<6, 6>(
                                       [&](const arr6& d) {
                                           return difference(
                                               se3::log(wide(yl) * se3::inverse(oplus(wide(x), d))),
                                               wide(ml));
                                       },
                                       h)),
                tolerance);
        }
    }
}

namespace {

using jet = ceres::Jet<double, 6>;

twist<jet> jet_variables(const twist<double>& at) {
    return {{jet(at.linear.x, 0), jet(at.linear.y, 1), jet(at.linear.z, 2)},
            {jet(at.angular.x, 3), jet(at.angular.y, 4), jet(at.angular.z, 5)}};
}
twist<jet> constant(const twist<double>& t) { return {vec3<jet>(t.linear), vec3<jet>(t.angular)}; }
matrix6<double> partials(const twist<jet>& t) {
    matrix6<double> m{};
    const jet entries[6] = {t.linear.x,  t.linear.y,  t.linear.z,
                            t.angular.x, t.angular.y, t.angular.z};
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c) m(r, c) = entries[r].v[c];
    return m;
}
dq<jet> value_of(const dq<jet>& x) {
    const auto v = [](const quaternion<jet>& q) {
        return quaternion<jet>{jet(q.w.a), jet(q.x.a), jet(q.y.a), jet(q.z.a)};
    };
    return {v(x.real), v(x.dual)};
}
/// The tangent derivatives of a unit dual quaternion of Jets X(d): X(0)^-1 X(d) is to first order
/// (1, omega/2) + eps (0, rho/2).
matrix6<double> tangent_partials(const dq<jet>& x) {
    const dq<jet> local = se3::inverse(value_of(x)) * x;
    return partials(twist<jet>{{local.dual.x, local.dual.y, local.dual.z},
                               {local.real.x, local.real.y, local.real.z}}) *
           2.0;
}
/// x ((1, omega/2) + eps (0, rho/2)) for Jet d = (rho, omega) at 0: the first-order right plus.
dq<jet> jet_plus(const dq<double>& x, const twist<jet>& d) {
    const dq<jet> step{
        quaternion<jet>{jet(1), d.angular.x * 0.5, d.angular.y * 0.5, d.angular.z * 0.5},
        quaternion<jet>{jet(0), d.linear.x * 0.5, d.linear.y * 0.5, d.linear.z * 0.5}};
    return dq<jet>(x) * step;
}
double max_difference(const matrix6<double>& a, const matrix6<double>& b) {
    double error = 0;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            if (!std::isfinite(a(i, j))) return std::numeric_limits<double>::infinity();
            error = std::max(error, std::abs(a(i, j) - b(i, j)));
        }
    return error;
}

}  // namespace

TEST_CASE(
    "se3 ceres::Jet derivatives of exp, log, plus and minus are finite and equal the "
    "analytic Jacobians, also at zero and tiny tangents") {
    test::random_rotations random;
    for (const double a : {0.0, 1e-300, 1e-12, 1e-6, 1e-4, 0.5, 2.0, 3.0, near_half_turn}) {
        const twist<double> t{random.vector<double>(), random.unit_vector<double>() * a};
        const twist<double> zero_rotation{t.linear, {0, 0, 0}};
        const dq<double> x = random.rigid_motion<double>();
        INFO("angle " << a);
        matrix6<double> d1{}, d2{};
        const twist<jet> zero = jet_variables({{0, 0, 0}, {0, 0, 0}});
        const double scale = 1 + norm(t.linear);

        (void)se3::exp(t, &d1);
        check("jet exp", max_difference(tangent_partials(se3::exp(jet_variables(t))), d1) / scale,
              4e-15);
        (void)se3::exp(zero_rotation, &d1);
        check("jet exp, no rotation",
              max_difference(tangent_partials(se3::exp(jet_variables(zero_rotation))), d1) / scale,
              4e-15);

        const dq<double> e = se3::exp(t);
        (void)se3::log(e, &d1);
        check("jet log", max_difference(partials(se3::log(jet_plus(e, zero))), d1) / scale, 4e-15);

        (void)se3::plus(x, t, &d1, &d2);
        check(
            "jet plus d_x",
            max_difference(tangent_partials(se3::plus(jet_plus(x, zero), constant(t))), d1) / scale,
            4e-15);
        check("jet plus d_t",
              max_difference(tangent_partials(se3::plus(dq<jet>(x), jet_variables(t))), d2) / scale,
              4e-15);

        const dq<double> y = x * e;
        (void)se3::minus(y, x, &d1, &d2);
        check("jet minus d_y",
              max_difference(partials(se3::minus(jet_plus(y, zero), dq<jet>(x))), d1) / scale,
              4e-15);
        check("jet minus d_x",
              max_difference(partials(se3::minus(dq<jet>(y), jet_plus(x, zero))), d2) / scale,
              4e-15);

        // The Jacobians themselves with Jet: finite derivatives at omega = 0.
        const matrix6<jet> jr = se3::right_jacobian_inverse(jet_variables(t));
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j)
                for (int k = 0; k < 6; ++k) CHECK(std::isfinite(jr(i, j).v[k]));
    }
}

TEMPLATE_TEST_CASE("se3 instantiates for float, double and long double", "", float, double,
                   long double) {
    using T = TestType;
    const twist<T> t{{T(1), T(-2), T(0.5)}, {T(0.1), T(-0.2), T(0.3)}};
    matrix6<T> d1{}, d2{};
    const dq<T> x = se3::exp(t, &d1);
    const twist<T> back = se3::log(x, &d2);
    CHECK(std::abs(back.linear.y - t.linear.y) <= 8 * std::numeric_limits<T>::epsilon());
    const matrix6<T> product = d1 * d2;
    CHECK(std::abs(product(0, 0) - T(1)) <= 16 * std::numeric_limits<T>::epsilon());
    CHECK(std::abs(product(0, 4)) <= 16 * std::numeric_limits<T>::epsilon());
    matrix<T, 3, 6> dp{};
    matrix3<T> dv{};
    (void)se3::compose(x, x, &d1, &d2);
    (void)se3::inverse(x, &d1);
    (void)se3::act(x, t.linear, &dp, &dv);
    (void)se3::between(x, x, &d1, &d2);
    (void)se3::plus(x, t, &d1, &d2);
    (void)se3::minus(x, x, &d1, &d2);
    (void)se3::plus_left(x, t, &d2, &d1);
    (void)se3::minus_left(x, x, &d1, &d2);
    (void)se3::left_jacobian(t);
    (void)se3::left_jacobian_inverse(t);
    constexpr matrix6<double> jr = se3::right_jacobian(se3::twist<double>{{1, 0, 0}, {0, 0, 0}});
    static_assert(jr(0, 0) == 1 && jr(1, 5) == 0.5 && jr(2, 4) == -0.5);
}

TEST_CASE("se3 gives NaN for NaN input, in the value and the Jacobians") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const twist<double> t{{0, 0, 0}, {nan, 0, 0}};
    const dq<double> x{quatd{nan, 0, 0, 0}, quatd{0, 0, 0, 0}};
    matrix6<double> d1{}, d2{};
    CHECK(std::isnan(se3::exp(t, &d1).real.w));
    CHECK(std::isnan(d1(0, 0)));
    CHECK(std::isnan(se3::log(x, &d1).angular.x));
    CHECK(std::isnan(d1(0, 0)));
    CHECK(std::isnan(se3::minus(x, dq<double>::identity(), &d1, &d2).linear.x));
    CHECK(std::isnan(d2(3, 3)));
    const twist<double> linear_nan{{nan, 0, 0}, {0, 0, 0}};
    CHECK(std::isnan(se3::exp(linear_nan).dual.x));
}

TEST_CASE("se3 a literal nullptr skips any Jacobian of every se3 function") {
    // As for so3: the value and the other Jacobian are those of the call that asks for both.
    test::random_rotations random;
    const dq<double> x = random.rigid_motion<double>(), y = random.rigid_motion<double>();
    const twist<double> t{random.vector<double>(), random.vector<double>()};
    const vec3<double> p = random.vector<double>();
    matrix6<double> full1{}, full2{}, one{};
    const auto same = [](const twist<double>& a, const twist<double>& b) {
        return se3::to_vector(a) == se3::to_vector(b);
    };

    const dq<double> e = se3::exp(t, &full1);
    CHECK(se3::exp(t, nullptr) == e);
    const twist<double> l = se3::log(x, &full1);
    CHECK(same(se3::log(x, nullptr), l));
    const homogeneous_matrix<double> h = to_homogeneous(x);
    const twist<double> lh = se3::log(h, &full1);
    CHECK(same(se3::log(h, nullptr), lh));
    const dq<double> i = se3::inverse(x, &full1);
    CHECK(se3::inverse(x, nullptr) == i);

    const dq<double> c = se3::compose(x, y, &full1, &full2);
    CHECK(se3::compose(x, y, nullptr, nullptr) == c);
    CHECK((se3::compose(x, y, &one, nullptr) == c && one == full1));
    CHECK((se3::compose(x, y, nullptr, &one) == c && one == full2));

    matrix<double, 3, 6> d_x{}, one_x{};
    matrix3<double> d_p{}, one_p{};
    const vec3<double> moved = se3::act(x, p, &d_x, &d_p);
    CHECK(se3::act(x, p, nullptr, nullptr) == moved);
    CHECK((se3::act(x, p, &one_x, nullptr) == moved && one_x == d_x));
    CHECK((se3::act(x, p, nullptr, &one_p) == moved && one_p == d_p));

    const dq<double> b = se3::between(x, y, &full1, &full2);
    CHECK(se3::between(x, y, nullptr, nullptr) == b);
    CHECK((se3::between(x, y, &one, nullptr) == b && one == full1));
    CHECK((se3::between(x, y, nullptr, &one) == b && one == full2));

    const dq<double> pp = se3::plus(x, t, &full1, &full2);
    CHECK(se3::plus(x, t, nullptr, nullptr) == pp);
    CHECK((se3::plus(x, t, &one, nullptr) == pp && one == full1));
    CHECK((se3::plus(x, t, nullptr, &one) == pp && one == full2));

    const twist<double> m = se3::minus(y, x, &full1, &full2);
    CHECK(same(se3::minus(y, x, nullptr, nullptr), m));
    CHECK((same(se3::minus(y, x, &one, nullptr), m) && one == full1));
    CHECK((same(se3::minus(y, x, nullptr, &one), m) && one == full2));

    const dq<double> pl = se3::plus_left(x, t, &full1, &full2);
    CHECK(se3::plus_left(x, t, nullptr, nullptr) == pl);
    CHECK((se3::plus_left(x, t, &one, nullptr) == pl && one == full1));
    CHECK((se3::plus_left(x, t, nullptr, &one) == pl && one == full2));

    const twist<double> ml = se3::minus_left(y, x, &full1, &full2);
    CHECK(same(se3::minus_left(y, x, nullptr, nullptr), ml));
    CHECK((same(se3::minus_left(y, x, &one, nullptr), ml) && one == full1));
    CHECK((same(se3::minus_left(y, x, nullptr, &one), ml) && one == full2));
}

TEST_CASE("se3 the Jacobians of exp and log are right_jacobian and its inverse, bit for bit") {
    // One coefficient path: so3's, whose accuracy tests/test_so3.cpp measures against a long
    // double series, makes the blocks of both.
    test::random_rotations random;
    for (int k = 0; k < 200; ++k) {
        const twist<double> t{random.vector<double>(),
                              random.unit_vector<double>() * random.uniform<double>(0, pi)};
        matrix6<double> exp_jacobian{}, log_jacobian{};
        const dq<double> x = se3::exp(t, &exp_jacobian);
        CHECK(exp_jacobian == se3::right_jacobian(t));
        const twist<double> back = se3::log(x, &log_jacobian);
        CHECK(log_jacobian == se3::right_jacobian_inverse(back));
    }
}

}  // namespace test_se3
