// The try_ functions are the checked API for untrusted input (quat.hpp: "try_* functions check
// untrusted input and return an empty std::optional instead of NaN"): whatever they are given
// (NaN or infinite components, zero, subnormal, huge, non-unit, empty or mismatched containers,
// bad weights or tolerances, unsorted times) they must return, never fire QUAT_ASSERT, and an
// engaged result must be finite (and, for a rotation, unit). Built without NDEBUG in every preset,
// so the debug checks are live. `quat_try_never_asserts` runs every case; `quat_try_never_asserts
// NAME` runs one (names are printed as they start), so a firing check does not hide the others.
#include <cmath>
#include <cstdio>
#if defined(__unix__) || defined(__APPLE__)
#include <sys/wait.h>
#include <unistd.h>
#define QUAT_TRY_CAN_FORK 1
#endif
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

// The call being made, for the handler's message.
static const char* quat_try_last_call = "";
#define QUAT_ASSERT(condition, message)                                                         \
    ((condition)                                                                                \
         ? void(0)                                                                              \
         : (std::fprintf(stdout, "QUAT_ASSERT fired in %s: %s\n", quat_try_last_call, message), \
            std::fflush(stdout), std::abort()))

#include <quat/lie/geodesic_mean.hpp>
#include <quat/quat.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>
#include <quat/trajectory.hpp>

namespace {

using quat::axis_angle;
using quat::dual_quaternion;
using quat::homogeneous_matrix;
using quat::quaternion;
using quat::rotation_matrix;
using quat::vec3;

int failures = 0;
const char* current = "";

template <class T>
bool finite(T x) {
    return std::isfinite(x);
}
template <class T>
bool finite(const vec3<T>& v) {
    return finite(v.x) && finite(v.y) && finite(v.z);
}
template <class T>
bool finite(const quaternion<T>& q) {
    return finite(q.w) && finite(q.x) && finite(q.y) && finite(q.z);
}
template <class T>
bool finite(const rotation_matrix<T>& m) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (!finite(m.elements[i][j])) return false;
    return true;
}
template <class T>
bool finite(const dual_quaternion<T>& dq) {
    return finite(dq.real) && finite(dq.dual);
}
template <class T>
bool finite(const quat::swing_twist_parts<T>& p) {
    return finite(p.swing) && finite(p.twist);
}

template <class T>
bool finite(const quat::alignment<T>& a) {
    return finite(a.rotation) && finite(a.rssd);
}

template <class T>
bool finite(const quat::hand_eye_calibration<T>& c) {
    return finite(c.mount) && finite(c.rotation_rms) && finite(c.translation_rms);
}
template <class T>
bool finite(const quat::hand_eye_with_target<T>& r) {
    return finite(r.calibration) && finite(r.target);
}
template <class T>
bool finite(const quat::point_alignment<T>& a) {
    return finite(a.motion) && finite(a.rms);
}
template <class T>
bool finite(const quat::similarity_alignment<T>& a) {
    return finite(a.motion) && finite(a.rms) && finite(a.scale) && a.scale > T(0);
}

template <class T>
bool finite(const quat::se3::twist<T>& x) {
    return finite(x.linear) && finite(x.angular);
}
template <class T, int R, int C>
bool finite(const quat::matrix<T, R, C>& m) {
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c)
            if (!finite(m(r, c))) return false;
    return true;
}
template <class T>
bool finite(const quat::so3_bspline_sample<T>& s) {
    return finite(s.rotation) && finite(s.angular_velocity) && finite(s.angular_acceleration) &&
           finite(s.angular_jerk);
}
template <class T>
bool finite(const quat::se3_bspline_sample<T>& s) {
    return finite(s.motion) && finite(s.velocity) && finite(s.acceleration) && finite(s.jerk);
}
template <class T>
bool finite(const quat::euclidean_bspline_sample<T>& s) {
    return finite(s.position) && finite(s.velocity) && finite(s.acceleration) && finite(s.jerk);
}
template <class T>
bool finite(const quat::split_bspline_sample<T>& s) {
    return finite(s.rotation) && finite(s.position) && finite(s.angular_velocity) &&
           finite(s.angular_acceleration) && finite(s.angular_jerk) && finite(s.linear_velocity) &&
           finite(s.linear_acceleration) && finite(s.linear_jerk) && finite(s.body_velocity) &&
           finite(s.body_acceleration);
}
template <class T>
bool finite(const quat::keyframe_path_state<T>& s) {
    return finite(s.pose) && finite(s.velocity) && finite(s.acceleration) &&
           finite(s.angular_velocity) && finite(s.angular_acceleration) &&
           finite(s.body_velocity) && finite(s.body_acceleration) &&
           finite(s.body_angular_velocity) && finite(s.body_angular_acceleration);
}

