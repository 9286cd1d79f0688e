// The harness of quat_try_never_asserts (tests/contracts/try_never_asserts.cpp and
// try_never_asserts_trajectory.cpp): QUAT_ASSERT replaced by a handler that names the call and
// aborts, defined before any quat header in every unit of the executable (so that quat's inline
// functions are the same in all of them); the checks on an engaged result (finite, unit); the
// guard that runs a call, in a child process with --each; the hostile values fed to the try_
// functions. Include it first.
#ifndef QUAT_TESTS_CONTRACTS_TRY_NEVER_ASSERTS_HPP
#define QUAT_TESTS_CONTRACTS_TRY_NEVER_ASSERTS_HPP

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
inline const char* quat_try_last_call = "";
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

namespace try_never_asserts {

using quat::axis_angle;
using quat::dual_quaternion;
using quat::homogeneous_matrix;
using quat::quaternion;
using quat::rotation_matrix;
using quat::vec3;

inline int failures = 0;          // calls that fired QUAT_ASSERT or returned a broken value
inline const char* current = "";  // the function being checked, for the messages

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

inline bool fork_each =
    false;  // `quat_try_never_asserts NAME --each`: every call in its own process

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

// The cases of trajectory/ (try_never_asserts_trajectory.cpp).
template <class T>
void trajectory_cases();
extern template void trajectory_cases<float>();
extern template void trajectory_cases<double>();

}  // namespace try_never_asserts

#endif  // QUAT_TESTS_CONTRACTS_TRY_NEVER_ASSERTS_HPP
