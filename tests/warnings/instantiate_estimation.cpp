// Instantiates align_vectors.hpp and mean.hpp (align_vectors, align_vectors_with_sensitivity,
// mean, try_mean) for float, double and long double under the strict warning flags, with weights
// of another scalar type beside them (a double weight converts to T). Compiled, not run, by the
// strict_warnings CTest test.
#include <array>
#include <vector>

#include <quat/align_vectors.hpp>
#include <quat/mean.hpp>

namespace {

template <class T>
T estimation() {
    using namespace quat;
    const std::vector<vec3<T>> sources{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::array<vec3<T>, 3> targets{vec3<T>{0, 1, 0}, vec3<T>{-1, 0, 0}, vec3<T>{0, 0, 1}};
    const std::vector<T> weights{1, 2, 3};
    const std::vector<double> double_weights{1, 2, 3};
    const alignment<T> plain = align_vectors(targets, sources);
    const alignment<T> weighted = align_vectors(targets, sources, double_weights);
    const auto [rotation, rssd, unique, sensitivity] =
        align_vectors_with_sensitivity(targets, sources, weights);
    T sum = plain.rotation.w + weighted.rssd + rotation.x + rssd + sensitivity(0, 1);
    sum += unique ? T(1) : T(0);
    const std::vector<quaternion<T>> rotations{quaternion<T>::identity(), rotation, -rotation};
    sum += mean(rotations).w + mean(rotations, weights).x;
    sum += try_mean(rotations).value_or(quaternion<T>::identity()).y;
    sum += try_mean(rotations, double_weights).value_or(quaternion<T>::identity()).z;
    return sum;
}

}  // namespace

int main() {
    return estimation<float>() + static_cast<float>(estimation<double>()) +
                       static_cast<float>(estimation<long double>()) >
                   0
               ? 0
               : 1;
}
