// Specification of interpolation.hpp: slerp, nlerp, pow and rotate_towards.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>
#include <quat/conversions.hpp>
#include <quat/interop/glm.hpp>
#include <quat/interpolation.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

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

// Twice the rotation angle between q and r: angle_between already returns the rotation angle (itself
// twice the 4D angle between the quaternions), so the factor 2 makes each bound below
// (tolerance<T>::slerp_angle) a bound of half that size on the rotation angle: stricter, not looser.
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
                      Approx(quat::pi_v<T>).margin(1e-3));
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
