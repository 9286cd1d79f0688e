// Instantiates the first-use spellings (q * v, m * v, dq * p, h * p, the to_homogeneous builders,
// from_translation, inverse(h), scalar * and / on dual quaternions, angle, axis, exp, log, radians,
// degrees, v[i], lerp, rotation_y<T>) and keyframe_squad for float, double and long double under
// the strict warning flags, with integer and double scalars beside them. Compiled, not run, by the
// strict_warnings CTest test.
#include <array>
#include <vector>

#include <quat/constants.hpp>
#include <quat/conversions.hpp>
#include <quat/paths/interpolation.hpp>
#include <quat/paths/keyframe_squad.hpp>
#include <quat/quaternion.hpp>
#include <quat/rigid/dual_quaternion.hpp>
#include <quat/rigid/homogeneous_matrix.hpp>
#include <quat/rotation_matrix.hpp>
#include <quat/vec3.hpp>

namespace {

template <class T>
T spellings() {
    using namespace quat;
    const quaternion<T> q = rotation_y<T>(numbers::pi);
    vec3<T> v{T(1), T(2), T(3)};
    v[0] = v[1] + v[2];
    const rotation_matrix<T> m = to_matrix(q);
    const dual_quaternion<T> dq = to_dual_quaternion(q, v);
    dual_quaternion<T> scaled = dq * T(2);
    scaled = 2 * dq;
    scaled = dq / 2;
    scaled *= T(0.5);
    scaled /= 3;
    const homogeneous_matrix<T> h = to_homogeneous(q, v);
    const homogeneous_matrix<T> product = inverse(h) * to_homogeneous(q) * to_homogeneous(m) *
                                          to_homogeneous(m, v) *
                                          homogeneous_matrix<T>::from_translation(v);
    const vec3<T> r = q * v + m * v + dq * v + h * v + product * v + axis(q) + lerp(v, v, T(0.5)) +
                      dual_quaternion<T>::from_translation(v) * v + to_dual_quaternion(q) * v;
    const quaternion<T> e = exp(q) + log(q) + exp(log(q * 2));
    const std::vector<double> times{0, 0.5, 2};
    const std::array<quaternion<T>, 3> keyframes{q, quaternion<T>::identity(), rotation_x(T(1))};
    const quaternion<T> k =
        keyframe_squad(times, keyframes, 1) * keyframe_squad(times, keyframes, T(1.5));
    return r[0] + angle(q) + e.w + radians(T(1)) + degrees(T(1)) + scaled.real.w + k.w;
}

}  // namespace

int main() {
    const float sum = spellings<float>() + static_cast<float>(spellings<double>()) +
                      static_cast<float>(spellings<long double>()) +
                      quat::rotation_x<float>(quat::numbers::pi).w +
                      static_cast<float>(quat::radians(90) + quat::degrees(1)) +
                      quat::radians(90.0f);
    return sum > 0 ? 0 : 1;
}
