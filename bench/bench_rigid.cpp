// Rigid motions x -> R x + t as dual quaternions and 4x4 matrices: transform_batch (n points moved
// by one motion, in cache and out of it; rotate_batch's copies of the same bytes are the floor),
// transform_point and transform_pairs (one point at a time: latency, and throughput with each
// point its own motion), rigid_chain (the product of 1024 motions), sclerp and blend. Eigen has no
// dual quaternion, so its entries are matrices, and for one point at a time also a unit quaternion
// with a translation; sclerp and blend have no counterpart in GLM or Eigen.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

// GLM 1.0 refuses gtx headers without this; 0.9.9 only names it in its optional messages.
#ifndef GLM_ENABLE_EXPERIMENTAL
#define GLM_ENABLE_EXPERIMENTAL
#endif
#include <glm/gtx/dual_quaternion.hpp>

#include <quat/batch/rigid_motions.hpp>
#include <quat/rigid/blend.hpp>
#include <quat/rigid/dual_quaternion.hpp>
#include <quat/rigid/homogeneous_matrix.hpp>
#include <quat/rigid/sclerp.hpp>

#include "common.hpp"

namespace bench {
namespace {

/// A seeded rigid motion in double, converted by each library: a random unit quaternion, then a
/// translation uniform in [-1, 1]^3.
struct motion {
    quat::quatd rotation;
    quat::vec3<double> translation;
};

motion random_motion(random_source& random) {
    motion m{random.rotation(), {}};
    // One statement per draw: the order of draws, hence the motion, must not depend on the
    // compiler.
    m.translation.x = random.uniform(-1, 1);
    m.translation.y = random.uniform(-1, 1);
    m.translation.z = random.uniform(-1, 1);
    return m;
}

/// quat: dual_quaternion and homogeneous_matrix, moved through its batch overloads.
template <class T>
struct rigid_quat {
    static constexpr const char* name = "quat";
    using scalar = T;
    using dual_quaternion = quat::dual_quaternion<T>;
    using matrix = quat::homogeneous_matrix<T>;
    using vector = quat::vec3<T>;
    static dual_quaternion make_dual_quaternion(const motion& m) {
        return quat::to_dual_quaternion(lib_quat<T>::make_quaternion(m.rotation),
                                        lib_quat<T>::make_vector(m.translation));
    }
    static matrix make_matrix(const motion& m) {
        return quat::to_homogeneous(make_dual_quaternion(m));
    }
    static vector make_vector(const quat::vec3<double>& v) { return lib_quat<T>::make_vector(v); }
    static dual_quaternion identity_dual_quaternion() { return dual_quaternion::identity(); }
    static matrix identity_matrix() { return matrix::identity(); }
    static dual_quaternion compose(const dual_quaternion& a, const dual_quaternion& b) {
        return a * b;
    }
    static matrix compose(const matrix& a, const matrix& b) { return a * b; }
    template <class R>
    static void transform_batch(const R& r, const vector* in, vector* out, std::size_t n) {
        quat::transform(r, in, out, n);
    }
    static dual_quaternion make_point_motion(const motion& m) { return make_dual_quaternion(m); }
    template <class R>
    static vector transform(const R& r, const vector& p) {
        return quat::transform(r, p);
    }
};

/// GLM 0.9.9: glm::tdualquat (gtx) and glm::mat4 on (x, y, z, 1), in the loops its users write.
template <class T>
struct rigid_glm {
    static constexpr const char* name = "glm";
    using scalar = T;
    using dual_quaternion = glm::tdualquat<T, glm::defaultp>;
    using matrix = glm::mat<4, 4, T, glm::defaultp>;
    using vector = glm::vec<3, T, glm::defaultp>;
    using point = glm::vec<4, T, glm::defaultp>;
    static dual_quaternion make_dual_quaternion(const motion& m) {
        // GLM's (rotation, translation) constructor: rotation first, as in quat.
        return dual_quaternion(lib_glm<T>::make_quaternion(m.rotation),
                               lib_glm<T>::make_vector(m.translation));
    }
    static matrix make_matrix(const motion& m) {
        matrix h(glm::mat3_cast(lib_glm<T>::make_quaternion(m.rotation)));
        h[3] = point(lib_glm<T>::make_vector(m.translation), T(1));  // column-major: [3] is t
        return h;
    }
    static vector make_vector(const quat::vec3<double>& v) { return lib_glm<T>::make_vector(v); }
    static dual_quaternion identity_dual_quaternion() {
        return glm::dual_quat_identity<T, glm::defaultp>();
    }
    static matrix identity_matrix() { return matrix(T(1)); }
    static dual_quaternion compose(const dual_quaternion& a, const dual_quaternion& b) {
        return a * b;
    }
    static matrix compose(const matrix& a, const matrix& b) { return a * b; }
    static void transform_batch(const dual_quaternion& dq, const vector* in, vector* out,
                                std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = dq * in[i];
    }
    static void transform_batch(const matrix& m, const vector* in, vector* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = vector(m * point(in[i], T(1)));
    }
    static dual_quaternion make_point_motion(const motion& m) { return make_dual_quaternion(m); }
    static vector transform(const dual_quaternion& dq, const vector& p) { return dq * p; }
    static vector transform(const matrix& m, const vector& p) { return vector(m * point(p, T(1))); }
};

/// Eigen 3.4: Isometry3 (a 4x4 matrix whose products Eigen specializes for rigid motions), applied
/// point by point. Unlike rotate_batch's Map<Matrix3X> product, iso * Map<Matrix3X> is not used:
/// it matched the loop at 1024 points and was 4x slower at 4M (Eigen 3.4, g++ 12).
template <class T>
struct rigid_eigen {
    static constexpr const char* name = "eigen";
    using scalar = T;
    using matrix = Eigen::Transform<T, 3, Eigen::Isometry>;
    using vector = Eigen::Matrix<T, 3, 1>;
    static matrix make_matrix(const motion& m) {
        return Eigen::Translation<T, 3>(lib_eigen<T>::make_vector(m.translation)) *
               lib_eigen<T>::make_quaternion(m.rotation);
    }
    static vector make_vector(const quat::vec3<double>& v) { return lib_eigen<T>::make_vector(v); }
    static matrix identity_matrix() { return matrix::Identity(); }
    static matrix compose(const matrix& a, const matrix& b) { return a * b; }
    static void transform_batch(const matrix& m, const vector* in, vector* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = m * in[i];
    }
    /// A unit quaternion and a translation, as Sophus's SE3 stores a motion: its SE3 * p is q * p
    /// + t with Eigen's quaternion product (Sophus itself is not a dependency of the benchmark).
    struct pose {
        Eigen::Quaternion<T> rotation;
        vector translation;
    };
    static pose make_point_motion(const motion& m) {
        return {lib_eigen<T>::make_quaternion(m.rotation), make_vector(m.translation)};
    }
    static vector transform(const pose& x, const vector& p) {
        return x.rotation * p + x.translation;
    }
    static vector transform(const matrix& m, const vector& p) { return m * p; }
};

/// Representation tags; the names differ from common.hpp's rotation tags, which stay visible here.
struct dual_quaternion_motion {
    static constexpr const char* name = "dual_quaternion";
    template <class Lib>
    static typename Lib::dual_quaternion make(const motion& m) {
        return Lib::make_dual_quaternion(m);
    }
    template <class Lib>
    static typename Lib::dual_quaternion identity() {
        return Lib::identity_dual_quaternion();
    }
};
struct matrix_motion {
    static constexpr const char* name = "matrix";
    template <class Lib>
    static typename Lib::matrix make(const motion& m) {
        return Lib::make_matrix(m);
    }
    template <class Lib>
    static typename Lib::matrix identity() {
        return Lib::identity_matrix();
    }
};

/// One point at a time, each library's own rigid motion: quat's and GLM's dual quaternions,
/// Eigen's quaternion and translation (rigid_eigen::pose).
struct point_motion {
    static constexpr const char* name = "motion";
    template <class Lib>
    static auto make(const motion& m) {
        return Lib::make_point_motion(m);
    }
};

// One motion applied to its own result (latency: one dependency chain), as rotate_point.
template <class Lib, class Rep>
void transform_point(benchmark::State& state) {
    random_source random;
    const auto r = Rep::template make<Lib>(random_motion(random));
    auto v = Lib::make_vector(random.vector());
    for (auto _ : state) {
        v = Lib::transform(r, v);
        benchmark::DoNotOptimize(v);
    }
    state.SetItemsProcessed(state.iterations());
}

// Each point moved by its own motion, all independent (throughput), as rotate_pairs: whatever a
// library spends on the motion itself is paid per point.
template <class Lib, class Rep>
void transform_pairs(benchmark::State& state, long long count) {
    const std::size_t n = static_cast<std::size_t>(count);
    random_source random;
    std::vector<decltype(Rep::template make<Lib>(random_motion(random)))> r;
    std::vector<typename Lib::vector> in(n);
    for (std::size_t i = 0; i < n; ++i) {
        r.push_back(Rep::template make<Lib>(random_motion(random)));
        in[i] = Lib::make_vector(random.vector());
    }
    time_pairs(state, r, in, [](const auto& x, const auto& p) { return Lib::transform(x, p); });
}

template <class T>
std::int64_t batch_bytes(std::size_t n) {
    // Read and written once each, as rotate_batch counts them, so the two compare byte for byte.
    return static_cast<std::int64_t>(2 * n * 3 * sizeof(T));
}

// n points moved by one motion per iteration; any conversion a library makes (quat's dual
// quaternion to a matrix) is paid once per batch, inside the timing.
template <class Lib, class Rep>
void transform_batch(benchmark::State& state, long long count) {
    using T = typename Lib::scalar;
    const std::size_t n = static_cast<std::size_t>(count);
    random_source random;
    const auto r = Rep::template make<Lib>(random_motion(random));
    std::vector<typename Lib::vector> in(n), out(n);
    for (auto& v : in) v = Lib::make_vector(random.vector());
    // Touch the output before timing: Eigen's vectors are not value-initialized, and first-touch
    // page faults would otherwise be timed (the 4M-point runs take only a few iterations).
    std::copy(in.begin(), in.end(), out.begin());
    for (auto _ : state) {
        Lib::transform_batch(fresh(r), in.data(), out.data(), n);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
    state.SetBytesProcessed(state.iterations() * batch_bytes<T>(n));
}

// quat's struct-of-arrays overload over the same points.
template <class T>
void transform_batch_soa(benchmark::State& state, long long count) {
    const std::size_t n = static_cast<std::size_t>(count);
    random_source random;
    const quat::dual_quaternion<T> dq = rigid_quat<T>::make_dual_quaternion(random_motion(random));
    std::vector<T> x(n), y(n), z(n), ox(n), oy(n), oz(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto v = random.vector();
        x[i] = T(v.x), y[i] = T(v.y), z[i] = T(v.z);
    }
    for (auto _ : state) {
        quat::transform(fresh(dq), quat::soa_points<const T>{x.data(), y.data(), z.data(), n},
                        quat::soa_points<T>{ox.data(), oy.data(), oz.data(), n});
        benchmark::DoNotOptimize(ox.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
    state.SetBytesProcessed(state.iterations() * batch_bytes<T>(n));
}

template <class Lib, class Rep>
auto motions(std::size_t n) {
    random_source random;
    std::vector<decltype(Rep::template make<Lib>(random_motion(random)))> r;
    r.reserve(n);
    for (std::size_t i = 0; i < n; ++i) r.push_back(Rep::template make<Lib>(random_motion(random)));
    return r;
}

template <class Lib, class Rep>
void rigid_chain(benchmark::State& state, long long k) {
    time_chain<Lib, Rep>(state, motions<Lib, Rep>(static_cast<std::size_t>(k)));
}

template <class T>
void rigid_chain_span(benchmark::State& state, long long k) {
    time_compose_span(state,
                      motions<rigid_quat<T>, dual_quaternion_motion>(static_cast<std::size_t>(k)));
}

// One sclerp per iteration over seeded pairs and parameters t in [0, 1], as the slerp benchmark.
template <class T>
void sclerp_pairs(benchmark::State& state) {
    random_source random;
    std::vector<quat::dual_quaternion<T>> dq;
    std::vector<T> t;
    for (std::size_t i = 0; i <= pool; ++i)
        dq.push_back(rigid_quat<T>::make_dual_quaternion(random_motion(random)));
    for (std::size_t i = 0; i < pool; ++i) t.push_back(T(random.uniform(0, 1)));
    std::size_t i = 0;
    for (auto _ : state) {
        auto r = quat::sclerp(dq[i], dq[i + 1], t[i]);
        benchmark::DoNotOptimize(r);
        i = (i + 1) % pool;
    }
    state.SetItemsProcessed(state.iterations());
}

constexpr std::size_t blend_count = 4;  // influences per skinned vertex, the common limit

/// One skinned vertex's influences: motions and weights in (0, 1] summing to 1.
template <class T>
struct influences {
    std::array<quat::dual_quaternion<T>, blend_count> transforms;
    std::array<T, blend_count> weights;
};

template <class T>
influences<T> random_influences(random_source& random) {
    influences<T> s{};
    double w[blend_count], sum = 0;
    for (std::size_t i = 0; i < blend_count; ++i) {
        s.transforms[i] = rigid_quat<T>::make_dual_quaternion(random_motion(random));
        w[i] = random.uniform(0.01, 1);
        sum += w[i];
    }
    for (std::size_t i = 0; i < blend_count; ++i) s.weights[i] = T(w[i] / sum);
    return s;
}

template <class Lib>
void register_single_points_of() {
    const char* type = type_name<typename Lib::scalar>;
    constexpr long long n = 1024;
    benchmark::RegisterBenchmark(name("transform_point", Lib::name, "motion", type).c_str(),
                                 transform_point<Lib, point_motion>);
    benchmark::RegisterBenchmark(name("transform_point", Lib::name, "matrix", type).c_str(),
                                 transform_point<Lib, matrix_motion>);
    benchmark::RegisterBenchmark(name("transform_pairs", Lib::name, "motion", type, n).c_str(),
                                 transform_pairs<Lib, point_motion>, n);
    benchmark::RegisterBenchmark(name("transform_pairs", Lib::name, "matrix", type, n).c_str(),
                                 transform_pairs<Lib, matrix_motion>, n);
}

// transform_batch at n points and rigid_chain of k motions for one library and representation.
template <class Lib, class Rep>
void register_pair(const std::vector<long long>& sizes, long long k) {
    const char* type = type_name<typename Lib::scalar>;
    for (const long long n : sizes)
        benchmark::RegisterBenchmark(name("transform_batch", Lib::name, Rep::name, type, n).c_str(),
                                     transform_batch<Lib, Rep>, n);
    benchmark::RegisterBenchmark(name("rigid_chain", Lib::name, Rep::name, type, k).c_str(),
                                 rigid_chain<Lib, Rep>, k);
}

// transform_point and transform_pairs for one library, motion and matrix, float and double.
template <template <class> class Lib>
void register_single_points() {
    register_single_points_of<Lib<float>>();
    register_single_points_of<Lib<double>>();
}

}  // namespace

void register_rigid() {
    register_single_points<rigid_quat>();
    register_single_points<rigid_glm>();
    register_single_points<rigid_eigen>();
    using T = float;  // the rigid-motion targets are float
    const char* type = type_name<T>;
    // One short batch (call overhead and the tail), one in L1/L2, one far beyond L3.
    const std::vector<long long> sizes = {64, 1024, 4194304};
    constexpr long long k = 1024;
    // quat's rigid_chain entry for dual quaternions is its compose(span), registered below; the
    // sequential loop runs as rigid_chain_sequential, as chain and chain_sequential do for
    // rotations.
    for (const long long n : sizes) {
        benchmark::RegisterBenchmark(
            name("transform_batch", "quat", "dual_quaternion", type, n).c_str(),
            transform_batch<rigid_quat<T>, dual_quaternion_motion>, n);
        benchmark::RegisterBenchmark(
            name("transform_batch", "quat", "dual_quaternion_soa", type, n).c_str(),
            transform_batch_soa<T>, n);
    }
    benchmark::RegisterBenchmark(name("rigid_chain", "quat", "dual_quaternion", type, k).c_str(),
                                 rigid_chain_span<T>, k);
    benchmark::RegisterBenchmark(
        name("rigid_chain_sequential", "quat", "dual_quaternion", type, k).c_str(),
        rigid_chain<rigid_quat<T>, dual_quaternion_motion>, k);
    register_pair<rigid_quat<T>, matrix_motion>(sizes, k);
    register_pair<rigid_glm<T>, dual_quaternion_motion>(sizes, k);
    register_pair<rigid_glm<T>, matrix_motion>(sizes, k);
    register_pair<rigid_eigen<T>, matrix_motion>(sizes, k);  // Eigen has no dual quaternion
    benchmark::RegisterBenchmark(name("sclerp", "quat", "dual_quaternion", type).c_str(),
                                 sclerp_pairs<T>);
    benchmark::RegisterBenchmark(
        name("blend", "quat", "dual_quaternion", type, static_cast<long long>(blend_count)).c_str(),
        [](benchmark::State& state) {
            cycle(state, random_influences<T>,
                  [](const influences<T>& s) { return quat::blend(s.transforms, s.weights); });
        });
}

}  // namespace bench
