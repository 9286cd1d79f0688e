// Hostile inputs: NaN, +Inf and -Inf in every component of every argument of every
// public function, for float and double, each checked against its doc comment; and the extreme
// magnitudes (subnormal, tiny, huge, max()) for the functions documented as accepting any non-zero
// scale or length. tests/test_nan_propagation.cpp puts the bad value in one place only; here the
// cases are generated, so a bug that needs the bad value in w (or in the dual part, or in a weight)
// is found as well.
//
// Expectations, per the docs:
//   all NaN   - "NaN in every component", "gives NaN" (read as: every component of the result),
//   non-finite- "a non-finite result", "Inf/NaN", IEEE arithmetic (operators, dot, cross,
//               products), and wherever the doc says nothing (marked "silent doc"): docs/api.md's
//               promise, "returns a non-finite component".
//   false     - predicates (is_unit, approx_equal).
//   empty     - try_ functions.
// Unit-precondition arguments (debug-checked) only get NaN/Inf, which pass the debug check by
// design (config.hpp); finite non-unit input to them is tests/contracts' business.
// Filter by function: ./quat_tests "hostile: to_axis_angle*", or by header: "[hostile][align]".
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/hostile.hpp"

namespace test_hostile_inputs {

namespace {
using namespace quat::test::hostile;  // NOLINT(google-build-using-namespace): the harness
}  // namespace

// ======================= quaternion.hpp =======================

HOSTILE("quaternion arithmetic", "quaternion") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("q", g.q, [&](const quaternion<T>& q, const std::string& w) {
        EXPECT_NONFINITE("-q with " << w, -q);
        EXPECT_NONFINITE("q + q2 with " << w, q + g.q2);
        EXPECT_NONFINITE("q2 - q with " << w, g.q2 - q);
        EXPECT_NONFINITE("q * q2 with " << w, q * g.q2);
        EXPECT_NONFINITE("q2 * q with " << w, g.q2 * q);
        EXPECT_NONFINITE("q * 2 with " << w, q * T(2));
        EXPECT_NONFINITE("q / 2 with " << w, q / T(2));
        EXPECT_NONFINITE("conjugate with " << w, quat::conjugate(q));
        EXPECT_NONFINITE("dot(q, q2) with " << w, quat::dot(q, g.q2));
        EXPECT_NONFINITE("squared_norm with " << w, quat::squared_norm(q));
        EXPECT_NONFINITE("norm with " << w, quat::norm(q));
        EXPECT_ALL_NAN("inverse(q) (doc: NaN in every component) with " << w, quat::inverse(q));
    });
    for_each_bad<T>("s", g.t, [&](T s, const std::string& w) {
        EXPECT_NONFINITE("q * s with " << w, g.q * s);
        EXPECT_NONFINITE("s * q with " << w, s * g.q);
    });
    // q / s for s = +-Inf is legitimately zero (IEEE); only NaN must show.
    EXPECT_NONFINITE("q / NaN", g.q / std::numeric_limits<T>::quiet_NaN());
}

HOSTILE("normalize(quaternion)", "quaternion") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("q", g.q, [&](const quaternion<T>& q, const std::string& w) {
        EXPECT_ALL_NAN("normalize(q) (doc: NaN in every component) with " << w, quat::normalize(q));
        EXPECT_EMPTY("try_normalize with " << w, quat::try_normalize(q));
        EXPECT_EMPTY("try_inverse with " << w, quat::try_inverse(q));
    });
}

HOSTILE("rotate(q, v)", "quaternion") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("q", g.q, [&](const quaternion<T>& q, const std::string& w) {
        EXPECT_NONFINITE("rotate(q, v) [silent doc] with " << w, quat::rotate(q, g.v));
    });
    for_each_bad<T>("v", g.v, [&](const vec3<T>& v, const std::string& w) {
        EXPECT_NONFINITE("rotate(q, v) [silent doc] with " << w, quat::rotate(g.q, v));
    });
}

HOSTILE("angle_between", "quaternion") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("a", g.q, [&](const quaternion<T>& a, const std::string& w) {
        EXPECT_ALL_NAN("angle_between(a, b) with " << w, quat::angle_between(a, g.q2));
        EXPECT_ALL_NAN("angle_between(b, a) with " << w, quat::angle_between(g.q2, a));
        EXPECT_ALL_NAN("angle_between(a, a) with " << w, quat::angle_between(a, a));
    });
}

HOSTILE("approx_equal", "quaternion") {
    using T = TestType;
    const good<T> g;
    const T inf = std::numeric_limits<T>::infinity();
    for_each_bad<T>("a", g.q, [&](const quaternion<T>& a, const std::string& w) {
        EXPECT_FALSE_("approx_equal(a, q, 1) with " << w, quat::approx_equal(a, g.q, T(1)));
        EXPECT_FALSE_("approx_equal(q, a, 1) with " << w, quat::approx_equal(g.q, a, T(1)));
        EXPECT_FALSE_("approx_equal(a, a, 1) with " << w, quat::approx_equal(a, a, T(1)));
        EXPECT_FALSE_("approx_equal(a, q, Inf) with " << w, quat::approx_equal(a, g.q, inf));
    });
    EXPECT_FALSE_("approx_equal(q, q, NaN) [silent doc]",
                  quat::approx_equal(g.q, g.q, std::numeric_limits<T>::quiet_NaN()));
}

HOSTILE("is_unit", "quaternion") {
    using T = TestType;
    const good<T> g;
    const T inf = std::numeric_limits<T>::infinity();
    for_each_bad<T>("q", g.q, [&](const quaternion<T>& q, const std::string& w) {
        EXPECT_FALSE_("is_unit(q, 0.1) with " << w, quat::is_unit(q, T(0.1)));
        EXPECT_FALSE_("is_unit(q, Inf) with " << w, quat::is_unit(q, inf));
    });
    for_each_bad<T>("q", quaternion<T>::identity(),
                    [&](const quaternion<T>& q, const std::string& w) {
                        EXPECT_FALSE_("is_unit(identity with bad component, Inf) with " << w,
                                      quat::is_unit(q, inf));
                    });
    EXPECT_FALSE_("is_unit(q, NaN) [silent doc]",
                  quat::is_unit(g.q, std::numeric_limits<T>::quiet_NaN()));
}

HOSTILE("rotation_x/y/z", "quaternion") {
    using T = TestType;
    for (const T a : bad_values<T>()) {
        EXPECT_NONFINITE("rotation_x(" << a << ") [silent doc]", quat::rotation_x(a));
        EXPECT_NONFINITE("rotation_y(" << a << ") [silent doc]", quat::rotation_y(a));
        EXPECT_NONFINITE("rotation_z(" << a << ") [silent doc]", quat::rotation_z(a));
    }
}

// ======================= vec3.hpp =======================

HOSTILE("vec3 functions", "vec3") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("v", g.v, [&](const vec3<T>& v, const std::string& w) {
        EXPECT_NONFINITE("-v with " << w, -v);
        EXPECT_NONFINITE("v + v2 with " << w, v + g.v2);
        EXPECT_NONFINITE("v2 - v with " << w, g.v2 - v);
        EXPECT_NONFINITE("v * 2 with " << w, v * T(2));
        EXPECT_NONFINITE("v / 2 with " << w, v / T(2));
        EXPECT_NONFINITE("dot(v, v2) with " << w, quat::dot(v, g.v2));
        EXPECT_NONFINITE("cross(v, v2) with " << w, quat::cross(v, g.v2));
        EXPECT_NONFINITE("cross(v2, v) with " << w, quat::cross(g.v2, v));
        EXPECT_NONFINITE("squared_norm with " << w, quat::squared_norm(v));
        EXPECT_NONFINITE("norm with " << w, quat::norm(v));
        EXPECT_SOME_NAN("normalize (doc: holds NaN) with " << w, quat::normalize(v));
        EXPECT_EMPTY("try_normalize with " << w, quat::try_normalize(v));
    });
    for_each_bad<T>("s", g.t, [&](T s, const std::string& w) {
        EXPECT_NONFINITE("v * s with " << w, g.v * s);
        EXPECT_NONFINITE("s * v with " << w, s * g.v);
    });
}

// ======================= rotation_matrix.hpp =======================

HOSTILE("rotation_matrix functions", "rotation_matrix") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("m", g.m, [&](const rotation_matrix<T>& m, const std::string& w) {
        EXPECT_NONFINITE("m * m2 with " << w, m * quat::to_matrix(g.q2));
        EXPECT_NONFINITE("m2 * m with " << w, quat::to_matrix(g.q2) * m);
        EXPECT_NONFINITE("rotate(m, v) with " << w, quat::rotate(m, g.v));
        EXPECT_NONFINITE("transpose with " << w, quat::transpose(m));
        EXPECT_NONFINITE("determinant with " << w, quat::determinant(m));
        EXPECT_NONFINITE("orthogonality_error (doc: NaN propagates) with " << w,
                         quat::orthogonality_error(m));
    });
    for_each_bad<T>("v", g.v, [&](const vec3<T>& v, const std::string& w) {
        EXPECT_NONFINITE("rotate(m, v) with " << w, quat::rotate(g.m, v));
    });
}

