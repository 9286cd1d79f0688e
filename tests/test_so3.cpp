// SO(3) as a Lie group (quat/lie/so3.hpp): every analytic Jacobian against central differences of
// the
// same function in long double, taken through the right plus and minus (the convention of the
// header: J = d (f(X exp(d)) (-) f(X)) / d d at d = 0), at fixed-seed random points, the identity,
// zero tangents, 1e-12 rad, around 1/4, both sides of the coefficients' switches (|w| = 2, 3) and
// near half turns (pi - 1e-8); ceres::Jet derivatives of exp, log, plus and minus, finite
// at zero and tiny tangents and equal to the analytic Jacobians; the identities between the
// Jacobians; NaN in, NaN out; Jr and Jr^-1 within a few epsilon of a long double series, and the
// Jacobians of exp and log equal to them bit for bit; a literal nullptr in every Jacobian
// position; the spellings docs/lie-groups.md gives under using namespace quat::so3.
//
// The reference: central differences of the long double function, Richardson-extrapolated twice
// over steps h, h/2, h/4 (error O(h^6)); errors are relative to the largest entry of the reference
// (absolute where it is zero). Where a function is smooth only within delta of the point (log near
// a half turn, where the angle reaches pi and the rotation vector flips), the step must stay below
// delta, and long double's rounding, about 1e-19 / h relative, limits the reference to 2e-9 there
// (steps from 4e-9).
// QUAT_LIE_REPORT=1 in the environment prints the worst error of every Jacobian.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include <ceres/jet.h>
#include <quat/lie/so3.hpp>

#include "support/catch.hpp"
#include "support/jacobian_check.hpp"
#include "support/random.hpp"