template <class T>
bool unit(const quat::alignment<T>& a) {
    return std::fabs(quat::squared_norm(a.rotation) - T(1)) <= T(1e-3);
}
template <class T>
bool unit(const quaternion<T>& q) {
    return std::fabs(quat::squared_norm(q) - T(1)) <= T(1e-3);
}
template <class T>
bool unit(const quat::hand_eye_calibration<T>& c) {
    return unit(c.mount.real) &&
           std::fabs(quat::dot(c.mount.real, c.mount.dual)) <= T(1e-3) * quat::norm(c.mount.dual);
}
template <class T>
bool unit(const quat::hand_eye_with_target<T>& r) {
    return unit(r.calibration) && unit(r.target.real) &&
           std::fabs(quat::dot(r.target.real, r.target.dual)) <=
               T(1e-3) * quat::norm(r.target.dual);
}
template <class T>
bool unit(const quat::point_alignment<T>& a) {
    // The dual part orthogonal to the real one, relative to its size (translations may be huge).
    return unit(a.motion.real) && std::fabs(quat::dot(a.motion.real, a.motion.dual)) <=
                                      T(1e-3) * quat::norm(a.motion.dual);
}
template <class T>
bool unit(const vec3<T>& v) {
    return std::fabs(quat::squared_norm(v) - T(1)) <= T(1e-3);
}
template <class T>
bool unit(const rotation_matrix<T>& m) {
    return quat::orthogonality_error(m) <= T(1e-3) && quat::determinant(m) > T(0);
}
template <class T>
bool unit(const dual_quaternion<T>& dq) {
    return unit(dq.real);
}
template <class T>
bool unit(const quat::swing_twist_parts<T>& p) {
    return unit(p.swing) && unit(p.twist);
}
template <class T>
bool unit(const quat::so3_bspline_sample<T>& s) {
    return unit(s.rotation);
}
template <class T>
bool unit(const quat::se3_bspline_sample<T>& s) {
    return unit(s.motion);
}
template <class T>
bool unit(const quat::split_bspline_sample<T>& s) {
    return unit(s.rotation);
}
template <class T>
bool unit(const quat::keyframe_path_state<T>& s) {
    return unit(s.pose);
}
template <class X>
bool unit(const X&) {
    return true;  // no unit-ness promised (try_inverse)
}

template <class X>
void check(const std::optional<X>& r, const std::string& call, bool rotation = true) {
    if (!r) return;
    if (!finite(*r)) {
        ++failures;
        std::printf("FAIL %s: %s returned an engaged optional holding NaN or Inf\n", current,
                    call.c_str());
    } else if (rotation && !unit(*r)) {
        ++failures;
        std::printf("FAIL %s: %s returned an engaged optional holding a non-unit rotation\n",
                    current, call.c_str());
    }
}

bool fork_each = false;  // `quat_try_never_asserts NAME --each`: every call in its own process

/// Runs f, the call described by `call`; with --each in a child process, so that a firing check
/// is reported and the remaining calls still run.
template <class F>
void guarded(const std::string& call, F&& f) {
    const std::string described = std::string(current) + ": " + call;
    quat_try_last_call = described.c_str();
#ifdef QUAT_TRY_CAN_FORK
    if (fork_each) {
        std::fflush(stdout);
        const pid_t child = fork();
        if (child == 0) {
            f();
            std::fflush(stdout);
            _exit(failures > 0 ? 1 : 0);
        }
        int status = 0;
        waitpid(child, &status, 0);
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) ++failures;
        quat_try_last_call = "";
        return;
    }
#endif
    f();
    quat_try_last_call = "";
}
#define CHECK_TRY(expr, call) guarded((call), [&] { check((expr), (call)); })
#define CHECK_TRY_NOT_ROTATION(expr, call) guarded((call), [&] { check((expr), (call), false); })

template <class T>
std::string str(T x) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(x));
    return buffer;
}
template <class T>
std::string str(const vec3<T>& v) {
    return "(" + str(v.x) + ", " + str(v.y) + ", " + str(v.z) + ")";
}
template <class T>
std::string str(const quaternion<T>& q) {
    return "(" + str(q.w) + ", " + str(q.x) + ", " + str(q.y) + ", " + str(q.z) + ")";
}
template <class T>
std::string str(const rotation_matrix<T>& m) {
    return "[" + str(quat::row(m, 0)) + str(quat::row(m, 1)) + str(quat::row(m, 2)) + "]";
}

// ---- the hostile values ----

template <class T>
std::vector<T> scalars() {
    using L = std::numeric_limits<T>;
    return {L::quiet_NaN(),  L::infinity(),    -L::infinity(), T(0),     -T(0),
            L::denorm_min(), -L::denorm_min(), L::min(),       T(1e-30), T(1e30),
            L::max(),        L::lowest(),      T(1),           T(-1),    T(2)};
}

template <class T>
std::vector<vec3<T>> vectors() {
    std::vector<vec3<T>> out;
    const vec3<T> base{T(0.3), T(-0.2), T(0.7)}, zero{T(0), T(0), T(0)};
    for (const T s : scalars<T>()) {
        for (int i = 0; i < 3; ++i) {
            vec3<T> v = base, w = zero;
            (i == 0 ? v.x : i == 1 ? v.y : v.z) = s;
            (i == 0 ? w.x : i == 1 ? w.y : w.z) = s;
            out.push_back(v);
            out.push_back(w);
        }
        out.push_back({s, s, s});
        out.push_back({T(-1), s, s});
    }
    out.push_back(base);
    out.push_back(-base);
    out.push_back({T(1), T(0), T(0)});
    return out;
}

