// Specification of paths/interpolation.hpp: slerp, nlerp, pow and rotate_towards.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>
#include <quat/conversions.hpp>
#include <quat/interop/glm.hpp>
#include <quat/paths/interpolation.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_interpolation {

using quat::from_glm;
using quat::quaternion;
using quat::to_glm;
using quat::vec3;
using quat::test::tolerance;

static_assert(quat::pow(quat::quatd{0, 0, 0, 1}, 0) == quat::quatd::identity());
static_assert(quat::pow(quat::quatd{-0.6, 0, 0, 0.8}, 1) == quat::quatd{0.6, 0, 0, -0.8}, "w >= 0");
constexpr double half_of_half_turn = quat::pow(quat::quatd{0, 0, 0, 1}, 0.5).z;  // sin(pi / 4)
static_assert(half_of_half_turn > 0.70710678118654752 - 1e-15 &&
              half_of_half_turn < 0.70710678118654752 + 1e-15);
static_assert(quat::rotate_towards(quat::quatd::identity(), quat::rotation_z(1.0), 2) ==
              quat::rotation_z(1.0));
static_assert(quat::rotate_towards(quat::quatd::identity(), quat::rotation_z(1.0), -1) ==
              quat::quatd::identity());

namespace {

// Independent reference in long double: rotate a by t times the relative rotation along the
// shorter arc, q(t) = a exp(t log(a* b)), from the axis-angle form of a* b.
template <class T>
quaternion<long double> reference_slerp(const quaternion<T>& a, const quaternion<T>& b,
                                        long double t) {
    const quaternion<long double> al{a.w, a.x, a.y, a.z}, bl{b.w, b.x, b.y, b.z};
    quaternion<long double> relative = quat::conjugate(al) * bl;
    if (relative.w < 0) relative = -relative;
    const long double s =
        std::sqrt(relative.x * relative.x + relative.y * relative.y + relative.z * relative.z);
    const long double half = std::atan2(s, relative.w);
    if (s == 0) return al;
    const long double k = std::sin(t * half) / s;
    return al * quaternion<long double>{std::cos(t * half), relative.x * k, relative.y * k,
                                        relative.z * k};
}

// Twice the rotation angle between q and r: angle_between already returns the rotation angle
// (itself twice the 4D angle between the quaternions), so the factor 2 makes each bound below
// (tolerance<T>::slerp_angle) a bound of half that size on the rotation angle: stricter, not
// looser.
template <class T>
long double distance(const quaternion<T>& q, const quaternion<long double>& r) {
    const quaternion<long double> ql{q.w, q.x, q.y, q.z};
    return 2 * quat::angle_between(ql, r);
}

}  // namespace

TEMPLATE_TEST_CASE("slerp is exact at the ends and takes the shorter arc", "[interpolation]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const auto a = random.unit_quaternion<T>(), b = random.unit_quaternion<T>();
        CHECK(quat::slerp(a, b, T(0)) == a);
        const quaternion<T> end = quat::slerp(a, b, T(1));
        CHECK((end == b || end == -b));
        CHECK(quat::dot(a, end) >= 0);
    }
}

TEMPLATE_TEST_CASE("slerp moves at constant angular velocity and stays unit", "[interpolation]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const auto a = random.unit_quaternion<T>(), b = random.unit_quaternion<T>();
        const T total = quat::angle_between(a, b);
        for (const T t : {T(-0.5), T(0.1), T(0.25), T(0.5), T(0.9), T(1.5)}) {
            const quaternion<T> q = quat::slerp(a, b, t);
            CHECK(std::abs(quat::norm(q) - 1) <= tolerance<T>::unit_norm);
            if (t >= 0 && t <= 1) {
                CHECK(std::abs(quat::angle_between(a, q) - t * total) <= tolerance<T>::slerp_angle);
            }
            CHECK(distance(q, reference_slerp(a, b, t)) <= tolerance<T>::slerp_angle);
        }
    }
}

