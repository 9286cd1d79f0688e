// The machinery of the hostile-input tests (test_hostile_inputs.cpp for quat.hpp's functions,
// test_hostile_estimation.cpp for the opt-in families): every value type flattened into its scalar
// components, one component at a time replaced by NaN, +Inf or -Inf, and checks that name the call
// and the input in their message, so that a failure list reads as a report.
#ifndef QUAT_TESTS_SUPPORT_HOSTILE_HPP_INCLUDED
#define QUAT_TESTS_SUPPORT_HOSTILE_HPP_INCLUDED

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <quat/lie/se3.hpp>
#include <quat/quat.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>

#include "catch.hpp"

namespace quat::test::hostile {

using quat::axis_angle;
using quat::dual_quaternion;
using quat::euler;
using quat::frame;
using quat::homogeneous_matrix;
using quat::quaternion;
using quat::rotation_matrix;
using quat::sequence;
using quat::vec3;

// ---- flattening a result into its scalar components ----

using flat_t = std::vector<long double>;

inline void flat(flat_t& o, float x) { o.push_back(x); }
inline void flat(flat_t& o, double x) { o.push_back(x); }
template <class T>
void flat(flat_t& o, const vec3<T>& v) {
    flat(o, v.x);
    flat(o, v.y);
    flat(o, v.z);
}
template <class T>
void flat(flat_t& o, const quaternion<T>& q) {
    flat(o, q.w);
    flat(o, q.x);
    flat(o, q.y);
    flat(o, q.z);
}
template <class T>
void flat(flat_t& o, const rotation_matrix<T>& m) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) flat(o, m.elements[i][j]);
}
template <class T>
void flat(flat_t& o, const homogeneous_matrix<T>& m) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) flat(o, m.elements[i][j]);
}
template <class T>
void flat(flat_t& o, const axis_angle<T>& a) {
    flat(o, a.axis);
    flat(o, a.angle);
}
template <class T, sequence S, frame F>
void flat(flat_t& o, const euler<T, S, F>& e) {
    for (int i = 0; i < 3; ++i) flat(o, e.angles[i]);
}
template <class T>
void flat(flat_t& o, const dual_quaternion<T>& dq) {
    flat(o, dq.real);
    flat(o, dq.dual);
}
template <class T>
void flat(flat_t& o, const quat::screw<T>& s) {
    flat(o, s.direction);
    flat(o, s.moment);
    flat(o, s.angle);
    flat(o, s.displacement);
}
template <class T>
void flat(flat_t& o, const quat::swing_twist_parts<T>& p) {
    flat(o, p.swing);
    flat(o, p.twist);
}
template <class T>
void flat(flat_t&, const quat::rotation_spline<T>&) {}  // shown as "engaged ()"

template <class T, int R, int C>
void flat(flat_t& o, const quat::matrix<T, R, C>& m) {
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) flat(o, m(i, j));
}
template <class T>
void flat(flat_t& o, const quat::se3::twist<T>& t) {
    flat(o, t.linear);
    flat(o, t.angular);
}
// A fit's answer and residuals; its unique flag is checked on its own.
template <class T>
void flat(flat_t& o, const quat::point_alignment<T>& a) {
    flat(o, a.motion);
    flat(o, a.rms);
}
template <class T>
void flat(flat_t& o, const quat::similarity_alignment<T>& a) {
    flat(o, a.motion);
    flat(o, a.rms);
    flat(o, a.scale);
}
template <class T>
void flat(flat_t& o, const quat::hand_eye_calibration<T>& c) {
    flat(o, c.mount);
    flat(o, c.rotation_rms);
    flat(o, c.translation_rms);
}
template <class T>
void flat(flat_t& o, const quat::hand_eye_with_target<T>& r) {
    flat(o, r.calibration);
    flat(o, r.target);
}

template <class R>
flat_t flatten(const R& r) {
    flat_t o;
    flat(o, r);
    return o;
}

template <class R>
std::string show(const R& r) {
    std::ostringstream s;
    s.precision(9);
    const flat_t v = flatten(r);
    for (std::size_t i = 0; i < v.size(); ++i) s << (i ? ", " : "") << v[i];
    return s.str();
}

template <class R>
bool all_nan(const R& r) {
    for (const long double x : flatten(r))
        if (!std::isnan(x)) return false;
    return true;
}
template <class R>
bool any_nonfinite(const R& r) {
    for (const long double x : flatten(r))
        if (!std::isfinite(x)) return true;
    return false;
}
template <class R>
bool any_nan(const R& r) {
    for (const long double x : flatten(r))
        if (std::isnan(x)) return true;
    return false;
}
template <class R>
bool all_finite(const R& r) {
    return !any_nonfinite(r);
}

// Each check names the call and the input in its message, so a failure list reads as a report.
#define EXPECT_ALL_NAN(where, expr)                                                             \
    do {                                                                                        \
        const auto result_ = (expr);                                                            \
        INFO(where << " -> (" << show(result_) << "); expected NaN in every component"          \
                   << (any_nonfinite(result_) ? " [weak rule holds]" : " [WEAK RULE BROKEN]")); \
        CHECK(all_nan(result_));                                                                \
    } while (0)
#define EXPECT_NONFINITE(where, expr)                                                    \
    do {                                                                                 \
        const auto result_ = (expr);                                                     \
        INFO(where << " -> (" << show(result_) << "); expected a non-finite component"); \
        CHECK(any_nonfinite(result_));                                                   \
    } while (0)
