// Printing quat's types: operator<< for streams and, where <format> exists, std::formatter.
// Opt-in: quat.hpp does not include this header, and no other quat header includes <ostream>.
//
// One format for every type: its name and brace initializer, components in declaration order.
//   vec3{1, -2, 0.5}
//   quaternion{1, 0, 0, 0}                                    w, x, y, z
//   rotation_matrix{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}          rows: m(0, 0), m(0, 1), ...
//   matrix{{1, 0, 0, 0, 0, 0}, ..., {0, 0, 0, 0, 0, 1}}      matrix<T, R, C>: R rows of C
//   axis_angle{vec3{0, 0, 1}, 1.5}                            axis, angle
//   euler<zyx, intrinsic>{0.5, 0.25, 0.125}                   e[0], e[1], e[2]
//   euler_extraction{euler<zyx, intrinsic>{0.5, 0, 0}, true}  angles, gimbal_lock
//   swing_twist_parts{quaternion{...}, quaternion{...}}       swing, twist
//   zyx   intrinsic                                           sequence and frame: their names
// and the families' results, which print where the user includes their header too (this header
// includes only the value types above, so printing a vec3 compiles no solver):
// fitting/align_vectors.hpp
//   alignment{quaternion{1, 0, 0, 0}, 0.25, true}             rotation, rssd, unique
//   alignment_with_sensitivity{alignment{...}, matrix{...}}   sensitivity
// rigid/dual_quaternion.hpp, rigid/homogeneous_matrix.hpp, rigid/screw.hpp
//   dual_quaternion{quaternion{...}, quaternion{...}}         real, dual
//   homogeneous_matrix{{1, 0, 0, 0}, ..., {0, 0, 0, 1}}       rows
//   screw{vec3{0, 0, 1}, vec3{0, -1, 0}, 1.5, 2}              direction, moment, angle,
//                                                             displacement
// registration/align_points.hpp, registration/hand_eye.hpp
//   point_alignment{dual_quaternion{...}, 0.25, true}         motion, rms, unique
//   similarity_alignment{point_alignment{...}, 2}             scale
//   hand_eye_calibration{dual_quaternion{...}, 0.1, 0.2, true, 0.01}
//                                                             mount, rotation_rms, translation_rms,
//                                                             unique, ambiguity
//   hand_eye_with_target{hand_eye_calibration{...}, dual_quaternion{...}, true}
//                                                             calibration, target, refined
// lie/se3.hpp
//   se3::twist{vec3{1, 0, 0}, vec3{0, 0, 0.5}}                linear, angular
//
// operator<< works like std::complex's: the stream's flags, precision and locale apply to every
// component (so at std::setprecision(std::numeric_limits<T>::max_digits10) the text reads back to
// the same values), then the whole text is inserted at once, so width, fill and adjustment apply to
// all of it. A scalar type only needs its own operator<<.
//
// std::format (C++20 libraries that define __cpp_lib_format) prints each component as
// std::format("{}", component) does, the shortest text that reads back exactly (for long double,
// as far as the library does: libc++ 19 formats it as a double). A format spec is the scalar's
// ("{:.3f}", "{:e}", "{:+}", "{:>8}", "{:L}") and applies to each component, width included;
// sequence and frame take a string spec ("{:>9}"). gimbal_lock and unique are always true or false.
// quat/interop/fmt.hpp gives fmt::format the same behaviour.
#ifndef QUAT_IO_HPP_INCLUDED
#define QUAT_IO_HPP_INCLUDED

#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#if __has_include(<version>)
#include <version>
#endif
#if defined(__cpp_lib_format) && __has_include(<format>)
#include <format>
#endif

#include "axis_angle.hpp"
#include "detail/print_layout.hpp"
#include "euler.hpp"
#include "matrix.hpp"
#include "quaternion.hpp"
#include "rotation_matrix.hpp"
#include "swing_twist.hpp"
#include "vec3.hpp"

namespace quat {

#include "detail/isa_namespace.inc"
namespace detail {

// The operators below exist only where the scalar T prints to the stream, so that asking whether
// a quat type of another scalar prints (as Catch2 does before it shows a value) says no instead of
// failing to compile inside operator<<.
template <class T, class CharT, class Traits>
using if_printable =
    decltype(std::declval<std::basic_ostream<CharT, Traits>&>() << std::declval<const T&>(),
             void());

// Writes to a stream that carries the flags, precision and locale of the user's stream.
template <class CharT, class Traits>
struct stream_printer {
    std::basic_ostream<CharT, Traits>& out;

