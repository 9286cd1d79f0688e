// Keyframe paths: squad and squad_control (quat against glm::squad and glm::intermediate, on
// keyframes with consecutive dot products >= 0, where the two compute the same path),
// keyframe_slerp and keyframe_squad over 1024 keyframes (quat only: GLM and Eigen have no
// keyframed squad), and rotation_spline (evaluation, angular velocity and acceleration at random
// times, evaluation over sorted times, and building from 1024 keyframes).
#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

#include <glm/gtx/quaternion.hpp>

#include <quat/paths/keyframe_slerp.hpp>
#include <quat/paths/keyframe_squad.hpp>
#include <quat/paths/rotation_spline.hpp>
#include <quat/paths/squad.hpp>

#include "common.hpp"

namespace bench {
namespace {

/// GLM's note, in the label of its squad benchmarks.
constexpr const char* glm_label = "intermediate() does not align neighbours to one hemisphere";

/// Keyframes of a path: uneven time steps in [0.25, 1.75) and random turns of at most 1 rad
/// about random axes, each quaternion on the hemisphere of the one before (dot >= 0).
template <class T>
struct keyframes {
    std::vector<T> times;
    std::vector<quat::quaternion<T>> rotations;
};

/// The next keyframe: q turned by at most max_angle about a random axis, on q's hemisphere.
quat::quatd step(random_source& random, const quat::quatd& q, double max_angle) {
    const quat::vec3<double> axis = quat::normalize(random.vector());
    quat::quatd next =
        quat::normalize(q * quat::from_rotation_vector(axis * random.uniform(0, max_angle)));
    if (quat::dot(q, next) < 0) next = -next;
    return next;
}

template <class T>
keyframes<T> make_keyframes(std::size_t n) {
    random_source random;
    keyframes<T> k;
    double time = 0;
    quat::quatd q = random.rotation();
    for (std::size_t i = 0; i < n; ++i) {
        k.times.push_back(T(time));
        k.rotations.push_back(lib_quat<T>::make_quaternion(q));
        time += random.uniform(0.25, 1.75);
        q = step(random, q, 1.0);
    }
    return k;
}

/// Four consecutive keyframes q0..q3 (the squad segment runs from q1 to q2) and a t in (0, 1).
struct segment {
    quat::quatd q[4];
    double t;
};

segment random_segment(random_source& random) {
    segment s{};
    s.q[0] = random.rotation();
    for (int i = 1; i < 4; ++i) s.q[i] = step(random, s.q[i - 1], 1.0);
    s.t = random.uniform(0.001, 0.999);
    return s;
}

/// One segment in a library's types, its inner controls precomputed.
template <class Lib>
struct squad_input {
    typename Lib::quaternion q1, a1, a2, q2;
    typename Lib::scalar t;
};

template <class T>
squad_input<lib_quat<T>> quat_squad_input(random_source& random) {
    const segment s = random_segment(random);
    quat::quaternion<T> q[4];
    for (int i = 0; i < 4; ++i) q[i] = lib_quat<T>::make_quaternion(s.q[i]);
    return {q[1], quat::squad_control(q[0], q[1], q[2]), quat::squad_control(q[1], q[2], q[3]),
            q[2], T(s.t)};
}

template <class T>
squad_input<lib_glm<T>> glm_squad_input(random_source& random) {
    const segment s = random_segment(random);
    typename lib_glm<T>::quaternion q[4];
    for (int i = 0; i < 4; ++i) q[i] = lib_glm<T>::make_quaternion(s.q[i]);
    return {q[1], glm::intermediate(q[0], q[1], q[2]), glm::intermediate(q[1], q[2], q[3]), q[2],
            T(s.t)};
}

/// Three consecutive keyframes, for the control points.
template <class Lib>
struct triple {
    typename Lib::quaternion previous, current, next;
};

template <class Lib>
triple<Lib> random_triple(random_source& random) {
    const segment s = random_segment(random);
    return {Lib::make_quaternion(s.q[0]), Lib::make_quaternion(s.q[1]),
            Lib::make_quaternion(s.q[2])};
}

template <class T>
void register_squad_for() {
    const char* type = type_name<T>;
    using Q = lib_quat<T>;
    using G = lib_glm<T>;
    benchmark::RegisterBenchmark(
        name("squad", "quat", "quaternion", type).c_str(), [](benchmark::State& state) {
            cycle(state, quat_squad_input<T>,
                  [](const squad_input<Q>& s) { return quat::squad(s.q1, s.a1, s.a2, s.q2, s.t); });
        });
    benchmark::RegisterBenchmark(
        name("squad", "glm", "quaternion", type).c_str(), [](benchmark::State& state) {
            cycle(state, glm_squad_input<T>,
                  [](const squad_input<G>& s) { return glm::squad(s.q1, s.q2, s.a1, s.a2, s.t); });
            state.SetLabel(glm_label);
        });
    benchmark::RegisterBenchmark(name("squad_control", "quat", "quaternion", type).c_str(),
                                 [](benchmark::State& state) {
                                     cycle(state, random_triple<Q>, [](const triple<Q>& k) {
                                         return quat::squad_control(k.previous, k.current, k.next);
                                     });
                                 });
    benchmark::RegisterBenchmark(name("squad_control", "glm", "quaternion", type).c_str(),
                                 [](benchmark::State& state) {
                                     cycle(state, random_triple<G>, [](const triple<G>& k) {
                                         return glm::intermediate(k.previous, k.current, k.next);
                                     });
                                     state.SetLabel(glm_label);
                                 });
}

constexpr std::size_t keyframe_count = 1024;
constexpr std::size_t sorted_times = 4096;

/// One call of f(t) per iteration at seeded random times within the keyframes' span.
template <class T, class F>
void at_random_times(benchmark::State& state, const keyframes<T>& k, F f) {
    const double first = double(k.times.front()), last = double(k.times.back());
    cycle(
        state, [first, last](random_source& random) { return T(random.uniform(first, last)); }, f);
}

template <class T>
void register_paths_for() {
    const char* type = type_name<T>;
    const auto n = static_cast<long long>(keyframe_count);
    if constexpr (std::is_same_v<T, float>) {
        benchmark::RegisterBenchmark(name("keyframe_slerp", "quat", "quaternion", type, n).c_str(),
                                     [](benchmark::State& state) {
                                         const keyframes<T> k = make_keyframes<T>(keyframe_count);
                                         at_random_times(state, k, [&k](T t) {
                                             return quat::keyframe_slerp(k.times, k.rotations, t);
                                         });
                                     });
        // The same keyframes and times through keyframe_squad: two control points per call.
        benchmark::RegisterBenchmark(name("keyframe_squad", "quat", "quaternion", type, n).c_str(),
                                     [](benchmark::State& state) {
                                         const keyframes<T> k = make_keyframes<T>(keyframe_count);
                                         at_random_times(state, k, [&k](T t) {
                                             return quat::keyframe_squad(k.times, k.rotations, t);
                                         });
                                     });
        benchmark::RegisterBenchmark(
            name("rotation_spline", "quat", "evaluate", type, n).c_str(),
            [](benchmark::State& state) {
                const keyframes<T> k = make_keyframes<T>(keyframe_count);
                const quat::rotation_spline<T> spline(k.times, k.rotations);
                at_random_times(state, k, [&spline](T t) { return spline(t); });
            });
        benchmark::RegisterBenchmark(
            name("rotation_spline", "quat", "angular_velocity", type, n).c_str(),
            [](benchmark::State& state) {
                const keyframes<T> k = make_keyframes<T>(keyframe_count);
                const quat::rotation_spline<T> spline(k.times, k.rotations);
                at_random_times(state, k, [&spline](T t) { return spline.angular_velocity(t); });
            });
        benchmark::RegisterBenchmark(
            name("rotation_spline", "quat", "angular_acceleration", type, n).c_str(),
            [](benchmark::State& state) {
                const keyframes<T> k = make_keyframes<T>(keyframe_count);
                const quat::rotation_spline<T> spline(k.times, k.rotations);
                at_random_times(state, k,
                                [&spline](T t) { return spline.angular_acceleration(t); });
            });
        // spline.evaluate over 4096 sorted times spanning all keyframes; items are times.
        benchmark::RegisterBenchmark(
            name("rotation_spline", "quat", "evaluate_sorted", type, n).c_str(),
            [](benchmark::State& state) {
                const keyframes<T> k = make_keyframes<T>(keyframe_count);
                const quat::rotation_spline<T> spline(k.times, k.rotations);
                random_source random;
                std::vector<T> ts(sorted_times);
                for (T& t : ts)
                    t = T(random.uniform(double(k.times.front()), double(k.times.back())));
                std::sort(ts.begin(), ts.end());
                std::vector<quat::quaternion<T>> out(ts.size());
                for (auto _ : state) {
                    spline.evaluate(ts, out);
                    benchmark::DoNotOptimize(out.data());
                    benchmark::ClobberMemory();
                }
                state.SetItemsProcessed(state.iterations() *
                                        static_cast<benchmark::IterationCount>(sorted_times));
            });
    }
    // Building (the Newton solve included) from 1024 keyframes prepared before timing; items are
    // builds.
    benchmark::RegisterBenchmark(name("rotation_spline", "quat", "build", type, n).c_str(),
                                 [](benchmark::State& state) {
                                     const keyframes<T> k = make_keyframes<T>(keyframe_count);
                                     for (auto _ : state) {
                                         quat::rotation_spline<T> spline(k.times, k.rotations);
                                         benchmark::DoNotOptimize(spline);
                                         benchmark::ClobberMemory();
                                     }
                                     state.SetItemsProcessed(state.iterations());
                                 });
}

}  // namespace

void register_keyframes() {
    register_squad_for<float>();
    register_squad_for<double>();
    register_paths_for<float>();
    register_paths_for<double>();
}

}  // namespace bench