template <class T>
std::vector<quaternion<T>> quaternions() {
    std::vector<quaternion<T>> out;
    const quaternion<T> base = quat::normalize(quaternion<T>{T(0.9), T(0.1), T(-0.3), T(0.2)});
    const quaternion<T> zero{T(0), T(0), T(0), T(0)};
    for (const T s : scalars<T>()) {
        for (int i = 0; i < 4; ++i) {
            quaternion<T> q = base, z = zero, id = quaternion<T>::identity();
            T* slots_q[] = {&q.w, &q.x, &q.y, &q.z};
            T* slots_z[] = {&z.w, &z.x, &z.y, &z.z};
            T* slots_i[] = {&id.w, &id.x, &id.y, &id.z};
            *slots_q[i] = s;
            *slots_z[i] = s;
            *slots_i[i] = s;
            out.push_back(q);
            out.push_back(z);
            out.push_back(id);
        }
        out.push_back({s, s, s, s});
    }
    out.push_back(base);
    return out;
}

template <class T>
std::vector<rotation_matrix<T>> matrices() {
    std::vector<rotation_matrix<T>> out;
    const rotation_matrix<T> base =
        quat::to_matrix(quat::normalize(quaternion<T>{T(0.9), T(0.1), T(-0.3), T(0.2)}));
    for (const T s : scalars<T>()) {
        for (int i = 0; i < 9; ++i) {
            rotation_matrix<T> m = base, z{};
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) z.elements[r][c] = T(0);
            m.elements[i / 3][i % 3] = s;
            z.elements[i / 3][i % 3] = s;
            out.push_back(m);
            out.push_back(z);
        }
        rotation_matrix<T> all{}, scaled = base;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                all.elements[r][c] = s;
                scaled.elements[r][c] = base.elements[r][c] * s;
            }
        out.push_back(all);
        out.push_back(scaled);
    }
    out.push_back(
        rotation_matrix<T>{{{T(-1), T(0), T(0)}, {T(0), T(-1), T(0)}, {T(0), T(0), T(-1)}}});
    out.push_back(
        rotation_matrix<T>{{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(-1)}}});
    out.push_back(
        rotation_matrix<T>{{{T(-1), T(0), T(0)}, {T(0), T(-1), T(0)}, {T(0), T(0), T(1)}}});
    out.push_back(base);
    return out;
}

// ---- the cases ----

template <class T>
void quaternion_cases() {
    current = "try_normalize(quaternion)";
    for (const quaternion<T>& q : quaternions<T>())
        CHECK_TRY(quat::try_normalize(q), "try_normalize" + str(q));
    current = "try_inverse";
    for (const quaternion<T>& q : quaternions<T>())
        CHECK_TRY_NOT_ROTATION(quat::try_inverse(q), "try_inverse" + str(q));
    current = "try_normalize(vec3)";
    for (const vec3<T>& v : vectors<T>())
        CHECK_TRY(quat::try_normalize(v), "try_normalize" + str(v));
}

template <class T>
void to_quaternion_cases() {
    current = "try_to_quaternion(matrix)";
    for (const rotation_matrix<T>& m : matrices<T>()) {
        CHECK_TRY(quat::try_to_quaternion(m), "try_to_quaternion(" + str(m) + ")");
        for (const T tolerance : scalars<T>())
            CHECK_TRY(quat::try_to_quaternion(m, tolerance),
                      "try_to_quaternion(" + str(m) + ", " + str(tolerance) + ")");
    }
    current = "try_to_quaternion(axis_angle)";
    for (const vec3<T>& axis : vectors<T>())
        for (const T angle : scalars<T>())
            CHECK_TRY(quat::try_to_quaternion(axis_angle<T>{axis, angle}),
                      "try_to_quaternion(axis " + str(axis) + ", angle " + str(angle) + ")");
}

template <class T>
void align_cases() {
    current = "try_rotation_between";
    const std::vector<vec3<T>> v = vectors<T>();
    for (const vec3<T>& a : v)
        for (const vec3<T>& b : v)
            CHECK_TRY(quat::try_rotation_between(a, b), "try_rotation_between" + str(a) + str(b));
    CHECK_TRY(quat::try_rotation_between(vec3<T>{T(1), T(0), T(0)},
                                         vec3<T>{T(-1), std::numeric_limits<T>::denorm_min(),
                                                 std::numeric_limits<T>::denorm_min()}),
              "try_rotation_between((1,0,0), (-1, denorm_min, denorm_min))");
    current = "try_look_rotation";
    for (const vec3<T>& a : v)
        for (const vec3<T>& b : v)
            CHECK_TRY(quat::try_look_rotation(a, b), "try_look_rotation" + str(a) + str(b));
    current = "try_align_vectors";
    const std::vector<vec3<T>> none,
        basis{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}};
    CHECK_TRY(quat::try_align_vectors(none, none), "try_align_vectors(no pairs)");
    CHECK_TRY(quat::try_align_vectors(basis, none), "try_align_vectors(3 targets, no sources)");
    CHECK_TRY(quat::try_align_vectors(none, basis, std::vector<T>{}),
              "try_align_vectors(no targets, 3 sources, no weights)");
    for (const vec3<T>& a : v) {
        std::vector<vec3<T>> with_a = basis;
        with_a[1] = a;
        CHECK_TRY(quat::try_align_vectors(with_a, basis),
                  "try_align_vectors(target " + str(a) + ")");
        CHECK_TRY(quat::try_align_vectors(basis, with_a),
                  "try_align_vectors(source " + str(a) + ")");
    }
    for (const T w : scalars<T>()) {
        CHECK_TRY(quat::try_align_vectors(basis, basis, std::vector<T>{T(1), w, T(1)}),
                  "try_align_vectors(weight " + str(w) + ")");
        CHECK_TRY(quat::try_align_vectors(basis, basis, std::vector<T>{w, w, w}),
                  "try_align_vectors(all weights " + str(w) + ")");
        CHECK_TRY(quat::try_align_vectors(basis, basis, std::vector<T>{w, w}),
                  "try_align_vectors(two weights " + str(w) + " for three pairs)");
    }
    current = "try_align_points";
    for (const vec3<T>& a : v) {
        std::vector<vec3<T>> with_a = basis;
        with_a[1] = a;
        CHECK_TRY(quat::try_align_points(with_a, basis), "try_align_points(target " + str(a) + ")");
        CHECK_TRY(quat::try_align_points(basis, with_a), "try_align_points(source " + str(a) + ")");
        CHECK_TRY(quat::try_align_points_with_scale(with_a, basis),
                  "try_align_points_with_scale(target " + str(a) + ")");
        CHECK_TRY(quat::try_align_points_with_scale(basis, with_a),
                  "try_align_points_with_scale(source " + str(a) + ")");
    }
    for (const T w : scalars<T>()) {
        CHECK_TRY(quat::try_align_points(basis, basis, std::vector<T>{T(1), w, T(1)}),
                  "try_align_points(weight " + str(w) + ")");
        CHECK_TRY(quat::try_align_points_with_scale(basis, basis, std::vector<T>{w, w, w}),
                  "try_align_points_with_scale(all weights " + str(w) + ")");
        CHECK_TRY(quat::try_align_points(basis, basis, std::vector<T>{w, w}),
                  "try_align_points(two weights " + str(w) + " for three pairs)");
    }
    CHECK_TRY(quat::try_align_points(none, none), "try_align_points(no points)");
    CHECK_TRY(quat::try_align_points_with_scale(basis, none),
              "try_align_points_with_scale(3 targets, no sources)");
}

