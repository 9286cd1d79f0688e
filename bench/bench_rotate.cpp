// rotate_point (latency of one rotation), rotate_pairs (throughput when every point has its own
// quaternion) and rotate_batch (throughput over n points, in and out of cache), with copies of the
// same bytes (memcpy, a plain loop, a streaming copy: common.hpp) as the memory-bound floor.
#include <algorithm>

#include "common.hpp"

namespace bench {
namespace {

// One point rotated again and again: each rotation waits for the previous one (latency).
template <class Lib, class Rep>
void rotate_point(benchmark::State& state) {
    random_source random;
    const auto r = Rep::template make<Lib>(random.rotation());
    auto v = Lib::make_vector(random.vector());
    for (auto _ : state) {
        v = Lib::rotate(r, v);
        benchmark::DoNotOptimize(v);
    }
    state.SetItemsProcessed(state.iterations());
}

// Each point by its own quaternion, all independent (throughput): unlike rotate_point (one q, one
// dependency chain) and rotate_batch (one matrix per batch), every operation rotate spends on q
// itself is paid per point and nothing hides behind a latency.
template <class Lib>
void rotate_pairs(benchmark::State& state, long long count) {
    const std::size_t n = static_cast<std::size_t>(count);
    random_source random;
    std::vector<typename Lib::quaternion> qs(n);
    std::vector<typename Lib::vector> in(n);
    for (std::size_t i = 0; i < n; ++i) {
        qs[i] = Lib::make_quaternion(random.rotation());
        in[i] = Lib::make_vector(random.vector());
    }
    time_pairs(state, qs, in, [](const auto& q, const auto& v) { return Lib::rotate(q, v); });
}

template <class T>
std::size_t batch_bytes(std::size_t n) {
    return 2 * n * 3 * sizeof(T);  // read and written once each
}

// With ViaMatrix (Rep a quaternion), each call first forms the rotation's matrix (quat's to_matrix,
// GLM's mat3_cast, Eigen's toRotationMatrix) and runs the matrix batch: what a user holding a
// quaternion writes for speed, the same job as quat's quaternion batch.
template <class Lib, class Rep, bool ViaMatrix = false>
void rotate_batch(benchmark::State& state, long long count) {
    using T = typename Lib::scalar;
    const std::size_t n = static_cast<std::size_t>(count);
    random_source random;
    const auto r = Rep::template make<Lib>(random.rotation());
    std::vector<typename Lib::vector> in(n), out(n);
    for (auto& v : in) v = Lib::make_vector(random.vector());
    // Touch the output before timing: Eigen's vectors are not value-initialized, and first-touch
    // page faults would otherwise be timed (the 4M-point runs take only a few iterations).
    std::copy(in.begin(), in.end(), out.begin());
    for (auto _ : state) {
        if constexpr (ViaMatrix) {
            Lib::rotate_batch(Lib::to_matrix(fresh(r)), in.data(), out.data(), n);
        } else {
            Lib::rotate_batch(fresh(r), in.data(), out.data(), n);
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(batch_bytes<T>(n)));
}

// quat's struct-of-arrays overload over the same points.
template <class T>
void rotate_batch_soa(benchmark::State& state, long long count) {
    const std::size_t n = static_cast<std::size_t>(count);
    random_source random;
    const quat::quaternion<T> q = lib_quat<T>::make_quaternion(random.rotation());
    std::vector<T> x(n), y(n), z(n), ox(n), oy(n), oz(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto v = random.vector();
        x[i] = T(v.x), y[i] = T(v.y), z[i] = T(v.z);
    }
    for (auto _ : state) {
        quat::rotate(fresh(q), quat::soa_points<const T>{x.data(), y.data(), z.data(), n},
                     quat::soa_points<T>{ox.data(), oy.data(), oz.data(), n});
        benchmark::DoNotOptimize(ox.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(batch_bytes<T>(n)));
}

template <class T>
const std::vector<long long>& batch_sizes() {
    // 64 ... 4M points in steps of 4: L1, L2, L3 and main memory.
    static const std::vector<long long> sizes = {64,    256,    1024,    4096,   16384,
                                                 65536, 262144, 1048576, 4194304};
    return sizes;
}

template <template <class> class Lib, class T>
void register_library() {
    using L = Lib<T>;
    const char* type = type_name<T>;
    benchmark::RegisterBenchmark(name("rotate_point", L::name, "quaternion", type).c_str(),
                                 rotate_point<L, quaternion_rep>);
    benchmark::RegisterBenchmark(name("rotate_point", L::name, "matrix", type).c_str(),
                                 rotate_point<L, matrix_rep>);
    benchmark::RegisterBenchmark(name("rotate_pairs", L::name, "quaternion", type, 1024).c_str(),
                                 rotate_pairs<L>, 1024);
    if (!std::is_same_v<T, float>) return;  // the batch targets are float
    for (const long long n : batch_sizes<T>()) {
        benchmark::RegisterBenchmark(name("rotate_batch", L::name, "quaternion", type, n).c_str(),
                                     rotate_batch<L, quaternion_rep>, n);
        benchmark::RegisterBenchmark(name("rotate_batch", L::name, "matrix", type, n).c_str(),
                                     rotate_batch<L, matrix_rep>, n);
        if (n <= 1024)  // in cache, where forming the matrix is not hidden behind memory
            benchmark::RegisterBenchmark(
                name("rotate_batch", L::name, "quaternion_via_matrix", type, n).c_str(),
                rotate_batch<L, quaternion_rep, true>, n);
    }
}

}  // namespace

void register_rotate() {
    register_library<lib_quat, float>();
    register_library<lib_glm, float>();
    register_library<lib_eigen, float>();
    register_library<lib_quat, double>();
    register_library<lib_glm, double>();
    register_library<lib_eigen, double>();
    for (const long long n : batch_sizes<float>()) {
        benchmark::RegisterBenchmark(
            name("rotate_batch", "quat", "quaternion_soa", "float", n).c_str(),
            rotate_batch_soa<float>, n);
    }
    // Copying the same bytes: no rotation can be faster once the points are out of cache.
    register_copy_floors("rotate_batch", 3, batch_bytes<float>(1), batch_sizes<float>());
}

}  // namespace bench
