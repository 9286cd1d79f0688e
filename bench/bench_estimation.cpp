// hand_eye_from_poses (quat alone: OpenCV, the peer, is timed in quat_accuracy --hand-eye);
// align_vectors (Wahba's problem), align_points (Kabsch, against Eigen's umeyama on the same
// points) and mean over n inputs, beside the two costs they cannot avoid: reading the input once
// (read_input: only the sums B = sum w t s^T, or sum q q^T for mean) and one 4x4 symmetric
// eigen-solve (eigen_solve). The target: align_vectors and mean within 2x of read_input +
// eigen_solve.
#include <cstddef>
#include <vector>

// g++ 12 at -O3 reports a false -Warray-bounds (and, with AVX-512, -Wmaybe-uninitialized) inside
// Eigen::umeyama's packet loads of its 3-vector means; the code is Eigen's, not quat's.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Warray-bounds"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <Eigen/Geometry>
#include <quat/fitting/align_vectors.hpp>
#include <quat/fitting/mean.hpp>
#include <quat/lie/se3.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>

#include "common.hpp"

namespace bench {
namespace {

template <class T>
struct vector_set {
    std::vector<quat::vec3<T>> targets, sources;
    std::vector<T> weights;
};

// Noisy pairs t = R s + e with random weights: what align_vectors is given in practice.
template <class T>
vector_set<T> make_vector_set(random_source& random, std::size_t n) {
    vector_set<T> set;
    const quat::quatd rotation = random.rotation();
    for (std::size_t i = 0; i < n; ++i) {
        const quat::vec3<double> s = random.vector();
        const quat::vec3<double> e = random.vector();
        set.sources.push_back(lib_quat<T>::make_vector(s));
        set.targets.push_back(lib_quat<T>::make_vector(quat::rotate(rotation, s) + e * 0.01));
        set.weights.push_back(T(random.uniform(0.5, 2)));
    }
    return set;
}

template <class T>
void align_vectors(benchmark::State& state, std::size_t n) {
    random_source random;
    const vector_set<T> set = make_vector_set<T>(random, n);
    for (auto _ : state) {
        const quat::alignment<T> result =
            quat::align_vectors(set.targets, set.sources, set.weights);
        benchmark::DoNotOptimize(result);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long long>(n));
}

// The rigid motion of n noisy point pairs: quat's align_points, or Eigen::umeyama on the same
// points held as 3 x n matrices (built once, outside the timing), or only the sums of both point
// sets (read_input: one read of the input). Small sets cycle through 64 different sets: the shape
// of three or four points decides how well separated the best rotation is, and with it the work
// (three random points have a rank-2 B, and most of them a small eigen-gap).
template <class T>
void align_points(benchmark::State& state, std::size_t n, bool eigen, bool read_only = false) {
    random_source random;
    const std::size_t sets = n <= 16 ? 64 : 1;
    std::vector<vector_set<T>> set;
    std::vector<Eigen::Matrix<T, 3, Eigen::Dynamic>> sources, targets;
    for (std::size_t k = 0; k < sets; ++k) {
        set.push_back(make_vector_set<T>(random, n));
        for (quat::vec3<T>& target : set[k].targets) target += quat::vec3<T>{T(1), T(2), T(3)};
        sources.emplace_back(3, Eigen::Index(n));
        targets.emplace_back(3, Eigen::Index(n));
        for (std::size_t i = 0; i < n; ++i) {
            const auto c = Eigen::Index(i);
            sources[k].col(c) << set[k].sources[i].x, set[k].sources[i].y, set[k].sources[i].z;
            targets[k].col(c) << set[k].targets[i].x, set[k].targets[i].y, set[k].targets[i].z;
        }
    }
    std::size_t k = 0;
    for (auto _ : state) {
        if (read_only) {  // the centroids' sums: what every method reads once
            quat::vec3<T> target_sum{}, source_sum{};
            for (std::size_t i = 0; i < n; ++i) {
                target_sum += set[k].targets[i];
                source_sum += set[k].sources[i];
            }
            benchmark::DoNotOptimize(target_sum);
            benchmark::DoNotOptimize(source_sum);
        } else if (eigen) {
            const Eigen::Matrix<T, 4, 4> result = Eigen::umeyama(sources[k], targets[k], false);
            benchmark::DoNotOptimize(result);
        } else {
            const quat::point_alignment<T> result =
                quat::align_points(set[k].targets, set[k].sources);
            benchmark::DoNotOptimize(result);
        }
        k = k + 1 == sets ? 0 : k + 1;
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long long>(n));
}

// The first of align_vectors' two passes alone, written out: nine sums of w t_i s_j.
template <class T>
void read_input(benchmark::State& state, std::size_t n) {
    random_source random;
    const vector_set<T> set = make_vector_set<T>(random, n);
    for (auto _ : state) {
        T b[3][3] = {};
        for (std::size_t i = 0; i < n; ++i) {
            const quat::vec3<T> t = set.targets[i] * set.weights[i], s = set.sources[i];
            const T tt[3] = {t.x, t.y, t.z}, ss[3] = {s.x, s.y, s.z};
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) b[r][c] += tt[r] * ss[c];
        }
        benchmark::DoNotOptimize(b);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long long>(n));
}

// Horn's (Davenport's) K of B = R + noise, the matrices align_vectors hands to the solver.
template <class T>
void eigen_solve(benchmark::State& state) {
    random_source random;
    struct matrix4 {
        T k[4][4];
    };
    std::vector<matrix4> in;
    for (std::size_t n = 0; n < pool; ++n) {
        quat::rotation_matrix<T> m = lib_quat<T>::make_matrix(random.rotation());
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m(i, j) += T(random.uniform(-0.05, 0.05));
        in.push_back({{{m(0, 0) + m(1, 1) + m(2, 2), m(2, 1) - m(1, 2), m(0, 2) - m(2, 0),
                        m(1, 0) - m(0, 1)},
                       {m(2, 1) - m(1, 2), m(0, 0) - m(1, 1) - m(2, 2), m(0, 1) + m(1, 0),
                        m(0, 2) + m(2, 0)},
                       {m(0, 2) - m(2, 0), m(0, 1) + m(1, 0), m(1, 1) - m(0, 0) - m(2, 2),
                        m(1, 2) + m(2, 1)},
                       {m(1, 0) - m(0, 1), m(0, 2) + m(2, 0), m(1, 2) + m(2, 1),
                        m(2, 2) - m(0, 0) - m(1, 1)}}});
    }
    std::size_t i = 0;
    for (auto _ : state) {
        const quat::detail::symmetric_eigen4<T> result = quat::detail::symmetric_eigen(in[i].k);
        benchmark::DoNotOptimize(result);
        i = (i + 1) % pool;
    }
    state.SetItemsProcessed(state.iterations());
}

// Rotations scattered by up to about 1 rad around a center, half of them negated; with read_only,
// only mean's pass over them (the ten sums of q q^T).
template <class T>
void mean(benchmark::State& state, std::size_t n, bool read_only) {
    random_source random;
    const quat::quatd center = random.rotation();
    std::vector<quat::quaternion<T>> rotations;
    for (std::size_t i = 0; i < n; ++i) {
        const quat::vec3<double> v = random.vector();
        const quat::quatd q = center * quat::from_rotation_vector(v * 0.5);
        rotations.push_back(lib_quat<T>::make_quaternion(i % 2 ? -q : q));
    }
    for (auto _ : state) {
        if (read_only) {
            T ww = 0, wx = 0, wy = 0, wz = 0, xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
            for (const quat::quaternion<T>& q : rotations) {
                ww += q.w * q.w;
                wx += q.w * q.x;
                wy += q.w * q.y;
                wz += q.w * q.z;
                xx += q.x * q.x;
                xy += q.x * q.y;
                xz += q.x * q.z;
                yy += q.y * q.y;
                yz += q.y * q.z;
                zz += q.z * q.z;
            }
            const T k[10] = {ww, wx, wy, wz, xx, xy, xz, yy, yz, zz};
            benchmark::DoNotOptimize(k);
        } else {
            const quat::quaternion<T> result = quat::mean(rotations);
            benchmark::DoNotOptimize(result);
        }
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long long>(n));
}

// hand_eye_from_poses on `motions` + 1 poses: a random mount X and target pose W, random hand poses
// H_j, and sensor poses S_j = X^-1 H_j^-1 W each turned and moved by about 1 mrad and 1 mm (the
// scene's unit is the metre), cycling through 16 such sets.
void hand_eye_from_poses(benchmark::State& state, std::size_t motions) {
    using dq = quat::dual_quaternion<double>;
    random_source random;
    std::vector<std::vector<dq>> hands(16), sensors(16);
    for (std::size_t k = 0; k < hands.size(); ++k) {
        const dq mount = quat::to_dual_quaternion(random.rotation(), random.vector() * 0.1);
        const dq target = quat::to_dual_quaternion(random.rotation(), random.vector());
        for (std::size_t j = 0; j <= motions; ++j) {
            const dq hand = quat::to_dual_quaternion(random.rotation(), random.vector());
            const quat::se3::twist<double> noise{random.vector() * 1e-3, random.vector() * 1e-3};
            hands[k].push_back(hand);
            sensors[k].push_back(quat::se3::plus(
                quat::normalize(quat::inverse(mount) * quat::inverse(hand) * target), noise));
        }
    }
    std::size_t k = 0;
    for (auto _ : state) {
        const quat::hand_eye_with_target<double> result =
            quat::hand_eye_from_poses(hands[k], sensors[k]);
        benchmark::DoNotOptimize(result);
        k = (k + 1) % hands.size();
    }
    state.SetItemsProcessed(state.iterations());
}

template <class T>
void register_estimation_for() {
    const char* type = type_name<T>;
    for (const std::size_t n : {std::size_t(2), std::size_t(16), std::size_t(1024)}) {
        const auto size = static_cast<long long>(n);
        benchmark::RegisterBenchmark(name("align_vectors", "quat", "vec3", type, size).c_str(),
                                     [n](benchmark::State& state) { align_vectors<T>(state, n); });
        benchmark::RegisterBenchmark(
            name("align_vectors", "read_input", "vec3", type, size).c_str(),
            [n](benchmark::State& state) { read_input<T>(state, n); });
    }
    // Three and four points (the smallest sets, where a fixed cost dominates) to 10,000 (where
    // reading the input does).
    for (const std::size_t n : {std::size_t(3), std::size_t(4), std::size_t(64), std::size_t(100),
                                std::size_t(4096), std::size_t(10000)}) {
        const auto size = static_cast<long long>(n);
        benchmark::RegisterBenchmark(
            name("align_points", "quat", "vec3", type, size).c_str(),
            [n](benchmark::State& state) { align_points<T>(state, n, false); });
        benchmark::RegisterBenchmark(
            name("align_points", "eigen", "vec3", type, size).c_str(),
            [n](benchmark::State& state) { align_points<T>(state, n, true); });
        benchmark::RegisterBenchmark(
            name("align_points", "read_input", "vec3", type, size).c_str(),
            [n](benchmark::State& state) { align_points<T>(state, n, false, true); });
    }
    benchmark::RegisterBenchmark(name("eigen_solve", "quat", "4x4", type).c_str(), eigen_solve<T>);
    benchmark::RegisterBenchmark(name("mean", "quat", "quaternion", type, 1024).c_str(),
                                 [](benchmark::State& state) { mean<T>(state, 1024, false); });
    benchmark::RegisterBenchmark(name("mean", "read_input", "quaternion", type, 1024).c_str(),
                                 [](benchmark::State& state) { mean<T>(state, 1024, true); });
}

}  // namespace

void register_estimation() {
    register_estimation_for<float>();
    register_estimation_for<double>();
    for (const std::size_t motions : {std::size_t(3), std::size_t(10), std::size_t(50)})
        benchmark::RegisterBenchmark(
            name("hand_eye", "quat", "from_poses", "double", static_cast<long long>(motions))
                .c_str(),
            [motions](benchmark::State& state) { hand_eye_from_poses(state, motions); });
}

}  // namespace bench