TEMPLATE_TEST_CASE("slerp is stable for nearly equal and nearly opposite rotations",
                   "[interpolation]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int k = 1; k <= 30; ++k) {
        const auto a = random.unit_quaternion<T>();
        const auto axis = random.unit_vector<T>();
        const T small = T(std::pow(10.0, -k / 2.0));
        const quaternion<T> turn{std::cos(small / 2), axis.x * std::sin(small / 2),
                                 axis.y * std::sin(small / 2), axis.z * std::sin(small / 2)};
        const quaternion<T> near = a * turn;
        for (const quaternion<T>& b : {near, -near, a, -a}) {
            const quaternion<T> q = quat::slerp(a, b, T(0.3));
            CAPTURE(k);
            CHECK(std::isfinite(q.w));
            CHECK(std::abs(quat::norm(q) - 1) <= tolerance<T>::unit_norm);
            CHECK(distance(q, reference_slerp(a, b, 0.3L)) <= tolerance<T>::slerp_angle);
        }
    }
}

TEMPLATE_TEST_CASE("nlerp follows the slerp path, normalized", "[interpolation]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const auto a = random.unit_quaternion<T>(), b = random.unit_quaternion<T>();
        const quaternion<T> q = quat::nlerp(a, b, T(0.5));
        CHECK(std::abs(quat::norm(q) - 1) <= tolerance<T>::unit_norm);
        // At t = 1/2 both interpolations give the arc's midpoint.
        CHECK(quat::angle_between(q, quat::slerp(a, b, T(0.5))) <= tolerance<T>::slerp_angle);
        CHECK(quat::angle_between(quat::nlerp(a, b, T(0)), a) <= tolerance<T>::slerp_angle);
    }
}

// ---- pow ----------------------------------------------------------------------------------------
//
// How GLM's pow maps to quat's: glm::pow(q, t) (glm/ext/quaternion_exponential.hpp) takes the angle
// of q as given, without choosing the sign with w >= 0, so for w < 0 it is not the principal power;
// and for |v|^2 < epsilon it returns (w^t, 0, 0, 0), dropping turns below sqrt(epsilon) rad.
// Where w >= 0 and |v|^2 >= epsilon the two agree.

namespace {

// Independent reference in long double: (cos(t h), sin(t h) axis), h = atan2(|v|, w) for the sign
// of q with w >= 0 (principal) or as given (the longer arc when w < 0, as GLM does).
template <class T>
quaternion<long double> reference_pow(const quaternion<T>& q, long double t,
                                      bool principal = true) {
    quaternion<long double> p{q.w, q.x, q.y, q.z};
    if (principal && p.w < 0) p = -p;
    const long double s = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    if (s == 0) return quaternion<long double>::identity();
    const long double half = t * std::atan2(s, p.w), k = std::sin(half) / s;
    return {std::cos(half), p.x * k, p.y * k, p.z * k};
}

}  // namespace

TEMPLATE_TEST_CASE("pow turns by t times the shorter angle and equals slerp from the identity",
                   "[interpolation][pow]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const quaternion<T> q = random.unit_quaternion<T>();
        for (const T t : {T(-2), T(-0.5), T(0.1), T(0.5), T(0.9), T(1.5), T(3)}) {
            const quaternion<T> r = quat::pow(q, t);
            CAPTURE(n, t);
            CHECK(std::abs(quat::norm(r) - 1) <= tolerance<T>::unit_norm);
            // The half angle's rounding is multiplied by t.
            CHECK(distance(r, reference_pow(q, t)) <=
                  tolerance<T>::slerp_angle * std::max(T(1), std::abs(t)));
            CHECK(quat::pow(-q, t) == r);
            if (t >= 0 && t <= 1) {
                CHECK(quat::angle_between(r, quat::slerp(quaternion<T>::identity(), q, t)) <=
                      tolerance<T>::slerp_angle);
            }
        }
        CHECK(quat::pow(q, T(0)) == quaternion<T>::identity());
        CHECK(quat::pow(q, T(1)) == (q.w < 0 ? -q : q));
        // pow(q, 2) is q q as a rotation.
        CHECK(quat::angle_between(quat::pow(q, T(2)), q * q) <= tolerance<T>::slerp_angle);
    }
}

