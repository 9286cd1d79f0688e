// The three libraries behind one interface, so every measurement runs the same loop on each.
// Each adapter converts the tool's plain arrays (scalar-first quaternions) to the library's types.
#pragma once

#include <array>
#include <optional>

#include <Eigen/Geometry>
#include <glm/ext/quaternion_exponential.hpp>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <quat/quat.hpp>

#include "reference.hpp"

namespace accuracy {

/// Coordinate-axis indices (0 = x, 1 = y, 2 = z) of a quat Euler sequence.
constexpr std::array<int, 3> axes_of(quat::sequence s) {
    switch (s) {
        case quat::sequence::xyz:
            return {0, 1, 2};
        case quat::sequence::xzy:
            return {0, 2, 1};
        case quat::sequence::yxz:
            return {1, 0, 2};
        case quat::sequence::yzx:
            return {1, 2, 0};
        case quat::sequence::zxy:
            return {2, 0, 1};
        case quat::sequence::zyx:
            return {2, 1, 0};
        case quat::sequence::xyx:
            return {0, 1, 0};
        case quat::sequence::xzx:
            return {0, 2, 0};
        case quat::sequence::yxy:
            return {1, 0, 1};
        case quat::sequence::yzy:
            return {1, 2, 1};
        case quat::sequence::zxz:
            return {2, 0, 2};
        case quat::sequence::zyz:
            return {2, 1, 2};
    }
    return {0, 0, 0};
}

struct quat_library {
    static constexpr const char* name = "quat";
    template <class T>
    static quat::quaternion<T> in(const q4<T>& q) {
        return {q[0], q[1], q[2], q[3]};
    }
    template <class T>
    static q4<T> out(const quat::quaternion<T>& q) {
        return {q.w, q.x, q.y, q.z};
    }

    template <class T>
    static q4<T> matrix_round_trip(const q4<T>& q) {
        return out(quat::to_quaternion(quat::to_matrix(in(q))));
    }
    template <class T>
    static q4<T> normalize(const q4<T>& q) {
        return out(quat::normalize(in(q)));
    }
    template <class T>
    static q4<T> slerp(const q4<T>& a, const q4<T>& b, T t) {
        return out(quat::slerp(in(a), in(b), t));
    }
    template <class T>
    static q4<T> exp(const v3<T>& v) {
        return out(quat::from_rotation_vector(quat::vec3<T>{v[0], v[1], v[2]}));
    }
    template <class T>
    static v3<T> log(const q4<T>& q) {
        const quat::vec3<T> v = quat::to_rotation_vector(in(q));
        return {v.x, v.y, v.z};
    }
    template <class T>
    static v3<T> rotate(const q4<T>& q, const v3<T>& v) {
        const quat::vec3<T> r = quat::rotate(in(q), quat::vec3<T>{v[0], v[1], v[2]});
        return {r.x, r.y, r.z};
    }
    /// Euler -> quaternion -> Euler in convention (S, F); always supported.
    template <class T, quat::sequence S, quat::frame F>
    static std::optional<v3<T>> euler_round_trip(const v3<T>& a) {
        const quat::euler<T, S, F> e{a[0], a[1], a[2]};
        const quat::euler<T, S, F> back = quat::to_euler<S, F>(quat::to_quaternion(e));
        return v3<T>{back[0], back[1], back[2]};
    }
};

// GLM: qua<T>(w, x, y, z) is scalar first; Hamilton product; mat3_cast/quat_cast act on column
// vectors like ours. GLM's Euler angles are (pitch, yaw, roll) = angles about (x, y, z) with q =
// q_z(roll) q_y(yaw) q_x(pitch): our intrinsic zyx {roll, yaw, pitch} = extrinsic xyz {pitch, yaw,
// roll}.
struct glm_library {
    static constexpr const char* name = "GLM";
    template <class T>
    static glm::qua<T> in(const q4<T>& q) {
        return glm::qua<T>(q[0], q[1], q[2], q[3]);
    }
    template <class T>
    static q4<T> out(const glm::qua<T>& q) {
        return {q.w, q.x, q.y, q.z};
    }

