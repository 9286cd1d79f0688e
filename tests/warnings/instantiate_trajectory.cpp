// Instantiates trajectory/ under the strict warning flags for float, double and long double:
// so3_bspline, se3_bspline, euclidean_bspline and split_bspline of orders 4 and 6 (every Jacobian
// requested, evaluate, try_evaluate and operator()), and split_keyframe_path, se3_keyframe_path and
// keyframe_path_state (with int and double times beside them). Compiled, not run, by the
// strict_warnings CTest test.
#include <vector>

#include <quat/trajectory.hpp>

namespace {

template <class T, std::size_t K>
T bsplines() {
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

template <template <class> class Path, class T, class Time>
T evaluate_path() {
    using namespace quat;
    const std::vector<Time> times{Time(0), Time(1), Time(3)};
    const std::vector<dual_quaternion<T>> poses{
        dual_quaternion<T>::identity(), to_dual_quaternion(rotation_x(T(0.5)), vec3<T>{1, 2, 3}),
        dual_quaternion<T>::from_translation(vec3<T>{3, 1, 0})};
    const Path<T> path(times, poses);
    const auto checked = Path<T>::try_make(times, poses);
    std::vector<dual_quaternion<T>> out(times.size());
    std::vector<keyframe_path_state<T>> states(times.size());
    path.evaluate(times, out);
    path.evaluate(times, states);
    const keyframe_path_state<T> s = path.state(T(1.5));
    return path(T(0.5)).real.w + s.velocity.x + s.body_angular_acceleration.z + out[1].dual.x +
           states[2].acceleration.y + (checked ? checked->state(2).body_velocity.x : T(0)) +
           path.times()[1];
}

template <class T>
T keyframe_paths() {
    return evaluate_path<quat::split_keyframe_path, T, T>() +
           evaluate_path<quat::split_keyframe_path, T, int>() +
           evaluate_path<quat::se3_keyframe_path, T, T>() +
           evaluate_path<quat::se3_keyframe_path, T, double>() +
           quat::split_keyframe_path<T>(
               std::vector<T>{0, 1},
               std::vector<quat::dual_quaternion<T>>(2, quat::dual_quaternion<T>::identity()))
               .orientation()(T(0.5))
               .w;
}

}  // namespace

int main() {
    const long double sum =
        static_cast<long double>(bsplines<float, 4>()) +
        static_cast<long double>(bsplines<double, 6>()) + bsplines<long double, 4>() +
        static_cast<long double>(keyframe_paths<float>()) +
        static_cast<long double>(keyframe_paths<double>()) + keyframe_paths<long double>();
    return sum > 0 ? 0 : 1;
}