TEMPLATE_TEST_CASE("pow is accurate near the identity and near a half turn", "[interpolation][pow]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    // Relative error of the result's vector part (the sine of the new half angle) against the
    // reference. Measured worst 0.89 eps (double) and 1.11 eps (float) from 1e-1 to 1e-30 rad;
    // bound 4.
    for (int decade = 1; decade <= 30; ++decade) {
        const vec3<T> axis = random.unit_vector<T>();
        const T angle = T(std::pow(10.0, -decade));
        const vec3<T> v = axis * std::sin(angle / 2);
        const quaternion<T> q{std::cos(angle / 2), v.x, v.y, v.z};
        const quaternion<T> r = quat::pow(q, T(0.3));
        const quaternion<long double> reference = reference_pow(q, 0.3L);
        const long double s = std::sqrt(reference.x * reference.x + reference.y * reference.y +
                                        reference.z * reference.z);
        const long double error = std::sqrt((r.x - reference.x) * (r.x - reference.x) +
                                            (r.y - reference.y) * (r.y - reference.y) +
                                            (r.z - reference.z) * (r.z - reference.z)) /
                                  s;
        CAPTURE(decade, angle);
        CHECK(error <= 4 * quat::test::eps<T>);
    }
    // Half turns and near-half turns: w = 0 or tiny, either sign.
    for (const T w : {T(0), T(1e-7), T(-1e-7), T(1e-30), T(-0.0)}) {
        const vec3<T> axis = random.unit_vector<T>();
        const T s = std::sqrt(1 - w * w);
        const quaternion<T> q{w, axis.x * s, axis.y * s, axis.z * s};
        CAPTURE(w);
        CHECK(distance(quat::pow(q, T(0.5)), reference_pow(q, 0.5L)) <= tolerance<T>::slerp_angle);
        CHECK(std::abs(quat::to_axis_angle(quat::pow(q, T(0.5))).angle -
                       quat::to_axis_angle(q).angle / 2) <= tolerance<T>::slerp_angle);
    }
}

TEMPLATE_TEST_CASE("pow of bad input is not finite", "[interpolation][pow]", float, double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    const quaternion<T> q = quat::normalize(quaternion<T>{1, 2, 3, 4});
    const auto finite = [](const quaternion<T>& r) {
        return std::isfinite(r.w) && std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.z);
    };
    CHECK_FALSE(finite(quat::pow(q, nan)));
    CHECK_FALSE(finite(quat::pow(q, inf)));
    CHECK_FALSE(finite(quat::pow(quaternion<T>::identity(), nan)));
    CHECK_FALSE(finite(quat::pow(quaternion<T>::identity(), inf)));
    CHECK_FALSE(finite(quat::pow(quaternion<T>{nan, 0, 0, 0}, T(0.5))));
    CHECK_FALSE(finite(quat::pow(quaternion<T>{nan, 0, 0, 0}, T(0))));
    CHECK_FALSE(finite(quat::pow(quaternion<T>{0, nan, 0, 0}, T(0.5))));
    CHECK(quat::pow(quaternion<T>::identity(), T(7)) == quaternion<T>::identity());
}

TEMPLATE_TEST_CASE("pow agrees with glm::pow for w >= 0 and not for w < 0", "[interpolation][pow]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        quaternion<T> q = random.unit_quaternion<T>();
        if (q.w < 0) q = -q;
        if (q.x * q.x + q.y * q.y + q.z * q.z < 16 * quat::test::eps<T>) continue;
        for (const T t : {T(0.25), T(0.5), T(2)}) {
            const quaternion<T> ours = quat::pow(q, t), theirs = from_glm(glm::pow(to_glm(q), t));
            CHECK(quat::test::max_difference(ours, theirs) <= tolerance<T>::glm);
            // With w < 0 GLM keeps the longer arc: its square root of -q is the other one,
            // half a turn away from the principal root, and matches the long-way reference.
            const quaternion<T> far = -q;
            const quaternion<T> long_way = from_glm(glm::pow(to_glm(far), t));
            if (t == T(0.5) && -far.w < std::cos(T(0.5))) {
                CHECK(quat::angle_between(long_way, quat::pow(far, t)) ==
                      Approx(quat::numbers::pi_v<T>).margin(1e-3));
                CHECK(distance(long_way, reference_pow(far, t, false)) <= tolerance<T>::glm);
            }
        }
    }
    // GLM drops turns with |v|^2 < epsilon; pow keeps them.
    const T tiny = std::sqrt(quat::test::eps<T>) / 4;
    const quaternion<T> small{std::cos(tiny / 2), std::sin(tiny / 2), 0, 0};
    CHECK(from_glm(glm::pow(to_glm(small), T(0.5))) == quaternion<T>::identity());
    CHECK(quat::pow(small, T(0.5)).x == Approx(std::sin(tiny / 4)).epsilon(4 * quat::test::eps<T>));
}

