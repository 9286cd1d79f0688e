// Shared pieces of quat_bench: seeded inputs, one adapter per library (quat, GLM, Eigen) with the
// same static functions, and the benchmark naming scheme
// <operation>/<library>/<representation>/<type>[/<n>].
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <quat/batch/rotations.hpp>
#include <quat/paths/slerp_fast.hpp>
#include <quat/quat.hpp>

namespace bench {

/// Every benchmark draws its inputs from this seed at run time, so the optimizer cannot fold them.
inline constexpr std::uint64_t seed = 20190501;

template <class T>
inline const char* type_name = std::is_same_v<T, float> ? "float" : "double";

/// "<operation>/<library>/<representation>/<type>" plus "/<n>" when n >= 0.
inline std::string name(const std::string& operation, const std::string& library,
                        const std::string& representation, const std::string& type,
                        long long n = -1) {
    std::string s = operation + "/" + library + "/" + representation + "/" + type;
    if (n >= 0) {
        // Appended piecewise: GCC 12's -Wrestrict misfires on "/" + std::string&& at -O3.
        s += '/';
        s += std::to_string(n);
    }
    return s;
}

/// Seeded random unit quaternions (double; each library converts), vectors and parameters.
class random_source {
public:
    explicit random_source(std::uint64_t s = seed) : engine_(s) {}
    quat::quatd rotation() {
        for (;;) {
            const double w = gauss_(engine_), x = gauss_(engine_), y = gauss_(engine_),
                         z = gauss_(engine_);
            const double n = std::sqrt(w * w + x * x + y * y + z * z);
            if (n > 1e-3) return {w / n, x / n, y / n, z / n};
        }
    }
    quat::vec3<double> vector() { return {gauss_(engine_), gauss_(engine_), gauss_(engine_)}; }
    double uniform(double low, double high) {
        return std::uniform_real_distribution<double>(low, high)(engine_);
    }

private:
    std::mt19937_64 engine_;
    std::normal_distribution<double> gauss_;
};

/// quat: the library under test.
template <class T>
struct lib_quat {
    static constexpr const char* name = "quat";
    using scalar = T;
    using quaternion = quat::quaternion<T>;
    using matrix = quat::rotation_matrix<T>;
    using vector = quat::vec3<T>;
    static quaternion make_quaternion(const quat::quatd& q) {
        return {T(q.w), T(q.x), T(q.y), T(q.z)};
    }
    static matrix make_matrix(const quat::quatd& q) { return to_matrix(make_quaternion(q)); }
    static matrix to_matrix(const quaternion& q) { return quat::to_matrix(q); }
    static vector make_vector(const quat::vec3<double>& v) { return {T(v.x), T(v.y), T(v.z)}; }
    static vector rotate(const quaternion& q, const vector& v) { return quat::rotate(q, v); }
    static vector rotate(const matrix& m, const vector& v) { return quat::rotate(m, v); }
    static quaternion compose(const quaternion& a, const quaternion& b) { return a * b; }
    static matrix compose(const matrix& a, const matrix& b) { return a * b; }
    static quaternion identity_quaternion() { return quaternion::identity(); }
    static matrix identity_matrix() { return matrix::identity(); }
    static quaternion normalize(const quaternion& q) { return quat::normalize(q); }
    static quaternion slerp(const quaternion& a, const quaternion& b, T t) {
        return quat::slerp(a, b, t);
    }
    static quaternion nlerp(const quaternion& a, const quaternion& b, T t) {
        return quat::nlerp(a, b, t);
    }
    static T norm(const quaternion& q) { return quat::norm(q); }
    template <class R>
    static void rotate_batch(const R& r, const vector* in, vector* out, std::size_t n) {
        quat::rotate(r, in, out, n);
    }
};

/// GLM 0.9.9: glm::qua (scalar w first in its constructor), glm::mat3, glm::vec3.
template <class T>
struct lib_glm {
    static constexpr const char* name = "glm";
    using scalar = T;
    using quaternion = glm::qua<T, glm::defaultp>;
    using matrix = glm::mat<3, 3, T, glm::defaultp>;
    using vector = glm::vec<3, T, glm::defaultp>;
    static quaternion make_quaternion(const quat::quatd& q) {
        return quaternion(T(q.w), T(q.x), T(q.y), T(q.z));
    }
    static matrix make_matrix(const quat::quatd& q) { return to_matrix(make_quaternion(q)); }
    static matrix to_matrix(const quaternion& q) { return glm::mat3_cast(q); }
    static vector make_vector(const quat::vec3<double>& v) {
        return vector(T(v.x), T(v.y), T(v.z));
    }
    static vector rotate(const quaternion& q, const vector& v) { return q * v; }
    static vector rotate(const matrix& m, const vector& v) { return m * v; }
    static quaternion compose(const quaternion& a, const quaternion& b) { return a * b; }
    static matrix compose(const matrix& a, const matrix& b) { return a * b; }
    static quaternion identity_quaternion() { return quaternion(T(1), T(0), T(0), T(0)); }
    static matrix identity_matrix() { return matrix(T(1)); }
    static quaternion normalize(const quaternion& q) { return glm::normalize(q); }
    static quaternion slerp(const quaternion& a, const quaternion& b, T t) {
        return glm::slerp(a, b, t);
    }
    // GLM has no nlerp; its users write normalize(lerp) after choosing the nearer sign themselves.
    static quaternion nlerp(const quaternion& a, const quaternion& b, T t) {
        return glm::normalize(glm::lerp(a, glm::dot(a, b) < T(0) ? -b : b, t));
    }
    static T norm(const quaternion& q) { return glm::length(q); }
    template <class R>
    static void rotate_batch(const R& r, const vector* in, vector* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = r * in[i];
    }
};

/// Eigen 3.4: Quaternion (constructor w, x, y, z), Matrix3, Vector3; batches of matrices as
/// Map<Matrix3X> products, the way Eigen users rotate many points.
template <class T>
struct lib_eigen {
    static constexpr const char* name = "eigen";
    using scalar = T;
    using quaternion = Eigen::Quaternion<T>;
    using matrix = Eigen::Matrix<T, 3, 3>;
    using vector = Eigen::Matrix<T, 3, 1>;
    static quaternion make_quaternion(const quat::quatd& q) {
        return quaternion(T(q.w), T(q.x), T(q.y), T(q.z));
    }
    static matrix make_matrix(const quat::quatd& q) { return to_matrix(make_quaternion(q)); }
    static matrix to_matrix(const quaternion& q) { return q.toRotationMatrix(); }
    static vector make_vector(const quat::vec3<double>& v) {
        return vector(T(v.x), T(v.y), T(v.z));
    }
    static vector rotate(const quaternion& q, const vector& v) { return q * v; }
    static vector rotate(const matrix& m, const vector& v) { return m * v; }
    static quaternion compose(const quaternion& a, const quaternion& b) { return a * b; }
    static matrix compose(const matrix& a, const matrix& b) { return a * b; }
    static quaternion identity_quaternion() { return quaternion::Identity(); }
    static matrix identity_matrix() { return matrix::Identity(); }
    static quaternion normalize(const quaternion& q) { return q.normalized(); }
    static quaternion slerp(const quaternion& a, const quaternion& b, T t) { return a.slerp(t, b); }
    static quaternion nlerp(const quaternion& a, const quaternion& b, T t) {
        const quaternion near = a.dot(b) < T(0) ? quaternion(-b.coeffs()) : b;
        return quaternion(a.coeffs() + (near.coeffs() - a.coeffs()) * t).normalized();
    }
    static T norm(const quaternion& q) { return q.norm(); }
    static void rotate_batch(const quaternion& q, const vector* in, vector* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = q * in[i];
    }
    static void rotate_batch(const matrix& m, const vector* in, vector* out, std::size_t n) {
        using points = Eigen::Matrix<T, 3, Eigen::Dynamic>;
        Eigen::Map<points>(out[0].data(), 3, static_cast<Eigen::Index>(n)).noalias() =
            m * Eigen::Map<const points>(in[0].data(), 3, static_cast<Eigen::Index>(n));
    }
};

/// Rotation type of a library for a representation tag.
struct quaternion_rep {
    static constexpr const char* name = "quaternion";
    template <class Lib>
    using type = typename Lib::quaternion;
    template <class Lib>
    static type<Lib> make(const quat::quatd& q) {
        return Lib::make_quaternion(q);
    }
    template <class Lib>
    static type<Lib> identity() {
        return Lib::identity_quaternion();
    }
};
struct matrix_rep {
    static constexpr const char* name = "matrix";
    template <class Lib>
    using type = typename Lib::matrix;
    template <class Lib>
    static type<Lib> make(const quat::quatd& q) {
        return Lib::make_matrix(q);
    }
    template <class Lib>
    static type<Lib> identity() {
        return Lib::identity_matrix();
    }
};

/// The rotation or motion of a batch as a value the compiler must take as new at every call, as
/// when a program moves each batch by one it has just computed. Without it g++ hoists an inlined
/// peer loop's setup (the nine splats of GLM's mat3 loop; with a quaternion, mat3_cast too) out of
/// the timing loop and times the loop body alone, while quat's out-of-line call sets up every
/// time: 64 points by GLM's mat3 loop took 17.9 ns hoisted and 24.4 ns not (Zen 4, harness).
template <class R>
R fresh(R r) {
    benchmark::DoNotOptimize(r);
    return r;
}

/// How many distinct seeded inputs the one-call-per-iteration benchmarks cycle through.
inline constexpr std::size_t pool = 256;

/// One call of f per iteration, cycling through `pool` inputs made by make(random_source&) before
/// timing starts; items are calls.
template <class Make, class Operation>
void cycle(benchmark::State& state, Make make, Operation f) {
    random_source random;
    std::vector<decltype(make(random))> in;
    for (std::size_t i = 0; i < pool; ++i) in.push_back(make(random));
    std::size_t i = 0;
    for (auto _ : state) {
        auto out = f(in[i]);
        benchmark::DoNotOptimize(out);
        i = (i + 1) % pool;
    }
    state.SetItemsProcessed(state.iterations());
}

/// out[i] = apply(transforms[i], in[i]) over all i per iteration, all independent (throughput):
/// whatever a library spends on the transform itself is paid per element; items are elements.
template <class Transforms, class Inputs, class Apply>
void time_pairs(benchmark::State& state, const Transforms& transforms, const Inputs& in,
                Apply apply) {
    const std::size_t n = in.size();
    Inputs out(n);
    for (auto _ : state) {
        for (std::size_t i = 0; i < n; ++i) out[i] = apply(transforms[i], in[i]);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

/// Times the product of `factors` left to right, each product waiting for the previous one: what
/// users of GLM and Eigen write. Lib::compose and Rep::identity<Lib> as in bench_compose.cpp.
template <class Lib, class Rep, class Factors>
void time_chain(benchmark::State& state, const Factors& factors) {
    for (auto _ : state) {
        auto product = Rep::template identity<Lib>();
        for (const auto& factor : factors) product = Lib::compose(product, factor);
        benchmark::DoNotOptimize(product);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long long>(factors.size()));
}

/// Times quat::compose over the whole span: independent partial products, joined at the end.
template <class Factors>
void time_compose_span(benchmark::State& state, const Factors& factors) {
    for (auto _ : state) {
        auto product = quat::compose(factors);
        benchmark::DoNotOptimize(product);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long long>(factors.size()));
}

/// The copy floor of a batch that moves `floats` floats per element each way: the same bytes
/// copied by memcpy, by a plain vectorized loop and, where input and output together exceed the
/// last-level cache, by non-temporal stores (quat's own stream_floats). `--table` takes the fastest
/// of the three as the floor, per size, and names it: no one copy is fastest on every CPU (glibc's
/// memcpy took 5 us for 12 KiB on a Zen 4 whose plain loop took 0.2).
enum class copy_kind { memcpy, loop, stream };

inline const char* copy_name(copy_kind kind) {
    return kind == copy_kind::memcpy ? "memcpy" : kind == copy_kind::loop ? "copy_loop" : "stream";
}

/// The plain loop: 32-byte vectors (GCC/clang vector extension), because g++ and clang turn a
/// float-by-float copy loop into a call of memcpy.
inline void copy_floats_loop(float* to, const float* from, std::size_t n) {
    using float8 = float __attribute__((vector_size(32)));
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        float8 v;
        std::memcpy(&v, from + i, sizeof v);
        std::memcpy(to + i, &v, sizeof v);
    }
    for (; i < n; ++i) to[i] = from[i];
}

template <copy_kind Kind>
void copy_floor(benchmark::State& state, long long count, std::size_t floats,
                std::size_t bytes_per_item) {
    const std::size_t n = static_cast<std::size_t>(count);
    random_source random;
    std::vector<float> in(floats * n), out(floats * n);
    for (auto& v : in) v = float(random.uniform(-1, 1));
    for (auto _ : state) {
        if constexpr (Kind == copy_kind::memcpy) {
            std::memcpy(out.data(), in.data(), in.size() * sizeof(float));
        } else if constexpr (Kind == copy_kind::loop) {
            copy_floats_loop(out.data(), in.data(), in.size());
        } else {
            quat::detail::stream_floats(out.data(), in.data(), in.size());
            quat::detail::stream_fence();
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(n * bytes_per_item));
}

/// Registers "<operation>/{memcpy,copy_loop,stream}/bytes/float/<n>" for each n; bytes_per_item is
/// what the operation's own benchmark counts per element.
inline void register_copy_floors(const std::string& operation, std::size_t floats,
                                 std::size_t bytes_per_item, const std::vector<long long>& sizes) {
    for (const long long n : sizes) {
        const std::size_t written = floats * sizeof(float) * static_cast<std::size_t>(n);
        benchmark::RegisterBenchmark(name(operation, "memcpy", "bytes", "float", n).c_str(),
                                     copy_floor<copy_kind::memcpy>, n, floats, bytes_per_item);
        benchmark::RegisterBenchmark(name(operation, "copy_loop", "bytes", "float", n).c_str(),
                                     copy_floor<copy_kind::loop>, n, floats, bytes_per_item);
        // The streaming copy only where quat's own rule streams the output.
        if (quat::detail::streams_output(written))
            benchmark::RegisterBenchmark(name(operation, "stream", "bytes", "float", n).c_str(),
                                         copy_floor<copy_kind::stream>, n, floats, bytes_per_item);
    }
}

/// Registration entry points, one per source file; each registers float and double variants.
void register_rotate();
void register_compose();
void register_conversions();
void register_interpolation();
void register_motion();      // bench_motion.cpp
void register_align();       // bench_align.cpp
void register_estimation();  // bench_estimation.cpp
void register_keyframes();   // bench_keyframes.cpp
void register_rigid();       // bench_rigid.cpp
void register_each();        // bench_each.cpp
void register_lie();         // bench_lie.cpp
void register_trajectory();  // bench_trajectory.cpp

/// `quat_bench --counts`: the operation-count tables.
int print_counts();

}  // namespace bench