// ======================= conversions.hpp =======================

HOSTILE("to_matrix(q)", "conversions") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("q", g.q, [&](const quaternion<T>& q, const std::string& w) {
        EXPECT_NONFINITE("to_matrix(q) [silent doc] with " << w, quat::to_matrix(q));
    });
}

HOSTILE("to_quaternion(m)", "conversions") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("m", g.m, [&](const rotation_matrix<T>& m, const std::string& w) {
        EXPECT_NONFINITE("to_quaternion(m) [silent doc] with " << w, quat::to_quaternion(m));
        EXPECT_NONFINITE("to_axis_angle(m) [silent doc] with " << w, quat::to_axis_angle(m));
        EXPECT_EMPTY("try_to_quaternion(m) with " << w, quat::try_to_quaternion(m));
        EXPECT_EMPTY("try_to_quaternion(m, 1) with " << w, quat::try_to_quaternion(m, T(1)));
    });
    EXPECT_EMPTY("try_to_quaternion(m, NaN tolerance)",
                 quat::try_to_quaternion(g.m, std::numeric_limits<T>::quiet_NaN()));
}

HOSTILE("axis_angle conversions", "conversions") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("aa", g.aa, [&](const axis_angle<T>& aa, const std::string& w) {
        EXPECT_NONFINITE("to_quaternion(axis_angle) [silent doc] with " << w,
                         quat::to_quaternion(aa));
        EXPECT_NONFINITE("to_matrix(axis_angle) [silent doc] with " << w, quat::to_matrix(aa));
        EXPECT_EMPTY("try_to_quaternion(axis_angle) with " << w, quat::try_to_quaternion(aa));
    });
}

HOSTILE("to_axis_angle(q)", "conversions") {
    using T = TestType;
    const good<T> g;
    for (const quaternion<T>& base : {g.q, g.q3, quaternion<T>::identity()})
        for_each_bad<T>("q", base, [&](const quaternion<T>& q, const std::string& w) {
            EXPECT_ALL_NAN("to_axis_angle(q) (doc: NaN) with " << w, quat::to_axis_angle(q));
        });
}

HOSTILE("to_rotation_vector", "conversions") {
    using T = TestType;
    const good<T> g;
    for (const quaternion<T>& base : {g.q, g.q3, quaternion<T>::identity()})
        for_each_bad<T>("q", base, [&](const quaternion<T>& q, const std::string& w) {
            EXPECT_NONFINITE("to_rotation_vector(q) [silent doc] with " << w,
                             quat::to_rotation_vector(q));
        });
}

HOSTILE("to_mrp", "conversions") {
    using T = TestType;
    const good<T> g;
    for (const quaternion<T>& base : {g.q, g.q3, quaternion<T>::identity()})
        for_each_bad<T>("q", base, [&](const quaternion<T>& q, const std::string& w) {
            EXPECT_ALL_NAN("to_mrp(q) (doc: NaN) with " << w, quat::to_mrp(q));
        });
}

HOSTILE("from_mrp and from_rotation_vector", "conversions") {
    using T = TestType;
    const good<T> g;
    for (const vec3<T>& base : {g.v, vec3<T>{T(0), T(0), T(0)}})
        for_each_bad<T>("p", base, [&](const vec3<T>& p, const std::string& w) {
            EXPECT_ALL_NAN("from_mrp(p) (doc: NaN) with " << w, quat::from_mrp(p));
            EXPECT_NONFINITE("from_rotation_vector(v) [silent doc] with " << w,
                             quat::from_rotation_vector(p));
        });
}

// ======================= euler.hpp, continuous_euler.hpp =======================

namespace {
template <sequence S, frame F, class T>
void check_euler_convention(const good<T>& g, const char* convention) {
    const euler<T, S, F> e{T(0.3), T(-0.4), T(0.2)};
    for_each_bad<T>("e", e, [&](const euler<T, S, F>& bad, const std::string& w) {
        EXPECT_NONFINITE(convention << " to_quaternion(e) [silent doc] with " << w,
                         quat::to_quaternion(bad));
        EXPECT_NONFINITE(convention << " to_matrix(e) [silent doc] with " << w,
                         quat::to_matrix(bad));
        EXPECT_NONFINITE(convention << " to_axis_angle(e) [silent doc] with " << w,
                         quat::to_axis_angle(bad));
        EXPECT_NONFINITE(convention << " to_euler<zxz>(e) [silent doc] with " << w,
                         (quat::to_euler<sequence::zxz, frame::intrinsic>(bad)));
    });
    for (const quaternion<T>& base : {g.q, quaternion<T>::identity()})
        for_each_bad<T>("q", base, [&](const quaternion<T>& q, const std::string& w) {
            EXPECT_NONFINITE(convention << " extract_euler(q).angles [silent doc] with " << w,
                             (quat::extract_euler<S, F>(q).angles));
            EXPECT_NONFINITE(convention << " to_euler(q) [silent doc] with " << w,
                             (quat::to_euler<S, F>(q)));
            EXPECT_ALL_NAN(convention << " to_euler(q, previous) (doc: NaN) with " << w,
                           (quat::to_euler<S, F>(q, e)));
        });
    for_each_bad<T>("previous", e, [&](const euler<T, S, F>& previous, const std::string& w) {
        EXPECT_SOME_NAN(convention << " to_euler(q, previous) (doc: NaN in that angle) with " << w,
                        (quat::to_euler<S, F>(g.q, previous)));
    });
    for_each_bad<T>("m", g.m, [&](const rotation_matrix<T>& m, const std::string& w) {
        EXPECT_NONFINITE(convention << " to_euler(m) [silent doc] with " << w,
                         (quat::to_euler<S, F>(m)));
    });
    for_each_bad<T>("aa", g.aa, [&](const axis_angle<T>& aa, const std::string& w) {
        EXPECT_NONFINITE(convention << " to_euler(axis_angle) [silent doc] with " << w,
                         (quat::to_euler<S, F>(aa)));
    });
}
}  // namespace

HOSTILE("euler", "euler") {
    using T = TestType;
    const good<T> g;
    check_euler_convention<sequence::zyx, frame::intrinsic>(g, "zyx intrinsic");
    check_euler_convention<sequence::xyz, frame::extrinsic>(g, "xyz extrinsic");
    check_euler_convention<sequence::zxz, frame::intrinsic>(g, "zxz intrinsic");
    check_euler_convention<sequence::yxy, frame::extrinsic>(g, "yxy extrinsic");
}

// ======================= paths/interpolation.hpp =======================

HOSTILE("slerp", "interpolation") {
    using T = TestType;
    const good<T> g;
    for (const T t : {T(0), T(0.3), T(1), T(-0.5), T(1.5)}) {
        for_each_bad<T>("a", g.q, [&](const quaternion<T>& a, const std::string& w) {
            EXPECT_NONFINITE("slerp(a, b, " << t << ") with " << w, quat::slerp(a, g.q2, t));
            EXPECT_NONFINITE("slerp(b, a, " << t << ") with " << w, quat::slerp(g.q2, a, t));
            EXPECT_NONFINITE("slerp(a, a, " << t << ") with " << w, quat::slerp(a, a, t));
        });
    }
    for (const quaternion<T>& b : {g.q2, g.q})
        for_each_bad<T>("t", g.t, [&](T t, const std::string& w) {
            EXPECT_NONFINITE("slerp(a, b, t) with " << w, quat::slerp(g.q, b, t));
        });
}

HOSTILE("nlerp", "interpolation") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("a", g.q, [&](const quaternion<T>& a, const std::string& w) {
        EXPECT_NONFINITE("nlerp(a, b, 0.3) [silent doc] with " << w, quat::nlerp(a, g.q2, T(0.3)));
        EXPECT_NONFINITE("nlerp(b, a, 0.3) [silent doc] with " << w, quat::nlerp(g.q2, a, T(0.3)));
    });
    for_each_bad<T>("t", g.t, [&](T t, const std::string& w) {
        EXPECT_NONFINITE("nlerp(a, b, t) [silent doc] with " << w, quat::nlerp(g.q, g.q2, t));
    });
}

HOSTILE("pow", "interpolation") {
    using T = TestType;
    const good<T> g;
    for (const quaternion<T>& base : {g.q, g.q3, quaternion<T>::identity()})
        for (const T t : {T(0), T(0.3), T(1), T(2.5)})
            for_each_bad<T>("q", base, [&](const quaternion<T>& q, const std::string& w) {
                EXPECT_NONFINITE("pow(q, " << t << ") with " << w, quat::pow(q, t));
            });
    for (const quaternion<T>& base : {g.q, quaternion<T>::identity()})
        for_each_bad<T>("t", g.t, [&](T t, const std::string& w) {
            EXPECT_NONFINITE("pow(q = " << show(base) << ", t) with " << w, quat::pow(base, t));
        });
}