// ---- rotate_towards -----------------------------------------------------------------------------

TEMPLATE_TEST_CASE(
    "rotate_towards steps at most max_angle along the shorter arc, ending exactly on "
    "to",
    "[interpolation][rotate_towards]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 2000; ++n) {
        const quaternion<T> from = random.unit_quaternion<T>(), to = random.unit_quaternion<T>();
        const T total = quat::angle_between(from, to);
        const T max_angle = random.uniform<T>(0, 3.2);
        const quaternion<T> r = quat::rotate_towards(from, to, max_angle);
        CAPTURE(n, total, max_angle);
        if (total <= max_angle) {
            CHECK(r == to);
        } else {
            CHECK(std::abs(quat::angle_between(from, r) - max_angle) <= tolerance<T>::slerp_angle);
            CHECK(std::abs(quat::angle_between(r, to) - (total - max_angle)) <=
                  tolerance<T>::slerp_angle);
        }
        CHECK(quat::rotate_towards(from, -to, max_angle) ==
              (total <= max_angle ? -to : quat::rotate_towards(from, to, max_angle)));
    }
}

TEMPLATE_TEST_CASE("rotate_towards reaches to in steps and stays there",
                   "[interpolation][rotate_towards]", float, double) {
    using T = TestType;
    const quaternion<T> from = quat::rotation_x(T(0.2)), to = quat::rotation_z(T(2.5));
    const T total = quat::angle_between(from, to), step = T(0.1);
    quaternion<T> q = from;
    int steps = 0;
    while (q != to && steps < 1000) {
        q = quat::rotate_towards(q, to, step);
        ++steps;
    }
    CHECK(steps == static_cast<int>(std::ceil(total / step)));
    CHECK(quat::rotate_towards(q, to, step) == to);
}

TEMPLATE_TEST_CASE("rotate_towards with zero, negative, infinite and NaN input",
                   "[interpolation][rotate_towards]", float, double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    const quaternion<T> from = quat::rotation_y(T(-1)), to = quat::rotation_x(T(1));
    CHECK(quat::rotate_towards(from, to, T(0)) == from);
    CHECK(quat::rotate_towards(from, to, T(-0.5)) == from);
    CHECK(quat::rotate_towards(from, from, T(-0.5)) == from);
    CHECK(quat::rotate_towards(from, to, inf) == to);
    CHECK(std::isnan(quat::rotate_towards(from, to, nan).w));
    CHECK(std::isnan(quat::rotate_towards(from, from, nan).w));
    CHECK(std::isnan(quat::rotate_towards(quaternion<T>{nan, 0, 0, 0}, to, T(0.1)).w));
    CHECK(std::isnan(quat::rotate_towards(from, quaternion<T>{0, inf, 0, 0}, T(0.1)).w));
}

namespace {

// e^w (cos|v|, sin|v| v / |v|) in long double, straight from the definition.
template <class T>
quaternion<long double> reference_exp(const quaternion<T>& q) {
    const long double w = q.w, x = q.x, y = q.y, z = q.z;
    const long double length = std::sqrt(x * x + y * y + z * z), e = std::exp(w);
    if (length == 0) return {e, x, y, z};
    const long double k = e * std::sin(length) / length;
    return {e * std::cos(length), x * k, y * k, z * k};
}

// (ln|q|, v / |v| atan2(|v|, w)) in long double.
template <class T>
quaternion<long double> reference_log(const quaternion<T>& q) {
    const long double w = q.w, x = q.x, y = q.y, z = q.z;
    const long double length = std::sqrt(x * x + y * y + z * z);
    const long double k = std::atan2(length, w) / length;
    return {std::log(std::sqrt(w * w + length * length)), x * k, y * k, z * k};
}

// Largest component error relative to |reference|.
template <class T>
long double relative_error(const quaternion<T>& q, const quaternion<long double>& reference) {
    const quaternion<long double> ql{q.w, q.x, q.y, q.z};
    return std::sqrt(quat::squared_norm(ql - reference) / quat::squared_norm(reference));
}

}  // namespace

