// rotation_between (quat, glm::rotation, Eigen's FromTwoVectors) and look_rotation (quat,
// glm::quatLookAtRH): rotation angle to the high-precision reference, in eps. GLM wants unit
// vectors, so it gets normalize(v) as its users would write it; Eigen normalizes inside.
#pragma once

#include <cmath>
#include <utility>
#include <vector>

#include <glm/gtx/quaternion.hpp>

#include <quat/align.hpp>

#include "measure.hpp"

namespace accuracy {

/// a b - c d to real's precision even where the products cancel (a cross product of nearly
/// parallel or opposite vectors): each product as its rounded value plus the exact remainder from
/// fma. A product of two doubles has 106 bits; long double (the reference where __float128 is
/// missing, as with clang) keeps 64, which alone leaves 1e-5 rad of noise in such an axis.
inline real difference_of_products(real a, real b, real c, real d) {
    const real ab = a * b, cd = c * d;
    return (ab - cd) + (r_fma(a, b, -ab) - r_fma(c, d, -cd));
}

inline hv cross(const hv& a, const hv& b) {
    return {difference_of_products(a[1], b[2], a[2], b[1]),
            difference_of_products(a[2], b[0], a[0], b[2]),
            difference_of_products(a[0], b[1], a[1], b[0])};
}

/// Shortest-arc rotation from a to b: half angle from the chords |a^ + b^| = 2 cos and
/// |a^ - b^| = 2 sin, axis a x b.
inline hq reference_rotation_between(const hv& a, const hv& b) {
    const real na = norm(a), nb = norm(b);
    const hv ua{a[0] / na, a[1] / na, a[2] / na}, ub{b[0] / nb, b[1] / nb, b[2] / nb};
    const hv sum{ua[0] + ub[0], ua[1] + ub[1], ua[2] + ub[2]};
    const hv diff{ua[0] - ub[0], ua[1] - ub[1], ua[2] - ub[2]};
    const hv c = cross(a, b);
    const real s = norm(diff) / (2 * norm(c));
    return {norm(sum) / 2, s * c[0], s * c[1], s * c[2]};
}

/// The camera frame (right, up', back) of look_rotation, as a quaternion.
inline hq reference_look_rotation(const hv& f, const hv& up) {
    const hv c = cross(f, up);
    const real nc = norm(c), nf = norm(f);
    const hv x{c[0] / nc, c[1] / nc, c[2] / nc}, z{-f[0] / nf, -f[1] / nf, -f[2] / nf};
    const hv y{z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]};
    // Columns x, y, z; the quaternion from the largest of 4 w^2, 4 x^2, 4 y^2, 4 z^2.
    const real w4 = 1 + x[0] + y[1] + z[2], x4 = 1 + x[0] - y[1] - z[2],
               y4 = 1 - x[0] + y[1] - z[2], z4 = 1 - x[0] - y[1] + z[2];
    if (w4 >= x4 && w4 >= y4 && w4 >= z4) {
        const real w = r_sqrt(w4) / 2;
        return {w, (y[2] - z[1]) / (4 * w), (z[0] - x[2]) / (4 * w), (x[1] - y[0]) / (4 * w)};
    }
    if (x4 >= y4 && x4 >= z4) {
        const real s = r_sqrt(x4) / 2;
        return {(y[2] - z[1]) / (4 * s), s, (y[0] + x[1]) / (4 * s), (z[0] + x[2]) / (4 * s)};
    }
    if (y4 >= z4) {
        const real s = r_sqrt(y4) / 2;
        return {(z[0] - x[2]) / (4 * s), (y[0] + x[1]) / (4 * s), s, (z[1] + y[2]) / (4 * s)};
    }
    const real s = r_sqrt(z4) / 2;
    return {(x[1] - y[0]) / (4 * s), (z[0] + x[2]) / (4 * s), (z[1] + y[2]) / (4 * s), s};
}