namespace test_so3 {

namespace {

using namespace quat;
using ld = long double;

constexpr double pi = 3.14159265358979323846;
constexpr double near_half_turn = pi - 1e-8;

template <class T, int R, int C>
using mat = matrix<T, R, C>;

quat::test::worst_errors worst("so3");

void check(const std::string& name, double error, double tolerance = 1e-12) {
    worst.check(name, error, tolerance);
}
using quat::test::central_differences;
using quat::test::relative_error;

// Conversions between quat's vectors and the arrays of the differences.
std::array<ld, 3> arr(const vec3<ld>& v) { return {v.x, v.y, v.z}; }
vec3<ld> vec(const std::array<ld, 3>& a) { return {a[0], a[1], a[2]}; }
vec3<ld> wide(const vec3<double>& v) { return vec3<ld>(v); }
quaternion<ld> wide(const quatd& q) { return quaternion<ld>(q); }

/// X (+) d and Y (-) X in long double, the reference's plus and minus.
quaternion<ld> oplus(const quaternion<ld>& x, const std::array<ld, 3>& d) {
    return x * from_rotation_vector(vec(d));
}
std::array<ld, 3> ominus(const quaternion<ld>& y, const quaternion<ld>& x) {
    return arr(to_rotation_vector(conjugate(x) * y));
}

quatd turn(const vec3<double>& axis, double angle) { return from_rotation_vector(axis * angle); }

/// The tangents the Jacobians are checked at: zero, tiny, around 1/4, both sides of the switches
/// of the coefficients to their closed forms (2 and 3), large.
std::array<double, 12> angles() {
    return {0.0,       1e-12,     1e-6, 0.2499999, 0.2500001, 0.3,
            1.9999999, 2.0000001, 2.5,  2.9999999, 3.0000001, near_half_turn};
}

/// The step for a point whose tangent has angle a: below the distance to the half turn.
ld step_for(double a) { return a > 3.1 ? 4e-9L : 1e-3L; }
double tolerance_for(double a) { return a > 3.1 ? 2e-9 : 1e-12; }

}  // namespace

TEST_CASE("so3 hat and vee are the cross product and its inverse") {
    test::random_rotations random;
    const vec3<double> a = random.vector<double>(), b = random.vector<double>();
    const vec3<double> c = so3::hat(a) * b, expected = cross(a, b);
    CHECK(c.x == expected.x);
    CHECK(c.y == expected.y);
    CHECK(c.z == expected.z);
    const vec3<double> back = so3::vee(so3::hat(a));
    CHECK((back.x == a.x && back.y == a.y && back.z == a.z));
    CHECK(so3::hat(a) == -transpose(so3::hat(a)));
}

TEST_CASE(
    "so3 exp and log are from_rotation_vector and to_rotation_vector, and invert each other") {
    test::random_rotations random;
    for (int k = 0; k < 50; ++k) {
        const quatd q = random.unit_quaternion<double>();
        const vec3<double> w = so3::log(q), expected = to_rotation_vector(q);
        CHECK((w.x == expected.x && w.y == expected.y && w.z == expected.z));
        CHECK(norm(w) <= pi);
        const vec3<double> negated = so3::log(-q);
        CHECK((negated.x == w.x && negated.y == w.y && negated.z == w.z));
        const quatd back = so3::exp(w), direct = from_rotation_vector(w);
        CHECK(back == direct);
        CHECK(angle_between(back, q) <= 1e-15);
    }
}

TEST_CASE("so3::adjoint holds the numbers of to_matrix, as a matrix3") {
    test::random_rotations random;
    for (int k = 0; k < 100; ++k) {
        const quatd q = random.unit_quaternion<double>();
        CHECK(so3::adjoint(q) == to_matrix3(to_matrix(q)));
    }
}

TEST_CASE(
    "so3 Jacobians satisfy Jr(w) = Jl(-w), Jl = R Jr, Jr^-1 Jr = I and the adjoint identity") {
    test::random_rotations random;
    const auto near = [](const matrix3<double>& a, const matrix3<double>& b, double tolerance) {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                if (!(std::abs(a(i, j) - b(i, j)) <= tolerance)) return false;
        return true;
    };
    for (const double a : angles()) {
        const vec3<double> w = random.unit_vector<double>() * a;
        INFO("angle " << a);
        CHECK(near(so3::right_jacobian(w), so3::left_jacobian(-w), 0));
        CHECK(
            near(so3::left_jacobian(w), so3::adjoint(so3::exp(w)) * so3::right_jacobian(w), 1e-15));
        const auto identity = matrix3<double>::identity();
        CHECK(near(so3::right_jacobian_inverse(w) * so3::right_jacobian(w), identity, 2e-15));
        CHECK(near(so3::left_jacobian_inverse(w) * so3::left_jacobian(w), identity, 2e-15));
        // q exp(v) = exp(Ad(q) v) q
        const quatd q = random.unit_quaternion<double>();
        const vec3<double> v = random.vector<double>();
        CHECK(angle_between(q * so3::exp(v), so3::exp(so3::adjoint(q) * v) * q) <= 2e-15);
    }
}

TEST_CASE("so3 exp's Jacobian equals central differences beyond a half turn") {
    test::random_rotations random;
    for (const double a : {3.5, 5.0, 6.2, 7.0, 10.0, 20.0}) {
        const vec3<double> w = random.unit_vector<double>() * a;
        matrix3<double> d{};
        const quatd e = so3::exp(w, &d);
        check("exp beyond pi", relative_error(d, central_differences<3, 3>(
                                                     [&](const std::array<ld, 3>& x) {
                                                         return ominus(
                                                             from_rotation_vector(wide(w) + vec(x)),
                                                             wide(e));
                                                     },
                                                     1e-3L)));
        check("right_jacobian beyond pi",
              relative_error(so3::right_jacobian(w),
                             central_differences<3, 3>(
                                 [&](const std::array<ld, 3>& x) {
                                     return ominus(from_rotation_vector(wide(w) + vec(x)), wide(e));
                                 },
                                 1e-3L)));
    }
}

TEST_CASE("so3 Jacobians equal central differences through the right plus and minus") {
    test::random_rotations random;
    for (int sample = 0; sample < 4; ++sample) {
        for (const double a : angles()) {
            const vec3<double> w = random.unit_vector<double>() * a;
            const quatd drawn = random.unit_quaternion<double>();
            const quatd x = sample == 0 ? quatd::identity() : drawn;    // the identity first
            const quatd y = x * turn(random.unit_vector<double>(), a);  // y (-) x has angle a
            const vec3<double> v = random.vector<double>();
            const ld h = step_for(a);
            const double tolerance = tolerance_for(a);
            INFO("angle " << a << ", sample " << sample);
            const std::string at = a > 3.1 ? " at pi - 1e-8" : "";
            matrix3<double> d1{}, d2{};

            // exp: vector in, group out.
            const quatd e = so3::exp(w, &d1);
            check(std::string("exp") + at,
                  relative_error(d1, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return ominus(from_rotation_vector(wide(w) + vec(d)),
                                                           wide(e));
                                         },
                                         1e-3L)));
            // log: group in, vector out (at the tangent w, below the half turn; exp is smooth
            // everywhere, so only log needs the short step).
            const double wa = norm(w);
            if (wa < pi) {
                const quatd q = from_rotation_vector(w);
                const vec3<double> l = so3::log(q, &d1);
                check(std::string("log") + at,
                      relative_error(d1, central_differences<3, 3>(
                                             [&](const std::array<ld, 3>& d) {
                                                 return arr(to_rotation_vector(oplus(wide(q), d)) -
                                                            wide(l));
                                             },
                                             step_for(wa))),
                      tolerance_for(wa));
            }
            // right and left Jacobians and their inverses as derivatives of exp and log:
            // Jl(w) = d log(exp(w + d) exp(w)^-1) / d d.
            check(
                std::string("left_jacobian") + at,
                relative_error(so3::left_jacobian(w),
                               central_differences<3, 3>(
                                   [&](const std::array<ld, 3>& d) {
                                       const auto ew = from_rotation_vector(wide(w));
                                       return arr(to_rotation_vector(
                                           from_rotation_vector(wide(w) + vec(d)) * conjugate(ew)));
                                   },
                                   1e-3L)));

            // compose
            const quatd c = so3::compose(x, y, &d1, &d2);
            check(std::string("compose d_a") + at,
                  relative_error(d1, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return ominus(oplus(wide(x), d) * wide(y), wide(c));
                                         },
                                         1e-3L)));
            check(std::string("compose d_b") + at,
                  relative_error(d2, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return ominus(wide(x) * oplus(wide(y), d), wide(c));
                                         },
                                         1e-3L)));
            // inverse
            const quatd i = so3::inverse(x, &d1);
            check(std::string("inverse") + at,
                  relative_error(d1, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return ominus(conjugate(oplus(wide(x), d)), wide(i));
                                         },
                                         1e-3L)));
            // act
            const vec3<double> moved = so3::act(x, v, &d1, &d2);
            check(std::string("act d_q") + at,
                  relative_error(d1, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return arr(rotate(oplus(wide(x), d), wide(v)) -
                                                        wide(moved));
                                         },
                                         1e-3L)));
            check(std::string("act d_v") + at,
                  relative_error(d2, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return arr(rotate(wide(x), wide(v) + vec(d)) -
                                                        wide(moved));
                                         },
                                         1e-3L)));
            // between
            const quatd b = so3::between(x, y, &d1, &d2);
            check(std::string("between d_x") + at,
                  relative_error(d1, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return ominus(conjugate(oplus(wide(x), d)) * wide(y),
                                                           wide(b));
                                         },
                                         1e-3L)));
            check(std::string("between d_y") + at,
                  relative_error(d2, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return ominus(conjugate(wide(x)) * oplus(wide(y), d),
                                                           wide(b));
                                         },
                                         1e-3L)));
            // plus
            const quatd p = so3::plus(x, w, &d1, &d2);
            check(std::string("plus d_x") + at,
                  relative_error(d1, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return ominus(oplus(oplus(wide(x), d), arr(wide(w))),
                                                           wide(p));
                                         },
                                         1e-3L)));
            check(std::string("plus d_w") + at,
                  relative_error(d2, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return ominus(oplus(wide(x), arr(wide(w) + vec(d))),
                                                           wide(p));
                                         },
                                         1e-3L)));
            // minus: y (-) x has angle a
            const vec3<double> m = so3::minus(y, x, &d1, &d2);
            check(std::string("minus d_y") + at,
                  relative_error(d1, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return arr(vec(ominus(oplus(wide(y), d), wide(x))) -
                                                        wide(m));
                                         },
                                         h)),
                  tolerance);
            check(std::string("minus d_x") + at,
                  relative_error(d2, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return arr(vec(ominus(wide(y), oplus(wide(x), d))) -
                                                        wide(m));
                                         },
                                         h)),
                  tolerance);
            // plus_left
            const quatd pl = so3::plus_left(x, w, &d2, &d1);
            check(std::string("plus_left d_w") + at,
                  relative_error(d1, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return ominus(
                                                 from_rotation_vector(wide(w) + vec(d)) * wide(x),
                                                 wide(pl));
                                         },
                                         1e-3L)));
            check(std::string("plus_left d_x") + at,
                  relative_error(d2, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return ominus(
                                                 from_rotation_vector(wide(w)) * oplus(wide(x), d),
                                                 wide(pl));
                                         },
                                         1e-3L)));
            // minus_left: y x^-1 has an angle a too, for y = exp(w) x
            const quatd yl = so3::exp(w) * x;
            const vec3<double> ml = so3::minus_left(yl, x, &d1, &d2);
            check(std::string("minus_left d_y") + at,
                  relative_error(d1, central_differences<3, 3>(
                                         [&](const std::array<ld, 3>& d) {
                                             return arr(to_rotation_vector(oplus(wide(yl), d) *
                                                                           conjugate(wide(x))) -
                                                        wide(ml));
                                         },
                                         step_for(wa))),
                  tolerance_for(wa));
            check(
                std::string("minus_left d_x") + at,
                relative_error(d2, central_differences<3, 3>(
                                       [&](const std::array<ld, 3>& d) {
                                           return arr(to_rotation_vector(
                                                          wide(yl) * conjugate(oplus(wide(x), d))) -
                                                      wide(ml));
                                       },
                                       step_for(wa))),
                tolerance_for(wa));
        }
    }
}

