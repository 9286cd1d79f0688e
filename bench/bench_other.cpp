// convert (each direction among euler, matrix, quaternion, axis_angle, where the library has it),
// slerp, slerp_batch, slerp_fast, nlerp and normalize.
#include <array>

#include "common.hpp"

namespace bench {
namespace {

struct euler_angles {
    double yaw, pitch, roll;  // R = Rz(yaw) Ry(pitch) Rx(roll), the thesis's order
};
struct axis_and_angle {
    quat::vec3<double> axis;
    double angle;
};

euler_angles random_euler(random_source& r) {
    return {r.uniform(-3.14, 3.14), r.uniform(-1.57, 1.57), r.uniform(-3.14, 3.14)};
}
axis_and_angle random_axis_angle(random_source& r) {
    quat::vec3<double> v = r.vector();
    return {quat::normalize(v), r.uniform(0, 3.14)};
}

template <class Make, class Convert>
void add_convert(const std::string& library, const std::string& direction, const char* type,
                 Make make, Convert f) {
    benchmark::RegisterBenchmark(name("convert", library, direction, type).c_str(),
                                 [make, f](benchmark::State& state) { cycle(state, make, f); });
}

template <class T>
void register_conversions_for() {
    const char* type = type_name<T>;
    using E = quat::euler<T>;
    using AA = quat::axis_angle<T>;
    using Q = lib_quat<T>;
    auto q_euler = [](random_source& r) {
        const auto e = random_euler(r);
        return E{{T(e.yaw), T(e.pitch), T(e.roll)}};
    };
    auto q_axis = [](random_source& r) {
        const auto a = random_axis_angle(r);
        return AA{Q::make_vector(a.axis), T(a.angle)};
    };
    auto q_quat = [](random_source& r) { return Q::make_quaternion(r.rotation()); };
    auto q_matrix = [](random_source& r) { return Q::make_matrix(r.rotation()); };
    add_convert("quat", "euler_to_quaternion", type, q_euler,
                [](const E& e) { return quat::to_quaternion(e); });
    add_convert("quat", "euler_to_matrix", type, q_euler,
                [](const E& e) { return quat::to_matrix(e); });
    add_convert("quat", "euler_to_axis_angle", type, q_euler,
                [](const E& e) { return quat::to_axis_angle(e); });
    add_convert("quat", "axis_angle_to_quaternion", type, q_axis,
                [](const AA& a) { return quat::to_quaternion(a); });
    add_convert("quat", "axis_angle_to_matrix", type, q_axis,
                [](const AA& a) { return quat::to_matrix(a); });
    add_convert("quat", "axis_angle_to_euler", type, q_axis,
                [](const AA& a) { return quat::to_euler<quat::sequence::zyx>(a); });
    add_convert("quat", "quaternion_to_matrix", type, q_quat,
                [](const quat::quaternion<T>& q) { return quat::to_matrix(q); });
    add_convert("quat", "quaternion_to_axis_angle", type, q_quat,
                [](const quat::quaternion<T>& q) { return quat::to_axis_angle(q); });
    add_convert("quat", "quaternion_to_euler", type, q_quat, [](const quat::quaternion<T>& q) {
        return quat::to_euler<quat::sequence::zyx>(q);
    });
    add_convert("quat", "matrix_to_quaternion", type, q_matrix,
                [](const quat::rotation_matrix<T>& m) { return quat::to_quaternion(m); });
    add_convert("quat", "matrix_to_axis_angle", type, q_matrix,
                [](const quat::rotation_matrix<T>& m) { return quat::to_axis_angle(m); });
    add_convert("quat", "matrix_to_euler", type, q_matrix, [](const quat::rotation_matrix<T>& m) {
        return quat::to_euler<quat::sequence::zyx>(m);
    });

    // GLM: its Euler angles are (pitch, yaw, roll) about x, y, z, R = Rz Ry Rx like ours.
    using G = lib_glm<T>;
    using gvec = typename G::vector;
    using gquat = typename G::quaternion;
    using gmat = typename G::matrix;
    auto g_euler = [](random_source& r) {
        const auto e = random_euler(r);
        return gvec(T(e.roll), T(e.pitch), T(e.yaw));
    };
    auto g_axis = [](random_source& r) {
        const auto a = random_axis_angle(r);
        return std::pair<gvec, T>(G::make_vector(a.axis), T(a.angle));
    };
    auto g_quat = [](random_source& r) { return G::make_quaternion(r.rotation()); };
    auto g_matrix = [](random_source& r) { return G::make_matrix(r.rotation()); };
    add_convert("glm", "euler_to_quaternion", type, g_euler,
                [](const gvec& e) { return gquat(e); });
    add_convert("glm", "axis_angle_to_quaternion", type, g_axis,
                [](const std::pair<gvec, T>& a) { return glm::angleAxis(a.second, a.first); });
    add_convert("glm", "quaternion_to_matrix", type, g_quat,
                [](const gquat& q) { return glm::mat3_cast(q); });
    add_convert("glm", "quaternion_to_axis_angle", type, g_quat,
                [](const gquat& q) { return std::pair<gvec, T>(glm::axis(q), glm::angle(q)); });
    add_convert("glm", "quaternion_to_euler", type, g_quat,
                [](const gquat& q) { return glm::eulerAngles(q); });
    add_convert("glm", "matrix_to_quaternion", type, g_matrix,
                [](const gmat& m) { return glm::quat_cast(m); });

    // Eigen: Euler angles as a product of AngleAxis, eulerAngles(2, 1, 0) for z-y-x.
    using EG = lib_eigen<T>;
    using evec = typename EG::vector;
    using equat = typename EG::quaternion;
    using emat = typename EG::matrix;
    using eaa = Eigen::AngleAxis<T>;
    auto e_euler = [](random_source& r) {
        const auto e = random_euler(r);
        return evec(T(e.yaw), T(e.pitch), T(e.roll));
    };
    auto e_axis = [](random_source& r) {
        const auto a = random_axis_angle(r);
        return eaa(T(a.angle), EG::make_vector(a.axis));
    };
    auto e_quat = [](random_source& r) { return EG::make_quaternion(r.rotation()); };
    auto e_matrix = [](random_source& r) { return EG::make_matrix(r.rotation()); };
    auto e_product = [](const evec& e) {
        return eaa(e[0], evec::UnitZ()) * eaa(e[1], evec::UnitY()) * eaa(e[2], evec::UnitX());
    };
    add_convert("eigen", "euler_to_quaternion", type, e_euler,
                [e_product](const evec& e) { return equat(e_product(e)); });
    add_convert("eigen", "euler_to_matrix", type, e_euler,
                [e_product](const evec& e) { return emat(e_product(e).toRotationMatrix()); });
    add_convert("eigen", "axis_angle_to_quaternion", type, e_axis,
                [](const eaa& a) { return equat(a); });
    add_convert("eigen", "axis_angle_to_matrix", type, e_axis,
                [](const eaa& a) { return emat(a.toRotationMatrix()); });
    add_convert("eigen", "quaternion_to_matrix", type, e_quat,
                [](const equat& q) { return emat(q.toRotationMatrix()); });
    add_convert("eigen", "quaternion_to_axis_angle", type, e_quat,
                [](const equat& q) { return eaa(q); });
    add_convert("eigen", "matrix_to_quaternion", type, e_matrix,
                [](const emat& m) { return equat(m); });
    add_convert("eigen", "matrix_to_axis_angle", type, e_matrix,
                [](const emat& m) { return eaa(m); });
    add_convert("eigen", "matrix_to_euler", type, e_matrix,
                [](const emat& m) { return evec(m.eulerAngles(2, 1, 0)); });
}

// One interpolation (or normalization) per iteration over seeded pairs and parameters t in [0, 1].
template <class Lib, class F>
void interpolate(benchmark::State& state, F f) {
    using T = typename Lib::scalar;
    random_source random;
    std::vector<typename Lib::quaternion> q;
    std::vector<T> t;
    for (std::size_t i = 0; i <= pool; ++i) q.push_back(Lib::make_quaternion(random.rotation()));
    for (std::size_t i = 0; i < pool; ++i) t.push_back(T(random.uniform(0, 1)));
    std::size_t i = 0;
    for (auto _ : state) {
        auto r = f(q[i], q[i + 1], t[i]);
        benchmark::DoNotOptimize(r);
        i = (i + 1) % pool;
    }
    state.SetItemsProcessed(state.iterations());
}

// slerp between one pair at n parameters: quat's batch form, or a per-call loop for GLM and Eigen.
template <class Lib>
void slerp_batch(benchmark::State& state, long long n) {
    using T = typename Lib::scalar;
    random_source random;
    const auto a = Lib::make_quaternion(random.rotation()),
               b = Lib::make_quaternion(random.rotation());
    std::vector<T> t(static_cast<std::size_t>(n));
    for (auto& x : t) x = T(random.uniform(0, 1));
    std::vector<typename Lib::quaternion> out(t.size());
    for (auto _ : state) {
        if constexpr (std::is_same_v<Lib, lib_quat<T>>) {
            quat::slerp(a, b, t, out);
        } else {
            for (std::size_t i = 0; i < t.size(); ++i) out[i] = Lib::slerp(a, b, t[i]);
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * n);
}

// The slerp_fast family, slerp_fast/quat/<method>/<type>, each labelled with its largest
// rotation-angle error: the bounds tests/test_slerp_fast.cpp asserts for nlerp, corrected_nlerp and
// slerp_fast ("eberly"), and for the exact slerp the 4 eps target that `quat_accuracy --slerp-fast`
// checks (tools/accuracy/measure_fast_slerp.hpp). Keep these strings equal to those bounds.
struct slerp_fast_labels {
    const char *nlerp, *corrected_nlerp, *eberly, *slerp;
};
constexpr slerp_fast_labels slerp_fast_float{"max error 0.143 rad", "max error 5.9e-4 rad",
                                             "max error 4e-7 rad", "max error 4.8e-7 rad"};
constexpr slerp_fast_labels slerp_fast_double{"max error 0.143 rad", "max error 5.9e-4 rad",
                                              "max error 3.4e-8 rad", "max error 8.9e-16 rad"};

template <class T, class F>
void add_slerp_fast(const char* method, const char* label, F f) {
    benchmark::RegisterBenchmark(name("slerp_fast", "quat", method, type_name<T>).c_str(),
                                 [label, f](benchmark::State& state) {
                                     interpolate<lib_quat<T>>(state, f);
                                     state.SetLabel(label);
                                 });
}

template <class T>
void register_slerp_fast_family() {
    using Q = quat::quaternion<T>;
    const slerp_fast_labels& label =
        std::is_same_v<T, float> ? slerp_fast_float : slerp_fast_double;
    add_slerp_fast<T>("nlerp", label.nlerp,
                      [](const Q& a, const Q& b, T t) { return quat::nlerp(a, b, t); });
    add_slerp_fast<T>("corrected_nlerp", label.corrected_nlerp,
                      [](const Q& a, const Q& b, T t) { return quat::corrected_nlerp(a, b, t); });
    add_slerp_fast<T>("eberly", label.eberly,
                      [](const Q& a, const Q& b, T t) { return quat::slerp_fast(a, b, t); });
    add_slerp_fast<T>("slerp", label.slerp,
                      [](const Q& a, const Q& b, T t) { return quat::slerp(a, b, t); });
}

template <template <class> class Lib, class T>
void register_interpolation_for() {
    using L = Lib<T>;
    using Q = typename L::quaternion;
    const char* type = type_name<T>;
    benchmark::RegisterBenchmark(
        name("slerp", L::name, "quaternion", type).c_str(), [](benchmark::State& s) {
            interpolate<L>(s, [](const Q& a, const Q& b, T t) { return L::slerp(a, b, t); });
        });
    benchmark::RegisterBenchmark(
        name("nlerp", L::name, "quaternion", type).c_str(), [](benchmark::State& s) {
            interpolate<L>(s, [](const Q& a, const Q& b, T t) { return L::nlerp(a, b, t); });
        });
    benchmark::RegisterBenchmark(
        name("normalize", L::name, "quaternion", type).c_str(), [](benchmark::State& s) {
            interpolate<L>(s, [](const Q& a, const Q&, T) { return L::normalize(a); });
        });
    for (const long long n : {64LL, 1024LL, 4194304LL})
        benchmark::RegisterBenchmark(name("slerp_batch", L::name, "quaternion", type, n).c_str(),
                                     slerp_batch<L>, n);
    if constexpr (std::is_same_v<L, lib_quat<T>>) register_slerp_fast_family<T>();
}

}  // namespace

void register_conversions() {
    register_conversions_for<float>();
    register_conversions_for<double>();
}

void register_interpolation() {
    register_interpolation_for<lib_quat, float>();
    register_interpolation_for<lib_glm, float>();
    register_interpolation_for<lib_eigen, float>();
    register_interpolation_for<lib_quat, double>();
    register_interpolation_for<lib_glm, double>();
    register_interpolation_for<lib_eigen, double>();
}

}  // namespace bench
