// Instantiates the trajectory family (split_keyframe_path, se3_keyframe_path, keyframe_path_state)
// for float, double and long double under the strict warning flags, with times of other types
// beside them (int and double times). Compiled, not run, by the strict_warnings CTest test.
#include <vector>

#include <quat/trajectory.hpp>

namespace {

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
T trajectory() {
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

float instantiate_trajectory_float() { return trajectory<float>(); }
double instantiate_trajectory_double() { return trajectory<double>(); }
long double instantiate_trajectory_long_double() { return trajectory<long double>(); }
