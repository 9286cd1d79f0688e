// The README's code sample, compiled and checked, so the front page cannot rot.
#include <quat/quat.hpp>

#include "support/catch.hpp"

TEST_CASE("the README example works as written", "[readme]") {
    // --- README begin
    using namespace quat;

    // The thesis's yaw-pitch-roll, R = Rz(yaw) Ry(pitch) Rx(roll): here a quarter turn of yaw.
    constexpr euler<double> attitude{{1.5707963267948966, 0.0, 0.0}};
    constexpr quatd q = to_quaternion(attitude);  // (cos 45°, 0, 0, sin 45°), at compile time

    vec3<double> v = rotate(q, vec3<double>{1, 0, 0});  // ≈ {0, 1, 0}: counter-clockwise about z
    auto angles = extract_euler<sequence::zyx>(q);      // {1.5708, 0, 0}, gimbal_lock == false
    quatd halfway = slerp(quatd::identity(), q, 0.5);   // 45° about z

    rotation_matrix<double> drifted = to_matrix(q);
    drifted(0, 1) += 1e-3;  // no longer orthogonal
    rotation_matrix<double> repaired = nearest_rotation(drifted);
    std::optional<quatd> checked = try_to_quaternion(drifted);  // empty: not a rotation
    // --- README end

    CHECK(v.y == Approx(1));
    CHECK(angles.angles[0] == Approx(1.5707963267948966));
    CHECK_FALSE(angles.gimbal_lock);
    CHECK(to_axis_angle(halfway).angle == Approx(0.7853981633974483));
    CHECK(orthogonality_error(repaired) < 1e-15);
    CHECK_FALSE(checked.has_value());
}
