// Specification of io.hpp's operator<<: one format for every type, the stream's flags, precision
// and locale applied to each component and its width to the whole text, as std::complex does, and
// text that reads back to the same values at max_digits10.
#include <iomanip>
#include <limits>
#include <locale>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>

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

#include "support/catch.hpp"
#include "support/read_back.hpp"

namespace test_io {

using quat::axis_angle;
using quat::euler;
using quat::euler_extraction;
using quat::frame;
using quat::quaternion;
using quat::rotation_matrix;
using quat::sequence;
using quat::vec3;

namespace {

template <class Value>
std::string text_of(const Value& value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

template <class Value>
std::string exact_text_of(const Value& value, int digits) {
    std::ostringstream out;
    out << std::setprecision(digits) << value;
    return out.str();
}

// A decimal comma and dots between thousands, as in German.
struct german_numbers : std::numpunct<char> {
    char do_decimal_point() const override { return ','; }
    char do_thousands_sep() const override { return '.'; }
    std::string do_grouping() const override { return "\3"; }
};

}  // namespace

namespace user {

/// A scalar with nothing but its own operator<<, which marks its values.
struct cents {
    long value;
};

std::ostream& operator<<(std::ostream& os, cents c) { return os << c.value << 'c'; }

/// A scalar that cannot be printed.
struct opaque {
    double value;
};

}  // namespace user

template <class Value, class = void>
struct prints : std::false_type {};
template <class Value>
struct prints<Value, decltype(std::declval<std::ostream&>() << std::declval<const Value&>(),
                              void())> : std::true_type {};

TEMPLATE_TEST_CASE("each type prints as its name and brace initializer", "[io]", float, double,
                   long double) {
    using T = TestType;
    CHECK(text_of(vec3<T>{T(1), T(-2), T(0.5)}) == "vec3{1, -2, 0.5}");
    CHECK(text_of(quaternion<T>{T(1), T(0), T(-0.0), T(0.25)}) == "quaternion{1, 0, -0, 0.25}");
    CHECK(text_of(rotation_matrix<T>::identity()) ==
          "rotation_matrix{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}");
    const auto rows = rotation_matrix<T>::from_rows(
        vec3<T>{T(1), T(2), T(3)}, vec3<T>{T(4), T(5), T(6)}, vec3<T>{T(7), T(8), T(9)});
    CHECK(text_of(rows) == "rotation_matrix{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}}");
    CHECK(text_of(axis_angle<T>{vec3<T>{T(0), T(0), T(1)}, T(1.5)}) ==
          "axis_angle{vec3{0, 0, 1}, 1.5}");
    CHECK(text_of(euler<T>{T(0.5), T(0.25), T(0.125)}) ==
          "euler<zyx, intrinsic>{0.5, 0.25, 0.125}");
    CHECK(text_of(euler<T, sequence::xzx, frame::extrinsic>{T(1), T(2), T(3)}) ==
          "euler<xzx, extrinsic>{1, 2, 3}");
    const euler_extraction<T, sequence::yzx, frame::intrinsic> locked{{T(1), T(-1.5), T(0)}, true};
    CHECK(text_of(locked) == "euler_extraction{euler<yzx, intrinsic>{1, -1.5, 0}, true}");
    const euler_extraction<T, sequence::zyx, frame::extrinsic> unlocked{{T(1), T(2), T(3)}, false};
    CHECK(text_of(unlocked) == "euler_extraction{euler<zyx, extrinsic>{1, 2, 3}, false}");
    const quat::alignment<T> fit{{T(1), T(0), T(0), T(0)}, T(0.25), true};
    CHECK(text_of(fit) == "alignment{quaternion{1, 0, 0, 0}, 0.25, true}");
    const quat::alignment_with_sensitivity<T> fit_with{{{T(0), T(1), T(0), T(0)}, T(2), false},
                                                       quat::matrix3<T>::identity()};
    CHECK(text_of(fit_with) ==
          "alignment_with_sensitivity{alignment{quaternion{0, 1, 0, 0}, 2, false}, "
          "matrix{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}");
    const quat::matrix<T, 2, 3> wide{{{T(1), T(2), T(3)}, {T(-4), T(0.5), T(0)}}};
    CHECK(text_of(wide) == "matrix{{1, 2, 3}, {-4, 0.5, 0}}");
    const quat::swing_twist_parts<T> parts{{T(0.5), T(0.5), T(0.5), T(0.5)},
                                           {T(1), T(0), T(0), T(0)}};
    CHECK(text_of(parts) ==
          "swing_twist_parts{quaternion{0.5, 0.5, 0.5, 0.5}, quaternion{1, 0, 0, 0}}");
    const quat::dual_quaternion<T> motion{{T(0), T(0), T(0), T(1)}, {T(-0.5), T(0), T(0), T(0)}};
    CHECK(text_of(motion) == "dual_quaternion{quaternion{0, 0, 0, 1}, quaternion{-0.5, 0, 0, 0}}");
    const quat::similarity_alignment<T> similar{{motion, T(0.25), true}, T(2)};
    CHECK(text_of(quat::point_alignment<T>(similar)) ==
          "point_alignment{dual_quaternion{quaternion{0, 0, 0, 1}, quaternion{-0.5, 0, 0, 0}}, "
          "0.25, true}");
    CHECK(text_of(similar) ==
          "similarity_alignment{point_alignment{dual_quaternion{quaternion{0, 0, 0, 1}, "
          "quaternion{-0.5, 0, 0, 0}}, 0.25, true}, 2}");
    const quat::hand_eye_calibration<T> mount{motion, T(0.125), T(0.5), false, T(1)};
    CHECK(text_of(mount) ==
          "hand_eye_calibration{dual_quaternion{quaternion{0, 0, 0, 1}, quaternion{-0.5, 0, 0, "
          "0}}, 0.125, 0.5, false, 1}");
    const quat::hand_eye_with_target<T> with{mount, motion, true};
    CHECK(text_of(with) ==
          "hand_eye_with_target{hand_eye_calibration{dual_quaternion{quaternion{0, 0, 0, 1}, "
          "quaternion{-0.5, 0, 0, 0}}, 0.125, 0.5, false, 1}, dual_quaternion{quaternion{0, 0, 0, "
          "1}, quaternion{-0.5, 0, 0, 0}}, true}");
    CHECK(text_of(quat::to_homogeneous(motion)) ==
          "homogeneous_matrix{{-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, 1, 1}, {0, 0, 0, 1}}");
    const quat::screw<T> s{{T(0), T(0), T(1)}, {T(0), T(-1), T(0)}, T(1.5), T(2)};
    CHECK(text_of(s) == "screw{vec3{0, 0, 1}, vec3{0, -1, 0}, 1.5, 2}");
    const quat::se3::twist<T> t{{T(1), T(-2), T(0)}, {T(0), T(0), T(0.5)}};
    CHECK(text_of(t) == "se3::twist{vec3{1, -2, 0}, vec3{0, 0, 0.5}}");
    // The stream's default precision is 6 significant digits, for every T alike.
    CHECK(text_of(vec3<T>{T(1) / T(3), T(2) / T(3), T(-100) / T(3)}) ==
          "vec3{0.333333, 0.666667, -33.3333}");
}

TEST_CASE("a quat type prints exactly when its scalar does", "[io]") {
    // So a printability check (Catch2 makes one before it shows a value) says no for a scalar
    // without operator<<, instead of failing to compile inside quat's operator<<.
    STATIC_REQUIRE(prints<quaternion<double>>::value);
    STATIC_REQUIRE(prints<quaternion<user::cents>>::value);
    STATIC_REQUIRE_FALSE(prints<quaternion<user::opaque>>::value);
    STATIC_REQUIRE_FALSE(prints<vec3<user::opaque>>::value);
    STATIC_REQUIRE_FALSE(prints<rotation_matrix<user::opaque>>::value);
    STATIC_REQUIRE_FALSE(prints<axis_angle<user::opaque>>::value);
    STATIC_REQUIRE_FALSE(prints<euler<user::opaque, sequence::zyx, frame::intrinsic>>::value);
    STATIC_REQUIRE_FALSE(prints<quat::matrix<user::opaque, 2, 3>>::value);
    CHECK(Catch::Detail::stringify(quaternion<user::opaque>{}) == "{?}");
}

TEST_CASE("sequence and frame print their names", "[io]") {
    const std::pair<sequence, const char*> sequences[] = {
        {sequence::xyz, "xyz"}, {sequence::xzy, "xzy"}, {sequence::yxz, "yxz"},
        {sequence::yzx, "yzx"}, {sequence::zxy, "zxy"}, {sequence::zyx, "zyx"},
        {sequence::xyx, "xyx"}, {sequence::xzx, "xzx"}, {sequence::yxy, "yxy"},
        {sequence::yzy, "yzy"}, {sequence::zxz, "zxz"}, {sequence::zyz, "zyz"}};
    for (const auto& [s, name] : sequences) CHECK(text_of(s) == name);
    CHECK(text_of(frame::intrinsic) == "intrinsic");
    CHECK(text_of(frame::extrinsic) == "extrinsic");
    std::ostringstream out;
    out << std::setw(6) << sequence::zxz << '|' << std::left << std::setw(10) << frame::extrinsic
        << '|';
    CHECK(out.str() == "   zxz|extrinsic |");
}

TEMPLATE_TEST_CASE("at max_digits10 the text reads back to the same values", "[io]", float, double,
                   long double) {
    using T = TestType;
    using namespace quat::test;
    constexpr int digits = std::numeric_limits<T>::max_digits10;
    // One digit fewer, except for IEEE binary128 (long double on AArch64): its 113 bits are spaced
    // 2^-113 = 0.96e-34 apart, barely finer than 35 digits' 1e-34, so 35 of max_digits10's 36 lose
    // too few values for 200 draws to show; 34 lose most.
    constexpr int fewer = std::numeric_limits<T>::digits >= 113 ? digits - 2 : digits - 1;
    awkward_values<T> values;
    int lost_with_fewer_digits = 0;
    for (int n = 0; n < 200; ++n) {
        const double scale = scales[n % 5];
        const auto v = values.next_vec3(scale);
        const auto q = values.next_quaternion(scale);
        const auto m = values.next_matrix(scale);
        const auto r = values.next_axis_angle(scale);
        const auto e = values.next_euler(scale);
        CHECK(read_back<T>(exact_text_of(v, digits), vec3_pattern) == printed_components(v));
        CHECK(read_back<T>(exact_text_of(q, digits), quaternion_pattern) == printed_components(q));
        CHECK(read_back<T>(exact_text_of(m, digits), matrix_pattern) == printed_components(m));
        CHECK(read_back<T>(exact_text_of(r, digits), axis_angle_pattern) == printed_components(r));
        CHECK(read_back<T>(exact_text_of(e, digits), euler_pattern) == printed_components(e));
        if (read_back<T>(exact_text_of(q, fewer), quaternion_pattern) != printed_components(q))
            ++lost_with_fewer_digits;
    }
    // Fewer digits lose some values: the inputs are hard enough for the test to tell.
    CHECK(lost_with_fewer_digits > 0);
    using limits = std::numeric_limits<T>;
    const quaternion<T> extremes{limits::max(), limits::lowest(), limits::min(), limits::epsilon()};
    CHECK(read_back<T>(exact_text_of(extremes, digits), quaternion_pattern) ==
          printed_components(extremes));
}

TEST_CASE("the stream's flags and precision apply to every component", "[io]") {
    std::ostringstream out;
    out << std::fixed << std::setprecision(2) << quaternion<double>{1, -0.5, 0.125, 1e3};
    CHECK(out.str() == "quaternion{1.00, -0.50, 0.12, 1000.00}");
    out.str("");
    out << std::scientific << std::setprecision(3) << vec3<double>{1234.56, -0.001, 0};
    CHECK(out.str() == "vec3{1.235e+03, -1.000e-03, 0.000e+00}");
    out.str("");
    out << std::uppercase << axis_angle<double>{{1e-7, 0, 1}, 2.5};
    CHECK(out.str() == "axis_angle{vec3{1.000E-07, 0.000E+00, 1.000E+00}, 2.500E+00}");
    out.str("");
    out << std::defaultfloat << std::nouppercase << std::showpos << std::setprecision(6)
        << euler<double>{1, -2, 0};
    CHECK(out.str() == "euler<zyx, intrinsic>{+1, -2, +0}");
    out.str("");
    out << std::noshowpos << std::hexfloat << vec3<double>{1, 0.5, -3};
    CHECK(out.str() == "vec3{0x1p+0, 0x1p-1, -0x1.8p+1}");
    // The user's stream keeps its settings.
    CHECK((out.flags() & std::ios_base::floatfield) == std::ios_base::floatfield);
    CHECK(out.precision() == 6);
}

TEST_CASE("the stream's width, fill and adjustment apply to the whole text", "[io]") {
    const vec3<double> v{1, 2, 3};  // "vec3{1, 2, 3}": 13 characters
    std::ostringstream out;
    out << std::setw(20) << v << '|' << v << '|';
    CHECK(out.str() == "       vec3{1, 2, 3}|vec3{1, 2, 3}|");  // the width is used up, as usual
    out.str("");
    out << std::left << std::setfill('*') << std::setw(20) << quaternion<double>{1, 0, 0, 0} << '|';
    CHECK(out.str() == "quaternion{1, 0, 0, 0}|");  // wider than 20: nothing to pad
    out.str("");
    out << std::setw(16) << v << '|';
    CHECK(out.str() == "vec3{1, 2, 3}***|");
    out.str("");
    out << std::right << std::setw(16) << std::setprecision(1) << std::fixed << v;
    CHECK(out.str() == "vec3{1.0, 2.0, 3.0}");
}

TEST_CASE("the stream's locale applies to every component", "[io]") {
    std::ostringstream out;
    out.imbue(std::locale(std::locale::classic(), new german_numbers));
    out << std::fixed << std::setprecision(1) << vec3<double>{1234567.5, -0.3, 2};
    CHECK(out.str() == "vec3{1.234.567,5, -0,3, 2,0}");
    out.str("");
    out << std::defaultfloat << std::setprecision(6) << euler<double>{0.5, 1500, -2.25};
    CHECK(out.str() == "euler<zyx, intrinsic>{0,5, 1.500, -2,25}");
}

TEST_CASE("wide streams print the same text", "[io]") {
    std::wostringstream out;
    out << quaternion<double>{1, 0.5, -2, 0} << L' ' << sequence::zyz << L' ' << frame::intrinsic;
    CHECK(out.str() == L"quaternion{1, 0.5, -2, 0} zyz intrinsic");
    out.str(L"");
    out << std::setw(20) << std::setfill(L'.') << vec3<float>{1, 2, 3};
    CHECK(out.str() == L".......vec3{1, 2, 3}");
}

TEST_CASE("a user scalar prints through its own operator<<, with the stream's flags", "[io]") {
    using user::cents;
    std::ostringstream out;
    out << vec3<cents>{cents{1}, cents{-20}, cents{300}};
    CHECK(out.str() == "vec3{1c, -20c, 300c}");
    out.str("");
    out << std::showpos << quaternion<cents>{cents{1}, cents{2}, cents{3}, cents{4}};
    CHECK(out.str() == "quaternion{+1c, +2c, +3c, +4c}");
}

}  // namespace test_io
