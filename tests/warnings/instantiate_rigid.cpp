// Instantiates the rigid-motion functions (rigid/dual_quaternion.hpp, rigid/homogeneous_matrix.hpp,
// rigid/screw.hpp, rigid/sclerp.hpp, rigid/blend.hpp, batch/rigid_motions.hpp) for float, double
// and long double under the strict warning flags, with scalars of other types beside them (an int
// converts to T). Compiled, not run, by the strict_warnings CTest test.
#include <vector>

#include <quat/batch/rigid_motions.hpp>
#include <quat/rigid/blend.hpp>
#include <quat/rigid/dual_quaternion.hpp>
#include <quat/rigid/homogeneous_matrix.hpp>
#include <quat/rigid/sclerp.hpp>
#include <quat/rigid/screw.hpp>

namespace {

template <class T>
T rigid() {
    using namespace quat;
    const quaternion<T> q = normalize(quaternion<T>{1, 2, 3, 4});
    const vec3<T> t{1, -2, 3};
    dual_quaternion<T> a = to_dual_quaternion(q, t);
    const dual_quaternion<T> b = a * inverse(a) * dual_quaternion<T>::identity();
    a *= b;
    T sum = rotation_of(a).w + translation_of(a).x + transform(a, t).y + transform_vector(a, t).z;
    sum += normalize(-a).dual.w + (try_normalize(b) ? T(1) : T(0)) + (a == b ? T(1) : T(0));
    sum += T(dual_quaternion<float>(a).real.w) + (a != b ? T(1) : T(0));
    homogeneous_matrix<T> m = to_homogeneous(a);
    m *= homogeneous_matrix<T>::identity();
    m(0, 3) = 2;
    sum += (m * m)(1, 2) + transform(m, t).x + transform_vector(m, t).y + rotation_block(m)(0, 0);
    sum += translation_of(m).z + to_dual_quaternion(m).real.w + (m == m ? T(1) : T(0));
    sum += try_to_dual_quaternion(m) ? T(1) : T(0);
    sum += try_to_dual_quaternion(m, 1) ? T(1) : T(0);
    sum += homogeneous_matrix<double>(m)(0, 0) > 0 ? T(1) : T(0);
    const screw<T> s = to_screw(a);
    sum += s.angle + from_screw(s).dual.x + sclerp(a, b, T(0.5)).dual.y + sclerp(a, b, 1).real.w;
    const std::vector<dual_quaternion<T>> bones{a, b};
    const std::vector<T> weights{T(0.25), T(0.75)};
    sum += blend(bones, weights).real.w + blend(bones.data(), weights.data(), 2).dual.z;
    sum += compose(bones).real.x + compose(bones.data(), bones.size()).dual.y;
    std::vector<vec3<T>> points(4, t), out(4);
    transform(a, points, out);
    transform(m, points, out);
    transform(a, points.data(), out.data(), points.size());
    std::vector<T> x(4, T(1)), y(4, T(2)), z(4, T(3));
    transform(a, soa_points<const T>{x.data(), y.data(), z.data(), 4},
              soa_points<T>{x.data(), y.data(), z.data(), 4});
    transform(m, soa_points<const T>{x.data(), y.data(), z.data(), 4},
              soa_points<T>{x.data(), y.data(), z.data(), 4});
    return sum + out[3].x + x[2];
}

}  // namespace

int main() {
    return rigid<float>() + static_cast<float>(rigid<double>()) +
                       static_cast<float>(rigid<long double>()) >
                   0
               ? 0
               : 1;
}
