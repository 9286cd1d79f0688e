// Reading printed quat values back, for the printing tests (io.hpp, std::format, fmt).
#pragma once

#include <locale>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <quat/quat.hpp>

#include "random.hpp"

namespace quat::test {

/// The numbers in text, which must match pattern: each '#' in it stands for one number (read with
/// >> in the classic locale), every other character must appear as is. Empty on any mismatch.
template <class T>
std::optional<std::vector<T>> read_back(const std::string& text, std::string_view pattern) {
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    std::vector<T> numbers;
    for (char expected : pattern) {
        if (expected == '#') {
            T value{};
            if (!(in >> value)) return std::nullopt;
            numbers.push_back(value);
        } else if (in.get() != std::istringstream::traits_type::to_int_type(expected)) {
            return std::nullopt;
        }
    }
    if (in.peek() != std::istringstream::traits_type::eof()) return std::nullopt;
    return numbers;
}

/// The components of each type in the order they are printed, with the pattern of their text.
/// (Not named components: support/bspline_checks.hpp's quat::test::components of a vec3, a
/// std::array, would make calls ambiguous where both headers are in one translation unit, as in a
/// unity build.)
/// @{
template <class T>
std::vector<T> printed_components(const vec3<T>& v) {
    return {v.x, v.y, v.z};
}
template <class T>
std::vector<T> printed_components(const quaternion<T>& q) {
    return {q.w, q.x, q.y, q.z};
}
template <class T>
std::vector<T> printed_components(const rotation_matrix<T>& m) {
    return {m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2)};
}
template <class T>
std::vector<T> printed_components(const axis_angle<T>& rotation) {
    return {rotation.axis.x, rotation.axis.y, rotation.axis.z, rotation.angle};
}
template <class T, sequence S, frame F>
std::vector<T> printed_components(const euler<T, S, F>& e) {
    return {e[0], e[1], e[2]};
}

inline constexpr std::string_view vec3_pattern = "vec3{#, #, #}";
inline constexpr std::string_view quaternion_pattern = "quaternion{#, #, #, #}";
inline constexpr std::string_view matrix_pattern =
    "rotation_matrix{{#, #, #}, {#, #, #}, {#, #, #}}";
inline constexpr std::string_view axis_angle_pattern = "axis_angle{vec3{#, #, #}, #}";
inline constexpr std::string_view euler_pattern = "euler<yxy, extrinsic>{#, #, #}";
/// @}

/// Values that use every digit of T: random numbers of magnitude about `scale`, divided by 7 in T.
template <class T>
struct awkward_values {
    random_rotations random{};

    T next_scalar(double scale) { return random.uniform<T>(-scale, scale) / T(7); }
    vec3<T> next_vec3(double scale) {
        return {next_scalar(scale), next_scalar(scale), next_scalar(scale)};
    }
    quaternion<T> next_quaternion(double scale) {
        return {next_scalar(scale), next_scalar(scale), next_scalar(scale), next_scalar(scale)};
    }
    rotation_matrix<T> next_matrix(double scale) {
        const vec3<T> r0 = next_vec3(scale), r1 = next_vec3(scale), r2 = next_vec3(scale);
        return rotation_matrix<T>::from_rows(r0, r1, r2);
    }
    axis_angle<T> next_axis_angle(double scale) { return {next_vec3(scale), next_scalar(scale)}; }
    euler<T, sequence::yxy, frame::extrinsic> next_euler(double scale) {
        return {next_scalar(scale), next_scalar(scale), next_scalar(scale)};
    }
};

/// Magnitudes from tiny to huge that T holds as normal numbers.
inline constexpr double scales[] = {1e-30, 1e-5, 1, 1e5, 1e30};

}  // namespace quat::test