HOSTILE("rotate_towards", "interpolation") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("from", g.q, [&](const quaternion<T>& from, const std::string& w) {
        EXPECT_ALL_NAN("rotate_towards(from, to, 0.1) (doc: NaN) with " << w,
                       quat::rotate_towards(from, g.q2, T(0.1)));
        EXPECT_ALL_NAN("rotate_towards(from, to, Inf) (doc: NaN) with " << w,
                       quat::rotate_towards(from, g.q2, std::numeric_limits<T>::infinity()));
        EXPECT_ALL_NAN("rotate_towards(to, from, 0.1) (doc: NaN) with " << w,
                       quat::rotate_towards(g.q2, from, T(0.1)));
        EXPECT_ALL_NAN("rotate_towards(to, from, Inf) (doc: NaN) with " << w,
                       quat::rotate_towards(g.q2, from, std::numeric_limits<T>::infinity()));
    });
    EXPECT_ALL_NAN("rotate_towards(from, to, NaN) (doc: NaN)",
                   quat::rotate_towards(g.q, g.q2, std::numeric_limits<T>::quiet_NaN()));
    // Documented: an infinite max_angle gives `to`; a negative one (-Inf too) counts as 0: `from`.
    CHECK(quat::rotate_towards(g.q, g.q2, std::numeric_limits<T>::infinity()) == g.q2);
    {
        const quaternion<T> r =
            quat::rotate_towards(g.q, g.q2, -std::numeric_limits<T>::infinity());
        INFO("rotate_towards(from, to, -Inf) -> (" << show(r) << "); expected from = (" << show(g.q)
                                                   << ")");
        CHECK(quat::angle_between(r, g.q) <= T(16) * std::numeric_limits<T>::epsilon());
    }
}

// ======================= paths/slerp_fast.hpp =======================

HOSTILE("corrected_nlerp and slerp_fast", "slerp_fast") {
    using T = TestType;
    const good<T> g;
    for (const T t : {T(0), T(0.3), T(1)})
        for_each_bad<T>("a", g.q, [&](const quaternion<T>& a, const std::string& w) {
            EXPECT_NONFINITE("corrected_nlerp(a, b, " << t << ") [silent doc] with " << w,
                             quat::corrected_nlerp(a, g.q2, t));
            EXPECT_NONFINITE("corrected_nlerp(b, a, " << t << ") [silent doc] with " << w,
                             quat::corrected_nlerp(g.q2, a, t));
            EXPECT_NONFINITE("slerp_fast(a, b, " << t << ") [silent doc] with " << w,
                             quat::slerp_fast(a, g.q2, t));
            EXPECT_NONFINITE("slerp_fast(b, a, " << t << ") [silent doc] with " << w,
                             quat::slerp_fast(g.q2, a, t));
        });
    for_each_bad<T>("t", g.t, [&](T t, const std::string& w) {
        EXPECT_NONFINITE("corrected_nlerp(a, b, t) [silent doc] with " << w,
                         quat::corrected_nlerp(g.q, g.q2, t));
        EXPECT_NONFINITE("slerp_fast(a, b, t) [silent doc] with " << w,
                         quat::slerp_fast(g.q, g.q2, t));
    });
}

// ======================= align.hpp =======================

HOSTILE("rotation_between", "align") {
    using T = TestType;
    const good<T> g;
    for (const vec3<T>& other : {g.v2, g.v, -g.v})
        for_each_bad<T>("v", g.v, [&](const vec3<T>& v, const std::string& w) {
            EXPECT_ALL_NAN("rotation_between(v, " << show(other) << ") with " << w,
                           quat::rotation_between(v, other));
            EXPECT_ALL_NAN("rotation_between(" << show(other) << ", v) with " << w,
                           quat::rotation_between(other, v));
            EXPECT_EMPTY("try_rotation_between(v, other) with " << w,
                         quat::try_rotation_between(v, other));
            EXPECT_EMPTY("try_rotation_between(other, v) with " << w,
                         quat::try_rotation_between(other, v));
        });
}

HOSTILE("look_rotation", "align") {
    using T = TestType;
    const good<T> g;
    const vec3<T> up{T(0), T(1), T(0)};
    for_each_bad<T>("forward", g.v, [&](const vec3<T>& forward, const std::string& w) {
        EXPECT_ALL_NAN("look_rotation(forward, up) with " << w, quat::look_rotation(forward, up));
        EXPECT_EMPTY("try_look_rotation(forward, up) with " << w,
                     quat::try_look_rotation(forward, up));
    });
    for_each_bad<T>("up", up, [&](const vec3<T>& bad_up, const std::string& w) {
        EXPECT_ALL_NAN("look_rotation(forward, up) with " << w, quat::look_rotation(g.v, bad_up));
        EXPECT_EMPTY("try_look_rotation(forward, up) with " << w,
                     quat::try_look_rotation(g.v, bad_up));
    });
}

// ======================= swing_twist.hpp =======================

HOSTILE("swing_twist", "swing_twist") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("q", g.q, [&](const quaternion<T>& q, const std::string& w) {
        EXPECT_ALL_NAN("swing_twist(q, axis) (doc: NaN results) with " << w,
                       quat::swing_twist(q, g.v));
        EXPECT_EMPTY("try_swing_twist(q, axis) with " << w, quat::try_swing_twist(q, g.v));
    });
    for_each_bad<T>("axis", g.v, [&](const vec3<T>& axis, const std::string& w) {
        EXPECT_ALL_NAN("swing_twist(q, axis) (doc: NaN results) with " << w,
                       quat::swing_twist(g.q, axis));
        EXPECT_EMPTY("try_swing_twist(q, axis) with " << w, quat::try_swing_twist(g.q, axis));
    });
}

// ======================= kinematics.hpp =======================

HOSTILE("angular velocity", "kinematics") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("q0", g.q, [&](const quaternion<T>& q, const std::string& w) {
        EXPECT_ALL_NAN("body_angular_velocity(q0, q1, 0.1) (doc: NaN) with " << w,
                       quat::body_angular_velocity(q, g.q2, T(0.1)));
        EXPECT_ALL_NAN("body_angular_velocity(q1, q0, 0.1) (doc: NaN) with " << w,
                       quat::body_angular_velocity(g.q2, q, T(0.1)));
        EXPECT_ALL_NAN("world_angular_velocity(q0, q1, 0.1) (doc: NaN) with " << w,
                       quat::world_angular_velocity(q, g.q2, T(0.1)));
        EXPECT_ALL_NAN("world_angular_velocity(q1, q0, 0.1) (doc: NaN) with " << w,
                       quat::world_angular_velocity(g.q2, q, T(0.1)));
    });
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    EXPECT_ALL_NAN("body_angular_velocity(q0, q1, NaN) (doc: NaN)",
                   quat::body_angular_velocity(g.q, g.q2, nan));
    EXPECT_ALL_NAN("world_angular_velocity(q0, q1, NaN) (doc: NaN)",
                   quat::world_angular_velocity(g.q, g.q2, nan));
    for (const T dt : {inf, -inf}) {  // documented: the limit 0
        const vec3<T> zero{T(0), T(0), T(0)};
        const vec3<T> b = quat::body_angular_velocity(g.q, g.q2, dt);
        const vec3<T> wv = quat::world_angular_velocity(g.q, g.q2, dt);
        INFO("dt = " << dt << ": body (" << show(b) << "), world (" << show(wv)
                     << "); expected 0 (doc: an infinite dt the limit 0)");
        CHECK(b == zero);
        CHECK(wv == zero);
    }
}

HOSTILE("integrate", "kinematics") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("q0", g.q, [&](const quaternion<T>& q, const std::string& w) {
        EXPECT_NONFINITE("integrate_body (doc: non-finite) with " << w,
                         quat::integrate_body(q, g.v, T(0.1)));
        EXPECT_NONFINITE("integrate_world (doc: non-finite) with " << w,
                         quat::integrate_world(q, g.v, T(0.1)));
    });
    for (const vec3<T>& base : {g.v, vec3<T>{T(0), T(0), T(0)}})
        for_each_bad<T>("omega", base, [&](const vec3<T>& omega, const std::string& w) {
            EXPECT_ALL_NAN("integrate_body (doc: NaN) with " << w,
                           quat::integrate_body(g.q, omega, T(0.1)));
            EXPECT_ALL_NAN("integrate_world (doc: NaN) with " << w,
                           quat::integrate_world(g.q, omega, T(0.1)));
        });
    for_each_bad<T>("dt", g.t, [&](T dt, const std::string& w) {
        EXPECT_ALL_NAN("integrate_body (doc: NaN) with " << w, quat::integrate_body(g.q, g.v, dt));
        EXPECT_ALL_NAN("integrate_world (doc: NaN) with " << w,
                       quat::integrate_world(g.q, g.v, dt));
        EXPECT_ALL_NAN("integrate_body, zero omega (doc: NaN) with " << w,
                       quat::integrate_body(g.q, vec3<T>{T(0), T(0), T(0)}, dt));
    });
}

