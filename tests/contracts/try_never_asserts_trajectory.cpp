// quat_try_never_asserts (tests/contracts/try_never_asserts.cpp), the cases of trajectory/: every
// B-spline's try_evaluate (SO(3), SE(3), Euclidean, split) at hostile times, with hostile origins,
// spacings, point counts, null points and control points, every Jacobian requested; the keyframe
// paths' try_make (split_keyframe_path, se3_keyframe_path) with hostile, unsorted or mismatched
// times and poses. An engaged result must be finite with unit rotations, and so must its Jacobians.
#include "try_never_asserts.hpp"  // first: it defines QUAT_ASSERT before any quat header

#include <cstddef>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace try_never_asserts {
namespace {

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
        // Appended piece by piece: g++ 12 at -O3 warns (-Wrestrict, a false positive) on
        // " " + std::string, the operator+ that inserts at the front.
        for (const T t : times) {
            listed += ' ';
            listed += str(t);
        }
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

}  // namespace

template <class T>
void trajectory_cases() {
    bspline_cases<T>();
    keyframe_path_cases<T, quat::split_keyframe_path<T>>("split_keyframe_path");
    keyframe_path_cases<T, quat::se3_keyframe_path<T>>("se3_keyframe_path");
}
template void trajectory_cases<float>();
template void trajectory_cases<double>();

}  // namespace try_never_asserts