template <class T>
void nearest_rotation_cases() {
    current = "try_nearest_rotation";
    for (const rotation_matrix<T>& m : matrices<T>())
        CHECK_TRY(quat::try_nearest_rotation(m), "try_nearest_rotation(" + str(m) + ")");
}

template <class T>
void dual_quaternion_cases() {
    current = "try_normalize(dual_quaternion)";
    const std::vector<quaternion<T>> q = quaternions<T>();
    const quaternion<T> real = quat::normalize(quaternion<T>{T(0.9), T(0.1), T(-0.3), T(0.2)});
    const quaternion<T> dual{T(0.1), T(0.2), T(-0.3), T(0.05)};
    for (const quaternion<T>& p : q) {
        CHECK_TRY(quat::try_normalize(dual_quaternion<T>{p, dual}),
                  "try_normalize(dq real " + str(p) + ")");
        CHECK_TRY(quat::try_normalize(dual_quaternion<T>{real, p}),
                  "try_normalize(dq dual " + str(p) + ")");
    }
    current = "try_to_dual_quaternion";
    const homogeneous_matrix<T> base = quat::to_homogeneous(dual_quaternion<T>{real, dual});
    for (const T s : scalars<T>()) {
        for (int i = 0; i < 16; ++i) {
            homogeneous_matrix<T> h = base;
            h.elements[i / 4][i % 4] = s;
            CHECK_TRY(quat::try_to_dual_quaternion(h),
                      "try_to_dual_quaternion(h[" + std::to_string(i / 4) + "][" +
                          std::to_string(i % 4) + "] = " + str(s) + ")");
        }
        CHECK_TRY(quat::try_to_dual_quaternion(base, s),
                  "try_to_dual_quaternion(h, tolerance " + str(s) + ")");
        homogeneous_matrix<T> all{};
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) all.elements[r][c] = s;
        CHECK_TRY(quat::try_to_dual_quaternion(all), "try_to_dual_quaternion(all " + str(s) + ")");
    }
}

template <class T>
void hand_eye_cases() {
    current = "try_hand_eye";
    const quaternion<T> real = quat::normalize(quaternion<T>{T(0.9), T(0.1), T(-0.3), T(0.2)});
    const quaternion<T> other = quat::normalize(quaternion<T>{T(0.2), T(0.7), T(0.1), T(-0.4)});
    const dual_quaternion<T> a0 = quat::to_dual_quaternion(real, vec3<T>{T(1), T(2), T(3)});
    const dual_quaternion<T> a1 = quat::to_dual_quaternion(other, vec3<T>{T(-1), T(0), T(2)});
    const std::vector<dual_quaternion<T>> good{a0, a1, a0 * a1};
    const quaternion<T> dual{T(0.1), T(0.2), T(-0.3), T(0.05)};
    for (const quaternion<T>& p : quaternions<T>()) {
        std::vector<dual_quaternion<T>> real_bad = good, dual_bad = good;
        real_bad[1] = dual_quaternion<T>{p, dual};
        dual_bad[1] = dual_quaternion<T>{real, p};
        CHECK_TRY(quat::try_hand_eye(good, real_bad), "try_hand_eye(b[1].real " + str(p) + ")");
        CHECK_TRY(quat::try_hand_eye(dual_bad, good), "try_hand_eye(a[1].dual " + str(p) + ")");
    }
    const std::vector<dual_quaternion<T>> none, one{a0};
    CHECK_TRY(quat::try_hand_eye(none, none), "try_hand_eye(no motions)");
    CHECK_TRY(quat::try_hand_eye(one, one), "try_hand_eye(one motion)");
    CHECK_TRY(quat::try_hand_eye(good, one), "try_hand_eye(3 and 1 motions)");
    CHECK_TRY(quat::try_hand_eye(good, good), "try_hand_eye(a = b)");

    current = "try_hand_eye_from_poses";
    for (const quaternion<T>& p : quaternions<T>()) {
        std::vector<dual_quaternion<T>> real_bad = good, dual_bad = good;
        real_bad[1] = dual_quaternion<T>{p, dual};
        dual_bad[1] = dual_quaternion<T>{real, p};
        CHECK_TRY(quat::try_hand_eye_from_poses(good, real_bad),
                  "try_hand_eye_from_poses(targets[1].real " + str(p) + ")");
        CHECK_TRY(quat::try_hand_eye_from_poses(dual_bad, good),
                  "try_hand_eye_from_poses(hands[1].dual " + str(p) + ")");
    }
    CHECK_TRY(quat::try_hand_eye_from_poses(none, none), "try_hand_eye_from_poses(no poses)");
    CHECK_TRY(quat::try_hand_eye_from_poses(good, one), "try_hand_eye_from_poses(3 and 1 poses)");
    CHECK_TRY(quat::try_hand_eye_from_poses(good, good),
              "try_hand_eye_from_poses(hands = targets)");
}

