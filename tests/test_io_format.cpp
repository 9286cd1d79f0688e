// Specification of io.hpp's std::formatter specializations: "{}" prints each component as
// std::format("{}", component) does, the shortest text that reads back exactly, and a format spec
// applies to each component. Compiled where the standard library has <format> (__cpp_lib_format):
// not g++ 12's libstdc++, so CTest runs these under clang++-19 with libc++ (tests/io/libcxx).
#include <quat/io.hpp>
// The families whose results are printed below: io.hpp prints them where their headers are
// included.
#include <quat/fitting/align_vectors.hpp>
#include <quat/lie/se3.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>
#include <quat/rigid/dual_quaternion.hpp>
#include <quat/rigid/homogeneous_matrix.hpp>
#include <quat/rigid/screw.hpp>

#if defined(__cpp_lib_format)

#include <format>
#include <locale>
#include <string>

#include "support/catch.hpp"
#include "support/read_back.hpp"

namespace test_io_format {

using quat::axis_angle;
using quat::euler;
using quat::euler_extraction;
using quat::frame;
using quat::quaternion;
using quat::rotation_matrix;
using quat::sequence;
using quat::vec3;

namespace {

struct german_numbers : std::numpunct<char> {
    char do_decimal_point() const override { return ','; }
    char do_thousands_sep() const override { return '.'; }
    std::string do_grouping() const override { return "\3"; }
};

}  // namespace

TEMPLATE_TEST_CASE("std::format prints the documented format", "[io][format]", float, double,
                   long double) {
    using T = TestType;
    CHECK(std::format("{}", vec3<T>{T(1), T(-2), T(0.5)}) == "vec3{1, -2, 0.5}");
    CHECK(std::format("{}", quaternion<T>{T(0.1), T(1), T(-0.0), T(1e10)}) ==
          "quaternion{0.1, 1, -0, 1e+10}");
    CHECK(std::format("{}", rotation_matrix<T>::identity()) ==
          "rotation_matrix{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}");
    CHECK(std::format("{}", axis_angle<T>{vec3<T>{T(0), T(0), T(1)}, T(1.5)}) ==
          "axis_angle{vec3{0, 0, 1}, 1.5}");
    CHECK(std::format("{}", euler<T>{T(0.5), T(0.25), T(0.125)}) ==
          "euler<zyx, intrinsic>{0.5, 0.25, 0.125}");
    const euler_extraction<T, sequence::yzx, frame::extrinsic> locked{{T(1), T(-1.5), T(0)}, true};
    CHECK(std::format("{}", locked) == "euler_extraction{euler<yzx, extrinsic>{1, -1.5, 0}, true}");
    const quat::alignment_with_sensitivity<T> fit{{{T(0), T(1), T(0), T(0)}, T(0.25), true},
                                                  quat::matrix3<T>::identity()};
    CHECK(std::format("{}", fit) ==
          "alignment_with_sensitivity{alignment{quaternion{0, 1, 0, 0}, 0.25, true}, "
          "matrix{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}");
    const quat::matrix<T, 2, 3> wide{{{T(1), T(2), T(3)}, {T(-4), T(0.5), T(0)}}};
    CHECK(std::format("{}", wide) == "matrix{{1, 2, 3}, {-4, 0.5, 0}}");
    CHECK(std::format("{}", quat::alignment<T>{fit.rotation, fit.rssd, false}) ==
          "alignment{quaternion{0, 1, 0, 0}, 0.25, false}");
    const quat::swing_twist_parts<T> parts{{T(0.5), T(0.5), T(0.5), T(0.5)},
                                           {T(1), T(0), T(0), T(0)}};
    CHECK(std::format("{}", parts) ==
          "swing_twist_parts{quaternion{0.5, 0.5, 0.5, 0.5}, quaternion{1, 0, 0, 0}}");
    const quat::dual_quaternion<T> motion{{T(0), T(0), T(0), T(1)}, {T(-0.5), T(0), T(0), T(0)}};
    const quat::similarity_alignment<T> similar{{motion, T(0.25), true}, T(2)};
    CHECK(std::format("{}", similar) ==
          "similarity_alignment{point_alignment{dual_quaternion{quaternion{0, 0, 0, 1}, "
          "quaternion{-0.5, 0, 0, 0}}, 0.25, true}, 2}");
    CHECK(std::format("{:.1f}",
                      quat::hand_eye_calibration<T>{motion, T(0.125), T(0.5), false, T(1)}) ==
          "hand_eye_calibration{dual_quaternion{quaternion{0.0, 0.0, 0.0, 1.0}, "
          "quaternion{-0.5, 0.0, 0.0, 0.0}}, 0.1, 0.5, false, 1.0}");
    CHECK(std::format("{}",
                      quat::hand_eye_with_target<T>{
                          {motion, T(0.125), T(0.5), true, T(0.25)}, motion, false}) ==
          "hand_eye_with_target{hand_eye_calibration{dual_quaternion{quaternion{0, 0, 0, 1}, "
          "quaternion{-0.5, 0, 0, 0}}, 0.125, 0.5, true, 0.25}, dual_quaternion{quaternion{0, 0, "
          "0, 1}, quaternion{-0.5, 0, 0, 0}}, false}");
    CHECK(std::format("{}", motion) ==
          "dual_quaternion{quaternion{0, 0, 0, 1}, quaternion{-0.5, 0, 0, 0}}");
    CHECK(std::format("{}", quat::to_homogeneous(motion)) ==
          "homogeneous_matrix{{-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, 1, 1}, {0, 0, 0, 1}}");
    const quat::screw<T> s{{T(0), T(0), T(1)}, {T(0), T(-1), T(0)}, T(1.5), T(2)};
    CHECK(std::format("{}", s) == "screw{vec3{0, 0, 1}, vec3{0, -1, 0}, 1.5, 2}");
    const quat::se3::twist<T> t{{T(1), T(-2), T(0)}, {T(0), T(0), T(0.5)}};
    CHECK(std::format("{}", t) == "se3::twist{vec3{1, -2, 0}, vec3{0, 0, 0.5}}");
}

TEST_CASE("std::format's default is the shortest text that reads back", "[io][format]") {
    CHECK(std::format("{}", vec3<float>{1.f / 3, 0.1f, 1e-20f}) == "vec3{0.33333334, 0.1, 1e-20}");
    CHECK(std::format("{}", vec3<double>{1. / 3, 0.1, 1e-20}) ==
          "vec3{0.3333333333333333, 0.1, 1e-20}");
}

// long double is left out: libc++ 19 formats it as a double (std::format("{}", 1.0L / 3) gives
// 16 digits), and the components follow std::format.
TEMPLATE_TEST_CASE("std::format's default reads back to the same values", "[io][format]", float,
                   double) {
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
        CHECK(read_back<T>(std::format("{}", v), vec3_pattern) == printed_components(v));
        CHECK(read_back<T>(std::format("{}", q), quaternion_pattern) == printed_components(q));
        CHECK(read_back<T>(std::format("{}", m), matrix_pattern) == printed_components(m));
        CHECK(read_back<T>(std::format("{}", r), axis_angle_pattern) == printed_components(r));
        CHECK(read_back<T>(std::format("{}", e), euler_pattern) == printed_components(e));
        CHECK(std::format("{}", q) ==
              std::format("quaternion{{{}, {}, {}, {}}}", q.w, q.x, q.y, q.z));
    }
}

