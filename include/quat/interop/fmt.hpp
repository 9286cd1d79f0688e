// Opt-in {fmt} support (not included by quat.hpp; needs {fmt} 9 or later): fmt::formatter for every
// quat type, printing the format documented in quat/io.hpp (a family's results, such as
// se3::twist, where that family's header is included too). "{}" prints each component as
// fmt::format("{}", component) does, the shortest text that reads back exactly (fmt 9 writes a
// long double with 20 significant digits: exact, not shortest); a spec is the scalar's ("{:.3f}",
// "{:e}", "{:>8}") and applies to each component; sequence and frame take a string spec.
// Includes quat/io.hpp, so operator<< comes with it.
#ifndef QUAT_INTEROP_FMT_HPP_INCLUDED
#define QUAT_INTEROP_FMT_HPP_INCLUDED

#include <fmt/format.h>
#include <fmt/ranges.h>  // declares fmt::is_tuple_like, specialized below

#include <string_view>
#include <type_traits>

#include "../io.hpp"

// Each specialization derives from quat::value_formatter or quat::name_formatter, which are not
// keyed by instruction set: quat/detail/print_layout.hpp says why.
namespace fmt {

/// Formats vec3{x, y, z}; the spec is T's and applies to each component.
template <class T, class Char>
struct formatter<::quat::vec3<T>, Char>
    : ::quat::value_formatter<::quat::vec3<T>, fmt::formatter<T, Char>> {};

/// Formats quaternion{w, x, y, z}; the spec is T's and applies to each component.
template <class T, class Char>
struct formatter<::quat::quaternion<T>, Char>
    : ::quat::value_formatter<::quat::quaternion<T>, fmt::formatter<T, Char>> {};

/// Formats rotation_matrix{{m00, m01, m02}, ...} by rows; the spec applies to each element.
template <class T, class Char>
struct formatter<::quat::rotation_matrix<T>, Char>
    : ::quat::value_formatter<::quat::rotation_matrix<T>, fmt::formatter<T, Char>> {};

/// Formats matrix{{m00, m01, ...}, ...} by rows; the spec applies to each element.
template <class T, int R, int C, class Char>
struct formatter<::quat::matrix<T, R, C>, Char>
    : ::quat::value_formatter<::quat::matrix<T, R, C>, fmt::formatter<T, Char>> {};

/// Formats axis_angle{vec3{x, y, z}, angle}; the spec applies to each component and the angle.
template <class T, class Char>
struct formatter<::quat::axis_angle<T>, Char>
    : ::quat::value_formatter<::quat::axis_angle<T>, fmt::formatter<T, Char>> {};

/// Formats euler<S, F>{e[0], e[1], e[2]}; the spec applies to each angle.
template <class T, ::quat::sequence S, ::quat::frame F, class Char>
struct formatter<::quat::euler<T, S, F>, Char>
    : ::quat::value_formatter<::quat::euler<T, S, F>, fmt::formatter<T, Char>> {};

/// euler is tuple-like (for structured bindings); fmt/ranges.h must not format it as a tuple too.
template <class T, ::quat::sequence S, ::quat::frame F>
struct is_tuple_like<::quat::euler<T, S, F>> : std::false_type {};

/// Formats euler_extraction{euler<S, F>{...}, gimbal_lock}; the spec applies to each angle.
template <class T, ::quat::sequence S, ::quat::frame F, class Char>
struct formatter<::quat::euler_extraction<T, S, F>, Char>
    : ::quat::value_formatter<::quat::euler_extraction<T, S, F>, fmt::formatter<T, Char>> {};

/// Formats alignment{quaternion{...}, rssd, unique}; the spec applies to each number.
template <class T, class Char>
struct formatter<::quat::alignment<T>, Char>
    : ::quat::value_formatter<::quat::alignment<T>, fmt::formatter<T, Char>> {};

/// Formats alignment_with_sensitivity{alignment{...}, matrix{...}}; the spec applies to each
/// number.
template <class T, class Char>
struct formatter<::quat::alignment_with_sensitivity<T>, Char>
    : ::quat::value_formatter<::quat::alignment_with_sensitivity<T>, fmt::formatter<T, Char>> {};

/// Formats point_alignment{dual_quaternion{...}, rms, unique}; the spec applies to each number.
template <class T, class Char>
struct formatter<::quat::point_alignment<T>, Char>
    : ::quat::value_formatter<::quat::point_alignment<T>, fmt::formatter<T, Char>> {};

/// Formats similarity_alignment{point_alignment{...}, scale}; the spec applies to each number.
template <class T, class Char>
struct formatter<::quat::similarity_alignment<T>, Char>
    : ::quat::value_formatter<::quat::similarity_alignment<T>, fmt::formatter<T, Char>> {};

/// Formats hand_eye_calibration{dual_quaternion{...}, rotation_rms, translation_rms, unique,
/// ambiguity}; the spec applies to each number.
template <class T, class Char>
struct formatter<::quat::hand_eye_calibration<T>, Char>
    : ::quat::value_formatter<::quat::hand_eye_calibration<T>, fmt::formatter<T, Char>> {};

/// Formats hand_eye_with_target{hand_eye_calibration{...}, dual_quaternion{...}, refined}; the spec
/// applies to each number.
template <class T, class Char>
struct formatter<::quat::hand_eye_with_target<T>, Char>
    : ::quat::value_formatter<::quat::hand_eye_with_target<T>, fmt::formatter<T, Char>> {};

/// Formats swing_twist_parts{quaternion{...}, quaternion{...}}; the spec applies to each component.
template <class T, class Char>
struct formatter<::quat::swing_twist_parts<T>, Char>
    : ::quat::value_formatter<::quat::swing_twist_parts<T>, fmt::formatter<T, Char>> {};

/// Formats dual_quaternion{quaternion{...}, quaternion{...}}; the spec applies to each component.
template <class T, class Char>
struct formatter<::quat::dual_quaternion<T>, Char>
    : ::quat::value_formatter<::quat::dual_quaternion<T>, fmt::formatter<T, Char>> {};

/// Formats homogeneous_matrix{{m00, m01, m02, m03}, ...} by rows; the spec applies to each element.
template <class T, class Char>
struct formatter<::quat::homogeneous_matrix<T>, Char>
    : ::quat::value_formatter<::quat::homogeneous_matrix<T>, fmt::formatter<T, Char>> {};

/// Formats screw{vec3{...}, vec3{...}, angle, displacement}; the spec applies to each number.
template <class T, class Char>
struct formatter<::quat::screw<T>, Char>
    : ::quat::value_formatter<::quat::screw<T>, fmt::formatter<T, Char>> {};

/// Formats se3::twist{vec3{...}, vec3{...}}, linear then angular; the spec applies to each
/// component.
template <class T, class Char>
struct formatter<::quat::se3::twist<T>, Char>
    : ::quat::value_formatter<::quat::se3::twist<T>, fmt::formatter<T, Char>> {};

/// Formats the sequence's name; the spec is a string's (width, fill, alignment).
template <class Char>
struct formatter<::quat::sequence, Char>
    : ::quat::name_formatter<::quat::sequence, fmt::formatter<std::basic_string_view<Char>, Char>> {
};

/// Formats the frame's name; the spec is a string's (width, fill, alignment).
template <class Char>
struct formatter<::quat::frame, Char>
    : ::quat::name_formatter<::quat::frame, fmt::formatter<std::basic_string_view<Char>, Char>> {};

}  // namespace fmt

#endif  // QUAT_INTEROP_FMT_HPP_INCLUDED