// ======================= fitting/nearest_rotation.hpp =======================

HOSTILE("nearest_rotation", "nearest_rotation") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("m", g.m, [&](const rotation_matrix<T>& m, const std::string& w) {
        EXPECT_ALL_NAN("nearest_rotation(m) (doc: NaN elements) with " << w,
                       quat::nearest_rotation(m));
        EXPECT_EMPTY("try_nearest_rotation(m) with " << w, quat::try_nearest_rotation(m));
    });
}

// ======================= fitting/mean.hpp =======================

HOSTILE("mean", "mean") {
    using T = TestType;
    const good<T> g;
    const std::vector<quaternion<T>> base{g.q, g.q2, g.q3, g.q4};
    for (std::size_t k = 0; k < base.size(); ++k)
        for_each_bad<T>("rotations[k]", base[k], [&](const quaternion<T>& q, const std::string& w) {
            std::vector<quaternion<T>> r = base;
            r[k] = q;
            const std::vector<T> weights{T(1), T(2), T(0.5), T(1)};
            EXPECT_ALL_NAN("mean k=" << k << " (doc: NaN) with " << w, quat::mean(r));
            EXPECT_ALL_NAN("weighted mean k=" << k << " (doc: NaN) with " << w,
                           quat::mean(r, weights));
            EXPECT_EMPTY("try_mean k=" << k << " with " << w, quat::try_mean(r));
            EXPECT_EMPTY("weighted try_mean k=" << k << " with " << w, quat::try_mean(r, weights));
        });
    // Weights: NaN and +Inf only (a negative weight, -Inf too, is a debug-checked precondition).
    for (std::size_t k = 0; k < base.size(); ++k)
        for (const T bad :
             {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity()}) {
            std::vector<T> weights{T(1), T(2), T(0.5), T(1)};
            weights[k] = bad;
            EXPECT_ALL_NAN("weighted mean, weights[" << k << "]=" << bad << " (doc: NaN)",
                           quat::mean(base, weights));
            EXPECT_EMPTY("weighted try_mean, weights[" << k << "]=" << bad,
                         quat::try_mean(base, weights));
        }
}

// ======================= fitting/align_vectors.hpp =======================

namespace {
template <class T, class A>
void check_bad_alignment(const std::string& where, const A& a) {
    INFO(where << " -> rotation (" << show(a.rotation) << "), rssd " << a.rssd << ", unique "
               << a.unique << "; expected NaN rotation and rssd, unique = false");
    CHECK(all_nan(a.rotation));
    CHECK(std::isnan(a.rssd));
    CHECK_FALSE(a.unique);
}
}  // namespace

HOSTILE("align_vectors", "align_vectors") {
    using T = TestType;
    const good<T> g;
    const std::vector<vec3<T>> sources{g.v, g.v2, vec3<T>{T(0.1), T(0.9), T(-0.3)}};
    std::vector<vec3<T>> targets;
    for (const vec3<T>& s : sources) targets.push_back(quat::rotate(g.q, s));
    const std::vector<T> weights{T(1), T(2), T(0.5)};
    for (const int which : {0, 1})
        for (std::size_t k = 0; k < sources.size(); ++k)
            for_each_bad<T>(which ? "sources[k]" : "targets[k]", (which ? sources : targets)[k],
                            [&](const vec3<T>& v, const std::string& w) {
                                std::vector<vec3<T>> s = sources, t = targets;
                                (which ? s : t)[k] = v;
                                std::ostringstream where;
                                where << "k=" << k << " " << w;
                                check_bad_alignment<T>("align_vectors " + where.str(),
                                                       quat::align_vectors(t, s));
                                check_bad_alignment<T>("weighted align_vectors " + where.str(),
                                                       quat::align_vectors(t, s, weights));
                                check_bad_alignment<T>(
                                    "align_vectors_with_sensitivity [silent doc] " + where.str(),
                                    quat::align_vectors_with_sensitivity(t, s, weights));
                            });
    // Weights, as documented with the scipy >= 1.11 semantics: a NaN weight, two infinite weights,
    // or an infinite weight on a zero vector give NaN; one infinite weight is the primary pair.
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    for (std::size_t k = 0; k < weights.size(); ++k) {
        std::vector<T> w = weights, two_inf = weights;
        w[k] = nan;
        two_inf[k] = inf;
        two_inf[(k + 1) % weights.size()] = inf;
        std::vector<vec3<T>> zero_source = sources;
        zero_source[k] = vec3<T>{T(0), T(0), T(0)};
        std::vector<T> one_inf = weights;
        one_inf[k] = inf;
        const std::string at = "weights[" + std::to_string(k) + "]";
        check_bad_alignment<T>("weighted align_vectors (doc: NaN result) " + at + "=nan",
                               quat::align_vectors(targets, sources, w));
        check_bad_alignment<T>("align_vectors_with_sensitivity [silent doc] " + at + "=nan",
                               quat::align_vectors_with_sensitivity(targets, sources, w));
        check_bad_alignment<T>(
            "weighted align_vectors (doc: NaN result) two infinite weights at " + at,
            quat::align_vectors(targets, sources, two_inf));
        check_bad_alignment<T>(
            "weighted align_vectors (doc: NaN result) infinite weight on a zero "
            "source at " +
                at,
            quat::align_vectors(targets, zero_source, one_inf));
        const quat::alignment<T> primary = quat::align_vectors(targets, sources, one_inf);
        INFO("weighted align_vectors, one infinite weight (doc: the primary pair) at "
             << at << " -> rotation (" << show(primary.rotation) << "), rssd " << primary.rssd
             << "; expected the rotation (" << show(g.q) << ") the consistent data came from");
        CHECK(all_finite(primary.rotation));
        CHECK(std::isfinite(primary.rssd));
        CHECK(quat::angle_between(primary.rotation, g.q) <= T(1e-4));
    }
}

// ================= paths/squad.hpp, paths/keyframe_slerp.hpp, paths/keyframe_squad.hpp
// =================

HOSTILE("squad", "squad") {
    using T = TestType;
    const good<T> g;
    const quaternion<T> keys[4] = {g.q, g.q2, g.q3, g.q4};
    for (int k = 0; k < 3; ++k)
        for_each_bad<T>("squad_control arg", keys[k],
                        [&](const quaternion<T>& q, const std::string& w) {
                            quaternion<T> a[3] = {keys[0], keys[1], keys[2]};
                            a[k] = q;
                            EXPECT_ALL_NAN("squad_control arg " << k << " (doc: NaN) with " << w,
                                           quat::squad_control(a[0], a[1], a[2]));
                        });
    const quaternion<T> a1 = quat::squad_control(keys[0], keys[1], keys[2]);
    const quaternion<T> a2 = quat::squad_control(keys[1], keys[2], keys[3]);
    const quaternion<T> args[4] = {keys[1], a1, a2, keys[2]};
    for (const T t : {T(0), T(0.3), T(1)})
        for (int k = 0; k < 4; ++k)
            for_each_bad<T>(
                "squad arg", args[k], [&](const quaternion<T>& q, const std::string& w) {
                    quaternion<T> a[4] = {args[0], args[1], args[2], args[3]};
                    a[k] = q;
                    EXPECT_NONFINITE(
                        "squad arg " << k << ", t=" << t << " (doc: non-finite) with " << w,
                        quat::squad(a[0], a[1], a[2], a[3], t));
                });
    for_each_bad<T>("t", g.t, [&](T t, const std::string& w) {
        EXPECT_ALL_NAN("squad(q1, a1, a2, q2, t) (doc: NaN; Inf t is outside [0, 1]) with " << w,
                       quat::squad(args[0], args[1], args[2], args[3], t));
    });
}

HOSTILE("keyframe_slerp", "keyframe_slerp") {
    using T = TestType;
    const good<T> g;
    const std::vector<T> times{T(0), T(1), T(2.5), T(4)};
    const std::vector<quaternion<T>> keys{g.q, g.q2, g.q3, g.q4};
    for (const T t : {T(-1), T(0), T(0.5), T(1), T(3), T(4), T(9)})
        for (std::size_t k = 0; k < keys.size(); ++k)
            for_each_bad<
                T>("rotations[k]", keys[k], [&](const quaternion<T>& q, const std::string& w) {
                std::vector<quaternion<T>> r = keys;
                r[k] = q;
                const quaternion<T> result = quat::keyframe_slerp(times, r, t);
                // Documented: NaN when the keyframe is used; a keyframe the segment does not touch
                // may be ignored, so only the segments around t are checked. Exactly rotations[i]
                // at times[i] (documented), so only that keyframe is used there.
                bool at_key = false;
                for (const T time : times) at_key = at_key || time == t;
                const bool used =
                    at_key
                        ? times[k] == t
                        : (t < times[0] && k == 0) || (t > times.back() && k + 1 == keys.size()) ||
                              (t > times[0] && t < times.back() &&
                               ((k > 0 && times[k - 1] < t && t < times[k]) ||
                                (k + 1 < keys.size() && times[k] < t && t < times[k + 1])));
                if (used)
                    EXPECT_NONFINITE(
                        "keyframe_slerp(t=" << t << ") k=" << k << " (doc: non-finite) with " << w,
                        result);
            });
    for_each_bad<T>("t", g.t, [&](T t, const std::string& w) {
        if (std::isnan(t))
            EXPECT_ALL_NAN("keyframe_slerp (doc: NaN t gives NaN) with " << w,
                           quat::keyframe_slerp(times, keys, t));
    });
    // Documented: t beyond the ends gives the end keyframe; +-Inf included.
    CHECK(quat::keyframe_slerp(times, keys, std::numeric_limits<T>::infinity()) == keys.back());
    CHECK(quat::keyframe_slerp(times, keys, -std::numeric_limits<T>::infinity()) == keys.front());
}

