// The README's code sample, compiled and checked, so the front page cannot rot. The lines between
// the markers are the README's block without its #include lines (CTest readme_example_in_sync).
#include <iostream>
#include <sstream>

#include <quat/io.hpp>
#include <quat/quat.hpp>

#include "support/catch.hpp"

namespace test_readme_example {

TEST_CASE("the README example works as written", "[readme]") {
    std::ostringstream printed;
    std::streambuf* const console = std::cout.rdbuf(printed.rdbuf());
    // --- README begin
    using namespace quat;

    // The thesis's yaw-pitch-roll, R = Rz(yaw) Ry(pitch) Rx(roll): here a quarter turn of yaw.
    constexpr euler<double> attitude{numbers::pi / 2, 0, 0};
    constexpr quatd q = to_quaternion(attitude);  // (cos 45°, 0, 0, sin 45°), at compile time
    static_assert(approx_equal(q, rotation_z(numbers::pi / 2), 1e-15));

    vec3<double> v = rotate(q, {1, 0, 0});  // ≈ {0, 1, 0}: counter-clockwise about z
    auto [yaw, pitch, roll] = to_euler<sequence::zyx>(q);     // 1.5708, 0, 0
    quatf halfway = slerp(quatf{q}, quatf::identity(), 0.5);  // 45° about z, in float
    std::cout << halfway << '\n';                             // quaternion{0.92388, 0, 0, 0.382683}

    rotation_matrix<double> drifted = to_matrix(q);
    drifted(0, 1) += 1e-3;  // no longer orthogonal
    rotation_matrix<double> repaired = nearest_rotation(drifted);
    std::optional<quatd> checked = try_to_quaternion(drifted);  // empty: not a rotation
    // --- README end
    std::cout.rdbuf(console);

    CHECK(v.y == Approx(1));
    CHECK(std::abs(v.x) < 1e-15);
    CHECK(yaw == Approx(1.5707963267948966));
    CHECK(pitch == 0);
    CHECK(roll == 0);
    CHECK(printed.str() == "quaternion{0.92388, 0, 0, 0.382683}\n");
    CHECK(halfway.z == Approx(std::sin(numbers::pi / 8)));
    CHECK(orthogonality_error(repaired) < 1e-15);
    CHECK_FALSE(checked.has_value());
}

}  // namespace test_readme_example