namespace {

using jet = ceres::Jet<double, 3>;

/// d as three Jet variables at 0.
vec3<jet> jet_variables(const vec3<double>& at) {
    return {jet(at.x, 0), jet(at.y, 1), jet(at.z, 2)};
}
/// The derivatives of a vector of Jets, as a 3x3 matrix.
matrix3<double> partials(const vec3<jet>& v) {
    matrix3<double> m{};
    for (int i = 0; i < 3; ++i) {
        m(0, i) = v.x.v[i];
        m(1, i) = v.y.v[i];
        m(2, i) = v.z.v[i];
    }
    return m;
}
/// The tangent derivatives of a quaternion of Jets q(d): 2 vec(q(0)^-1 dq/dd), the inverse of the
/// 4x3 plus-Jacobian q(0) (0, d/2) of the unit sphere.
matrix3<double> tangent_partials(const quaternion<jet>& q) {
    const quaternion<jet> at{jet(q.w.a), jet(q.x.a), jet(q.y.a), jet(q.z.a)};
    const quaternion<jet> local = conjugate(at) * q;
    return partials(vec3<jet>{local.x, local.y, local.z}) * 2.0;
}
/// x (1, d/2) for Jet d at 0: the first-order right plus, whose derivative is the plus-Jacobian.
quaternion<jet> jet_plus(const quatd& x, const vec3<jet>& d) {
    return quaternion<jet>(x) * quaternion<jet>{jet(1), d.x * 0.5, d.y * 0.5, d.z * 0.5};
}
double max_difference(const matrix3<double>& a, const matrix3<double>& b) {
    double error = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            if (!std::isfinite(a(i, j))) return std::numeric_limits<double>::infinity();
            error = std::max(error, std::abs(a(i, j) - b(i, j)));
        }
    return error;
}

}  // namespace