HOSTILE("keyframe_squad", "keyframe_squad") {
    using T = TestType;
    const good<T> g;
    const std::vector<T> times{T(0), T(1), T(2.5), T(4), T(4.5)};
    const std::vector<quaternion<T>> keys{g.q, g.q2, g.q3, g.q4, g.q};
    const std::size_t last = keys.size() - 1;
    for (const T t : {T(-1), T(0), T(0.5), T(1), T(3), T(4), T(4.2), T(4.5), T(9)})
        for (std::size_t k = 0; k <= last; ++k)
            for_each_bad<T>(
                "rotations[k]", keys[k], [&](const quaternion<T>& q, const std::string& w) {
                    std::vector<quaternion<T>> r = keys;
                    r[k] = q;
                    // Documented: non-finite on every segment the keyframe is an end or a control
                    // point of (segments i - 1 to i + 2 use keyframes i - 1 to i + 2); the end
                    // keyframes alone at and beyond the ends.
                    std::size_t i = 0;
                    while (i + 2 <= last && !(t < times[i + 1])) ++i;
                    const bool used = t <= times[0]      ? k == 0
                                      : t >= times[last] ? k == last
                                                         : k + 1 >= i && k <= i + 2;
                    if (used)
                        EXPECT_NONFINITE("keyframe_squad(t=" << t << ") k=" << k
                                                             << " (doc: non-finite) with " << w,
                                         quat::keyframe_squad(times, r, t));
                });
    for_each_bad<T>("t", g.t, [&](T t, const std::string& w) {
        if (std::isnan(t))
            EXPECT_ALL_NAN("keyframe_squad (doc: NaN t gives NaN) with " << w,
                           quat::keyframe_squad(times, keys, t));
    });
    // Documented: t beyond the ends gives the end keyframe; +-Inf included.
    CHECK(quat::keyframe_squad(times, keys, std::numeric_limits<T>::infinity()) == keys.back());
    CHECK(quat::keyframe_squad(times, keys, -std::numeric_limits<T>::infinity()) == keys.front());
}

// ======================= paths/rotation_spline.hpp =======================

HOSTILE("rotation_spline", "rotation_spline") {
    using T = TestType;
    const good<T> g;
    const std::vector<T> times{T(0), T(1), T(2.5), T(4)};
    const std::vector<quaternion<T>> keys{g.q, g.q2, g.q3, g.q4};
    const quat::rotation_spline<T> spline(times, keys);
    for_each_bad<T>("t", g.t, [&](T t, const std::string& w) {
        EXPECT_ALL_NAN("spline(t) (doc: NaN for NaN t; Inf silent) with " << w, spline(t));
        EXPECT_ALL_NAN("angular_velocity(t) (doc: NaN for NaN t; Inf silent) with " << w,
                       spline.angular_velocity(t));
        EXPECT_ALL_NAN("angular_acceleration(t) (doc: NaN for NaN t; Inf silent) with " << w,
                       spline.angular_acceleration(t));
        const std::vector<T> ts{T(0.5), t, T(3)};
        std::vector<quaternion<T>> out(3);
        spline.evaluate(ts, out);
        EXPECT_ALL_NAN("evaluate, element 1 with " << w, out[1]);
        INFO("evaluate, good elements beside " << w << ": (" << show(out[0]) << "), ("
                                               << show(out[2]) << ")");
        CHECK(all_finite(out[0]));
        CHECK(all_finite(out[2]));
    });
    for (std::size_t k = 0; k < keys.size(); ++k)
        for_each_bad<T>("rotations[k]", keys[k], [&](const quaternion<T>& q, const std::string& w) {
            std::vector<quaternion<T>> r = keys;
            r[k] = q;
            EXPECT_EMPTY("try_make, k=" << k << " with " << w,
                         (quat::rotation_spline<T>::try_make(times, r)));
            // Documented: a meaningless (often non-finite) spline, never UB; not NaN-checked here.
            const quat::rotation_spline<T> s(times, r);
            (void)s(T(1.7));
        });
}

// ======================= rigid/dual_quaternion.hpp, rigid/screw.hpp, rigid/sclerp.hpp
// =======================

HOSTILE("dual_quaternion functions", "dual_quaternion") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("rotation", g.q, [&](const quaternion<T>& q, const std::string& w) {
        EXPECT_NONFINITE("to_dual_quaternion(q, t) with " << w, quat::to_dual_quaternion(q, g.v));
    });
    for_each_bad<T>("translation", g.v, [&](const vec3<T>& v, const std::string& w) {
        EXPECT_NONFINITE("to_dual_quaternion(q, t) with " << w, quat::to_dual_quaternion(g.q, v));
    });
    for_each_bad<T>("dq", g.dq, [&](const dual_quaternion<T>& dq, const std::string& w) {
        EXPECT_NONFINITE("-dq with " << w, -dq);
        EXPECT_NONFINITE("dq * dq2 with " << w, dq * g.dq2);
        EXPECT_NONFINITE("dq2 * dq with " << w, g.dq2 * dq);
        EXPECT_SOME_NAN("inverse(dq) (doc: NaN) with " << w, quat::inverse(dq));
        EXPECT_SOME_NAN("normalize(dq) (doc: holds NaN) with " << w, quat::normalize(dq));
        EXPECT_EMPTY("try_normalize(dq) with " << w, quat::try_normalize(dq));
        EXPECT_NONFINITE("transform(dq, p) [silent doc] with " << w, quat::transform(dq, g.v2));
        EXPECT_SOME_NAN("to_screw(dq) (doc: NaN) with " << w, quat::to_screw(dq));
        EXPECT_NONFINITE("to_homogeneous(dq) [silent doc] with " << w, quat::to_homogeneous(dq));
    });
    for_each_bad<T>("dq.real", g.dq.real, [&](const quaternion<T>& q, const std::string& w) {
        const dual_quaternion<T> dq{q, g.dq.dual};
        EXPECT_NONFINITE("translation_of(dq) [silent doc] with " << w, quat::translation_of(dq));
        EXPECT_NONFINITE("transform_vector(dq, v) [silent doc] with " << w,
                         quat::transform_vector(dq, g.v2));
    });
    for_each_bad<T>("dq.dual", g.dq.dual, [&](const quaternion<T>& q, const std::string& w) {
        const dual_quaternion<T> dq{g.dq.real, q};
        EXPECT_NONFINITE("translation_of(dq) with " << w, quat::translation_of(dq));
    });
    for_each_bad<T>("p", g.v2, [&](const vec3<T>& p, const std::string& w) {
        EXPECT_NONFINITE("transform(dq, p) [silent doc] with " << w, quat::transform(g.dq, p));
        EXPECT_NONFINITE("transform_vector(dq, v) [silent doc] with " << w,
                         quat::transform_vector(g.dq, p));
    });
    const quat::screw<T> s = quat::to_screw(g.dq);
    for_each_bad<T>("screw", s, [&](const quat::screw<T>& bad, const std::string& w) {
        EXPECT_NONFINITE("from_screw(s) [silent doc] with " << w, quat::from_screw(bad));
    });
}

HOSTILE("sclerp", "sclerp") {
    using T = TestType;
    const good<T> g;
    for (const T t : {T(0), T(0.3), T(1), T(1.5)})
        for_each_bad<T>("a", g.dq, [&](const dual_quaternion<T>& a, const std::string& w) {
            EXPECT_NONFINITE("sclerp(a, b, " << t << ") with " << w, quat::sclerp(a, g.dq2, t));
            EXPECT_NONFINITE("sclerp(b, a, " << t << ") with " << w, quat::sclerp(g.dq2, a, t));
        });
    for_each_bad<T>("t", g.t, [&](T t, const std::string& w) {
        EXPECT_NONFINITE("sclerp(a, b, t) with " << w, quat::sclerp(g.dq, g.dq2, t));
        EXPECT_NONFINITE("sclerp(a, a, t) with " << w, quat::sclerp(g.dq, g.dq, t));
    });
}