template <class T>
void swing_twist_cases() {
    current = "try_swing_twist";
    const std::vector<vec3<T>> v = vectors<T>();
    for (const quaternion<T>& q : quaternions<T>())
        for (const vec3<T>& axis : v)
            CHECK_TRY(quat::try_swing_twist(q, axis),
                      "try_swing_twist(" + str(q) + ", " + str(axis) + ")");
}

template <class T>
std::vector<std::vector<quaternion<T>>> rotation_sets() {
    const quaternion<T> a = quat::normalize(quaternion<T>{T(0.9), T(0.1), T(-0.3), T(0.2)});
    const quaternion<T> b = quat::normalize(quaternion<T>{T(0.2), T(-0.5), T(0.7), T(0.4)});
    std::vector<std::vector<quaternion<T>>> sets{{}, {a}, {a, b}, {a, -a}, {a, b, a}};
    for (const quaternion<T>& q : quaternions<T>()) {
        sets.push_back({q});
        sets.push_back({a, q, b});
    }
    return sets;
}

template <class T>
void mean_cases() {
    current = "try_mean";
    for (const auto& r : rotation_sets<T>())
        CHECK_TRY(quat::try_mean(r), "try_mean(" + std::to_string(r.size()) + " rotations)");
    current = "try_mean(weights)";
    for (const auto& r : rotation_sets<T>())
        for (const T w : scalars<T>()) {
            std::vector<T> weights(r.size(), T(1));
            if (!weights.empty()) weights[weights.size() / 2] = w;
            CHECK_TRY(quat::try_mean(r, weights), "try_mean(" + std::to_string(r.size()) +
                                                      " rotations, weight " + str(w) + ")");
            const std::vector<T> all(r.size(), w);
            CHECK_TRY(quat::try_mean(r, all), "try_mean(all weights " + str(w) + ")");
        }
    current = "try_mean(weights, mismatched sizes)";
    for (const auto& r : rotation_sets<T>()) {
        const std::vector<T> longer(r.size() + 1, T(1));
        CHECK_TRY(quat::try_mean(r, longer),
                  "try_mean(" + std::to_string(r.size()) + " rotations, one weight more)");
        if (!r.empty()) {
            const std::vector<T> shorter(r.size() - 1, T(1));
            CHECK_TRY(quat::try_mean(r, shorter), "try_mean(one weight fewer)");
        }
    }
}

template <class T>
void geodesic_mean_cases() {
    current = "try_geodesic_mean";
    for (const auto& r : rotation_sets<T>())
        CHECK_TRY(quat::try_geodesic_mean(r),
                  "try_geodesic_mean(" + std::to_string(r.size()) + " rotations)");
    current = "try_geodesic_mean(weights)";
    for (const auto& r : rotation_sets<T>())
        for (const T w : scalars<T>()) {
            std::vector<T> weights(r.size(), T(1));
            if (!weights.empty()) weights[weights.size() / 2] = w;
            CHECK_TRY(quat::try_geodesic_mean(r, weights),
                      "try_geodesic_mean(" + std::to_string(r.size()) + " rotations, weight " +
                          str(w) + ")");
            const std::vector<T> all(r.size(), w);
            CHECK_TRY(quat::try_geodesic_mean(r, all),
                      "try_geodesic_mean(all weights " + str(w) + ")");
        }
    current = "try_geodesic_mean(weights, mismatched sizes)";
    for (const auto& r : rotation_sets<T>()) {
        const std::vector<T> longer(r.size() + 1, T(1));
        CHECK_TRY(quat::try_geodesic_mean(r, longer), "try_geodesic_mean(one weight more)");
    }
}