TEST_CASE(
    "so3 ceres::Jet derivatives of exp, log, plus and minus are finite and equal the "
    "analytic Jacobians, also at zero and tiny tangents") {
    test::random_rotations random;
    for (const double a : {0.0, 1e-300, 1e-12, 1e-6, 1e-4, 0.5, 2.0, 3.0, near_half_turn}) {
        const vec3<double> w = random.unit_vector<double>() * a;
        const quatd x = random.unit_quaternion<double>();
        INFO("angle " << a);
        matrix3<double> d1{}, d2{};
        const vec3<jet> zero = jet_variables({0, 0, 0});

        (void)so3::exp(w, &d1);
        check("jet exp", max_difference(tangent_partials(so3::exp(jet_variables(w))), d1), 2e-15);

        const quatd q = so3::exp(w);
        (void)so3::log(q, &d1);
        check("jet log", max_difference(partials(so3::log(jet_plus(q, zero))), d1), 4e-15);

        (void)so3::plus(x, w, &d1, &d2);
        check("jet plus d_x",
              max_difference(tangent_partials(so3::plus(jet_plus(x, zero), vec3<jet>(w))), d1),
              2e-15);
        check("jet plus d_w",
              max_difference(tangent_partials(so3::plus(quaternion<jet>(x), jet_variables(w))), d2),
              2e-15);

        const quatd y = x * q;
        (void)so3::minus(y, x, &d1, &d2);
        check("jet minus d_y",
              max_difference(partials(so3::minus(jet_plus(y, zero), quaternion<jet>(x))), d1),
              4e-15);
        check("jet minus d_x",
              max_difference(partials(so3::minus(quaternion<jet>(y), jet_plus(x, zero))), d2),
              4e-15);

        // The Jacobians themselves with Jet: finite derivatives at w = 0 (the coefficients'
        // series), d Jr(w) v / dw = hat(v) / 2 there.
        const vec3<double> v = random.vector<double>();
        const vec3<jet> jr_v = so3::right_jacobian(jet_variables(w)) * vec3<jet>(v);
        const matrix3<double> rate = partials(jr_v);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) CHECK(std::isfinite(rate(i, j)));
        const vec3<jet> spline_v = detail::right_jacobian(jet_variables(w), vec3<jet>(v));
        CHECK(max_difference(partials(spline_v), rate) <= 1e-15);
        if (a == 0.0) CHECK(max_difference(rate, so3::hat(v) * 0.5) == 0);
        const matrix3<jet> inverse = so3::right_jacobian_inverse(jet_variables(w));
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k) CHECK(std::isfinite(inverse(i, j).v[k]));
    }
}