// ======================= rigid/homogeneous_matrix.hpp, rigid/blend.hpp =======================

HOSTILE("homogeneous_matrix functions", "homogeneous_matrix") {
    using T = TestType;
    const good<T> g;
    const homogeneous_matrix<T> h2 = quat::to_homogeneous(g.dq2);
    for_each_bad<T>("h", g.h, [&](const homogeneous_matrix<T>& h, const std::string& w) {
        EXPECT_NONFINITE("h * h2 with " << w, h * h2);
        EXPECT_NONFINITE("h2 * h with " << w, h2 * h);
        EXPECT_NONFINITE("transform(h, p) [silent doc] with " << w, quat::transform(h, g.v2));
        EXPECT_NONFINITE("to_dual_quaternion(h) [silent doc] with " << w,
                         quat::to_dual_quaternion(h));
        EXPECT_EMPTY("try_to_dual_quaternion(h) with " << w, quat::try_to_dual_quaternion(h));
    });
    // The last row: not read by transform (documented), but try_to_dual_quaternion checks it.
    for (const T bad : bad_values<T>())
        for (int j = 0; j < 4; ++j) {
            homogeneous_matrix<T> h = g.h;
            h.elements[3][j] = bad;
            EXPECT_EMPTY("try_to_dual_quaternion(h) with h[3][" << j << "]=" << bad,
                         quat::try_to_dual_quaternion(h));
        }
    EXPECT_EMPTY("try_to_dual_quaternion(h, NaN tolerance)",
                 quat::try_to_dual_quaternion(g.h, std::numeric_limits<T>::quiet_NaN()));
    for (const T bad : bad_values<T>())
        for (int i = 0; i < 9; ++i) {
            homogeneous_matrix<T> h = g.h;
            h.elements[i / 3][i % 3] = bad;
            EXPECT_NONFINITE("transform_vector(h, v) [silent doc] with h[" << i / 3 << "][" << i % 3
                                                                           << "]=" << bad,
                             quat::transform_vector(h, g.v2));
        }
    for_each_bad<T>("p", g.v2, [&](const vec3<T>& p, const std::string& w) {
        EXPECT_NONFINITE("transform(h, p) [silent doc] with " << w, quat::transform(g.h, p));
        EXPECT_NONFINITE("transform_vector(h, v) [silent doc] with " << w,
                         quat::transform_vector(g.h, p));
    });
}

HOSTILE("blend", "blend") {
    using T = TestType;
    const good<T> g;
    const std::vector<dual_quaternion<T>> transforms{g.dq, g.dq2,
                                                     quat::to_dual_quaternion(g.q3, g.v)};
    const std::vector<T> weights{T(0.5), T(0.3), T(0.2)};
    for (std::size_t k = 0; k < transforms.size(); ++k)
        for_each_bad<T>("transforms[k]", transforms[k],
                        [&](const dual_quaternion<T>& dq, const std::string& w) {
                            std::vector<dual_quaternion<T>> d = transforms;
                            d[k] = dq;
                            EXPECT_NONFINITE("blend k=" << k << " [silent doc] with " << w,
                                             quat::blend(d, weights));
                        });
    for (std::size_t k = 0; k < weights.size(); ++k)
        for (const T bad : bad_values<T>()) {
            std::vector<T> w = weights;
            w[k] = bad;
            EXPECT_ALL_NAN("blend weights[" << k << "]=" << bad << " (doc: NaN)",
                           quat::blend(transforms, w));
        }
}

// ======================= batch/rotations.hpp, batch/rigid_motions.hpp, batch/elementwise.hpp
// ======================= A bad element stays bad in its own output (the scalar function's
// expectation), and the other outputs stay finite; a bad shared argument (q, m, a, b) makes every
// output bad.

namespace {
constexpr std::size_t batch_size = 37;  // not a multiple of any vector width
constexpr std::size_t bad_positions[] = {0, 17, 36};

template <class T>
std::vector<vec3<T>> batch_points() {
    std::vector<vec3<T>> p(batch_size);
    for (std::size_t i = 0; i < batch_size; ++i)
        p[i] = vec3<T>{T(0.1) * T(i % 7), T(1) - T(0.05) * T(i), T(0.3) + T(0.01) * T(i)};
    return p;
}

template <class T, class V>
void check_one_bad(const std::string& where, const std::vector<V>& out, std::size_t bad) {
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (i == bad) {
            INFO(where << ": output[" << i << "] (the bad element) = (" << show(out[i])
                       << "); expected a non-finite component");
            CHECK(any_nonfinite(out[i]));
        } else {
            INFO(where << ": output[" << i << "] (a good element) = (" << show(out[i])
                       << "); expected finite");
            CHECK(all_finite(out[i]));
        }
    }
}

template <class T, class V>
void check_all_bad(const std::string& where, const std::vector<V>& out) {
    for (std::size_t i = 0; i < out.size(); ++i) {
        INFO(where << ": output[" << i << "] = (" << show(out[i])
                   << "); expected a non-finite component");
        CHECK(any_nonfinite(out[i]));
    }
}

template <class T>
std::vector<vec3<T>> soa_rotate(const quaternion<T>& q, const std::vector<vec3<T>>& p) {
    std::vector<T> x, y, z;
    for (const vec3<T>& v : p) {
        x.push_back(v.x);
        y.push_back(v.y);
        z.push_back(v.z);
    }
    std::vector<T> ox(p.size()), oy(p.size()), oz(p.size());
    quat::rotate(q, quat::soa_points<const T>{x.data(), y.data(), z.data(), p.size()},
                 quat::soa_points<T>{ox.data(), oy.data(), oz.data(), p.size()});
    std::vector<vec3<T>> out;
    for (std::size_t i = 0; i < p.size(); ++i) out.push_back({ox[i], oy[i], oz[i]});
    return out;
}
}  // namespace

HOSTILE("batch rotate and compose", "batch") {
    using T = TestType;
    const good<T> g;
    const std::vector<vec3<T>> points = batch_points<T>();
    for (const std::size_t k : bad_positions)
        for_each_bad<T>("point", points[k], [&](const vec3<T>& v, const std::string& w) {
            std::vector<vec3<T>> p = points, out(batch_size);
            p[k] = v;
            std::ostringstream where;
            where << "k=" << k << " " << w;
            quat::rotate(g.q, p, out);
            check_one_bad<T>("batch rotate(q, AoS) " + where.str(), out, k);
            quat::rotate(g.m, p, out);
            check_one_bad<T>("batch rotate(m, AoS) " + where.str(), out, k);
            check_one_bad<T>("batch rotate(q, SoA) " + where.str(), soa_rotate(g.q, p), k);
        });
    for_each_bad<T>("q", g.q, [&](const quaternion<T>& q, const std::string& w) {
        std::vector<vec3<T>> out(batch_size);
        quat::rotate(q, points, out);
        check_all_bad<T>("batch rotate(q, AoS) with " + w, out);
        check_all_bad<T>("batch rotate(q, SoA) with " + w, soa_rotate(q, points));
    });
    const std::vector<quaternion<T>> factors(batch_size, g.q);
    for (const std::size_t k : bad_positions)
        for_each_bad<T>("factor", g.q, [&](const quaternion<T>& q, const std::string& w) {
            std::vector<quaternion<T>> f = factors;
            f[k] = q;
            EXPECT_NONFINITE("compose(factors) k=" << k << " with " << w, quat::compose(f));
            EXPECT_NONFINITE("compose(first 5) k=0 with " << w,
                             quat::compose(f.data(), k < 5 ? 5 : k + 1));
        });
}

HOSTILE("batch slerp", "batch") {
    using T = TestType;
    const good<T> g;
    std::vector<T> ts(batch_size);
    for (std::size_t i = 0; i < batch_size; ++i) ts[i] = T(i) / T(batch_size - 1);
    for (const quaternion<T>& b : {g.q2, g.q})
        for (const std::size_t k : bad_positions)
            for_each_bad<T>("t", ts[k], [&](T t, const std::string& w) {
                std::vector<T> tt = ts;
                tt[k] = t;
                std::vector<quaternion<T>> out(batch_size);
                quat::slerp(g.q, b, tt, out);
                check_one_bad<T>(
                    "batch slerp (b = " + show(b) + "), k=" + std::to_string(k) + " " + w, out, k);
            });
    for_each_bad<T>("a", g.q, [&](const quaternion<T>& a, const std::string& w) {
        std::vector<quaternion<T>> out(batch_size);
        quat::slerp(a, g.q2, ts, out);
        check_all_bad<T>("batch slerp(a, b, t) with " + w, out);
        quat::slerp(g.q2, a, ts, out);
        check_all_bad<T>("batch slerp(b, a, t) with " + w, out);
    });
}