    template <class T>
    static q4<T> matrix_round_trip(const q4<T>& q) {
        return out(glm::quat_cast(glm::mat3_cast(in(q))));
    }
    template <class T>
    static q4<T> normalize(const q4<T>& q) {
        return out(glm::normalize(in(q)));
    }
    template <class T>
    static q4<T> slerp(const q4<T>& a, const q4<T>& b, T t) {
        return out(glm::slerp(in(a), in(b), t));
    }
    /// GLM's exp of the pure quaternion (0, v/2) is the rotation by |v| about v.
    template <class T>
    static q4<T> exp(const v3<T>& v) {
        return out(glm::exp(glm::qua<T>(T(0), v[0] / 2, v[1] / 2, v[2] / 2)));
    }
    /// GLM's log of a unit quaternion is (0, half the rotation vector).
    template <class T>
    static v3<T> log(const q4<T>& q) {
        const glm::qua<T> l = glm::log(in(q));
        return {2 * l.x, 2 * l.y, 2 * l.z};
    }
    template <class T>
    static v3<T> rotate(const q4<T>& q, const v3<T>& v) {
        const glm::vec<3, T> r = in(q)*glm::vec<3, T>(v[0], v[1], v[2]);
        return {r.x, r.y, r.z};
    }
    template <class T, quat::sequence S, quat::frame F>
    static std::optional<v3<T>> euler_round_trip(const v3<T>& a) {
        constexpr bool zyx_intrinsic = S == quat::sequence::zyx && F == quat::frame::intrinsic;
        constexpr bool xyz_extrinsic = S == quat::sequence::xyz && F == quat::frame::extrinsic;
        if constexpr (zyx_intrinsic || xyz_extrinsic) {
            // (pitch, yaw, roll) = angles about x, y, z.
            const glm::vec<3, T> pyr =
                zyx_intrinsic ? glm::vec<3, T>(a[2], a[1], a[0]) : glm::vec<3, T>(a[0], a[1], a[2]);
            const glm::vec<3, T> back = glm::eulerAngles(glm::qua<T>(pyr));
            if (zyx_intrinsic) return v3<T>{back.z, back.y, back.x};
            return v3<T>{back.x, back.y, back.z};
        } else {
            return std::nullopt;
        }
    }
};

// Eigen: Quaternion(w, x, y, z) is scalar first (stored xyzw); Hamilton product; matrices act on
// column vectors. Matrix3::eulerAngles(i, j, k) returns (a0, a1, a2) with R = R_i(a0) R_j(a1)
// R_k(a2), i.e. our intrinsic ijk; our extrinsic ijk {a0, a1, a2} is Eigen's (k, j, i) with (a2,
// a1, a0).
struct eigen_library {
    static constexpr const char* name = "Eigen";
    template <class T>
    static Eigen::Quaternion<T> in(const q4<T>& q) {
        return Eigen::Quaternion<T>(q[0], q[1], q[2], q[3]);
    }
    template <class T>
    static q4<T> out(const Eigen::Quaternion<T>& q) {
        return {q.w(), q.x(), q.y(), q.z()};
    }
    template <class T>
    static Eigen::Matrix<T, 3, 1> axis(int i) {
        return Eigen::Matrix<T, 3, 1>::Unit(i);
    }

    template <class T>
    static q4<T> matrix_round_trip(const q4<T>& q) {
        return out(Eigen::Quaternion<T>(in(q).toRotationMatrix()));
    }
    template <class T>
    static q4<T> normalize(const q4<T>& q) {
        return out(in(q).normalized());
    }
    template <class T>
    static q4<T> slerp(const q4<T>& a, const q4<T>& b, T t) {
        return out(in(a).slerp(t, in(b)));
    }
    /// Eigen has no exp map on vectors; AngleAxis(|v|, v/|v|) is how its users write it.
    template <class T>
    static q4<T> exp(const v3<T>& v) {
        const Eigen::Matrix<T, 3, 1> w(v[0], v[1], v[2]);
        const T angle = w.norm();
        if (angle == T(0)) return {1, 0, 0, 0};
        return out(Eigen::Quaternion<T>(Eigen::AngleAxis<T>(angle, w / angle)));
    }
    template <class T>
    static v3<T> log(const q4<T>& q) {
        const Eigen::AngleAxis<T> aa(in(q));
        const Eigen::Matrix<T, 3, 1> v = aa.angle() * aa.axis();
        return {v.x(), v.y(), v.z()};
    }
    template <class T>
    static v3<T> rotate(const q4<T>& q, const v3<T>& v) {
        const Eigen::Matrix<T, 3, 1> r = in(q)*Eigen::Matrix<T, 3, 1>(v[0], v[1], v[2]);
        return {r.x(), r.y(), r.z()};
    }
    template <class T, quat::sequence S, quat::frame F>
    static std::optional<v3<T>> euler_round_trip(const v3<T>& a) {
        constexpr std::array<int, 3> ax = axes_of(S);
        const Eigen::Quaternion<T> q0(Eigen::AngleAxis<T>(a[0], axis<T>(ax[0])));
        const Eigen::Quaternion<T> q1(Eigen::AngleAxis<T>(a[1], axis<T>(ax[1])));
        const Eigen::Quaternion<T> q2(Eigen::AngleAxis<T>(a[2], axis<T>(ax[2])));
        if constexpr (F == quat::frame::intrinsic) {
            const Eigen::Matrix<T, 3, 1> e =
                (q0 * q1 * q2).toRotationMatrix().eulerAngles(ax[0], ax[1], ax[2]);
            return v3<T>{e[0], e[1], e[2]};
        } else {
            const Eigen::Matrix<T, 3, 1> e =
                (q2 * q1 * q0).toRotationMatrix().eulerAngles(ax[2], ax[1], ax[0]);
            return v3<T>{e[2], e[1], e[0]};
        }
    }
};

}  // namespace accuracy