/// Pairs of one family: 0 random directions, 1 at angle 10^-k, 2 at pi - 10^-k (k = 1..15);
/// lengths 10^e, e uniform in [-3, 3].
template <class T>
std::vector<std::pair<v3<T>, v3<T>>> direction_pairs(rng& g, int family, int count) {
    std::vector<std::pair<v3<T>, v3<T>>> out;
    for (int i = 0; i < count; ++i) {
        const v3<double> a = g.unit_vector();
        v3<double> b = g.unit_vector();
        if (family != 0) {
            const double delta = std::pow(10.0, -(1 + i % 15));
            const double angle = family == 1 ? delta : 3.141592653589793 - delta;
            const v3<double> r = g.unit_vector();  // axis a x r, turned in high precision
            const hv n{real(a[1] * r[2] - a[2] * r[1]), real(a[2] * r[0] - a[0] * r[2]),
                       real(a[0] * r[1] - a[1] * r[0])};
            const real nn = norm(n);
            const hq turn = exp_map(hv{angle * n[0] / nn, angle * n[1] / nn, angle * n[2] / nn});
            const hq moved = mul(mul(turn, hq{0, real(a[0]), real(a[1]), real(a[2])}), conj(turn));
            b = {double(moved[1]), double(moved[2]), double(moved[3])};
        }
        const double la = std::pow(10.0, g.uniform(-3, 3)), lb = std::pow(10.0, g.uniform(-3, 3));
        out.emplace_back(narrow<T>(v3<double>{a[0] * la, a[1] * la, a[2] * la}),
                         narrow<T>(v3<double>{b[0] * lb, b[1] * lb, b[2] * lb}));
    }
    return out;
}

enum class align_library { quat, glm, eigen };

template <class T>
q4<T> library_rotation_between(align_library lib, const v3<T>& a, const v3<T>& b) {
    if (lib == align_library::quat) {
        const quat::quaternion<T> q = quat::rotation_between(quat::vec3<T>{a[0], a[1], a[2]},
                                                             quat::vec3<T>{b[0], b[1], b[2]});
        return {q.w, q.x, q.y, q.z};
    }
    if (lib == align_library::glm) {
        using gv = glm::vec<3, T, glm::defaultp>;
        const glm::qua<T, glm::defaultp> q = glm::rotation(glm::normalize(gv(a[0], a[1], a[2])),
                                                           glm::normalize(gv(b[0], b[1], b[2])));
        return {q.w, q.x, q.y, q.z};
    }
    using ev = Eigen::Matrix<T, 3, 1>;
    const Eigen::Quaternion<T> q =
        Eigen::Quaternion<T>::FromTwoVectors(ev(a[0], a[1], a[2]), ev(b[0], b[1], b[2]));
    return {q.w(), q.x(), q.y(), q.z()};
}

template <class T>
q4<T> library_look_rotation(align_library lib, const v3<T>& f, const v3<T>& up) {
    if (lib == align_library::quat) {
        const quat::quaternion<T> q = quat::look_rotation(quat::vec3<T>{f[0], f[1], f[2]},
                                                          quat::vec3<T>{up[0], up[1], up[2]});
        return {q.w, q.x, q.y, q.z};
    }
    using gv = glm::vec<3, T, glm::defaultp>;
    const glm::qua<T, glm::defaultp> q =
        glm::quatLookAtRH(glm::normalize(gv(f[0], f[1], f[2])), gv(up[0], up[1], up[2]));
    return {q.w, q.x, q.y, q.z};
}

/// Rotation-angle error in eps over pairs, for rotation_between (look = false) or look_rotation.
template <class T>
error_stats measure_align(align_library lib, const std::vector<std::pair<v3<T>, v3<T>>>& pairs,
                          bool look) {
    error_stats s;
    for (const auto& [a, b] : pairs) {
        const hq ref = look ? reference_look_rotation(widen(a), widen(b))
                            : reference_rotation_between(widen(a), widen(b));
        const q4<T> got =
            look ? library_look_rotation(lib, a, b) : library_rotation_between(lib, a, b);
        if (s.add(in_eps<T>(rotation_angle_between(widen(got), ref))))
            s.worst_case = describe(a) + " " + describe(b);
    }
    return s;
}

}  // namespace accuracy
