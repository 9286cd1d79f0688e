// Instantiates align.hpp (rotation_between, look_rotation and their try_ forms) for float, double
// and long double under the strict warning flags, in constant and in run-time evaluation.
// Compiled, not run, by the strict_warnings CTest test.
#include <quat/align.hpp>

namespace {

template <class T>
constexpr T align() {
    using namespace quat;
    const vec3<T> from{1, 2, 3}, to{-3, 1, T(0.5)}, up{0, 1, 0};
    T sum = rotation_between(from, to).w + rotation_between(from, from * T(-2)).x +
            try_rotation_between(from, to)->y + look_rotation(from, up).z +
            look_rotation(from, from).w + try_look_rotation(to, up)->x +
            rotation_between(from * T(1e10), to * T(1e-10)).x + look_rotation(to * T(1e10), up).y;
    sum += T(try_rotation_between(from, vec3<T>{0, 0, 0}).has_value()) +
           T(try_look_rotation(from, from).has_value());
    return sum;
}

static_assert(align<float>() == align<float>() && align<double>() == align<double>() &&
              align<long double>() == align<long double>());

}  // namespace

int main() {
    const float f = align<float>();
    const double d = align<double>();
    const long double l = align<long double>();
    return static_cast<int>(static_cast<long double>(f) + static_cast<long double>(d) + l) > 100;
}