TEMPLATE_TEST_CASE("so3 instantiates for float, double and long double", "", float, double,
                   long double) {
    using T = TestType;
    const vec3<T> w{T(0.1), T(-0.2), T(0.3)};
    matrix3<T> d1{}, d2{};
    const quaternion<T> q = so3::exp(w, &d1);
    const vec3<T> back = so3::log(q, &d2);
    CHECK(std::abs(back.x - w.x) <= 4 * std::numeric_limits<T>::epsilon());
    const matrix3<T> product = d1 * d2;  // Jr(w) Jr(log exp w)^-1 = I
    CHECK(std::abs(product(0, 0) - T(1)) <= 8 * std::numeric_limits<T>::epsilon());
    CHECK(std::abs(product(1, 2)) <= 8 * std::numeric_limits<T>::epsilon());
    (void)so3::compose(q, q, &d1, &d2);
    (void)so3::inverse(q, &d1);
    (void)so3::act(q, w, &d1, &d2);
    (void)so3::between(q, q, &d1, &d2);
    (void)so3::plus(q, w, &d1, &d2);
    (void)so3::minus(q, q, &d1, &d2);
    (void)so3::plus_left(q, w, &d2, &d1);
    (void)so3::minus_left(q, q, &d1, &d2);
    (void)so3::left_jacobian(w);
    (void)so3::left_jacobian_inverse(w);
    constexpr matrix3<double> h = so3::hat(vec3<double>{1, 2, 3});
    static_assert(h(2, 1) == 1 && h(0, 2) == 2 && h(1, 0) == 3);
    constexpr matrix3<double> jr = so3::right_jacobian(vec3<double>{0, 0, 0});
    static_assert(jr(0, 0) == 1 && jr(0, 1) == 0);
}

TEST_CASE("so3 gives NaN for NaN input, in the value and the Jacobians") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const vec3<double> w{nan, 0, 0};
    const quatd q{nan, 0, 0, 0};
    matrix3<double> d1{}, d2{};
    CHECK(std::isnan(so3::exp(w, &d1).w));
    CHECK(std::isnan(d1(1, 1)));
    CHECK(std::isnan(so3::log(q, &d1).x));
    CHECK(std::isnan(d1(0, 0)));
    CHECK(std::isnan(so3::minus(q, quatd::identity(), &d1, &d2).x));
    CHECK(std::isnan(d2(0, 0)));
    CHECK(std::isnan(so3::plus(quatd::identity(), w, &d1, &d2).w));
    CHECK(std::isnan(d2(2, 2)));
    CHECK(std::isnan(so3::right_jacobian_inverse(w)(1, 1)));
}

