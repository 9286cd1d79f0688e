// Instantiates trajectory/ (so3_bspline, se3_bspline, euclidean_bspline and split_bspline of orders 4
// and 6, every Jacobian requested, evaluate, try_evaluate and operator()) for float, double and long
// double under the strict warning flags. Compiled, not run, by the strict_warnings CTest test.
#include <vector>

#include <quat/trajectory.hpp>

namespace {

template <class T, int K>
T trajectory() {
    using namespace quat;
    const std::vector<quaternion<T>> q(8, quaternion<T>::identity());
    const std::vector<dual_quaternion<T>> x(8, dual_quaternion<T>::identity());
    const std::vector<vec3<T>> p(8, vec3<T>{T(1), T(2), T(3)});
    typename so3_bspline<T, K>::jacobian_blocks a{}, b{}, c{}, d{};
    typename se3_bspline<T, K>::jacobian_blocks e{}, f{}, g{}, h{};
    typename euclidean_bspline<T, K>::jacobian_weights i{}, j{}, k{}, l{};
    const so3_bspline<T, K> rotations(q, T(0), T(0.5));
    const se3_bspline<T, K> motions(x, T(0), T(0.5));
    const euclidean_bspline<T, K> points(p, T(0), T(0.5));
    const split_bspline<T, K> poses(q, p, T(0), T(0.5));
    T sum = rotations.evaluate(T(1), &a, &b, &c, &d).angular_jerk.x + rotations(T(1)).w +
            rotations.try_evaluate(T(1))->rotation.x + rotations.end_time();
    sum += motions.evaluate(T(1), &e, &f, &g, &h).jerk.linear.x + motions(T(1)).real.w +
           motions.try_evaluate(T(1))->motion.dual.x;
    sum += points.evaluate(T(1), &i, &j, &k, &l).jerk.z + points(T(1)).x +
           points.try_evaluate(T(1))->position.y;
    sum += poses.evaluate(T(1), &a, &b, &c, &d, &i, &j, &k, &l).body_acceleration.linear.x +
           poses(T(1)).dual.x + poses.try_evaluate(T(1))->position.z;
    return sum + a[0](0, 0) + e[0](0, 0) + i[0];
}

}  // namespace

int main() {
    return trajectory<float, 4>() + static_cast<float>(trajectory<double, 6>()) +
                       static_cast<float>(trajectory<long double, 4>()) >
                   0
               ? 0
               : 1;
}
