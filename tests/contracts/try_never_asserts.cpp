// The try_ functions are the checked API for untrusted input (quat.hpp: "try_* functions check
// untrusted input and return an empty std::optional instead of NaN"): whatever they are given
// (NaN or infinite components, zero, subnormal, huge, non-unit, empty or mismatched containers,
// bad weights or tolerances, unsorted times) they must return, never fire QUAT_ASSERT, and an
// engaged result must be finite (and, for a rotation, unit). Built without NDEBUG in every preset,
// so the debug checks are live. `quat_try_never_asserts` runs every case; `quat_try_never_asserts
// NAME` runs one (names are printed as they start), so a firing check does not hide the others.
// The harness and the hostile values are in try_never_asserts.hpp; the cases of trajectory/ (the
// B-splines' try_evaluate, the keyframe paths' try_make) in try_never_asserts_trajectory.cpp.
#include "try_never_asserts.hpp"  // first: it defines QUAT_ASSERT before any quat header

#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace try_never_asserts {
namespace {

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
                for (const T t : times) {
                    listed += ' ';  // not " " + str(t): g++ 12's false -Wrestrict at -O3
                    listed += str(t);
                }
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
}  // namespace try_never_asserts

int main(int argc, char** argv) {
    using namespace try_never_asserts;
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