TEST_CASE(
    "so3 the Jacobians' coefficients differentiate in n^2 with ceres::Jet, also at zero and "
    "across their switches to series") {
    using j1 = ceres::Jet<double, 1>;
    // Each coefficient as a function of n2 and n = sqrt(n2), for Jet and for long double.
    const auto each = [](auto n2, auto n) {
        return std::array<decltype(n2), 6>{detail::one_minus_cos_over_square(n2, n),
                                           detail::n_minus_sin_over_cube(n2, n),
                                           detail::quartic_coefficient(n2, n),
                                           detail::quintic_coefficient(n2, n),
                                           detail::cosine_remainder_coefficient(n2, n),
                                           detail::inverse_jacobian_coefficient(n2, n)};
    };
    const char* names[6] = {"one_minus_cos_over_square",    "n_minus_sin_over_cube",
                            "quartic_coefficient",          "quintic_coefficient",
                            "cosine_remainder_coefficient", "inverse_jacobian_coefficient"};
    for (const double n : {0.0, 1e-12, 1e-6, 1e-3, 0.5, 1.9999999, 2.0000001, 2.9999999, 3.0000001,
                           near_half_turn}) {
        const double n2 = n * n;
        const j1 x(n2, 0);
        const auto got = each(x, sqrt(x));
        // d/d(n2): to n = 1e-3 the series' c_1 + 2 c_2 n^2 (the next term is 1e-12 times
        // smaller), elsewhere central differences in long double with steps n^2 / 4 at most, on
        // which both sides of the switches are accurate.
        const std::array<ld, 6> c1{-1.0L / 24,  -1.0L / 120, -1.0L / 180,
                                   1.0L / 1260, -1.0L / 720, 1.0L / 720};
        const std::array<ld, 6> c2{1.0L / 720,    1.0L / 5040,  1.0L / 6720,
                                   -1.0L / 60480, 1.0L / 40320, 1.0L / 30240};
        const ld h = std::min<ld>(static_cast<ld>(n2) / 4, 0.05L);
        std::array<std::array<ld, 3>, 6> estimate{};
        for (int k = 0; k < 3 && n > 1e-3; ++k) {
            const ld step = h / static_cast<ld>(1 << k);
            const ld up2 = static_cast<ld>(n2) + step, down2 = static_cast<ld>(n2) - step;
            const auto up = each(up2, std::sqrt(up2)), down = each(down2, std::sqrt(down2));
            for (std::size_t c = 0; c < 6; ++c)
                estimate[c][static_cast<std::size_t>(k)] = (up[c] - down[c]) / (2 * step);
        }
        for (std::size_t c = 0; c < 6; ++c) {
            const auto& e = estimate[c];
            const ld first = (4 * e[1] - e[0]) / 3, second = (4 * e[2] - e[1]) / 3;
            const ld derivative =
                n <= 1e-3 ? c1[c] + 2 * c2[c] * static_cast<ld>(n2) : (16 * second - first) / 15;
            const ld value = static_cast<ld>(got[c].a);
            INFO(names[c] << " at n = " << n);
            CHECK(std::isfinite(got[c].v[0]));
            CHECK(std::abs(static_cast<ld>(got[c].v[0]) - derivative) <=
                  1e-11L * std::abs(derivative));
            CHECK(std::abs(value - each(static_cast<ld>(n2), static_cast<ld>(n))[c]) <=
                  1e-15L * std::abs(value));
        }
    }
}

TEST_CASE("so3 a literal nullptr skips any Jacobian of every so3 function") {
    // The Jacobian pointers are not deduced, so nullptr (std::nullptr_t) converts like any
    // pointer; the value and the other Jacobian are those of the call that asks for both.
    test::random_rotations random;
    const quatd x = random.unit_quaternion<double>(), y = random.unit_quaternion<double>();
    const vec3<double> w = random.vector<double>(), v = random.vector<double>();
    matrix3<double> full1{}, full2{}, one{};

    const quatd e = so3::exp(w, &full1);
    CHECK(so3::exp(w, nullptr) == e);
    const vec3<double> l = so3::log(x, &full1);
    CHECK(so3::log(x, nullptr) == l);
    const quatd i = so3::inverse(x, &full1);
    CHECK(so3::inverse(x, nullptr) == i);

    const quatd c = so3::compose(x, y, &full1, &full2);
    CHECK(so3::compose(x, y, nullptr, nullptr) == c);
    CHECK((so3::compose(x, y, &one, nullptr) == c && one == full1));
    CHECK((so3::compose(x, y, nullptr, &one) == c && one == full2));

    const vec3<double> moved = so3::act(x, v, &full1, &full2);
    CHECK(so3::act(x, v, nullptr, nullptr) == moved);
    CHECK((so3::act(x, v, &one, nullptr) == moved && one == full1));
    CHECK((so3::act(x, v, nullptr, &one) == moved && one == full2));

    const quatd b = so3::between(x, y, &full1, &full2);
    CHECK(so3::between(x, y, nullptr, nullptr) == b);
    CHECK((so3::between(x, y, &one, nullptr) == b && one == full1));
    CHECK((so3::between(x, y, nullptr, &one) == b && one == full2));

    const quatd p = so3::plus(x, w, &full1, &full2);
    CHECK(so3::plus(x, w, nullptr, nullptr) == p);
    CHECK((so3::plus(x, w, &one, nullptr) == p && one == full1));
    CHECK((so3::plus(x, w, nullptr, &one) == p && one == full2));

    const vec3<double> m = so3::minus(y, x, &full1, &full2);
    CHECK(so3::minus(y, x, nullptr, nullptr) == m);
    CHECK((so3::minus(y, x, &one, nullptr) == m && one == full1));
    CHECK((so3::minus(y, x, nullptr, &one) == m && one == full2));

    const quatd pl = so3::plus_left(x, w, &full1, &full2);
    CHECK(so3::plus_left(x, w, nullptr, nullptr) == pl);
    CHECK((so3::plus_left(x, w, &one, nullptr) == pl && one == full1));
    CHECK((so3::plus_left(x, w, nullptr, &one) == pl && one == full2));

    const vec3<double> ml = so3::minus_left(y, x, &full1, &full2);
    CHECK(so3::minus_left(y, x, nullptr, nullptr) == ml);
    CHECK((so3::minus_left(y, x, &one, nullptr) == ml && one == full1));
    CHECK((so3::minus_left(y, x, nullptr, &one) == ml && one == full2));
}

