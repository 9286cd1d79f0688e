// compose (one product), chain (k dependent products), apply_chain (k rotations applied to n
// points: composed first, or applied one after another) and drift (many products, with and
// without renormalization).
#include <cmath>

#include "common.hpp"

namespace bench {
namespace {

template <class Lib, class Rep>
auto rotations(std::size_t n) {
    random_source random;
    std::vector<typename Rep::template type<Lib>> r;
    r.reserve(n);
    for (std::size_t i = 0; i < n; ++i) r.push_back(Rep::template make<Lib>(random.rotation()));
    return r;
}

template <class Lib, class Rep>
void compose(benchmark::State& state) {
    const auto r = rotations<Lib, Rep>(pool + 1);
    std::size_t i = 0;
    for (auto _ : state) {
        auto product = Lib::compose(r[i], r[i + 1]);
        benchmark::DoNotOptimize(product);
        i = (i + 1) % pool;
    }
    state.SetItemsProcessed(state.iterations());
}

template <class Lib, class Rep>
void chain(benchmark::State& state, long long k) {
    time_chain<Lib, Rep>(state, rotations<Lib, Rep>(static_cast<std::size_t>(k)));
}

template <class T>
void chain_span(benchmark::State& state, long long k) {
    time_compose_span(state, rotations<lib_quat<T>, quaternion_rep>(static_cast<std::size_t>(k)));
}

constexpr long long apply_k = 8;  // rotations in the apply_chain benchmarks

// k rotations turned into one (k - 1 products), then applied to each of n points.
template <class Lib, class Rep>
void apply_composed(benchmark::State& state, long long n) {
    const auto r = rotations<Lib, Rep>(apply_k);
    random_source random(seed + 1);
    std::vector<typename Lib::vector> points(static_cast<std::size_t>(n));
    for (auto& p : points) p = Lib::make_vector(random.vector());
    for (auto _ : state) {
        auto total = r[0];
        for (std::size_t j = 1; j < r.size(); ++j) total = Lib::compose(total, r[j]);
        for (auto& p : points) benchmark::DoNotOptimize(Lib::rotate(total, p));
    }
    state.SetItemsProcessed(state.iterations() * n);
}

// The same k rotations applied one after another to each point (last factor first, like the
// product).
template <class Lib, class Rep>
void apply_each(benchmark::State& state, long long n) {
    const auto r = rotations<Lib, Rep>(apply_k);
    random_source random(seed + 1);
    std::vector<typename Lib::vector> points(static_cast<std::size_t>(n));
    for (auto& p : points) p = Lib::make_vector(random.vector());
    for (auto _ : state) {
        for (auto& p : points) {
            auto v = p;
            for (std::size_t j = r.size(); j-- > 0;) v = Lib::rotate(r[j], v);
            benchmark::DoNotOptimize(v);
        }
    }
    state.SetItemsProcessed(state.iterations() * n);
}

// 1024 products of unit quaternions; the counter norm_error is |1 - |q|| at the end.
template <class Lib>
void drift(benchmark::State& state, long long k, bool renormalize) {
    const auto r = rotations<Lib, quaternion_rep>(static_cast<std::size_t>(k));
    double error = 0;
    for (auto _ : state) {
        auto product = Lib::identity_quaternion();
        if (renormalize)
            for (const auto& factor : r) product = Lib::normalize(Lib::compose(product, factor));
        else
            for (const auto& factor : r) product = Lib::compose(product, factor);
        benchmark::DoNotOptimize(product);
        error = std::abs(1.0 - static_cast<double>(Lib::norm(product)));
    }
    state.SetItemsProcessed(state.iterations() * k);
    state.counters["norm_error"] = error;
}

template <template <class> class Lib, class T>
void register_library() {
    using L = Lib<T>;
    const char* type = type_name<T>;
    benchmark::RegisterBenchmark(name("compose", L::name, "quaternion", type).c_str(),
                                 compose<L, quaternion_rep>);
    benchmark::RegisterBenchmark(name("compose", L::name, "matrix", type).c_str(),
                                 compose<L, matrix_rep>);
    for (const long long k : {2LL, 8LL, 64LL, 1024LL}) {
        // quat's quaternion entry is its compose(span); the sequential loop runs as
        // chain_sequential.
        const std::string library = L::name;
        if (library == "quat") {
            benchmark::RegisterBenchmark(name("chain", "quat", "quaternion", type, k).c_str(),
                                         chain_span<T>, k);
            benchmark::RegisterBenchmark(
                name("chain_sequential", "quat", "quaternion", type, k).c_str(),
                chain<L, quaternion_rep>, k);
        } else {
            benchmark::RegisterBenchmark(name("chain", L::name, "quaternion", type, k).c_str(),
                                         chain<L, quaternion_rep>, k);
        }
        benchmark::RegisterBenchmark(name("chain", L::name, "matrix", type, k).c_str(),
                                     chain<L, matrix_rep>, k);
    }
    benchmark::RegisterBenchmark(name("drift", L::name, "quaternion", type, 1024).c_str(), drift<L>,
                                 1024, false);
    benchmark::RegisterBenchmark(
        name("drift_normalized", L::name, "quaternion", type, 1024).c_str(), drift<L>, 1024, true);
    if (!std::is_same_v<T, float>) return;
    for (const long long n : {1LL, 2LL, 4LL, 8LL, 16LL, 64LL, 256LL}) {
        benchmark::RegisterBenchmark(
            name("apply_chain_composed", L::name, "quaternion", type, n).c_str(),
            apply_composed<L, quaternion_rep>, n);
        benchmark::RegisterBenchmark(
            name("apply_chain_composed", L::name, "matrix", type, n).c_str(),
            apply_composed<L, matrix_rep>, n);
        benchmark::RegisterBenchmark(
            name("apply_chain_each", L::name, "quaternion", type, n).c_str(),
            apply_each<L, quaternion_rep>, n);
        benchmark::RegisterBenchmark(name("apply_chain_each", L::name, "matrix", type, n).c_str(),
                                     apply_each<L, matrix_rep>, n);
    }
}

}  // namespace

void register_compose() {
    register_library<lib_quat, float>();
    register_library<lib_glm, float>();
    register_library<lib_eigen, float>();
    register_library<lib_quat, double>();
    register_library<lib_glm, double>();
    register_library<lib_eigen, double>();
}

}  // namespace bench
