// The two Lie groups `quat_accuracy --trajectory` measures B-splines on, as the measurement code
// of measure_trajectory_bspline.hpp reads them: the point and tangent types, right plus and minus
// in long double, the sample's value and rates as flat arrays, the first-order plus and the local
// tangent that forward-mode derivatives go through, the value's error against the product rule,
// and the control points of each sample class (as tests/test_so3_bspline_derivatives.cpp and
// tests/test_se3_bspline.cpp make them).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>
#include <quat/trajectory/se3_bspline.hpp>
#include <quat/trajectory/so3_bspline.hpp>

#include "support/bspline_reference.hpp"
#include "support/random.hpp"

namespace accuracy {
namespace trajectory {

using ld = long double;

constexpr double pi = 3.14159265358979323846;

/// SO(3): unit quaternions, rotation-vector tangents.
struct so3_kind {
    static constexpr std::size_t dim = 3;
    static constexpr const char* name = "so3_bspline";
    static constexpr const char* value_name = "R";
    static constexpr const char* rate_names[3] = {"ω", "ω′", "ω″"};
    template <class T>
    using point = quat::quaternion<T>;
    template <class T, int K>
    using spline = quat::so3_bspline<T, K>;
    using reference = quat::test::so3_reference<ld>;

    template <class S>
    static std::array<S, 3> flat(const quat::vec3<S>& v) {
        return {v.x, v.y, v.z};
    }
    static point<ld> plus(const point<ld>& x, const std::array<ld, 3>& d) {
        return x * quat::so3::exp(quat::vec3<ld>{d[0], d[1], d[2]});
    }
    static std::array<ld, 3> minus(const point<ld>& y, const point<ld>& x) {
        return flat(quat::so3::minus(y, x));
    }
    template <class Sample>
    static auto value(const Sample& s) {
        return s.rotation;
    }
    template <class Sample>
    static auto rates(const Sample& s) {
        return std::array{flat(s.angular_velocity), flat(s.angular_acceleration),
                          flat(s.angular_jerk)};
    }
    template <class S>
    static point<S> widen(const point<double>& q) {
        return {S(q.w), S(q.x), S(q.y), S(q.z)};
    }
    /// x (1, v / 2): the right plus to first order, v the forward-mode variables.
    template <class S>
    static point<S> first_order_plus(const point<S>& x, const S* v) {
        const S half(0.5);
        return x * point<S>{S(1), v[0] * half, v[1] * half, v[2] * half};
    }
    /// The tangent of value^-1 y to first order, value = y without its partials.
    template <class S>
    static std::array<S, 3> local_tangent(const point<S>& y) {
        const auto v = [](const S& s) { return S(s.value); };
        const point<S> local = conjugate(point<S>{v(y.w), v(y.x), v(y.y), v(y.z)}) * y;
        return {local.x * S(2), local.y * S(2), local.z * S(2)};
    }
    /// The angle between the value and the product rule's (reach, a length, is not read).
    template <class S>
    static double value_error(const point<S>& got, const point<ld>& want, ld /*reach*/) {
        return static_cast<double>(norm(quat::so3::minus(point<ld>(got), want)));
    }
    /// 1: rotations have no length.
    static ld reach(const std::vector<point<ld>>&) { return 1; }

    /// Random steps up to 1 rad with random signs; points within 1e-7 rad of the identity; steps
    /// of pi - 1e-2 rad.
    static std::vector<point<double>> points(quat::test::random_rotations& random, int kind,
                                             std::size_t count) {
        if (kind == 0) return quat::test::random_walk<double>(random, count, 1.0);
        std::vector<point<double>> out;
        if (kind == 1) {
            while (out.size() < count)
                out.push_back(from_rotation_vector(random.unit_vector<double>() *
                                                   random.uniform<double>(0, 1e-7)));
            return out;
        }
        out.push_back(random.unit_quaternion<double>());
        while (out.size() < count) {
            const quat::vec3<double> step = random.unit_vector<double>() * (pi - 1e-2);
            out.push_back(normalize(out.back() * from_rotation_vector(step)));
        }
        return out;
    }
};

/// SE(3): unit dual quaternions, twists (linear, angular).
struct se3_kind {
    static constexpr std::size_t dim = 6;
    static constexpr const char* name = "se3_bspline";
    static constexpr const char* value_name = "X";
    static constexpr const char* rate_names[3] = {"ξ", "ξ′", "ξ″"};
    template <class T>
    using point = quat::dual_quaternion<T>;
    template <class T, int K>
    using spline = quat::se3_bspline<T, K>;
    using reference = quat::test::se3_reference<ld>;