namespace {

/// Jr(w) = I - a [w]x + b [w]x^2 in long double, with a = (1 - cos n)/n^2 and b = (n - sin n)/n^3
/// summed from their Taylor series, a = sum (-1)^k n^2k / (2k+2)!, b = sum (-1)^k n^2k / (2k+3)!:
/// written apart from the library's coefficients. For n <= pi the terms cancel by less than 3
/// times, so the sums keep about 62 of long double's 64 bits, 2^-9 of double's epsilon.
matrix3<ld> series_right_jacobian(const vec3<ld>& w) {
    const ld n2 = squared_norm(w);
    ld a = 0, b = 0, term = 0.5L;  // term = (-1)^k n^2k / (2k+2)!
    for (int k = 0; k < 40; ++k) {
        a += term;
        b += term / (2 * k + 3);
        term *= -n2 / ((2 * k + 3) * (2 * k + 4));
    }
    const matrix3<ld> hat{{{0, -w.z, w.y}, {w.z, 0, -w.x}, {-w.y, w.x, 0}}};
    return matrix3<ld>::identity() - a * hat + b * (hat * hat);
}

/// The inverse of a 3x3 matrix by its cofactors, in long double.
matrix3<ld> inverse_by_cofactors(const matrix3<ld>& m) {
    matrix3<ld> c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c(j, i) = m(i1, j1) * m(i2, j2) - m(i1, j2) * m(i2, j1);  // transposed: the adjugate
        }
    const ld determinant = m(0, 0) * c(0, 0) + m(0, 1) * c(1, 0) + m(0, 2) * c(2, 0);
    return c * (1 / determinant);
}

/// Bounds on the worst error of so3's Jr and Jr^-1 in units of T's epsilon, relative to the
/// largest entry (relative_error's measure), over [0, pi) with random axes. Measured (g++ 12 and
/// clang 14, x86-64): Jr 2.34 (double) and 2.31 (float), Jr^-1 1.62 and 1.55.
template <class T>
struct jacobian_accuracy {
    static constexpr double right = 2.5, inverse = 2.0;
};

}  // namespace