template <class T>
void rotation_spline_cases() {
    using spline = quat::rotation_spline<T>;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    const quaternion<T> a = quat::normalize(quaternion<T>{T(0.9), T(0.1), T(-0.3), T(0.2)});
    const quaternion<T> b = quat::normalize(quaternion<T>{T(0.2), T(-0.5), T(0.7), T(0.4)});
    const std::vector<quaternion<T>> three{a, b, a};
    current = "rotation_spline::try_make(times)";
    const std::vector<std::vector<T>> time_sets{
        {},
        {T(0)},
        {T(0), T(1)},
        {T(0), T(1), T(2)},
        {T(0), T(2), T(1)},
        {T(0), T(0), T(1)},
        {T(2), T(1), T(0)},
        {nan, T(1), T(2)},
        {T(0), nan, T(2)},
        {-inf, T(0), T(1)},
        {T(0), T(1), inf},
        {T(0), T(1e-30), T(2e-30)},
        {T(0), std::numeric_limits<T>::denorm_min(), T(1)},
        {std::numeric_limits<T>::lowest(), T(0), std::numeric_limits<T>::max()},
        {T(0), T(1), T(1) + std::numeric_limits<T>::epsilon()}};
    for (const auto& times : time_sets) {
        auto made = spline::try_make(times, three);
        if (made) {
            const T inside = times[0] / 2 + times[1] / 2;  // within the keyframes
            const quaternion<T> q = (*made)(inside);
            if (!quat::try_normalize(q)) {
                ++failures;
                std::string listed;
                for (const T t : times) listed += " " + str(t);
                std::printf(
                    "FAIL %s: try_make with times%s gave a spline that evaluates to %s at %s\n",
                    current, listed.c_str(), str(q).c_str(), str(inside).c_str());
            }
        }
    }
    current = "rotation_spline::try_make(rotations)";
    const std::vector<T> times{T(0), T(1), T(2)};
    for (const quaternion<T>& q : quaternions<T>()) {
        for (int k = 0; k < 3; ++k) {
            std::vector<quaternion<T>> r = three;
            r[static_cast<std::size_t>(k)] = q;
            auto made = spline::try_make(times, r);
            if (made) {
                const quaternion<T> p = (*made)(T(0.5));
                if (!finite(p) || !unit(p)) {
                    ++failures;
                    std::printf(
                        "FAIL %s: try_make with keyframe %d = %s gave a spline that evaluates to "
                        "%s\n",
                        current, k, str(q).c_str(), str(p).c_str());
                }
            }
        }
    }
    current = "rotation_spline::try_make(mismatched sizes)";
    (void)spline::try_make(std::vector<T>{T(0), T(1)}, three);
    (void)spline::try_make(times, std::vector<quaternion<T>>{a, b});
    (void)spline::try_make(std::vector<T>{}, std::vector<quaternion<T>>{});
}

// ---- trajectory/: the B-splines' try_evaluate and the keyframe paths' try_make ----

template <class B>
bool all_finite(const B& blocks) {
    for (const auto& b : blocks)
        if (!finite(b)) return false;
    return true;
}

/// try_evaluate of `spline` at every hostile time and inside, with every Jacobian requested: an
/// engaged sample must be finite with a unit rotation, and so must every Jacobian block.
template <class T, class Spline, class... Blocks>
void bspline_times(const Spline& spline, const std::string& what, Blocks&... blocks) {
    std::vector<T> times = scalars<T>();
    times.push_back(T(0.5));
    times.push_back(T(2.999));
    times.push_back(T(3));
    times.push_back(T(3) + T(1e-3));
    times.push_back(-T(1e-3));
    for (const T t : times)
        guarded(what + ".try_evaluate(" + str(t) + ")", [&] {
            const auto sample = spline.try_evaluate(t, &blocks...);
            check(sample, what + ".try_evaluate(" + str(t) + ")");
            bool blocks_finite = true;
            if (sample) ((blocks_finite = blocks_finite && all_finite(blocks)), ...);
            if (!blocks_finite) {
                ++failures;
                std::printf("FAIL %s: %s.try_evaluate(%s) wrote a non-finite Jacobian\n", current,
                            what.c_str(), str(t).c_str());
            }
        });
}