    void text(std::string_view ascii) {
        for (char c : ascii) out.put(out.widen(c));
    }
    template <class T>
    void value(const T& component) {
        out << component;
    }
};

// std::complex's recipe: format into a local stream with os's flags, precision and locale (its
// width is 0), then insert the whole text, to which os's width, fill and adjustment apply.
template <class CharT, class Traits, class Value>
std::basic_ostream<CharT, Traits>& print_to_stream(std::basic_ostream<CharT, Traits>& os,
                                                   const Value& value) {
    std::basic_ostringstream<CharT, Traits> text;
    text.flags(os.flags());
    text.imbue(os.getloc());
    text.precision(os.precision());
    stream_printer<CharT, Traits> printer{text};
    write_layout(printer, value);
    return os << text.str();
}

}  // namespace detail

/// Prints the axis sequence's name, e.g. zyx.
template <class CharT, class Traits>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os, sequence s) {
    return detail::print_to_stream(os, s);
}

/// Prints the frame's name: intrinsic or extrinsic.
template <class CharT, class Traits>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os, frame f) {
    return detail::print_to_stream(os, f);
}

/// Prints vec3{x, y, z}: the stream's flags, precision and locale apply to each component, its
/// width to the whole text.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const vec3<T>& v) {
    return detail::print_to_stream(os, v);
}

/// Prints quaternion{w, x, y, z}, scalar first; stream settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const quaternion<T>& q) {
    return detail::print_to_stream(os, q);
}

/// Prints rotation_matrix{{m00, m01, m02}, {m10, m11, m12}, {m20, m21, m22}}, row by row; stream
/// settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const rotation_matrix<T>& m) {
    return detail::print_to_stream(os, m);
}

/// Prints matrix{{m00, m01, ...}, ..., {...}}, Rows braces of Cols elements; stream settings as for
/// vec3.
template <class T, int R, int C, class CharT, class Traits,
          class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const matrix<T, R, C>& m) {
    return detail::print_to_stream(os, m);
}

/// Prints axis_angle{vec3{x, y, z}, angle}; stream settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const axis_angle<T>& rotation) {
    return detail::print_to_stream(os, rotation);
}

/// Prints euler<S, F>{e[0], e[1], e[2]} with the convention's names, e.g. euler<zyx,
/// intrinsic>{...}; stream settings as for vec3.
template <class T, sequence S, frame F, class CharT, class Traits,
          class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const euler<T, S, F>& e) {
    return detail::print_to_stream(os, e);
}

/// Prints euler_extraction{euler<S, F>{...}, gimbal_lock} with gimbal_lock as true or false;
/// stream settings as for vec3.
template <class T, sequence S, frame F, class CharT, class Traits,
          class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const euler_extraction<T, S, F>& extraction) {
    return detail::print_to_stream(os, extraction);
}

/// Prints alignment{quaternion{...}, rssd, unique} with unique as true or false
/// (fitting/align_vectors.hpp); stream settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const alignment<T>& a) {
    return detail::print_to_stream(os, a);
}

/// Prints alignment_with_sensitivity{alignment{...}, matrix{...}}, the sensitivity matrix by rows
/// (fitting/align_vectors.hpp); stream settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const alignment_with_sensitivity<T>& a) {
    return detail::print_to_stream(os, a);
}

/// Prints point_alignment{dual_quaternion{...}, rms, unique} (registration/align_points.hpp);
/// stream settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const point_alignment<T>& a) {
    return detail::print_to_stream(os, a);
}

/// Prints similarity_alignment{point_alignment{...}, scale} (registration/align_points.hpp);
/// stream settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const similarity_alignment<T>& a) {
    return detail::print_to_stream(os, a);
}

/// Prints hand_eye_calibration{dual_quaternion{...}, rotation_rms, translation_rms, unique,
/// ambiguity} (registration/hand_eye.hpp); stream settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const hand_eye_calibration<T>& c) {
    return detail::print_to_stream(os, c);
}

