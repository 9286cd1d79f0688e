// The text layout of quat's types, written once for every printer: streams (io.hpp), std::format
// (io.hpp) and {fmt} (interop/fmt.hpp). io.hpp documents the format. A printer p offers
// p.text(ascii) for the fixed text and p.value(component) for each scalar; format_printer adapts
// the layout to std::format and fmt, whose formatters derive from value_formatter and
// name_formatter (the end of this file says why those two are not keyed). No <ostream> and no
// <format> here: those are the printers' own.
#ifndef QUAT_DETAIL_PRINT_LAYOUT_HPP_INCLUDED
#define QUAT_DETAIL_PRINT_LAYOUT_HPP_INCLUDED

#include <cstddef>
#include <string_view>

namespace quat {

// The types laid out below, declared here and defined by their own headers: this file is part of
// detail/, which includes no public header, so printing a vec3 does not compile the families'
// solvers. io.hpp includes the value types' headers; a family's results (fitting/, rigid/,
// registration/, lie/se3.hpp) print where the user includes that family's header too, as the
// layout is instantiated only for a type that is complete. The declarations repeat no default
// argument (euler's are in euler.hpp), so they agree with the definitions in either order.
enum class sequence;
enum class frame;
template <class T>
struct vec3;
template <class T>
struct quaternion;
template <class T>
struct rotation_matrix;
template <class T, int Rows, int Cols>
struct matrix;
template <class T>
struct axis_angle;
template <class T, sequence S, frame F>
struct euler;
template <class T, sequence S, frame F>
struct euler_extraction;
template <class T>
struct swing_twist_parts;
template <class T>
struct alignment;
template <class T>
struct alignment_with_sensitivity;
template <class T>
struct dual_quaternion;
template <class T>
struct homogeneous_matrix;
template <class T>
struct screw;
template <class T>
struct point_alignment;
template <class T>
struct similarity_alignment;
template <class T>
struct hand_eye_calibration;
template <class T>
struct hand_eye_with_target;
namespace se3 {
template <class T>
struct twist;
}  // namespace se3

#include "isa_namespace.inc"
namespace detail {

// Names in the enumerators' order (sequence and frame count from 0 without gaps).
inline constexpr std::string_view sequence_names[] = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx",
                                                      "xyx", "xzx", "yxy", "yzy", "zxz", "zyz"};
inline constexpr std::string_view frame_names[] = {"intrinsic", "extrinsic"};

template <class Enum, std::size_t N>
[[nodiscard]] constexpr std::string_view name_in(const std::string_view (&names)[N], Enum value,
                                                 std::string_view unknown) noexcept {
    const auto index = static_cast<std::size_t>(value);  // a negative value wraps to a huge index
    return index < N ? names[index] : unknown;
}

[[nodiscard]] constexpr std::string_view spelling(sequence s) noexcept {
    return name_in(sequence_names, s, "sequence?");
}

[[nodiscard]] constexpr std::string_view spelling(frame f) noexcept {
    return name_in(frame_names, f, "frame?");
}

// "{a, b, ...}"
template <class Printer, class T, class... Rest>
void write_braced(Printer& p, const T& first, const Rest&... rest) {
    p.text("{");
    p.value(first);
    ((p.text(", "), p.value(rest)), ...);
    p.text("}");
}

template <class Printer>
void write_layout(Printer& p, sequence s) {
    p.text(spelling(s));
}

template <class Printer>
void write_layout(Printer& p, frame f) {
    p.text(spelling(f));
}

template <class Printer, class T>
void write_layout(Printer& p, const vec3<T>& v) {
    p.text("vec3");
    write_braced(p, v.x, v.y, v.z);
}

template <class Printer, class T>
void write_layout(Printer& p, const quaternion<T>& q) {
    p.text("quaternion");
    write_braced(p, q.w, q.x, q.y, q.z);
}

template <class Printer, class T>
void write_layout(Printer& p, const rotation_matrix<T>& m) {
    p.text("rotation_matrix{");
    for (int row = 0; row < 3; ++row) {
        if (row > 0) p.text(", ");
        write_braced(p, m(row, 0), m(row, 1), m(row, 2));
    }
    p.text("}");
}

template <class Printer, class T, int R, int C>
void write_layout(Printer& p, const matrix<T, R, C>& m) {
    p.text("matrix{");
    for (int row = 0; row < R; ++row) {
        p.text(row > 0 ? ", {" : "{");
        for (int col = 0; col < C; ++col) {
            if (col > 0) p.text(", ");
            p.value(m(row, col));
        }
        p.text("}");
    }
    p.text("}");
}

template <class Printer, class T>
void write_layout(Printer& p, const axis_angle<T>& rotation) {
    p.text("axis_angle{");
    write_layout(p, rotation.axis);
    p.text(", ");
    p.value(rotation.angle);
    p.text("}");
}

template <class Printer, class T, sequence S, frame F>
void write_layout(Printer& p, const euler<T, S, F>& e) {
    p.text("euler<");
    p.text(spelling(S));
    p.text(", ");
    p.text(spelling(F));
    p.text(">");
    write_braced(p, e[0], e[1], e[2]);
}

template <class Printer, class T, sequence S, frame F>
void write_layout(Printer& p, const euler_extraction<T, S, F>& extraction) {
    p.text("euler_extraction{");
    write_layout(p, extraction.angles);
    p.text(extraction.gimbal_lock ? ", true}" : ", false}");
}

template <class Printer, class T>
void write_layout(Printer& p, const alignment<T>& a) {
    p.text("alignment{");
    write_layout(p, a.rotation);
    p.text(", ");
    p.value(a.rssd);
    p.text(a.unique ? ", true}" : ", false}");
}

template <class Printer, class T>
void write_layout(Printer& p, const alignment_with_sensitivity<T>& a) {
    p.text("alignment_with_sensitivity{");
    write_layout(p, static_cast<const alignment<T>&>(a));
    p.text(", ");
    write_layout(p, a.sensitivity);
    p.text("}");
}

template <class Printer, class T>
void write_layout(Printer& p, const point_alignment<T>& a) {
    p.text("point_alignment{");
    write_layout(p, a.motion);
    p.text(", ");
    p.value(a.rms);
    p.text(a.unique ? ", true}" : ", false}");
}

template <class Printer, class T>
void write_layout(Printer& p, const similarity_alignment<T>& a) {
    p.text("similarity_alignment{");
    write_layout(p, static_cast<const point_alignment<T>&>(a));
    p.text(", ");
    p.value(a.scale);
    p.text("}");
}

template <class Printer, class T>
void write_layout(Printer& p, const hand_eye_calibration<T>& c) {
    p.text("hand_eye_calibration{");
    write_layout(p, c.mount);
    p.text(", ");
    p.value(c.rotation_rms);
    p.text(", ");
    p.value(c.translation_rms);
    p.text(c.unique ? ", true, " : ", false, ");
    p.value(c.ambiguity);
    p.text("}");
}

template <class Printer, class T>
void write_layout(Printer& p, const hand_eye_with_target<T>& r) {
    p.text("hand_eye_with_target{");
    write_layout(p, r.calibration);
    p.text(", ");
    write_layout(p, r.target);
    p.text(r.refined ? ", true}" : ", false}");
}

template <class Printer, class T>
void write_layout(Printer& p, const swing_twist_parts<T>& parts) {
    p.text("swing_twist_parts{");
    write_layout(p, parts.swing);
    p.text(", ");
    write_layout(p, parts.twist);
    p.text("}");
}

template <class Printer, class T>
void write_layout(Printer& p, const dual_quaternion<T>& dq) {
    p.text("dual_quaternion{");
    write_layout(p, dq.real);
    p.text(", ");
    write_layout(p, dq.dual);
    p.text("}");
}

template <class Printer, class T>
void write_layout(Printer& p, const homogeneous_matrix<T>& m) {
    p.text("homogeneous_matrix{");
    for (int row = 0; row < 4; ++row) {
        if (row > 0) p.text(", ");
        write_braced(p, m(row, 0), m(row, 1), m(row, 2), m(row, 3));
    }
    p.text("}");
}

template <class Printer, class T>
void write_layout(Printer& p, const screw<T>& s) {
    p.text("screw{");
    write_layout(p, s.direction);
    p.text(", ");
    write_layout(p, s.moment);
    p.text(", ");
    p.value(s.angle);
    p.text(", ");
    p.value(s.displacement);
    p.text("}");
}

template <class Printer, class T>
void write_layout(Printer& p, const se3::twist<T>& t) {
    p.text("se3::twist{");
    write_layout(p, t.linear);
    p.text(", ");
    write_layout(p, t.angular);
    p.text("}");
}

// Writes to a std::format or fmt context, each component through Formatter, which parsed the spec.
template <class Formatter, class Context>
struct format_printer {
    const Formatter& component_formatter;
    Context& context;

