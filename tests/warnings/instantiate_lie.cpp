// Instantiates matrix.hpp, lie/so3.hpp, lie/se3.hpp, lie/geodesic_mean.hpp and
// lie/relative_pose.hpp (every function with its Jacobians requested, the means of rotations and of
// rigid motions with and without weights and their try_ forms) for float, double and long double
// under the strict warning flags. Compiled, not run, by the strict_warnings CTest test.
#include <vector>

#include <quat/lie/geodesic_mean.hpp>
#include <quat/lie/relative_pose.hpp>
#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>
#include <quat/matrix.hpp>

namespace {

template <class T>
T lie() {
    using namespace quat;
    const vec3<T> w{T(0.1), T(-0.2), T(0.3)}, p{T(1), T(2), T(3)};
    matrix3<T> a{}, b{};
    const quaternion<T> x = so3::exp(w, &a), y = so3::plus(x, w, &a, &b);
    T sum = so3::log(y, &a).x + so3::minus(y, x, &a, &b).y + so3::minus_left(y, x, &a, &b).z;
    sum += so3::compose(x, y, &a, &b).w + so3::inverse(x, &a).x + so3::between(x, y, &a, &b).y;
    sum += so3::act(x, p, &a, &b).z + so3::plus_left(x, w, &b, &a).w + so3::vee(so3::hat(w)).x;
    sum += (so3::right_jacobian(w) * so3::left_jacobian(w) * so3::right_jacobian_inverse(w) *
            so3::left_jacobian_inverse(w) * so3::adjoint(x))(0, 0);
    const se3::twist<T> t{p, w};
    matrix6<T> c{}, d{};
    matrix<T, 3, 6> e{};
    const dual_quaternion<T> m = se3::exp(t, &c), n = se3::plus(m, t * T(2), &c, &d);
    sum += se3::log(n, &c).linear.x + se3::minus(n, m, &c, &d).angular.y +
           se3::minus_left(n, m, &c, &d).linear.z + se3::log(to_homogeneous(m), &c).linear.y;
    sum += se3::compose(m, n, &c, &d).real.w + se3::inverse(m, &c).dual.x +
           se3::between(m, n, &c, &d).real.y + se3::act(m, p, &e, &a).z +
           se3::plus_left(m, t, &d, &c).real.z;
    sum += se3::vee(se3::hat(t - t + -t)).angular.x + se3::to_twist(se3::to_vector(t)).linear.x;
    sum += (se3::right_jacobian(t) * se3::left_jacobian(t) * se3::right_jacobian_inverse(t) *
            se3::left_jacobian_inverse(t) * se3::adjoint(m))(5, 5);
    sum += block<3, 3>(transpose(c) + c - c * T(0.5), 3, 0)(1, 1) + (a * p).x;
    set_block(c, 0, 0, a);
    const std::vector<quaternion<T>> rotations{x, y};
    const std::vector<dual_quaternion<T>> motions{m, n};
    const std::vector<double> weights{1, 2};
    sum += geodesic_mean(rotations).w + geodesic_mean(rotations, weights).x +
           try_geodesic_mean(rotations).value_or(x).y +
           try_geodesic_mean(rotations, weights).value_or(x).z;
    sum += geodesic_mean(motions).real.w + geodesic_mean(motions, weights).dual.x +
           try_geodesic_mean(motions).value_or(m).real.y +
           try_geodesic_mean(motions, weights).value_or(m).dual.z;
    sum += so3xr3::relative_pose_error(m, n, m, &c, &d)(3, 0) +
           se3::relative_pose_error(m, n, n, &c, &d)(4, 0);
    return sum + c(0, 0);
}

}  // namespace

int main() {
    return lie<float>() + static_cast<float>(lie<double>()) +
                       static_cast<float>(lie<long double>()) >
                   0
               ? 0
               : 1;
}