    template <class S>
    static std::array<S, 6> flat(const quat::se3::twist<S>& t) {
        return {t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z};
    }
    static point<ld> plus(const point<ld>& x, const std::array<ld, 6>& d) {
        return x * quat::se3::exp(quat::se3::twist<ld>{{d[0], d[1], d[2]}, {d[3], d[4], d[5]}});
    }
    static std::array<ld, 6> minus(const point<ld>& y, const point<ld>& x) {
        return flat(quat::se3::minus(y, x));
    }
    template <class Sample>
    static auto value(const Sample& s) {
        return s.motion;
    }
    template <class Sample>
    static auto rates(const Sample& s) {
        return std::array{flat(s.velocity), flat(s.acceleration), flat(s.jerk)};
    }
    template <class S>
    static point<S> widen(const point<double>& x) {
        return {so3_kind::widen<S>(x.real), so3_kind::widen<S>(x.dual)};
    }
    /// x ((1, omega / 2) + eps (0, rho / 2)), v = (rho, omega).
    template <class S>
    static point<S> first_order_plus(const point<S>& x, const S* v) {
        const S half(0.5), zero(0), one(1);
        return x * point<S>{{one, v[3] * half, v[4] * half, v[5] * half},
                            {zero, v[0] * half, v[1] * half, v[2] * half}};
    }
    template <class S>
    static std::array<S, 6> local_tangent(const point<S>& y) {
        const auto v = [](const quat::quaternion<S>& q) {
            return quat::quaternion<S>{S(q.w.value), S(q.x.value), S(q.y.value), S(q.z.value)};
        };
        const point<S> local = point<S>{conjugate(v(y.real)), conjugate(v(y.dual))} * y;
        const S two(2);
        return {local.dual.x * two, local.dual.y * two, local.dual.z * two,
                local.real.x * two, local.real.y * two, local.real.z * two};
    }
    /// The largest component of log(want^-1 got), relative to max(reach, |translation|): reach
    /// the largest translation among the set's control points, which the value's translation
    /// sums and whose own rounding is relative to them, not to the (possibly shorter) sum.
    template <class S>
    static double value_error(const point<S>& got, const point<ld>& want, ld reach) {
        ld error = 0;
        for (const ld c : flat(quat::se3::minus(point<ld>(got), want)))
            error = std::max(error, std::abs(c));
        return static_cast<double>(error / std::max(reach, norm(translation_of(want))));
    }
    /// max(1, the largest |translation| among the points).
    static ld reach(const std::vector<point<ld>>& points) {
        ld r = 1;
        for (const point<ld>& x : points) r = std::max(r, norm(translation_of(x)));
        return r;
    }

    /// X_(i+1) = X_i exp(step): rotation steps up to 1 rad and translation steps of about 1;
    /// steps below 1e-7 from the identity; rotation steps of pi - 1e-2 rad. Random signs.
    static std::vector<point<double>> points(quat::test::random_rotations& random, int kind,
                                             std::size_t count) {
        const double low = kind == 2 ? pi - 1e-2 : 0, high = kind == 0 ? 1 : kind == 1 ? 1e-7 : low;
        const double reach = kind == 1 ? 1e-7 : 1;
        std::vector<point<double>> out{kind == 1 ? point<double>::identity()
                                                 : random.rigid_motion<double>()};
        while (out.size() < count) {
            const quat::vec3<double> axis = random.unit_vector<double>();
            const double angle = random.uniform<double>(low, high);
            const quat::vec3<double> linear = random.vector<double>(reach);
            out.push_back(normalize(
                out.back() * quat::se3::exp(quat::se3::twist<double>{linear, axis * angle})));
        }
        for (point<double>& x : out)
            if (random.uniform<double>(0, 1) < 0.5) x = -x;
        return out;
    }
};

}  // namespace trajectory
}  // namespace accuracy
