// Specification of quat/interop/fmt.hpp: fmt::format prints the format of io.hpp, "{}" the shortest
// text that reads back exactly, and a format spec applies to each component. Built into quat_tests
// when CMake finds {fmt} (Debian libfmt-dev); see tests/CMakeLists.txt.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fmt/xchar.h>

#include <locale>
#include <string>

#include <quat/interop/fmt.hpp>
// The families whose results are printed below: io.hpp prints them where their headers are
// included.
#include <quat/fitting/align_vectors.hpp>
#include <quat/lie/se3.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>
#include <quat/rigid/dual_quaternion.hpp>
#include <quat/rigid/homogeneous_matrix.hpp>
#include <quat/rigid/screw.hpp>

#include "support/catch.hpp"
#include "support/read_back.hpp"

namespace test_interop_fmt {

using quat::axis_angle;
using quat::euler;
using quat::euler_extraction;
using quat::frame;
using quat::quaternion;
using quat::rotation_matrix;
using quat::sequence;
using quat::vec3;

TEMPLATE_TEST_CASE("fmt::format prints the documented format", "[io][fmt]", float, double,
                   long double) {
    using T = TestType;
    CHECK(fmt::format("{}", vec3<T>{T(1), T(-2), T(0.5)}) == "vec3{1, -2, 0.5}");
    // fmt writes up to 16 integer digits before it switches to an exponent (std::format: fewer).
    CHECK(fmt::format("{}", quaternion<T>{T(0.5), T(1), T(-0.0), T(1e10)}) ==
          "quaternion{0.5, 1, -0, 10000000000}");
    CHECK(fmt::format("{}", rotation_matrix<T>::identity()) ==
          "rotation_matrix{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}");
    CHECK(fmt::format("{}", axis_angle<T>{vec3<T>{T(0), T(0), T(1)}, T(1.5)}) ==
          "axis_angle{vec3{0, 0, 1}, 1.5}");
    // euler is tuple-like (structured bindings); with fmt/ranges.h included it still prints as
    // euler.
    CHECK(fmt::format("{}", euler<T>{T(0.5), T(0.25), T(0.125)}) ==
          "euler<zyx, intrinsic>{0.5, 0.25, 0.125}");
    const euler_extraction<T, sequence::yzx, frame::extrinsic> locked{{T(1), T(-1.5), T(0)}, true};
    CHECK(fmt::format("{}", locked) == "euler_extraction{euler<yzx, extrinsic>{1, -1.5, 0}, true}");
    const quat::alignment_with_sensitivity<T> fit{{{T(0), T(1), T(0), T(0)}, T(0.25), true},
                                                  quat::matrix3<T>::identity()};
    CHECK(fmt::format("{}", fit) ==
          "alignment_with_sensitivity{alignment{quaternion{0, 1, 0, 0}, 0.25, true}, "
          "matrix{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}");
    const quat::matrix<T, 2, 3> wide{{{T(1), T(2), T(3)}, {T(-4), T(0.5), T(0)}}};
    CHECK(fmt::format("{}", wide) == "matrix{{1, 2, 3}, {-4, 0.5, 0}}");
    CHECK(fmt::format("{}", quat::alignment<T>{fit.rotation, fit.rssd, false}) ==
          "alignment{quaternion{0, 1, 0, 0}, 0.25, false}");
    const quat::swing_twist_parts<T> parts{{T(0.5), T(0.5), T(0.5), T(0.5)},
                                           {T(1), T(0), T(0), T(0)}};
    CHECK(fmt::format("{}", parts) ==
          "swing_twist_parts{quaternion{0.5, 0.5, 0.5, 0.5}, quaternion{1, 0, 0, 0}}");
    const quat::dual_quaternion<T> motion{{T(0), T(0), T(0), T(1)}, {T(-0.5), T(0), T(0), T(0)}};
    CHECK(fmt::format("{}", motion) ==
          "dual_quaternion{quaternion{0, 0, 0, 1}, quaternion{-0.5, 0, 0, 0}}");
    CHECK(fmt::format("{}",
                      quat::hand_eye_with_target<T>{
                          {motion, T(0.125), T(0.5), true, T(0.25)}, motion, false}) ==
          "hand_eye_with_target{hand_eye_calibration{dual_quaternion{quaternion{0, 0, 0, 1}, "
          "quaternion{-0.5, 0, 0, 0}}, 0.125, 0.5, true, 0.25}, dual_quaternion{quaternion{0, 0, "
          "0, 1}, quaternion{-0.5, 0, 0, 0}}, false}");
    CHECK(fmt::format("{}", quat::to_homogeneous(motion)) ==
          "homogeneous_matrix{{-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, 1, 1}, {0, 0, 0, 1}}");
    const quat::screw<T> s{{T(0), T(0), T(1)}, {T(0), T(-1), T(0)}, T(1.5), T(2)};
    CHECK(fmt::format("{}", s) == "screw{vec3{0, 0, 1}, vec3{0, -1, 0}, 1.5, 2}");
    const quat::se3::twist<T> t{{T(1), T(-2), T(0)}, {T(0), T(0), T(0.5)}};
    CHECK(fmt::format("{}", t) == "se3::twist{vec3{1, -2, 0}, vec3{0, 0, 0.5}}");
}

// fmt 9 writes a long double with 20 significant digits (0.1L as 0.10000000000000000555), which
// reads back exactly but is not the shortest text; float and double get the shortest.
TEST_CASE("fmt::format's default is the shortest text that reads back", "[io][fmt]") {
    CHECK(fmt::format("{}", vec3<float>{1.f / 3, 0.1f, 1e-20f}) == "vec3{0.33333334, 0.1, 1e-20}");
    CHECK(fmt::format("{}", vec3<double>{1. / 3, 0.1, 1e-20}) ==
          "vec3{0.3333333333333333, 0.1, 1e-20}");
    CHECK(fmt::format("{}", vec3<double>{1e20, -1e-20, 1e-3}) == "vec3{1e+20, -1e-20, 0.001}");
}

TEMPLATE_TEST_CASE("fmt::format's default reads back to the same values", "[io][fmt]", float,
                   double, long double) {
    using T = TestType;
    using namespace quat::test;
    awkward_values<T> values;
    for (int n = 0; n < 200; ++n) {
        const double scale = scales[n % 5];
        const auto v = values.next_vec3(scale);
        const auto q = values.next_quaternion(scale);
        const auto m = values.next_matrix(scale);
        const auto r = values.next_axis_angle(scale);
        const auto e = values.next_euler(scale);
        CHECK(read_back<T>(fmt::format("{}", v), vec3_pattern) == printed_components(v));
        CHECK(read_back<T>(fmt::format("{}", q), quaternion_pattern) == printed_components(q));
        CHECK(read_back<T>(fmt::format("{}", m), matrix_pattern) == printed_components(m));
        CHECK(read_back<T>(fmt::format("{}", r), axis_angle_pattern) == printed_components(r));
        CHECK(read_back<T>(fmt::format("{}", e), euler_pattern) == printed_components(e));
        CHECK(fmt::format("{}", q) ==
              fmt::format("quaternion{{{}, {}, {}, {}}}", q.w, q.x, q.y, q.z));
        CHECK(fmt::format("{:.4e}", q) ==
              fmt::format("quaternion{{{:.4e}, {:.4e}, {:.4e}, {:.4e}}}", q.w, q.x, q.y, q.z));
    }
}

TEST_CASE("a fmt::format spec applies to each component", "[io][fmt]") {
    const quaternion<double> q{1, 0.1, -2.5, 1e10};
    CHECK(fmt::format("{:.3f}", q) == "quaternion{1.000, 0.100, -2.500, 10000000000.000}");
    CHECK(fmt::format("{:e}", vec3<double>{1, 0.5, -3}) ==
          "vec3{1.000000e+00, 5.000000e-01, -3.000000e+00}");
    CHECK(fmt::format("{:>6.2}", vec3<double>{1. / 3, 2, -0.5}) == "vec3{  0.33,      2,   -0.5}");
    CHECK(fmt::format("{:.1f}", quat::se3::twist<double>{{1, 2, 3}, {0, 0, 0.5}}) ==
          "se3::twist{vec3{1.0, 2.0, 3.0}, vec3{0.0, 0.0, 0.5}}");
    CHECK(fmt::format("{:+}", euler<float>{1, -2, 0}) == "euler<zyx, intrinsic>{+1, -2, +0}");
    CHECK(fmt::format("{:*<5g}", axis_angle<double>{{0, 0, 1}, 2}) ==
          "axis_angle{vec3{0****, 0****, 1****}, 2****}");
    const euler_extraction<double, sequence::xyz, frame::intrinsic> e{{0.5, 1.25, 0}, false};
    CHECK(fmt::format("{:.1f}", e) ==
          "euler_extraction{euler<xyz, intrinsic>{0.5, 1.2, 0.0}, false}");
    CHECK(fmt::format("[{}] [{:.2f}]", q, vec3<float>{1, 2, 3}) ==
          "[quaternion{1, 0.1, -2.5, 10000000000}] [vec3{1.00, 2.00, 3.00}]");
    CHECK_THROWS_AS(fmt::format(fmt::runtime("{:q}"), vec3<double>{1, 2, 3}), fmt::format_error);
}

TEST_CASE("fmt::format prints sequence and frame with a string spec", "[io][fmt]") {
    CHECK(fmt::format("{}|{:>5}|{:*<10}", sequence::zyx, sequence::xyx, frame::extrinsic) ==
          "zyx|  xyx|extrinsic*");
    CHECK(fmt::format("{:^11}", frame::intrinsic) == " intrinsic ");
}

TEST_CASE("fmt::format prints wide strings", "[io][fmt]") {
    CHECK(fmt::format(L"{}", quaternion<double>{1, 0.5, -2, 0}) == L"quaternion{1, 0.5, -2, 0}");
    CHECK(fmt::format(L"{:.1f} {:>4}", vec3<float>{1, 2, 3}, sequence::zxz) ==
          L"vec3{1.0, 2.0, 3.0}  zxz");
}

}  // namespace test_interop_fmt