/// Prints hand_eye_with_target{hand_eye_calibration{...}, dual_quaternion{...}, refined}
/// (registration/hand_eye.hpp); stream settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const hand_eye_with_target<T>& r) {
    return detail::print_to_stream(os, r);
}

/// Prints swing_twist_parts{quaternion{...}, quaternion{...}}, swing then twist; stream settings as
/// for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const swing_twist_parts<T>& parts) {
    return detail::print_to_stream(os, parts);
}

/// Prints dual_quaternion{quaternion{...}, quaternion{...}}, real then dual
/// (rigid/dual_quaternion.hpp); stream settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const dual_quaternion<T>& dq) {
    return detail::print_to_stream(os, dq);
}

/// Prints homogeneous_matrix{{m00, m01, m02, m03}, ..., {m30, m31, m32, m33}}, row by row
/// (rigid/homogeneous_matrix.hpp); stream settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const homogeneous_matrix<T>& m) {
    return detail::print_to_stream(os, m);
}

/// Prints screw{vec3{direction}, vec3{moment}, angle, displacement} (rigid/screw.hpp); stream
/// settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const screw<T>& s) {
    return detail::print_to_stream(os, s);
}
}  // inline namespace isa_...

namespace se3 {

#include "detail/isa_namespace.inc"  // NOLINT(readability-duplicate-include): opened again

/// Prints se3::twist{vec3{linear}, vec3{angular}} (lie/se3.hpp); stream settings as for vec3.
template <class T, class CharT, class Traits, class = detail::if_printable<T, CharT, Traits>>
std::basic_ostream<CharT, Traits>& operator<<(std::basic_ostream<CharT, Traits>& os,
                                              const twist<T>& t) {
    return ::quat::detail::print_to_stream(os, t);
}
}  // inline namespace isa_...

}  // namespace se3

}  // namespace quat

#if defined(__cpp_lib_format) && __has_include(<format>)

// std::format support: the format above, each component formatted by std::formatter<T, CharT> with
// the spec given ("{}" is the shortest text that reads back exactly). Each specialization derives
// from quat::value_formatter or quat::name_formatter, which are not keyed by instruction set:
// detail/print_layout.hpp says why.

