// Instantiates the motion functions (kinematics.hpp, random.hpp, swing_twist.hpp, pow,
// rotate_towards, to_mrp / from_mrp) for float, double and long double under the strict warning
// flags, with scalars of other types beside them (an int converts to T). Compiled, not run, by
// the strict_warnings CTest test.
#include <random>

#include <quat/conversions.hpp>
#include <quat/kinematics.hpp>
#include <quat/paths/interpolation.hpp>
#include <quat/random.hpp>
#include <quat/swing_twist.hpp>

namespace {

template <class T>
T motion() {
    using namespace quat;
    std::mt19937 engine32(1);
    std::mt19937_64 engine64(2);
    std::minstd_rand engine_minstd(3);
    const quaternion<T> q0 = random_rotation<T>(engine32);
    const quaternion<T> q1 = random_rotation<T>(engine64) * random_rotation<T>(engine_minstd);
    const vec3<T> axis{1, 2, 3};
    const vec3<T> body = body_angular_velocity(q0, q1, T(0.5));
    const vec3<T> world = world_angular_velocity(q0, q1, 2);
    T sum = body.x + world.y + integrate_body(q0, body, T(0.5)).w + integrate_world(q0, world, 2).z;
    sum += pow(q0, T(0.25)).w + pow(q1, 2).x + rotate_towards(q0, q1, 1).y +
           rotate_towards(q0, q1, T(0.1)).z;
    const vec3<T> p = to_mrp(q0);
    sum += p.x + from_mrp(p).w + from_mrp(p * T(1e30)).x;
    const auto [swing, twist] = swing_twist(q0, axis);
    sum += swing.w + twist.x;
    const std::optional<swing_twist_parts<T>> parts = try_swing_twist(q1, axis);
    if (parts) sum += parts->swing.y + parts->twist.z;
    return sum;
}

}  // namespace

int main() {
    return motion<float>() + static_cast<float>(motion<double>()) +
                       static_cast<float>(motion<long double>()) >
                   0
               ? 0
               : 1;
}
