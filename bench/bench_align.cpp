// rotation_between (quat, glm::rotation, Eigen's FromTwoVectors) and look_rotation (quat,
// glm::quatLookAtRH) on seeded random vectors of random length. GLM's functions want unit
// vectors, so its loops normalize first, as its users must; Eigen normalizes inside.
#include <utility>
#include <vector>

#include <glm/gtx/quaternion.hpp>

#include <quat/align.hpp>

#include "common.hpp"

namespace bench {
namespace {

// A pair of vectors with lengths from 0.1 to 10, in the library's vector type.
template <class Lib>
std::pair<typename Lib::vector, typename Lib::vector> vector_pair(random_source& random) {
    const quat::vec3<double> a = random.vector() * random.uniform(0.1, 10);
    const quat::vec3<double> b = random.vector() * random.uniform(0.1, 10);
    return {Lib::make_vector(a), Lib::make_vector(b)};
}

template <class Lib, class Operation>
void add(const char* operation, Operation f) {
    benchmark::RegisterBenchmark(
        name(operation, Lib::name, "vec3", type_name<typename Lib::scalar>).c_str(),
        [f](benchmark::State& state) {
            cycle(state, vector_pair<Lib>, [f](const auto& p) { return f(p.first, p.second); });
        });
}

template <class T>
void register_align_for() {
    using Q = typename lib_quat<T>::vector;
    using G = typename lib_glm<T>::vector;
    using E = typename lib_eigen<T>::vector;
    add<lib_quat<T>>("rotation_between",
                     [](const Q& a, const Q& b) { return quat::rotation_between(a, b); });
    add<lib_glm<T>>("rotation_between", [](const G& a, const G& b) {
        return glm::rotation(glm::normalize(a), glm::normalize(b));
    });
    add<lib_eigen<T>>("rotation_between", [](const E& a, const E& b) {
        return Eigen::Quaternion<T>::FromTwoVectors(a, b);
    });
    add<lib_quat<T>>("look_rotation",
                     [](const Q& f, const Q& up) { return quat::look_rotation(f, up); });
    add<lib_glm<T>>("look_rotation", [](const G& f, const G& up) {
        return glm::quatLookAtRH(glm::normalize(f), up);
    });
}

}  // namespace

void register_align() {
    register_align_for<float>();
    register_align_for<double>();
}

}  // namespace bench