TEMPLATE_TEST_CASE("exp(q) is e^w (cos|v|, sin|v| v / |v|) for any q, tiny to huge |v|",
                   "[interpolation][exp]", float, double) {
    using T = TestType;
    const T eps = std::numeric_limits<T>::epsilon();
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        const T scale = std::pow(T(10), random.uniform<T>(-12, 3));
        const vec3<T> v = random.vector<T>(1.0) * scale;
        const quaternion<T> q{random.uniform<T>(-3, 3), v.x, v.y, v.z};
        const quaternion<T> e = exp(q);  // found by argument-dependent lookup
        CHECK(relative_error(e, reference_exp(q)) <= 8 * eps * (1 + quat::norm(v)));
        // Each vector component keeps its relative accuracy, however small |v| (the rounding of
        // |v| itself, an angle, costs eps |v| e^w).
        const quaternion<long double> reference = reference_exp(q);
        CHECK(std::abs(e.x - reference.x) <=
              8 * eps * (std::abs(reference.x) + quat::norm(v) * std::exp(q.w)));
    }
    // Real q: (e^w, v) with v's zeros kept; e^w may overflow without making the zeros NaN.
    CHECK(exp(quaternion<T>{1, 0, 0, 0}) == quaternion<T>{std::exp(T(1)), 0, 0, 0});
    const quaternion<T> huge = exp(quaternion<T>{T(1000), 0, T(-0.0), 0});
    CHECK(huge.w == std::numeric_limits<T>::infinity());
    CHECK((huge.x == 0 && huge.z == 0 && std::signbit(huge.y)));
    // A subnormal v: the direction and size survive.
    const T tiny = std::numeric_limits<T>::denorm_min() * 8;
    CHECK(exp(quaternion<T>{0, tiny, 0, 0}) == quaternion<T>{1, tiny, 0, 0});
    // NaN in, NaN out; an infinite v has no defined direction.
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    CHECK(std::isnan(exp(quaternion<T>{0, nan, 0, 0}).w));
    CHECK(std::isnan(exp(quaternion<T>{nan, 1, 0, 0}).x));
    CHECK(std::isnan(exp(quaternion<T>{nan, 0, 0, 0}).w));
    CHECK(std::isnan(exp(quaternion<T>{0, inf, 0, 0}).w));
}