TEMPLATE_TEST_CASE(
    "so3 the Jacobians of exp, log, plus and minus are within a few epsilon of a long double "
    "series, as right_jacobian and right_jacobian_inverse are",
    "", float, double) {
    using T = TestType;
    const double eps = std::numeric_limits<T>::epsilon();
    test::random_rotations random;
    double worst_right = 0, worst_exp = 0, worst_inverse = 0, worst_log = 0;
    for (int k = 0; k < 4000; ++k) {
        // Uniform angles in [0, pi), and a tenth of them within 0.1 of the half turn.
        const double angle =
            k % 10 == 0 ? random.uniform<double>(pi - 0.1, pi) : random.uniform<double>(0, pi);
        const vec3<T> w = random.unit_vector<T>() * T(angle);
        INFO("w = " << w.x << ", " << w.y << ", " << w.z);
        matrix3<T> exp_jacobian{}, d_w{}, log_jacobian{}, d_y{};
        const quaternion<T> q = so3::exp(w, &exp_jacobian);
        (void)so3::plus(quaternion<T>::identity(), w, nullptr, &d_w);
        const matrix3<T> right = so3::right_jacobian(w);
        // exp shares its half angle's sincos with right_jacobian's coefficients: the same bits.
        CHECK(exp_jacobian == right);
        CHECK(d_w == right);
        const vec3<T> l = so3::log(q, &log_jacobian);
        (void)so3::minus(q, quaternion<T>::identity(), &d_y, nullptr);
        const matrix3<T> inverse = so3::right_jacobian_inverse(l);
        CHECK(log_jacobian == inverse);
        CHECK(d_y == inverse);

        const matrix3<ld> reference = series_right_jacobian(vec3<ld>(w));
        const matrix3<ld> inverse_reference =
            inverse_by_cofactors(series_right_jacobian(vec3<ld>(l)));
        worst_right = std::max(worst_right, relative_error(right, reference) / eps);
        worst_exp = std::max(worst_exp, relative_error(exp_jacobian, reference) / eps);
        worst_inverse = std::max(worst_inverse, relative_error(inverse, inverse_reference) / eps);
        worst_log = std::max(worst_log, relative_error(log_jacobian, inverse_reference) / eps);
    }
    const std::string type = std::is_same_v<T, float> ? " (float, eps)" : " (double, eps)";
    check("right_jacobian" + type, worst_right, jacobian_accuracy<T>::right);
    check("exp Jacobian" + type, worst_exp, jacobian_accuracy<T>::right);
    check("right_jacobian_inverse" + type, worst_inverse, jacobian_accuracy<T>::inverse);
    check("log Jacobian" + type, worst_log, jacobian_accuracy<T>::inverse);
}

// docs/lie-groups.md: code that imports so3 with a using-directive calls the one-argument log and
// inverse qualified, so3::log(q) and so3::inverse(q), since log(q) and inverse(q) also name quat's
// quaternion logarithm and inverse (found by argument-dependent lookup), which differ from so3's;
// every other so3 function, and log and inverse with a Jacobian, read the same unqualified.
namespace imported_so3 {
using namespace quat::so3;

template <class Q, class = void>
struct unqualified_log_compiles : std::false_type {};
template <class Q>
struct unqualified_log_compiles<Q, std::void_t<decltype(log(std::declval<const Q&>()))>>
    : std::true_type {};
template <class Q, class = void>
struct unqualified_inverse_compiles : std::false_type {};
template <class Q>
struct unqualified_inverse_compiles<Q, std::void_t<decltype(inverse(std::declval<const Q&>()))>>
    : std::true_type {};
static_assert(!unqualified_log_compiles<quatd>::value, "log(q): quat::log or so3::log?");
static_assert(!unqualified_inverse_compiles<quatd>::value, "inverse(q): quat:: or so3::?");

/// Every so3 function in the spelling the documentation gives under the using-directive.
vec3<double> spelled_as_documented(const quatd& x, const quatd& y, const vec3<double>& w) {
    namespace so3 = quat::so3;
    matrix3<double> j{};
    const vec3<double> l = so3::log(x) + log(x, &j);
    const quatd i = so3::inverse(x) * inverse(x, &j);
    const quatd e =
        exp(w) * exp(w, &j) * compose(x, y) * between(x, y) * plus(x, w) * plus_left(x, w);
    const vec3<double> m = minus(y, x) + minus_left(y, x) + act(x, w);
    const matrix3<double> jacobians = hat(w) * adjoint(x) * right_jacobian(w) * left_jacobian(w) *
                                      right_jacobian_inverse(w) * left_jacobian_inverse(w);
    return l + m + vee(jacobians) + vec3<double>{i.x, e.y, e.z};
}

}  // namespace imported_so3

TEST_CASE("so3 under using namespace quat::so3: so3::log(q) and so3::inverse(q), the rest as is") {
    test::random_rotations random;
    const quatd x = random.unit_quaternion<double>(), y = random.unit_quaternion<double>();
    const vec3<double> w = random.vector<double>();
    CHECK(std::isfinite(imported_so3::spelled_as_documented(x, y, w).x));
    // The two logarithms the qualification tells apart: a rotation vector, and the quaternion
    // logarithm, (0, angle/2 axis) for a unit quaternion with w >= 0.
    const quatd positive = x.w < 0 ? -x : x;
    const vec3<double> rotation_vector = quat::so3::log(positive);
    const quatd quaternion_log = quat::log(positive);
    CHECK(std::abs(rotation_vector.x - 2 * quaternion_log.x) <= 1e-15);
}

}  // namespace test_so3