/// Six control points (K = 4: three segments over [0, 3]), one replaced by each hostile value.
template <class T>
void bspline_cases() {
    constexpr std::size_t K = 4;
    const quaternion<T> a = quat::normalize(quaternion<T>{T(0.9), T(0.1), T(-0.3), T(0.2)});
    const quaternion<T> b = quat::normalize(quaternion<T>{T(0.2), T(-0.5), T(0.7), T(0.4)});
    const std::vector<quaternion<T>> rotations{a, b, a, -b, b, a};
    std::vector<vec3<T>> positions;
    std::vector<dual_quaternion<T>> motions;
    for (std::size_t i = 0; i < rotations.size(); ++i) {
        positions.push_back({T(i), T(0.5) * T(i), T(1) - T(i)});
        motions.push_back(quat::to_dual_quaternion(rotations[i], positions[i]));
    }
    typename quat::so3_bspline<T, K>::jacobian_blocks Jq{}, Jw{}, Ja{}, Jj{};
    typename quat::se3_bspline<T, K>::jacobian_blocks Jx{}, Jv{}, Jb{}, Jy{};
    typename quat::euclidean_bspline<T, K>::jacobian_weights Wp{}, Wv{}, Wa{}, Wj{};

    current = "so3/se3/euclidean/split_bspline::try_evaluate(t)";
    bspline_times<T>(quat::so3_bspline<T, K>(rotations, T(0), T(1)), "so3_bspline", Jq, Jw, Ja, Jj);
    bspline_times<T>(quat::se3_bspline<T, K>(motions, T(0), T(1)), "se3_bspline", Jx, Jv, Jb, Jy);
    bspline_times<T>(quat::euclidean_bspline<T, K>(positions, T(0), T(1)), "euclidean_bspline", Wp,
                     Wv, Wa, Wj);
    bspline_times<T>(quat::split_bspline<T, K>(rotations, positions, T(0), T(1)), "split_bspline",
                     Jq, Jw, Ja, Jj, Wp, Wv, Wa, Wj);

    current = "so3/se3/euclidean/split_bspline::try_evaluate(t0, dt, count, null points)";
    for (const T s : scalars<T>()) {
        bspline_times<T>(quat::so3_bspline<T, K>(rotations, s, T(1)),
                         "so3_bspline(t0 " + str(s) + ")", Jq, Jw, Ja, Jj);
        bspline_times<T>(quat::so3_bspline<T, K>(rotations, T(0), s),
                         "so3_bspline(dt " + str(s) + ")", Jq, Jw, Ja, Jj);
        bspline_times<T>(quat::se3_bspline<T, K>(motions, T(0), s),
                         "se3_bspline(dt " + str(s) + ")", Jx, Jv, Jb, Jy);
        bspline_times<T>(quat::euclidean_bspline<T, K>(positions, T(0), s),
                         "euclidean_bspline(dt " + str(s) + ")", Wp, Wv, Wa, Wj);
        bspline_times<T>(quat::split_bspline<T, K>(rotations, positions, s, T(1)),
                         "split_bspline(t0 " + str(s) + ")", Jq, Jw, Ja, Jj, Wp, Wv, Wa, Wj);
    }
    for (std::size_t count = 0; count < K; ++count) {
        bspline_times<T>(quat::so3_bspline<T, K>(rotations.data(), count, T(0), T(1)),
                         "so3_bspline(" + std::to_string(count) + " points)", Jq);
        bspline_times<T>(quat::se3_bspline<T, K>(motions.data(), count, T(0), T(1)),
                         "se3_bspline(" + std::to_string(count) + " points)", Jx);
    }
    bspline_times<T>(
        quat::so3_bspline<T, K>(static_cast<const quaternion<T>*>(nullptr), 6, T(0), T(1)),
        "so3_bspline(null)", Jq);
    bspline_times<T>(quat::split_bspline<T, K>(rotations.data(), nullptr, 6, T(0), T(1)),
                     "split_bspline(null positions)", Jq, Jw, Ja, Jj, Wp, Wv, Wa, Wj);
    const std::vector<vec3<T>> five(positions.begin(), positions.end() - 1);
    bspline_times<T>(quat::split_bspline<T, K>(rotations, five, T(0), T(1)),
                     "split_bspline(6 rotations, 5 positions)", Jq, Jw, Ja, Jj, Wp, Wv, Wa, Wj);

    current = "so3/se3/split_bspline::try_evaluate(hostile control point)";
    for (const quaternion<T>& q : quaternions<T>())
        for (const std::size_t slot : {std::size_t(0), std::size_t(2)}) {
            std::vector<quaternion<T>> r = rotations;
            std::vector<dual_quaternion<T>> m = motions;
            r[slot] = q;
            m[slot].real = q;
            bspline_times<T>(quat::so3_bspline<T, K>(r, T(0), T(1)),
                             "so3_bspline(point " + std::to_string(slot) + " = " + str(q) + ")", Jq,
                             Jw, Ja, Jj);
            bspline_times<T>(
                quat::se3_bspline<T, K>(m, T(0), T(1)),
                "se3_bspline(point " + std::to_string(slot) + ".real = " + str(q) + ")", Jx, Jv, Jb,
                Jy);
            m[slot] = motions[slot];
            m[slot].dual = q;
            bspline_times<T>(
                quat::se3_bspline<T, K>(m, T(0), T(1)),
                "se3_bspline(point " + std::to_string(slot) + ".dual = " + str(q) + ")", Jx);
            bspline_times<T>(
                quat::split_bspline<T, K>(r, positions, T(0), T(1)),
                "split_bspline(rotation " + std::to_string(slot) + " = " + str(q) + ")", Jq, Jw, Ja,
                Jj, Wp);
        }
    for (const vec3<T>& v : vectors<T>()) {
        std::vector<vec3<T>> p = positions;
        p[2] = v;
        bspline_times<T>(quat::euclidean_bspline<T, K>(p, T(0), T(1)),
                         "euclidean_bspline(point 2 = " + str(v) + ")", Wp, Wv, Wa, Wj);
        bspline_times<T>(quat::split_bspline<T, K>(rotations, p, T(0), T(1)),
                         "split_bspline(position 2 = " + str(v) + ")", Jq, Jw, Ja, Jj, Wp);
    }
}

/// try_make of a keyframe path; an engaged path's state inside the keyframes must be finite with a
/// unit pose.
template <class Path, class T, class Times, class Poses>
void keyframe_path_made(const Times& times, const Poses& poses, const std::string& what) {
    guarded(what, [&] {
        const std::optional<Path> made = Path::try_make(times, poses);
        if (!made || quat::detail::size_of(times) < 2) return;
        const T inside = T(times[0]) / 2 + T(times[1]) / 2;
        check(std::optional<quat::keyframe_path_state<T>>(made->state(inside)),
              what + " then state(" + str(inside) + ")");
    });
}

