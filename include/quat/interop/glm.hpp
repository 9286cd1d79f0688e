// Opt-in conversions between quat and GLM (not included by quat.hpp; needs GLM's headers).
// GLM's conventions: glm::qua is Hamilton with q v q* like quat, so values carry over unchanged;
// only the layout differs (GLM stores x, y, z, w and glm::mat3 is column-major, m[col][row]).
#ifndef QUAT_INTEROP_GLM_HPP_INCLUDED
#define QUAT_INTEROP_GLM_HPP_INCLUDED

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "../quaternion.hpp"
#include "../rigid/homogeneous_matrix.hpp"
#include "../rotation_matrix.hpp"
#include "../vec3.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
/// The same quaternion as glm::qua: components copied by name (w to w, ...), so the result does not
/// depend on GLM's storage order or on GLM_FORCE_QUAT_DATA_WXYZ.
template <class T>
[[nodiscard]] glm::qua<T, glm::defaultp> to_glm(const quaternion<T>& q) noexcept {
    glm::qua<T, glm::defaultp> out;
    out.w = q.w;
    out.x = q.x;
    out.y = q.y;
    out.z = q.z;
    return out;
}

/// The same quaternion from a glm::qua, components copied by name.
template <class T, glm::qualifier Q>
[[nodiscard]] quaternion<T> from_glm(const glm::qua<T, Q>& q) noexcept {
    return {q.w, q.x, q.y, q.z};
}

/// The same matrix as glm::mat3: element (row, col) goes to GLM's column-major m[col][row], so
/// glm_matrix * glm_vector equals rotate(m, v).
template <class T>
[[nodiscard]] glm::mat<3, 3, T, glm::defaultp> to_glm(const rotation_matrix<T>& m) noexcept {
    glm::mat<3, 3, T, glm::defaultp> out(T(1));
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) out[col][row] = m(row, col);
    return out;
}

/// The same matrix from a glm::mat3 (column-major m[col][row]).
template <class T, glm::qualifier Q>
[[nodiscard]] rotation_matrix<T> from_glm(const glm::mat<3, 3, T, Q>& m) noexcept {
    rotation_matrix<T> out{};
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) out(row, col) = m[col][row];
    return out;
}

/// The same matrix as glm::mat4: element (row, col) goes to m[col][row], so glm_matrix *
/// glm::vec4(p, 1) equals (transform(m, p), 1).
template <class T>
[[nodiscard]] glm::mat<4, 4, T, glm::defaultp> to_glm(const homogeneous_matrix<T>& m) noexcept {
    glm::mat<4, 4, T, glm::defaultp> out(T(1));
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) out[col][row] = m(row, col);
    return out;
}

/// The same matrix from a glm::mat4 (column-major m[col][row]).
template <class T, glm::qualifier Q>
[[nodiscard]] homogeneous_matrix<T> from_glm(const glm::mat<4, 4, T, Q>& m) noexcept {
    homogeneous_matrix<T> out{};
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) out(row, col) = m[col][row];
    return out;
}

/// The same vector as glm::vec3.
template <class T>
[[nodiscard]] glm::vec<3, T, glm::defaultp> to_glm(const vec3<T>& v) noexcept {
    return glm::vec<3, T, glm::defaultp>(v.x, v.y, v.z);
}

/// The same vector from a glm::vec3.
template <class T, glm::qualifier Q>
[[nodiscard]] vec3<T> from_glm(const glm::vec<3, T, Q>& v) noexcept {
    return {v.x, v.y, v.z};
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_INTEROP_GLM_HPP_INCLUDED