    void text(std::string_view ascii) {
        auto out = context.out();
        for (char c : ascii) *out++ = static_cast<typename Context::char_type>(c);
        context.advance_to(out);
    }
    template <class T>
    void value(const T& component) {
        context.advance_to(component_formatter.format(component, context));
    }
};

// The work of value_formatter::format (below): the layout of value, each component through
// component_formatter, which parsed the spec.
template <class ComponentFormatter, class Value, class Context>
auto format_value(const ComponentFormatter& component_formatter, const Value& value,
                  Context& context) {
    format_printer<ComponentFormatter, Context> printer{component_formatter, context};
    write_layout(printer, value);
    return context.out();
}

// The work of name_formatter::format (below): the name of a sequence or frame through
// string_formatter, the formatter of std::basic_string_view<CharT>, so string specs such as width
// and fill apply.
template <class StringFormatter, class Enum, class Context>
auto format_name(const StringFormatter& string_formatter, Enum value, Context& context) {
    using CharT = typename Context::char_type;
    constexpr std::size_t longest = 16;  // "intrinsic" and "extrinsic" have 9 letters
    const std::string_view ascii = spelling(value);
    const std::size_t length = ascii.size() < longest ? ascii.size() : longest;
    CharT name[longest]{};
    for (std::size_t i = 0; i < length; ++i) name[i] = static_cast<CharT>(ascii[i]);
    return string_formatter.format(std::basic_string_view<CharT>(name, length), context);
}

}  // namespace detail
}  // inline namespace isa_...