HOSTILE("rigid batch", "rigid_batch") {
    using T = TestType;
    const good<T> g;
    const std::vector<vec3<T>> points = batch_points<T>();
    for (const std::size_t k : bad_positions)
        for_each_bad<T>("point", points[k], [&](const vec3<T>& v, const std::string& w) {
            std::vector<vec3<T>> p = points, out(batch_size);
            p[k] = v;
            const std::string where = "k=" + std::to_string(k) + " " + w;
            quat::transform(g.dq, p, out);
            check_one_bad<T>("batch transform(dq) " + where, out, k);
            quat::transform(g.h, p, out);
            check_one_bad<T>("batch transform(h) " + where, out, k);
        });
    for_each_bad<T>("dq", g.dq, [&](const dual_quaternion<T>& dq, const std::string& w) {
        std::vector<vec3<T>> out(batch_size);
        quat::transform(dq, points, out);
        check_all_bad<T>("batch transform(dq) with " + w, out);
    });
    const std::vector<dual_quaternion<T>> factors(batch_size, g.dq);
    for (const std::size_t k : bad_positions)
        for_each_bad<T>("factor", g.dq, [&](const dual_quaternion<T>& dq, const std::string& w) {
            std::vector<dual_quaternion<T>> f = factors;
            f[k] = dq;
            EXPECT_NONFINITE("compose(dual factors) k=" << k << " with " << w, quat::compose(f));
        });
}

HOSTILE("elementwise", "elementwise") {
    using T = TestType;
    const good<T> g;
    const std::vector<vec3<T>> points = batch_points<T>();
    const std::vector<quaternion<T>> rotations(batch_size, g.q), others(batch_size, g.q2);
    const std::vector<rotation_matrix<T>> matrices(batch_size, g.m);
    for (const std::size_t k : bad_positions) {
        const std::string at = "k=" + std::to_string(k) + " ";
        for_each_bad<T>("rotation", g.q, [&](const quaternion<T>& q, const std::string& w) {
            std::vector<quaternion<T>> r = rotations, composed(batch_size);
            r[k] = q;
            std::vector<vec3<T>> out(batch_size);
            quat::rotate_each(r, points, out);
            check_one_bad<T>("rotate_each " + at + w, out, k);
            quat::compose_each(r, others, composed);
            check_one_bad<T>("compose_each(a bad) " + at + w, composed, k);
            quat::compose_each(others, r, composed);
            check_one_bad<T>("compose_each(b bad) " + at + w, composed, k);
            std::vector<rotation_matrix<T>> m(batch_size);
            quat::to_matrix_each(r, m);
            check_one_bad<T>("to_matrix_each " + at + w, m, k);
            // SoA rotate_each
            std::vector<T> qw, qx, qy, qz, px, py, pz;
            for (std::size_t i = 0; i < batch_size; ++i) {
                qw.push_back(r[i].w);
                qx.push_back(r[i].x);
                qy.push_back(r[i].y);
                qz.push_back(r[i].z);
                px.push_back(points[i].x);
                py.push_back(points[i].y);
                pz.push_back(points[i].z);
            }
            std::vector<T> ox(batch_size), oy(batch_size), oz(batch_size);
            quat::rotate_each(
                quat::soa_quaternions<const T>{qw.data(), qx.data(), qy.data(), qz.data(),
                                               batch_size},
                quat::soa_points<const T>{px.data(), py.data(), pz.data(), batch_size},
                quat::soa_points<T>{ox.data(), oy.data(), oz.data(), batch_size});
            std::vector<vec3<T>> soa_out;
            for (std::size_t i = 0; i < batch_size; ++i) soa_out.push_back({ox[i], oy[i], oz[i]});
            check_one_bad<T>("rotate_each SoA " + at + w, soa_out, k);
        });
        for_each_bad<T>("point", points[k], [&](const vec3<T>& v, const std::string& w) {
            std::vector<vec3<T>> p = points, out(batch_size);
            p[k] = v;
            quat::rotate_each(rotations, p, out);
            check_one_bad<T>("rotate_each " + at + w, out, k);
        });
        for_each_bad<T>("matrix", g.m, [&](const rotation_matrix<T>& mm, const std::string& w) {
            std::vector<rotation_matrix<T>> m = matrices;
            m[k] = mm;
            std::vector<quaternion<T>> out(batch_size);
            quat::to_quaternion_each(m, out);
            check_one_bad<T>("to_quaternion_each " + at + w, out, k);
        });
    }
}

// ======================= extreme magnitudes =======================
// Functions documented for any non-zero scale or length give the result of the unit-scaled input.

namespace {
template <class T>
struct scale_case {
    std::string name;
    T factor;  // multiplies a direction whose largest |component| is 4
};

template <class T>
std::vector<scale_case<T>> extreme_scales() {
    using L = std::numeric_limits<T>;
    std::vector<scale_case<T>> s;
    if constexpr (std::is_same_v<T, double>) {
        s.push_back({"1e-300", 1e-300 / 4});
        s.push_back({"1e300", 1e300 / 4});
        s.push_back({"2^-1030 (subnormal)", std::ldexp(1.0, -1032)});
    } else {
        s.push_back({"1e-38", 1e-38f / 4});
        s.push_back({"1e38", 1e38f / 4});
        s.push_back({"2^-140 (subnormal)", std::ldexp(1.0f, -142)});
    }
    s.push_back({"denorm_min", L::denorm_min()});  // small integer multiples of it: exact
    s.push_back({"max", L::max() / 4});
    return s;
}

template <class T>
bool close(const flat_t& a, const flat_t& b, T tolerance) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!(std::fabs(a[i] - b[i]) <= tolerance * (1 + std::fabs(b[i])))) return false;
    return true;
}

#define EXPECT_SAME(where, got_expr, want_expr, tolerance)                             \
    do {                                                                               \
        const auto got_ = (got_expr);                                                  \
        const auto want_ = (want_expr);                                                \
        INFO(where << " -> (" << show(got_) << "); expected (" << show(want_) << ")"); \
        CHECK(close(flatten(got_), flatten(want_), tolerance));                        \
    } while (0)
}  // namespace

TEMPLATE_TEST_CASE("hostile: extreme magnitudes, vec3 and quaternion", "[hostile][magnitude]",
                   float, double) {
    using T = TestType;
    const T tol = T(16) * std::numeric_limits<T>::epsilon();
    const vec3<T> d{T(4), T(-2), T(4)};               // |d| = 6
    const quaternion<T> dq{T(4), T(1), T(-2), T(2)};  // |dq| = 5
    const vec3<T> unit_v = d / T(6);
    const quaternion<T> unit_q = dq / T(5);
    for (const auto& s : extreme_scales<T>()) {
        const vec3<T> v = d * s.factor;
        const quaternion<T> q = dq * s.factor;
        const std::string at = " at scale " + s.name;
        EXPECT_SAME("normalize(vec3)" << at, quat::normalize(v), unit_v, tol);
        {
            const auto r = quat::try_normalize(v);
            INFO("try_normalize(vec3)" << at);
            CHECK(r.has_value());
            if (r) EXPECT_SAME("try_normalize(vec3)" << at, *r, unit_v, tol);
        }
        // |v| is 1.5 max at the largest scale: overflow to Inf is the right answer there.
        if (s.factor * T(6) <= std::numeric_limits<T>::max())
            EXPECT_SAME("norm(vec3) / scale" << at, quat::norm(v) / s.factor, T(6), tol);
        EXPECT_SAME("normalize(q)" << at, quat::normalize(q), unit_q, tol);
        {
            const auto r = quat::try_normalize(q);
            INFO("try_normalize(q)" << at);
            CHECK(r.has_value());
            if (r) EXPECT_SAME("try_normalize(q)" << at, *r, unit_q, tol);
        }
        if (s.factor * T(5) <= std::numeric_limits<T>::max())
            EXPECT_SAME("norm(q) / scale" << at, quat::norm(q) / s.factor, T(5), tol);
        // inverse: accurate wherever the inverse is representable (|q| = 1e300 gives 1e-300).
        if (T(1) / (T(5) * s.factor) >= std::numeric_limits<T>::min() &&
            T(1) / (T(5) * s.factor) <= std::numeric_limits<T>::max())
            EXPECT_SAME("inverse(q) * 5 scale" << at, quat::inverse(q) * (T(5) * s.factor),
                        quat::conjugate(unit_q), tol);
        EXPECT_SAME("to_axis_angle(q)" << at, quat::to_axis_angle(q), quat::to_axis_angle(unit_q),
                    tol);
        EXPECT_SAME("to_axis_angle(-q)" << at, quat::to_axis_angle(-q), quat::to_axis_angle(unit_q),
                    tol);
        EXPECT_SAME("to_rotation_vector(q)" << at, quat::to_rotation_vector(q),
                    quat::to_rotation_vector(unit_q), tol);
        EXPECT_SAME("to_mrp(q)" << at, quat::to_mrp(q), quat::to_mrp(unit_q), tol);
        EXPECT_SAME("to_euler<zyx>(q)" << at, quat::to_euler<sequence::zyx>(q),
                    quat::to_euler<sequence::zyx>(unit_q), tol);
        EXPECT_SAME("to_euler<zxz>(q)" << at, quat::to_euler<sequence::zxz>(q),
                    quat::to_euler<sequence::zxz>(unit_q), tol);
        const euler<T> previous{T(0.1), T(0.2), T(0.3)};
        EXPECT_SAME("to_euler<zyx>(q, previous)" << at,
                    (quat::to_euler<sequence::zyx>(q, previous)),
                    (quat::to_euler<sequence::zyx>(unit_q, previous)), tol);
        // A pure rotation about an axis (w = 0 and w = 0-ish), scaled.
        const quaternion<T> half_turn{T(0), T(4), T(0), T(0)};
        EXPECT_SAME("to_axis_angle(half turn)" << at, quat::to_axis_angle(half_turn * s.factor),
                    quat::to_axis_angle(quaternion<T>{T(0), T(1), T(0), T(0)}), tol);
        EXPECT_SAME("to_rotation_vector(identity)" << at,
                    quat::to_rotation_vector(quaternion<T>{T(4), T(0), T(0), T(0)} * s.factor),
                    (vec3<T>{T(0), T(0), T(0)}), tol);
        {
            const axis_angle<T> aa{v, T(0.7)};
            const auto r = quat::try_to_quaternion(aa);
            INFO("try_to_quaternion(axis_angle with axis scaled)" << at);
            CHECK(r.has_value());
            if (r)
                EXPECT_SAME("try_to_quaternion(axis_angle)" << at, *r,
                            quat::to_quaternion(axis_angle<T>{unit_v, T(0.7)}), tol);
        }
        {
            const quaternion<T> r = quat::from_mrp(v);
            INFO("from_mrp(p) with p " << show(v) << at << " -> (" << show(r)
                                       << "); expected a finite unit quaternion");
            CHECK(all_finite(r));
            CHECK(std::fabs(quat::squared_norm(r) - T(1)) <= tol);
        }
    }
}

