// pow (quat against glm::pow, on inputs with w >= 0 where the two agree), random_rotation with a
// 64-bit and a 32-bit engine, swing_twist, body_angular_velocity and rotate_towards.
#include <random>
#include <utility>
#include <vector>

#include <glm/gtx/quaternion.hpp>

#include <quat/kinematics.hpp>
#include <quat/paths/interpolation.hpp>
#include <quat/random.hpp>
#include <quat/swing_twist.hpp>

#include "common.hpp"

namespace bench {
namespace {

template <class Make, class Operation>
void add(const std::string& operation, const std::string& library, const char* type, Make make,
         Operation f) {
    benchmark::RegisterBenchmark(name(operation, library, "quaternion", type).c_str(),
                                 [make, f](benchmark::State& state) { cycle(state, make, f); });
}

// A rotation with w >= 0 and a parameter, so quat::pow and glm::pow compute the same power.
template <class T>
std::pair<quat::quaternion<T>, T> power_input(random_source& r) {
    quat::quatd q = r.rotation();
    if (q.w < 0) q = -q;
    return {lib_quat<T>::make_quaternion(q), T(r.uniform(-2, 2))};
}

template <class T, class Engine>
void random_rotations(benchmark::State& state) {
    Engine engine(seed);
    for (auto _ : state) {
        auto q = quat::random_rotation<T>(engine);
        benchmark::DoNotOptimize(q);
    }
    state.SetItemsProcessed(state.iterations());
}

template <class T>
void register_motion_for() {
    const char* type = type_name<T>;
    using Q = quat::quaternion<T>;
    using V = quat::vec3<T>;
    using G = lib_glm<T>;
    add("pow", "quat", type, power_input<T>,
        [](const std::pair<Q, T>& p) { return quat::pow(p.first, p.second); });
    add("pow", "glm", type, power_input<T>, [](const std::pair<Q, T>& p) {
        const Q& q = p.first;
        return glm::pow(typename G::quaternion(q.w, q.x, q.y, q.z), p.second);
    });
    auto pair_input = [](random_source& r) {
        return std::pair<Q, Q>(lib_quat<T>::make_quaternion(r.rotation()),
                               lib_quat<T>::make_quaternion(r.rotation()));
    };
    add("rotate_towards", "quat", type, pair_input,
        [](const std::pair<Q, Q>& p) { return quat::rotate_towards(p.first, p.second, T(0.1)); });
    add("body_angular_velocity", "quat", type, pair_input, [](const std::pair<Q, Q>& p) {
        return quat::body_angular_velocity(p.first, p.second, T(0.01));
    });
    add(
        "swing_twist", "quat", type,
        [](random_source& r) {
            return std::pair<Q, V>(lib_quat<T>::make_quaternion(r.rotation()),
                                   lib_quat<T>::make_vector(r.vector()));
        },
        [](const std::pair<Q, V>& p) { return quat::swing_twist(p.first, p.second); });
    benchmark::RegisterBenchmark(name("random_rotation", "quat", "mt19937_64", type).c_str(),
                                 random_rotations<T, std::mt19937_64>);
    benchmark::RegisterBenchmark(name("random_rotation", "quat", "mt19937", type).c_str(),
                                 random_rotations<T, std::mt19937>);
}

}  // namespace

void register_motion() {
    register_motion_for<float>();
    register_motion_for<double>();
}

}  // namespace bench