// The bases of the std::formatter and fmt::formatter specializations for quat's types (io.hpp,
// interop/fmt.hpp). Those specializations cannot be keyed: std::formatter<vec3<double>, char> is
// named by the standard's template and an unkeyed value type, so it is one class in the whole
// program whichever -m flags a unit is built with. Derived from a keyed class, it would have a
// different base in each instruction set, one definition broken by construction. So the bases live
// outside the key too and, like the value types' own members, their member functions are always
// inlined: no copy of them is emitted for the linker to share between units, and what each unit
// inlines only calls its own key's detail::format_value or detail::format_name. What the key cannot
// cover, as for std::vector<vec3<float>>: the functions std::format and fmt instantiate for a quat
// type (fmt's format_custom_arg, into which these calls are inlined) are theirs, unkeyed, and the
// linker keeps one copy of each for the whole program.

/// The formatter of a quat value type for std::format and fmt, the base of their specializations:
/// ComponentFormatter, the scalar's own formatter, parses the spec once and formats every
/// component with it. Users need not name it.
template <class Value, class ComponentFormatter>
struct value_formatter {
    ComponentFormatter component_formatter;  ///< The scalar's formatter, holding the parsed spec.

    /// Parses the spec as the scalar's formatter does ("{:.3f}", "{:e}", "{:>8}").
    template <class ParseContext>
    [[gnu::always_inline]] constexpr auto parse(ParseContext& context) {
        return component_formatter.parse(context);
    }
    /// Writes value's layout (io.hpp), each component with the parsed spec.
    template <class FormatContext>
    [[gnu::always_inline]] auto format(const Value& value, FormatContext& context) const {
        return detail::format_value(component_formatter, value, context);
    }
};

/// The formatter of sequence and frame for std::format and fmt, the base of their
/// specializations: the name through StringFormatter, the formatter of std::basic_string_view of
/// the context's characters. Users need not name it.
template <class Enum, class StringFormatter>
struct name_formatter {
    StringFormatter string_formatter;  ///< The string's formatter, holding the parsed spec.

    /// Parses the spec as a string's (width, fill, alignment).
    template <class ParseContext>
    [[gnu::always_inline]] constexpr auto parse(ParseContext& context) {
        return string_formatter.parse(context);
    }
    /// Writes the name, e.g. zyx or intrinsic, with the parsed spec.
    template <class FormatContext>
    [[gnu::always_inline]] auto format(Enum value, FormatContext& context) const {
        return detail::format_name(string_formatter, value, context);
    }
};

}  // namespace quat

#endif  // QUAT_DETAIL_PRINT_LAYOUT_HPP_INCLUDED