TEMPLATE_TEST_CASE("log(q) is (ln|q|, v / |v| atan2(|v|, w)), the principal logarithm",
                   "[interpolation][exp]", float, double) {
    using T = TestType;
    const T eps = std::numeric_limits<T>::epsilon();
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        const T scale = std::pow(T(10), random.uniform<T>(-12, 3));
        const vec3<T> v = random.vector<T>(1.0) * scale;
        const quaternion<T> q{random.uniform<T>(-3, 3), v.x, v.y, v.z};
        const quaternion<T> l = log(q);
        const quaternion<long double> reference = reference_log(q);
        CHECK(std::abs(l.w - reference.w) <= 4 * eps * (1 + std::abs(reference.w)));
        const vec3<long double> lv{l.x, l.y, l.z}, rv{reference.x, reference.y, reference.z};
        CHECK(std::sqrt(quat::squared_norm(lv - rv)) <=
              4 * eps * std::sqrt(quat::squared_norm(rv)));
        CHECK(quat::norm(vec3<T>{l.x, l.y, l.z}) <= quat::numbers::pi_v<T> * (1 + 2 * eps));
        // exp undoes log, at any scale of q.
        CHECK(relative_error(exp(l), quaternion<long double>{q.w, q.x, q.y, q.z}) <= 16 * eps);
        // And log undoes exp while |v| < pi.
        if (quat::norm(v) < 3) {
            CHECK(quat::test::max_difference(log(exp(q)), q) <= 16 * eps * (1 + quat::norm(v)));
        }
    }
    // Real q: (ln w, 0) for w > 0, (ln|w|, pi, 0, 0) for w < 0 (axis x, as to_axis_angle's).
    CHECK(log(quaternion<T>{1, 0, 0, 0}) == quaternion<T>{0, 0, 0, 0});
    CHECK(log(quaternion<T>{-2, 0, 0, 0}) ==
          quaternion<T>{std::log(T(2)), quat::numbers::pi_v<T>, 0, 0});
    CHECK(log(quaternion<T>{0, 0, 0, 0}).w == -std::numeric_limits<T>::infinity());
    // Extreme magnitudes: |q|^2 would overflow or underflow, ln|q| does not.
    const T big = std::numeric_limits<T>::max() / 2;
    const quaternion<T> from_big = log(quaternion<T>{big, big, 0, 0});
    CHECK(from_big.w == Approx(std::log(big) + std::log(std::sqrt(T(2)))).epsilon(4 * eps));
    CHECK(from_big.x == Approx(quat::numbers::pi_v<T> / 4).epsilon(4 * eps));
    const T tiny = std::numeric_limits<T>::denorm_min() * 16;
    const quaternion<T> from_tiny = log(quaternion<T>{tiny, 0, tiny, 0});
    CHECK(from_tiny.w == Approx(std::log(tiny) + std::log(std::sqrt(T(2)))).epsilon(4 * eps));
    CHECK(from_tiny.y == Approx(quat::numbers::pi_v<T> / 4).epsilon(4 * eps));
    // A tiny v beside w = 1: no 0/0, v itself.
    CHECK(log(quaternion<T>{1, T(1e-30), 0, 0}) == quaternion<T>{0, T(1e-30), 0, 0});
    // NaN or infinite components give NaN everywhere.
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    for (const quaternion<T>& bad : std::vector<quaternion<T>>{
             {nan, 1, 0, 0}, {1, 0, nan, 0}, {inf, 0, 0, 0}, {1, 0, 0, -inf}}) {
        const quaternion<T> l = log(bad);
        CHECK((std::isnan(l.w) && std::isnan(l.x) && std::isnan(l.y) && std::isnan(l.z)));
    }
}

TEMPLATE_TEST_CASE(
    "exp((0, r / 2)) is from_rotation_vector(r); log of unit q with w >= 0 is half "
    "to_rotation_vector(q)",
    "[interpolation][exp]", float, double) {
    using T = TestType;
    const T eps = std::numeric_limits<T>::epsilon();
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        const vec3<T> r = random.unit_vector<T>() * std::pow(T(10), random.uniform<T>(-9, 0.8));
        CHECK(quat::test::max_difference(exp(quaternion<T>{0, r.x / 2, r.y / 2, r.z / 2}),
                                         quat::from_rotation_vector(r)) <= 2 * eps);
        const quaternion<T> q = random.unit_quaternion<T>();
        const quaternion<T> p = q.w < 0 ? -q : q;
        const vec3<T> half = quat::to_rotation_vector(p) / T(2);
        const quaternion<T> l = log(p);
        CHECK(std::abs(l.w) <= 2 * eps);
        CHECK(quat::test::max_difference(vec3<T>{l.x, l.y, l.z}, half) <= 4 * eps);
        // For w < 0, log keeps q's sign: the rotation the longer way round, |vector part| > pi / 2.
        if (q.w < 0)
            CHECK(quat::norm(vec3<T>{log(q).x, log(q).y, log(q).z}) > quat::numbers::pi_v<T> / 2);
    }
}

TEST_CASE("exp and log are found by argument-dependent lookup beside std::exp and std::log",
          "[interpolation][exp][first-use]") {
    using std::exp;
    using std::log;
    const quat::quatd q{0.5, 0.1, -0.2, 0.3};
    const quat::quatd e = exp(q), l = log(q);  // quat::exp, quat::log: not "cannot convert"
    CHECK(e.w == quat::exp(q).w);
    CHECK(l.x == quat::log(q).x);
    CHECK(exp(1.0) == std::exp(1.0));
    constexpr quat::quatd one = quat::exp(quat::quatd{0, 0, 0, 0});
    static_assert(one == quat::quatd::identity());
    constexpr quat::quatd zero = quat::log(quat::quatd{1, 0, 0, 0});
    static_assert(zero == quat::quatd{0, 0, 0, 0});
}

}  // namespace test_interpolation