#define EXPECT_SOME_NAN(where, expr)                                              \
    do {                                                                          \
        const auto result_ = (expr);                                              \
        INFO(where << " -> (" << show(result_) << "); expected a NaN component"); \
        CHECK(any_nan(result_));                                                  \
    } while (0)
#define EXPECT_FALSE_(where, expr)                              \
    do {                                                        \
        const bool result_ = (expr);                            \
        INFO(where << " -> " << result_ << "; expected false"); \
        CHECK_FALSE(result_);                                   \
    } while (0)
#define EXPECT_EMPTY(where, expr)                                                        \
    do {                                                                                 \
        const auto result_ = (expr);                                                     \
        INFO(where << " -> " << (result_ ? "engaged (" + show(*result_) + ")" : "empty") \
                   << "; expected empty");                                               \
        CHECK_FALSE(result_.has_value());                                                \
    } while (0)

// ---- the bad values and where they go ----

template <class T>
std::vector<T> bad_values() {
    return {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
            -std::numeric_limits<T>::infinity()};
}

template <class T>
int count_of(const T&) {
    return 1;
}
template <class T>
int count_of(const vec3<T>&) {
    return 3;
}
template <class T>
int count_of(const quaternion<T>&) {
    return 4;
}
template <class T>
int count_of(const rotation_matrix<T>&) {
    return 9;
}
template <class T>
int count_of(const dual_quaternion<T>&) {
    return 8;
}
template <class T>
int count_of(const homogeneous_matrix<T>&) {
    return 12;  // the last row is documented as not read by transform; see the report
}
template <class T>
int count_of(const axis_angle<T>&) {
    return 4;
}
template <class T, sequence S, frame F>
int count_of(const euler<T, S, F>&) {
    return 3;
}
template <class T>
int count_of(const quat::screw<T>&) {
    return 8;
}

template <class T>
int count_of(const quat::se3::twist<T>&) {
    return 6;
}
template <class T, int R, int C>
int count_of(const quat::matrix<T, R, C>&) {
    return R * C;
}

template <class T>
T* slot(T& x, int) {
    return &x;
}
template <class T>
T* slot(vec3<T>& v, int i) {
    T* p[] = {&v.x, &v.y, &v.z};
    return p[i];
}
template <class T>
T* slot(quaternion<T>& q, int i) {
    T* p[] = {&q.w, &q.x, &q.y, &q.z};
    return p[i];
}
template <class T>
T* slot(rotation_matrix<T>& m, int i) {
    return &m.elements[i / 3][i % 3];
}
template <class T>
T* slot(dual_quaternion<T>& dq, int i) {
    return i < 4 ? slot(dq.real, i) : slot(dq.dual, i - 4);
}
template <class T>
T* slot(homogeneous_matrix<T>& m, int i) {
    return &m.elements[i / 4][i % 4];
}
template <class T>
T* slot(axis_angle<T>& a, int i) {
    return i < 3 ? slot(a.axis, i) : &a.angle;
}
template <class T, sequence S, frame F>
T* slot(euler<T, S, F>& e, int i) {
    return &e.angles[i];
}
template <class T>
T* slot(quat::screw<T>& s, int i) {
    if (i < 3) return slot(s.direction, i);
    if (i < 6) return slot(s.moment, i - 3);
    return i == 6 ? &s.angle : &s.displacement;
}

template <class T, int R, int C>
T* slot(quat::matrix<T, R, C>& m, int i) {
    return &m(i / C, i % C);
}
template <class T>
T* slot(quat::se3::twist<T>& t, int i) {
    return i < 3 ? slot(t.linear, i) : slot(t.angular, i - 3);
}

/// Calls f(x, "name[i]=value") for every component i of base and every bad value.
template <class T, class X, class F>
void for_each_bad(const char* name, const X& base, F&& f) {
    for (const T value : bad_values<T>())
        for (int i = 0; i < count_of(base); ++i) {
            X x = base;
            *slot(x, i) = value;
            std::ostringstream label;
            label << name << "[" << i << "]=" << value;
            f(x, label.str());
        }
}

// ---- well-behaved inputs that the bad values go into ----

template <class T>
struct good {
    quaternion<T> q = quat::normalize(quaternion<T>{T(0.9), T(0.1), T(-0.3), T(0.2)});
    quaternion<T> q2 = quat::normalize(quaternion<T>{T(0.2), T(-0.5), T(0.7), T(0.4)});
    quaternion<T> q3 = quat::normalize(quaternion<T>{T(-0.4), T(0.3), T(0.6), T(-0.1)});
    quaternion<T> q4 = quat::normalize(quaternion<T>{T(0.7), T(0.7), T(0.1), T(0.2)});
    vec3<T> v{T(0.3), T(-0.2), T(0.7)};
    vec3<T> v2{T(-0.6), T(0.5), T(0.1)};
    T t = T(0.3);
    rotation_matrix<T> m = quat::to_matrix(q);
    axis_angle<T> aa{quat::normalize(vec3<T>{T(1), T(2), T(2)}), T(0.7)};
    euler<T> e{T(0.3), T(-0.4), T(0.2)};
    dual_quaternion<T> dq = quat::to_dual_quaternion(q, v);
    dual_quaternion<T> dq2 = quat::to_dual_quaternion(q2, v2);
    homogeneous_matrix<T> h = quat::to_homogeneous(dq);
};

}  // namespace quat::test::hostile

#define HOSTILE(name, tag) TEMPLATE_TEST_CASE("hostile: " name, "[hostile][" tag "]", float, double)

#endif  // QUAT_TESTS_SUPPORT_HOSTILE_HPP_INCLUDED
