// Per-element batches (quat/batch/elementwise.hpp): rotate_each (point i by rotation i; arrays of
// structs and struct of arrays), compose_each (a[i] * b[i]), to_matrix_each and
// to_quaternion_each. GLM and Eigen run the loops their users write, out[i] = q[i] * p[i] and so
// on, which g++ vectorizes too. One iteration is a whole batch; items are elements.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <quat/batch/elementwise.hpp>

#include "common.hpp"

namespace bench {
namespace {

/// quat: the batch functions under test.
template <class T>
struct each_quat : lib_quat<T> {
    using typename lib_quat<T>::quaternion;
    using typename lib_quat<T>::matrix;
    using typename lib_quat<T>::vector;
    static void rotate(const quaternion* q, const vector* p, vector* out, std::size_t n) {
        quat::rotate_each(q, p, out, n);
    }
    static void compose(const quaternion* a, const quaternion* b, quaternion* out, std::size_t n) {
        quat::compose_each(a, b, out, n);
    }
    static void to_matrix(const quaternion* q, matrix* out, std::size_t n) {
        quat::to_matrix_each(q, out, n);
    }
    static void to_quaternion(const matrix* m, quaternion* out, std::size_t n) {
        quat::to_quaternion_each(m, out, n);
    }
};

/// GLM: q * v rotates, a * b composes (b first, as in quat), mat3_cast and quat_cast convert.
template <class T>
struct each_glm : lib_glm<T> {
    using typename lib_glm<T>::quaternion;
    using typename lib_glm<T>::matrix;
    using typename lib_glm<T>::vector;
    static void rotate(const quaternion* q, const vector* p, vector* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = q[i] * p[i];
    }
    static void compose(const quaternion* a, const quaternion* b, quaternion* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = a[i] * b[i];
    }
    static void to_matrix(const quaternion* q, matrix* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = glm::mat3_cast(q[i]);
    }
    static void to_quaternion(const matrix* m, quaternion* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = glm::quat_cast(m[i]);
    }
};

/// Eigen: q * v rotates, a * b composes, toRotationMatrix() and Quaternion(m) convert.
template <class T>
struct each_eigen : lib_eigen<T> {
    using typename lib_eigen<T>::quaternion;
    using typename lib_eigen<T>::matrix;
    using typename lib_eigen<T>::vector;
    static void rotate(const quaternion* q, const vector* p, vector* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = q[i] * p[i];
    }
    static void compose(const quaternion* a, const quaternion* b, quaternion* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = a[i] * b[i];
    }
    static void to_matrix(const quaternion* q, matrix* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = q[i].toRotationMatrix();
    }
    static void to_quaternion(const matrix* m, quaternion* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = quaternion(m[i]);
    }
};

template <class Lib>
std::vector<typename Lib::quaternion> rotations(random_source& random, std::size_t n) {
    std::vector<typename Lib::quaternion> q(n);
    for (auto& r : q) r = Lib::make_quaternion(random.rotation());
    return q;
}

template <class Lib>
std::vector<typename Lib::matrix> matrices(random_source& random, std::size_t n) {
    std::vector<typename Lib::matrix> m(n);
    for (auto& r : m) r = Lib::make_matrix(random.rotation());
    return m;
}

void count(benchmark::State& state, std::size_t n, std::size_t bytes_per_element) {
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(n * bytes_per_element));
}

// Point i turned by rotation i. The output is written before timing (a copy of the points):
// Eigen's vectors are not value-initialized, and first-touch page faults would otherwise be timed.
template <class Lib>
void rotate_each(benchmark::State& state, long long size) {
    using T = typename Lib::scalar;
    const std::size_t n = static_cast<std::size_t>(size);
    random_source random;
    const auto q = rotations<Lib>(random, n);
    std::vector<typename Lib::vector> p(n), out(n);
    for (auto& v : p) v = Lib::make_vector(random.vector());
    std::copy(p.begin(), p.end(), out.begin());
    for (auto _ : state) {
        Lib::rotate(q.data(), p.data(), out.data(), n);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    count(state, n, 10 * sizeof(T));  // a quaternion and a point read, a point written
}

// quat's struct-of-arrays form over the same rotations and points.
template <class T>
void rotate_each_soa(benchmark::State& state, long long size) {
    const std::size_t n = static_cast<std::size_t>(size);
    random_source random;
    std::vector<T> w(n), x(n), y(n), z(n), px(n), py(n), pz(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto q = lib_quat<T>::make_quaternion(random.rotation());
        w[i] = q.w, x[i] = q.x, y[i] = q.y, z[i] = q.z;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const auto v = lib_quat<T>::make_vector(random.vector());
        px[i] = v.x, py[i] = v.y, pz[i] = v.z;
    }
    std::vector<T> ox = px, oy = py, oz = pz;
    for (auto _ : state) {
        quat::rotate_each(quat::soa_quaternions<const T>{w.data(), x.data(), y.data(), z.data(), n},
                          quat::soa_points<const T>{px.data(), py.data(), pz.data(), n},
                          quat::soa_points<T>{ox.data(), oy.data(), oz.data(), n});
        benchmark::DoNotOptimize(ox.data());
        benchmark::ClobberMemory();
    }
    count(state, n, 10 * sizeof(T));
}

template <class Lib>
void compose_each(benchmark::State& state, long long size) {
    using T = typename Lib::scalar;
    const std::size_t n = static_cast<std::size_t>(size);
    random_source random;
    const auto a = rotations<Lib>(random, n);
    const auto b = rotations<Lib>(random, n);
    auto out = a;
    for (auto _ : state) {
        Lib::compose(a.data(), b.data(), out.data(), n);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    count(state, n, 12 * sizeof(T));  // two quaternions read, one written
}

template <class Lib>
void to_matrix_each(benchmark::State& state, long long size) {
    using T = typename Lib::scalar;
    const std::size_t n = static_cast<std::size_t>(size);
    random_source random;
    const auto q = rotations<Lib>(random, n);
    auto out = matrices<Lib>(random, n);
    for (auto _ : state) {
        Lib::to_matrix(q.data(), out.data(), n);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    count(state, n, 13 * sizeof(T));  // a quaternion read, a 3x3 matrix written
}

template <class Lib>
void to_quaternion_each(benchmark::State& state, long long size) {
    using T = typename Lib::scalar;
    const std::size_t n = static_cast<std::size_t>(size);
    random_source random;
    const auto m = matrices<Lib>(random, n);
    auto out = rotations<Lib>(random, n);
    for (auto _ : state) {
        Lib::to_quaternion(m.data(), out.data(), n);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    count(state, n, 13 * sizeof(T));
}

// The sizes the requirement names: one short batch (call overhead and the tail), one in
// L1/L2, one far beyond L3 (memory bound).
const std::vector<long long> each_sizes = {64, 1024, 4194304};

template <class Lib>
void register_library() {
    const char* type = type_name<typename Lib::scalar>;
    for (const long long n : each_sizes) {
        benchmark::RegisterBenchmark(name("rotate_each", Lib::name, "quaternion", type, n).c_str(),
                                     rotate_each<Lib>, n);
        benchmark::RegisterBenchmark(name("compose_each", Lib::name, "quaternion", type, n).c_str(),
                                     compose_each<Lib>, n);
        benchmark::RegisterBenchmark(
            name("to_matrix_each", Lib::name, "quaternion", type, n).c_str(), to_matrix_each<Lib>,
            n);
        benchmark::RegisterBenchmark(
            name("to_quaternion_each", Lib::name, "matrix", type, n).c_str(),
            to_quaternion_each<Lib>, n);
    }
}

}  // namespace

void register_each() {
    using T = float;  // the per-element targets are float
    register_library<each_quat<T>>();
    register_library<each_glm<T>>();
    register_library<each_eigen<T>>();
    for (const long long n : each_sizes)
        benchmark::RegisterBenchmark(
            name("rotate_each", "quat", "quaternion_soa", "float", n).c_str(), rotate_each_soa<T>,
            n);
    // The memory floor of rotate_each: it reads 28 bytes (float) and writes 12 per element. A copy
    // reads and writes equal amounts, so these copy 20 bytes per element, moving the same 40.
    register_copy_floors("rotate_each", 5, 10 * sizeof(T), each_sizes);
    // compose_each reads 32 bytes and writes 16 per element: a copy of 24 moves the same 48.
    register_copy_floors("compose_each", 6, 12 * sizeof(T), each_sizes);
}

}  // namespace bench