namespace std {

/// Formats vec3{x, y, z}; the spec is T's and applies to each component.
template <class T, class CharT>
struct formatter<::quat::vec3<T>, CharT>
    : ::quat::value_formatter<::quat::vec3<T>, std::formatter<T, CharT>> {};

/// Formats quaternion{w, x, y, z}; the spec is T's and applies to each component.
template <class T, class CharT>
struct formatter<::quat::quaternion<T>, CharT>
    : ::quat::value_formatter<::quat::quaternion<T>, std::formatter<T, CharT>> {};

/// Formats rotation_matrix{{m00, m01, m02}, ...} by rows; the spec applies to each element.
template <class T, class CharT>
struct formatter<::quat::rotation_matrix<T>, CharT>
    : ::quat::value_formatter<::quat::rotation_matrix<T>, std::formatter<T, CharT>> {};

/// Formats matrix{{m00, m01, ...}, ...} by rows; the spec applies to each element.
template <class T, int R, int C, class CharT>
struct formatter<::quat::matrix<T, R, C>, CharT>
    : ::quat::value_formatter<::quat::matrix<T, R, C>, std::formatter<T, CharT>> {};

/// Formats axis_angle{vec3{x, y, z}, angle}; the spec applies to each component and the angle.
template <class T, class CharT>
struct formatter<::quat::axis_angle<T>, CharT>
    : ::quat::value_formatter<::quat::axis_angle<T>, std::formatter<T, CharT>> {};

/// Formats euler<S, F>{e[0], e[1], e[2]}; the spec applies to each angle.
template <class T, ::quat::sequence S, ::quat::frame F, class CharT>
struct formatter<::quat::euler<T, S, F>, CharT>
    : ::quat::value_formatter<::quat::euler<T, S, F>, std::formatter<T, CharT>> {};

/// Formats euler_extraction{euler<S, F>{...}, gimbal_lock}; the spec applies to each angle.
template <class T, ::quat::sequence S, ::quat::frame F, class CharT>
struct formatter<::quat::euler_extraction<T, S, F>, CharT>
    : ::quat::value_formatter<::quat::euler_extraction<T, S, F>, std::formatter<T, CharT>> {};

/// Formats alignment{quaternion{...}, rssd, unique}; the spec applies to each number.
template <class T, class CharT>
struct formatter<::quat::alignment<T>, CharT>
    : ::quat::value_formatter<::quat::alignment<T>, std::formatter<T, CharT>> {};

/// Formats alignment_with_sensitivity{alignment{...}, matrix{...}}; the spec applies to each
/// number.
template <class T, class CharT>
struct formatter<::quat::alignment_with_sensitivity<T>, CharT>
    : ::quat::value_formatter<::quat::alignment_with_sensitivity<T>, std::formatter<T, CharT>> {};

/// Formats point_alignment{dual_quaternion{...}, rms, unique}; the spec applies to each number.
template <class T, class CharT>
struct formatter<::quat::point_alignment<T>, CharT>
    : ::quat::value_formatter<::quat::point_alignment<T>, std::formatter<T, CharT>> {};

/// Formats similarity_alignment{point_alignment{...}, scale}; the spec applies to each number.
template <class T, class CharT>
struct formatter<::quat::similarity_alignment<T>, CharT>
    : ::quat::value_formatter<::quat::similarity_alignment<T>, std::formatter<T, CharT>> {};

/// Formats hand_eye_calibration{dual_quaternion{...}, rotation_rms, translation_rms, unique,
/// ambiguity}; the spec applies to each number.
template <class T, class CharT>
struct formatter<::quat::hand_eye_calibration<T>, CharT>
    : ::quat::value_formatter<::quat::hand_eye_calibration<T>, std::formatter<T, CharT>> {};

/// Formats hand_eye_with_target{hand_eye_calibration{...}, dual_quaternion{...}, refined}; the spec
/// applies to each number.
template <class T, class CharT>
struct formatter<::quat::hand_eye_with_target<T>, CharT>
    : ::quat::value_formatter<::quat::hand_eye_with_target<T>, std::formatter<T, CharT>> {};

/// Formats swing_twist_parts{quaternion{...}, quaternion{...}}; the spec applies to each component.
template <class T, class CharT>
struct formatter<::quat::swing_twist_parts<T>, CharT>
    : ::quat::value_formatter<::quat::swing_twist_parts<T>, std::formatter<T, CharT>> {};

/// Formats dual_quaternion{quaternion{...}, quaternion{...}}; the spec applies to each component.
template <class T, class CharT>
struct formatter<::quat::dual_quaternion<T>, CharT>
    : ::quat::value_formatter<::quat::dual_quaternion<T>, std::formatter<T, CharT>> {};

/// Formats homogeneous_matrix{{m00, m01, m02, m03}, ...} by rows; the spec applies to each element.
template <class T, class CharT>
struct formatter<::quat::homogeneous_matrix<T>, CharT>
    : ::quat::value_formatter<::quat::homogeneous_matrix<T>, std::formatter<T, CharT>> {};

/// Formats screw{vec3{...}, vec3{...}, angle, displacement}; the spec applies to each number.
template <class T, class CharT>
struct formatter<::quat::screw<T>, CharT>
    : ::quat::value_formatter<::quat::screw<T>, std::formatter<T, CharT>> {};

/// Formats se3::twist{vec3{...}, vec3{...}}, linear then angular; the spec applies to each
/// component.
template <class T, class CharT>
struct formatter<::quat::se3::twist<T>, CharT>
    : ::quat::value_formatter<::quat::se3::twist<T>, std::formatter<T, CharT>> {};

/// Formats the sequence's name; the spec is a string's (width, fill, alignment).
template <class CharT>
struct formatter<::quat::sequence, CharT>
    : ::quat::name_formatter<::quat::sequence,
                             std::formatter<std::basic_string_view<CharT>, CharT>> {};

/// Formats the frame's name; the spec is a string's (width, fill, alignment).
template <class CharT>
struct formatter<::quat::frame, CharT>
    : ::quat::name_formatter<::quat::frame, std::formatter<std::basic_string_view<CharT>, CharT>> {
};

}  // namespace std

#endif  // __cpp_lib_format

#endif  // QUAT_IO_HPP_INCLUDED