template <class T, class Path>
void keyframe_path_cases(const char* name) {
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    const quaternion<T> a = quat::normalize(quaternion<T>{T(0.9), T(0.1), T(-0.3), T(0.2)});
    const quaternion<T> b = quat::normalize(quaternion<T>{T(0.2), T(-0.5), T(0.7), T(0.4)});
    const std::vector<dual_quaternion<T>> three{quat::to_dual_quaternion(a, {T(0), T(0), T(0)}),
                                                quat::to_dual_quaternion(b, {T(1), T(2), T(3)}),
                                                quat::to_dual_quaternion(a, {T(-1), T(0), T(1)})};
    const std::string prefix = std::string(name) + "::try_make";
    current = "keyframe paths: try_make(times)";
    const std::vector<std::vector<T>> time_sets{
        {},
        {T(0)},
        {T(0), T(1)},
        {T(0), T(1), T(2)},
        {T(0), T(2), T(1)},
        {T(0), T(0), T(1)},
        {nan, T(1), T(2)},
        {T(0), nan, T(2)},
        {-inf, T(0), T(1)},
        {T(0), T(1), inf},
        {T(0), T(1e-30), T(2e-30)},
        {T(0), std::numeric_limits<T>::denorm_min(), T(1)},
        {std::numeric_limits<T>::lowest(), T(0), std::numeric_limits<T>::max()},
        {T(0), T(1), T(1) + std::numeric_limits<T>::epsilon()}};
    for (const auto& times : time_sets) {
        std::string listed;
        for (const T t : times) listed += " " + str(t);
        if (times.size() == three.size())
            keyframe_path_made<Path, T>(times, three, prefix + "(times" + listed + ")");
        else
            keyframe_path_made<Path, T>(times,
                                        std::vector<dual_quaternion<T>>(times.size(), three[0]),
                                        prefix + "(times" + listed + ")");
    }
    current = "keyframe paths: try_make(poses)";
    const std::vector<T> times{T(0), T(1), T(2)};
    for (const quaternion<T>& q : quaternions<T>())
        for (int part = 0; part < 2; ++part) {
            std::vector<dual_quaternion<T>> poses = three;
            (part == 0 ? poses[1].real : poses[1].dual) = q;
            keyframe_path_made<Path, T>(
                times, poses,
                prefix + "(pose 1." + (part == 0 ? "real = " : "dual = ") + str(q) + ")");
        }
    current = "keyframe paths: try_make(mismatched sizes)";
    keyframe_path_made<Path, T>(std::vector<T>{T(0), T(1)}, three, prefix + "(2 times, 3 poses)");
    keyframe_path_made<Path, T>(times, std::vector<dual_quaternion<T>>{three[0], three[1]},
                                prefix + "(3 times, 2 poses)");
    keyframe_path_made<Path, T>(std::vector<double>{0.0, 1e300, 2e300}, three,
                                prefix + "(double times beyond T)");
}

template <class T>
void trajectory_cases() {
    bspline_cases<T>();
    keyframe_path_cases<T, quat::split_keyframe_path<T>>("split_keyframe_path");
    keyframe_path_cases<T, quat::se3_keyframe_path<T>>("se3_keyframe_path");
}

struct named_case {
    const char* name;
    void (*run)();
};

const named_case cases[] = {
    {"quaternion_float", [] { quaternion_cases<float>(); }},
    {"quaternion_double", [] { quaternion_cases<double>(); }},
    {"to_quaternion_float", [] { to_quaternion_cases<float>(); }},
    {"to_quaternion_double", [] { to_quaternion_cases<double>(); }},
    {"align_float", [] { align_cases<float>(); }},
    {"align_double", [] { align_cases<double>(); }},
    {"nearest_rotation_float", [] { nearest_rotation_cases<float>(); }},
    {"nearest_rotation_double", [] { nearest_rotation_cases<double>(); }},
    {"hand_eye_float", [] { hand_eye_cases<float>(); }},
    {"hand_eye_double", [] { hand_eye_cases<double>(); }},
    {"dual_quaternion_float", [] { dual_quaternion_cases<float>(); }},
    {"dual_quaternion_double", [] { dual_quaternion_cases<double>(); }},
    {"rotation_spline_float", [] { rotation_spline_cases<float>(); }},
    {"rotation_spline_double", [] { rotation_spline_cases<double>(); }},
    {"mean_float", [] { mean_cases<float>(); }},
    {"mean_double", [] { mean_cases<double>(); }},
    {"geodesic_mean_float", [] { geodesic_mean_cases<float>(); }},
    {"geodesic_mean_double", [] { geodesic_mean_cases<double>(); }},
    {"swing_twist_float", [] { swing_twist_cases<float>(); }},
    {"swing_twist_double", [] { swing_twist_cases<double>(); }},
    {"trajectory_float", [] { trajectory_cases<float>(); }},
    {"trajectory_double", [] { trajectory_cases<double>(); }},
};

}  // namespace

int main(int argc, char** argv) {
    bool ran = false;
    fork_each = argc > 2 && std::strcmp(argv[2], "--each") == 0;
    for (const named_case& c : cases) {
        if (argc > 1 && std::strcmp(argv[1], c.name) != 0) continue;
        std::printf("case %s\n", c.name);
        std::fflush(stdout);
        c.run();
        ran = true;
    }
    if (!ran) {
        std::printf("unknown case %s\n", argv[1]);
        return 2;
    }
    if (failures > 0) {
        std::printf("%d try_ calls fired QUAT_ASSERT or returned NaN, Inf or a non-unit rotation\n",
                    failures);
        return 1;
    }
    std::printf("all try_ functions returned\n");
    return 0;
}