TEMPLATE_TEST_CASE("each component prints as std::format prints it", "[io][format]", float, double,
                   long double) {
    using T = TestType;
    quat::test::awkward_values<T> values;
    for (int n = 0; n < 50; ++n) {
        const auto q = values.next_quaternion(quat::test::scales[n % 5]);
        CHECK(std::format("{}", q) ==
              std::format("quaternion{{{}, {}, {}, {}}}", q.w, q.x, q.y, q.z));
        CHECK(std::format("{:.4e}", q) ==
              std::format("quaternion{{{:.4e}, {:.4e}, {:.4e}, {:.4e}}}", q.w, q.x, q.y, q.z));
    }
}

TEST_CASE("a std::format spec applies to each component", "[io][format]") {
    const quaternion<double> q{1, 0.1, -2.5, 1e10};
    CHECK(std::format("{:.3f}", q) == "quaternion{1.000, 0.100, -2.500, 10000000000.000}");
    CHECK(std::format("{:e}", vec3<double>{1, 0.5, -3}) ==
          "vec3{1.000000e+00, 5.000000e-01, -3.000000e+00}");
    CHECK(std::format("{:>6.2}", vec3<double>{1. / 3, 2, -0.5}) == "vec3{  0.33,      2,   -0.5}");
    CHECK(std::format("{:.1f}", quat::se3::twist<double>{{1, 2, 3}, {0, 0, 0.5}}) ==
          "se3::twist{vec3{1.0, 2.0, 3.0}, vec3{0.0, 0.0, 0.5}}");
    CHECK(std::format("{:+}", euler<float>{1, -2, 0}) == "euler<zyx, intrinsic>{+1, -2, +0}");
    CHECK(std::format("{:*<5g}", axis_angle<double>{{0, 0, 1}, 2}) ==
          "axis_angle{vec3{0****, 0****, 1****}, 2****}");
    CHECK(std::format("{:a}", rotation_matrix<double>::identity()) ==
          "rotation_matrix{{1p+0, 0p+0, 0p+0}, {0p+0, 1p+0, 0p+0}, {0p+0, 0p+0, 1p+0}}");
    const euler_extraction<double, sequence::xyz, frame::intrinsic> e{{0.5, 1.25, 0}, false};
    CHECK(std::format("{:.1f}", e) ==
          "euler_extraction{euler<xyz, intrinsic>{0.5, 1.2, 0.0}, false}");
    CHECK(std::format("[{}] [{:.2f}]", q, vec3<float>{1, 2, 3}) ==
          "[quaternion{1, 0.1, -2.5, 1e+10}] [vec3{1.00, 2.00, 3.00}]");
    const vec3<double> v{1, 2, 3};
    CHECK_THROWS_AS(std::vformat("{:q}", std::make_format_args(v)), std::format_error);
}

TEST_CASE("std::format's L applies the locale to each component", "[io][format]") {
    const std::locale german(std::locale::classic(), new german_numbers);
    CHECK(std::format(german, "{:L}", vec3<double>{1234567.5, -0.25, 2}) ==
          "vec3{1.234.567,5, -0,25, 2}");
    CHECK(std::format(german, "{}", vec3<double>{1234567.5, -0.25, 2}) ==
          "vec3{1234567.5, -0.25, 2}");
}

TEST_CASE("std::format prints sequence and frame with a string spec", "[io][format]") {
    CHECK(std::format("{}|{:>5}|{:*<10}", sequence::zyx, sequence::xyx, frame::extrinsic) ==
          "zyx|  xyx|extrinsic*");
    CHECK(std::format("{:^11}", frame::intrinsic) == " intrinsic ");
}

TEST_CASE("std::format prints wide strings", "[io][format]") {
    CHECK(std::format(L"{}", quaternion<double>{1, 0.5, -2, 0}) == L"quaternion{1, 0.5, -2, 0}");
    CHECK(std::format(L"{:.1f} {:>4}", vec3<float>{1, 2, 3}, sequence::zxz) ==
          L"vec3{1.0, 2.0, 3.0}  zxz");
}

}  // namespace test_io_format

#endif  // __cpp_lib_format