TEMPLATE_TEST_CASE("hostile: extreme magnitudes, align and swing_twist", "[hostile][magnitude]",
                   float, double) {
    using T = TestType;
    const T tol = T(16) * std::numeric_limits<T>::epsilon();
    const vec3<T> from{T(4), T(-2), T(4)}, to{T(-1), T(4), T(2)}, up{T(0), T(4), T(1)};
    const vec3<T> opposite = -from;
    const good<T> g;
    for (const auto& s : extreme_scales<T>())
        for (const auto& s2 : extreme_scales<T>()) {
            const std::string at = " at scales " + s.name + ", " + s2.name;
            EXPECT_SAME("rotation_between" << at,
                        quat::rotation_between(from * s.factor, to * s2.factor),
                        quat::rotation_between(from / T(6), to / T(std::sqrt(21.0))), tol);
            EXPECT_SAME("rotation_between(opposite)" << at,
                        quat::rotation_between(from * s.factor, opposite * s2.factor),
                        quat::rotation_between(from, opposite), tol);
            {
                const auto r = quat::try_rotation_between(from * s.factor, to * s2.factor);
                INFO("try_rotation_between" << at);
                CHECK(r.has_value());
                if (r)
                    EXPECT_SAME("try_rotation_between" << at, *r, quat::rotation_between(from, to),
                                tol);
            }
            EXPECT_SAME("look_rotation" << at, quat::look_rotation(from * s.factor, up * s2.factor),
                        quat::look_rotation(from, up), tol);
            {
                const auto r = quat::try_look_rotation(from * s.factor, up * s2.factor);
                INFO("try_look_rotation" << at);
                CHECK(r.has_value());
                if (r)
                    EXPECT_SAME("try_look_rotation" << at, *r, quat::look_rotation(from, up), tol);
            }
        }
    for (const auto& s : extreme_scales<T>()) {
        const std::string at = " at scale " + s.name;
        EXPECT_SAME("swing_twist axis" << at, quat::swing_twist(g.q, from * s.factor),
                    quat::swing_twist(g.q, from), tol);
        const auto r = quat::try_swing_twist(g.q, from * s.factor);
        INFO("try_swing_twist" << at);
        CHECK(r.has_value());
        if (r) EXPECT_SAME("try_swing_twist axis" << at, *r, quat::swing_twist(g.q, from), tol);
    }
}

TEST_CASE("hostile: extreme magnitudes, the named cases", "[hostile][magnitude]") {
    const double tol = 16 * std::numeric_limits<double>::epsilon();
    const double h = std::sqrt(0.5);
    EXPECT_SAME("normalize(vec3{1.3e308, 1.3e308, 0})",
                quat::normalize(vec3<double>{1.3e308, 1.3e308, 0}), (vec3<double>{h, h, 0}), tol);
    EXPECT_SAME("normalize(vec3{5e-324, 5e-324, 0})",
                quat::normalize(vec3<double>{5e-324, 5e-324, 0}), (vec3<double>{h, h, 0}), tol);
    EXPECT_SAME("normalize(vec3{max, max, max})",
                quat::normalize(vec3<double>{std::numeric_limits<double>::max(),
                                             std::numeric_limits<double>::max(),
                                             std::numeric_limits<double>::max()}),
                (vec3<double>{1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)}), tol);
    EXPECT_SAME("normalize(vec3f{1e38, 1e38, 0})", quat::normalize(vec3<float>{1e38f, 1e38f, 0}),
                (vec3<float>{float(h), float(h), 0}), 16 * std::numeric_limits<float>::epsilon());
    EXPECT_SAME("normalize(vec3f{denorm_min x2})",
                quat::normalize(vec3<float>{std::numeric_limits<float>::denorm_min(),
                                            std::numeric_limits<float>::denorm_min(), 0}),
                (vec3<float>{float(h), float(h), 0}), 16 * std::numeric_limits<float>::epsilon());
    {
        const quaternion<double> q =
            quat::rotation_between(vec3<double>{1, 0, 0}, vec3<double>{-1, 1e-322, 1e-322});
        INFO("rotation_between((1,0,0), (-1, 1e-322, 1e-322)) -> ("
             << show(q) << "), |q|^2 - 1 = " << quat::squared_norm(q) - 1);
        CHECK(std::fabs(quat::squared_norm(q) - 1) <= 4 * std::numeric_limits<double>::epsilon());
    }
    {
        const quaternion<float> q =
            quat::rotation_between(vec3<float>{1, 0, 0}, vec3<float>{-1, 1e-44f, 1e-44f});
        INFO("rotation_between((1,0,0), (-1, 1e-44f, 1e-44f)) -> (" << show(q) << ")");
        CHECK(std::fabs(quat::squared_norm(q) - 1) <= 4 * std::numeric_limits<float>::epsilon());
    }
}

TEMPLATE_TEST_CASE("hostile: extreme magnitudes, nearest_rotation and rotation_spline",
                   "[hostile][magnitude]", float, double) {
    using T = TestType;
    using L = std::numeric_limits<T>;
    const T tol = T(64) * L::epsilon();
    const good<T> g;
    for (const T factor :
         {std::ldexp(T(1), L::min_exponent + 4), std::ldexp(T(1), L::max_exponent - 2)}) {
        rotation_matrix<T> m = g.m;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m.elements[i][j] *= factor;
        EXPECT_SAME("nearest_rotation(" << factor << " R)", quat::nearest_rotation(m), g.m, tol);
        const auto r = quat::try_nearest_rotation(m);
        INFO("try_nearest_rotation(" << factor << " R)");
        CHECK(r.has_value());
        if (r) EXPECT_SAME("try_nearest_rotation(" << factor << " R)", *r, g.m, tol);
    }
    // "non-zero quaternions, normalized here": keyframes of any scale give the same spline. Turns
    // well below a half turn, so rounding cannot flip which way a segment goes.
    const std::vector<T> times{T(0), T(1), T(2.5), T(4)};
    const quaternion<T> k1 = g.q * quat::rotation_x(T(0.5)), k2 = k1 * quat::rotation_y(T(-0.7));
    const std::vector<quaternion<T>> keys{g.q, k1, k2, k2 * quat::rotation_z(T(0.9))};
    const quat::rotation_spline<T> reference(times, keys);
    for (const auto& s : extreme_scales<T>()) {
        if (s.factor < L::min())
            continue;  // a unit quaternion times a subnormal loses its direction
        std::vector<quaternion<T>> scaled_keys;
        for (const quaternion<T>& q : keys) scaled_keys.push_back(q * s.factor);
        const quat::rotation_spline<T> spline(times, scaled_keys);
        for (const T t : {T(0), T(0.7), T(2), T(4)})
            EXPECT_SAME("rotation_spline with keyframes scaled " << s.name << " at t=" << t,
                        spline(t), reference(t), tol);
        const auto made = quat::rotation_spline<T>::try_make(times, scaled_keys);
        INFO("rotation_spline::try_make with keyframes scaled " << s.name);
        CHECK(made.has_value());
    }
}

}  // namespace test_hostile_inputs

#undef EXPECT_SAME
