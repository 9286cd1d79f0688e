// Hostile inputs for the opt-in estimation families (lie/so3.hpp, lie/se3.hpp,
// lie/geodesic_mean.hpp, registration/align_points.hpp, registration/hand_eye.hpp): NaN, +Inf and
// -Inf in every component of every argument of every public overload, for float and double, each
// checked against its doc comment, as test_hostile_inputs.cpp does for quat.hpp. Where a doc says
// nothing of non-finite input, docs/api.md's promise holds: a non-finite component in the result.
// Jacobians are requested too, so that their code runs on the bad values (under the sanitizers of
// the CI presets), and the value returned with them is checked as the value without them.
#include <cstddef>
#include <string>
#include <vector>

#include <quat/lie/geodesic_mean.hpp>
#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>
#include <quat/quat.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>

#include "support/catch.hpp"
#include "support/hostile.hpp"

namespace test_hostile_estimation {

namespace {

using namespace quat::test::hostile;  // NOLINT(google-build-using-namespace): the harness
using quat::matrix;
using quat::se3::twist;

template <class T>
twist<T> good_twist() {
    return {{T(0.4), T(-0.1), T(0.3)}, {T(0.2), T(0.5), T(-0.3)}};
}

#ifdef NDEBUG
constexpr bool debug_checks = false;
#else
constexpr bool debug_checks = true;  // a broken precondition stops the program
#endif

// The component index in for_each_bad's label "name[i]=value".
int component_of(const std::string& where) { return std::stoi(where.substr(where.rfind('[') + 1)); }

template <class T>
using matrix3 = matrix<T, 3, 3>;
template <class T>
using matrix6 = matrix<T, 6, 6>;

}  // namespace

// ======================= lie/so3.hpp =======================

HOSTILE("so3 of a tangent vector", "so3") {
    using T = TestType;
    const good<T> g;
    for_each_bad<T>("w", g.v, [&](const vec3<T>& w, const std::string& where) {
        EXPECT_NONFINITE("so3::hat with " << where, quat::so3::hat(w));
        EXPECT_NONFINITE("so3::right_jacobian with " << where, quat::so3::right_jacobian(w));
        EXPECT_NONFINITE("so3::left_jacobian with " << where, quat::so3::left_jacobian(w));
        EXPECT_NONFINITE("so3::right_jacobian_inverse with " << where,
                         quat::so3::right_jacobian_inverse(w));
        EXPECT_NONFINITE("so3::left_jacobian_inverse with " << where,
                         quat::so3::left_jacobian_inverse(w));
        matrix3<T> j{}, d_x{}, d_w{};
        // exp's doc: "NaN in w gives NaN"; an infinite w is outside "any finite w".
        if (std::isnan(w.x) || std::isnan(w.y) || std::isnan(w.z)) {
            EXPECT_ALL_NAN("so3::exp (doc: NaN in w gives NaN) with " << where, quat::so3::exp(w));
        }
        EXPECT_NONFINITE("so3::exp with " << where, quat::so3::exp(w));
        EXPECT_NONFINITE("so3::exp and its Jacobian with " << where, quat::so3::exp(w, &j));
        EXPECT_NONFINITE("so3::plus with " << where, quat::so3::plus(g.q, w));
        EXPECT_NONFINITE("so3::plus and its Jacobians with " << where,
                         quat::so3::plus(g.q, w, &d_x, &d_w));
        EXPECT_NONFINITE("so3::plus_left with " << where, quat::so3::plus_left(g.q, w));
        EXPECT_NONFINITE("so3::plus_left and its Jacobians with " << where,
                         quat::so3::plus_left(g.q, w, &d_x, &d_w));
        EXPECT_NONFINITE("so3::act with v " << where, quat::so3::act(g.q, w));
        EXPECT_NONFINITE("so3::act and its Jacobians with v " << where,
                         quat::so3::act(g.q, w, &d_x, &d_w));
    });
    // vee reads the skew part (m - m^T) / 2: the diagonal does not enter.
    for_each_bad<T>("m", quat::so3::hat(g.v), [&](const matrix3<T>& m, const std::string& where) {
        if (component_of(where) % 4 != 0)
            EXPECT_NONFINITE("so3::vee with " << where, quat::so3::vee(m));
    });
}

HOSTILE("so3 of rotations", "so3") {
    using T = TestType;
    const good<T> g;
    matrix3<T> d_a{}, d_b{};
    for_each_bad<T>("q", g.q, [&](const quaternion<T>& q, const std::string& where) {
        EXPECT_NONFINITE("so3::adjoint with " << where, quat::so3::adjoint(q));
        EXPECT_NONFINITE("so3::log with " << where, quat::so3::log(q));
        EXPECT_NONFINITE("so3::log and its Jacobian with " << where, quat::so3::log(q, &d_a));
        EXPECT_NONFINITE("so3::inverse with " << where, quat::so3::inverse(q));
        EXPECT_NONFINITE("so3::inverse and its Jacobian with " << where,
                         quat::so3::inverse(q, &d_a));
        EXPECT_NONFINITE("so3::act with q " << where, quat::so3::act(q, g.v));
        EXPECT_NONFINITE("so3::act and its Jacobians with q " << where,
                         quat::so3::act(q, g.v, &d_a, &d_b));
        EXPECT_NONFINITE("so3::plus with x " << where, quat::so3::plus(q, g.v));
        EXPECT_NONFINITE("so3::plus and its Jacobians with x " << where,
                         quat::so3::plus(q, g.v, &d_a, &d_b));
        EXPECT_NONFINITE("so3::plus_left with x " << where, quat::so3::plus_left(q, g.v));
        EXPECT_NONFINITE("so3::plus_left and its Jacobians with x " << where,
                         quat::so3::plus_left(q, g.v, &d_b, &d_a));
        // Each binary operation with the bad rotation first and second.
        EXPECT_NONFINITE("so3::compose(q, q2) with " << where, quat::so3::compose(q, g.q2));
        EXPECT_NONFINITE("so3::compose(q2, q) and its Jacobians with " << where,
                         quat::so3::compose(g.q2, q, &d_a, &d_b));
        EXPECT_NONFINITE("so3::between(q, q2) with " << where, quat::so3::between(q, g.q2));
        EXPECT_NONFINITE("so3::between(q2, q) and its Jacobians with " << where,
                         quat::so3::between(g.q2, q, &d_a, &d_b));
        EXPECT_NONFINITE("so3::minus(q, q2) with " << where, quat::so3::minus(q, g.q2));
        EXPECT_NONFINITE("so3::minus(q2, q) and its Jacobians with " << where,
                         quat::so3::minus(g.q2, q, &d_a, &d_b));
        EXPECT_NONFINITE("so3::minus_left(q, q2) with " << where, quat::so3::minus_left(q, g.q2));
        EXPECT_NONFINITE("so3::minus_left(q2, q) and its Jacobians with " << where,
                         quat::so3::minus_left(g.q2, q, &d_a, &d_b));
    });
}

// ======================= lie/se3.hpp =======================

HOSTILE("se3 of a twist", "se3") {
    using T = TestType;
    const good<T> g;
    matrix6<T> j{}, d_x{};
    for_each_bad<T>("t", good_twist<T>(), [&](const twist<T>& t, const std::string& where) {
        EXPECT_NONFINITE("twist + with " << where, t + good_twist<T>());
        EXPECT_NONFINITE("twist - with " << where, good_twist<T>() - t);
        EXPECT_NONFINITE("-twist with " << where, -t);
        EXPECT_NONFINITE("twist * s with " << where, t * T(2));
        EXPECT_NONFINITE("s * twist with " << where, T(2) * t);
        EXPECT_NONFINITE("se3::to_vector with " << where, quat::se3::to_vector(t));
        EXPECT_NONFINITE("se3::hat with " << where, quat::se3::hat(t));
        EXPECT_NONFINITE("se3::left_jacobian with " << where, quat::se3::left_jacobian(t));
        EXPECT_NONFINITE("se3::right_jacobian with " << where, quat::se3::right_jacobian(t));
        EXPECT_NONFINITE("se3::left_jacobian_inverse with " << where,
                         quat::se3::left_jacobian_inverse(t));
        EXPECT_NONFINITE("se3::right_jacobian_inverse with " << where,
                         quat::se3::right_jacobian_inverse(t));
        EXPECT_ALL_NAN("se3::exp (doc: NaN in every component) with " << where, quat::se3::exp(t));
        EXPECT_ALL_NAN("se3::exp and its Jacobian with " << where, quat::se3::exp(t, &j));
        EXPECT_NONFINITE("se3::plus with " << where, quat::se3::plus(g.dq, t));
        EXPECT_NONFINITE("se3::plus and its Jacobians with " << where,
                         quat::se3::plus(g.dq, t, &d_x, &j));
        EXPECT_NONFINITE("se3::plus_left with " << where, quat::se3::plus_left(g.dq, t));
        EXPECT_NONFINITE("se3::plus_left and its Jacobians with " << where,
                         quat::se3::plus_left(g.dq, t, &d_x, &j));
    });
    for_each_bad<T>("v", quat::se3::to_vector(good_twist<T>()),
                    [&](const matrix<T, 6, 1>& v, const std::string& where) {
                        EXPECT_NONFINITE("se3::to_twist with " << where, quat::se3::to_twist(v));
                    });
    for_each_bad<T>("m", quat::se3::hat(good_twist<T>()),
                    [&](const matrix<T, 4, 4>& m, const std::string& where) {
                        // vee reads the skew part of the upper-left 3 x 3 block and the last
                        // column above the corner: not the diagonal nor the last row.
                        const int i = component_of(where);
                        if (i % 5 != 0 && i < 12)
                            EXPECT_NONFINITE("se3::vee with " << where, quat::se3::vee(m));
                    });
}

HOSTILE("se3 of rigid motions", "se3") {
    using T = TestType;
    const good<T> g;
    matrix6<T> d_a{}, d_b{};
    matrix<T, 3, 6> d_p{};
    matrix3<T> d_v{};
    for_each_bad<T>("x", g.dq, [&](const dual_quaternion<T>& x, const std::string& where) {
        if (component_of(where) < 4)  // the rotation does not read the dual part
            EXPECT_NONFINITE("so3::adjoint of the rotation with " << where,
                             quat::so3::adjoint(x.real));
        EXPECT_NONFINITE("se3::adjoint with " << where, quat::se3::adjoint(x));
        EXPECT_NONFINITE("se3::inverse with " << where, quat::se3::inverse(x));
        EXPECT_NONFINITE("se3::inverse and its Jacobian with " << where,
                         quat::se3::inverse(x, &d_a));
        EXPECT_NONFINITE("se3::log with " << where, quat::se3::log(x));
        EXPECT_NONFINITE("se3::log and its Jacobian with " << where, quat::se3::log(x, &d_a));
        EXPECT_NONFINITE("se3::act with " << where, quat::se3::act(x, g.v));
        EXPECT_NONFINITE("se3::act and its Jacobians with " << where,
                         quat::se3::act(x, g.v, &d_p, &d_v));
        EXPECT_NONFINITE("se3::plus with x " << where, quat::se3::plus(x, good_twist<T>()));
        EXPECT_NONFINITE("se3::plus_left with x " << where,
                         quat::se3::plus_left(x, good_twist<T>(), &d_b, &d_a));
        EXPECT_NONFINITE("se3::compose(x, dq2) with " << where, quat::se3::compose(x, g.dq2));
        EXPECT_NONFINITE("se3::compose(dq2, x) and its Jacobians with " << where,
                         quat::se3::compose(g.dq2, x, &d_a, &d_b));
        EXPECT_NONFINITE("se3::between(x, dq2) with " << where, quat::se3::between(x, g.dq2));
        EXPECT_NONFINITE("se3::between(dq2, x) and its Jacobians with " << where,
                         quat::se3::between(g.dq2, x, &d_a, &d_b));
        EXPECT_NONFINITE("se3::minus(x, dq2) with " << where, quat::se3::minus(x, g.dq2));
        EXPECT_NONFINITE("se3::minus(dq2, x) and its Jacobians with " << where,
                         quat::se3::minus(g.dq2, x, &d_a, &d_b));
        EXPECT_NONFINITE("se3::minus_left(x, dq2) with " << where, quat::se3::minus_left(x, g.dq2));
        EXPECT_NONFINITE("se3::minus_left(dq2, x) and its Jacobians with " << where,
                         quat::se3::minus_left(g.dq2, x, &d_a, &d_b));
    });
    for_each_bad<T>("p", g.v, [&](const vec3<T>& p, const std::string& where) {
        EXPECT_NONFINITE("se3::act with " << where, quat::se3::act(g.dq, p, &d_p, &d_v));
    });
    for_each_bad<T>("h", g.h, [&](const homogeneous_matrix<T>& h, const std::string& where) {
        EXPECT_NONFINITE("se3::log(homogeneous) with " << where, quat::se3::log(h));
        EXPECT_NONFINITE("se3::log(homogeneous) and its Jacobian with " << where,
                         quat::se3::log(h, &d_a));
    });
}

// ======================= lie/geodesic_mean.hpp =======================

HOSTILE("geodesic_mean", "geodesic_mean") {
    using T = TestType;
    const good<T> g;
    const std::vector<T> weights{T(1), T(2), T(0.5)};
    for_each_bad<T>("rotations[1]", g.q2, [&](const quaternion<T>& q, const std::string& where) {
        const std::vector<quaternion<T>> rotations{g.q, q, g.q3};
        EXPECT_ALL_NAN("geodesic_mean (doc: NaN for a NaN or infinite component) with " << where,
                       quat::geodesic_mean(rotations));
        EXPECT_ALL_NAN("weighted geodesic_mean with " << where,
                       quat::geodesic_mean(rotations, weights));
        EXPECT_EMPTY("try_geodesic_mean with " << where, quat::try_geodesic_mean(rotations));
        EXPECT_EMPTY("weighted try_geodesic_mean with " << where,
                     quat::try_geodesic_mean(rotations, weights));
    });
    for_each_bad<T>(
        "motions[1]", g.dq2, [&](const dual_quaternion<T>& x, const std::string& where) {
            const std::vector<dual_quaternion<T>> motions{g.dq, x, g.dq};
            EXPECT_ALL_NAN("geodesic_mean of motions with " << where, quat::geodesic_mean(motions));
            EXPECT_ALL_NAN("weighted geodesic_mean of motions with " << where,
                           quat::geodesic_mean(motions, weights));
            EXPECT_EMPTY("try_geodesic_mean of motions with " << where,
                         quat::try_geodesic_mean(motions));
            EXPECT_EMPTY("weighted try_geodesic_mean of motions with " << where,
                         quat::try_geodesic_mean(motions, weights));
        });
    const std::vector<quaternion<T>> rotations{g.q, g.q2, g.q3};
    const std::vector<dual_quaternion<T>> motions{g.dq, g.dq2, g.dq};
    for_each_bad<T>("weights[1]", weights[1], [&](T w, const std::string& where) {
        const std::vector<T> bad{T(1), w, T(0.5)};
        EXPECT_EMPTY("try_geodesic_mean with " << where, quat::try_geodesic_mean(rotations, bad));
        // A negative weight breaks the debug-checked precondition; unchecked, NaN.
        if (debug_checks && w < T(0)) return;
        EXPECT_ALL_NAN("geodesic_mean (doc: NaN for a NaN or infinite weight) with " << where,
                       quat::geodesic_mean(rotations, bad));
        EXPECT_ALL_NAN("geodesic_mean of motions with " << where,
                       quat::geodesic_mean(motions, bad));
        EXPECT_EMPTY("try_geodesic_mean of motions with " << where,
                     quat::try_geodesic_mean(motions, bad));
    });
}

// ======================= registration/align_points.hpp =======================

HOSTILE("align_points", "align_points") {
    using T = TestType;
    const good<T> g;
    const std::vector<vec3<T>> sources{g.v, g.v2, {T(1), T(0.25), T(-2)}, {T(-1), T(3), T(0.5)}};
    std::vector<vec3<T>> targets;
    for (const vec3<T>& s : sources) targets.push_back(quat::transform(g.dq, s));
    const std::vector<T> weights{T(1), T(2), T(0.5), T(1)};
    // The doc: a NaN or infinite component gives NaN in every component, rms NaN, unique false.
    const auto expect_nan = [](const auto& result, const std::string& what) {
        EXPECT_ALL_NAN(what, result);
        CHECK_FALSE(result.unique);
    };
    for (int side = 0; side < 2; ++side)
        for_each_bad<T>(side == 0 ? "targets[2]" : "sources[2]", targets[2],
                        [&](const vec3<T>& p, const std::string& where) {
                            std::vector<vec3<T>> t = targets, s = sources;
                            (side == 0 ? t : s)[2] = p;
                            expect_nan(quat::align_points(t, s), "align_points with " + where);
                            expect_nan(quat::align_points(t, s, weights),
                                       "weighted align_points with " + where);
                            expect_nan(quat::align_points_with_scale(t, s),
                                       "align_points_with_scale with " + where);
                            expect_nan(quat::align_points_with_scale(t, s, weights),
                                       "weighted align_points_with_scale with " + where);
                            EXPECT_EMPTY("try_align_points with " << where,
                                         quat::try_align_points(t, s));
                            EXPECT_EMPTY("weighted try_align_points with " << where,
                                         quat::try_align_points(t, s, weights));
                            EXPECT_EMPTY("try_align_points_with_scale with " << where,
                                         quat::try_align_points_with_scale(t, s));
                            EXPECT_EMPTY("weighted try_align_points_with_scale with " << where,
                                         quat::try_align_points_with_scale(t, s, weights));
                        });
    // The doc: unchecked, a negative, NaN or infinite weight gives the NaN result.
    for_each_bad<T>("weights[1]", weights[1], [&](T w, const std::string& where) {
        const std::vector<T> bad{T(1), w, T(0.5), T(1)};
        EXPECT_EMPTY("try_align_points with " << where,
                     quat::try_align_points(targets, sources, bad));
        EXPECT_EMPTY("try_align_points_with_scale with " << where,
                     quat::try_align_points_with_scale(targets, sources, bad));
        if (debug_checks) return;  // the precondition is debug-checked
        expect_nan(quat::align_points(targets, sources, bad), "align_points with " + where);
        expect_nan(quat::align_points_with_scale(targets, sources, bad),
                   "align_points_with_scale with " + where);
    });
}

// ======================= registration/hand_eye.hpp =======================

HOSTILE("hand_eye", "hand_eye") {
    using T = TestType;
    const good<T> g;
    // Three motion pairs that determine the mount X = dq: B_i = X^-1 A_i X.
    const std::vector<dual_quaternion<T>> a{g.dq2, quat::to_dual_quaternion(g.q3, g.v),
                                            quat::to_dual_quaternion(g.q4, g.v2)};
    std::vector<dual_quaternion<T>> b;
    for (const dual_quaternion<T>& m : a) b.push_back(quat::inverse(g.dq) * m * g.dq);
    for (int side = 0; side < 2; ++side)
        for_each_bad<T>(
            side == 0 ? "a[1]" : "b[1]", a[1],
            [&](const dual_quaternion<T>& m, const std::string& where) {
                std::vector<dual_quaternion<T>> ma = a, mb = b;
                (side == 0 ? ma : mb)[1] = m;
                for (const auto method :
                     {quat::hand_eye_method::daniilidis, quat::hand_eye_method::rotation_first}) {
                    const auto c = quat::hand_eye(ma, mb, method);
                    EXPECT_ALL_NAN("hand_eye (doc: NaN in every component) with " << where, c);
                    CHECK_FALSE(c.unique);
                    EXPECT_EMPTY("try_hand_eye with " << where, quat::try_hand_eye(ma, mb, method));
                }
            });
}

HOSTILE("hand_eye_from_poses", "hand_eye") {
    using T = TestType;
    const good<T> g;
    // Four hand poses and the target's poses S_j = X^-1 H_j^-1 W for X = dq, W = dq2.
    const std::vector<dual_quaternion<T>> hands{
        quat::to_dual_quaternion(g.q, g.v), quat::to_dual_quaternion(g.q2, g.v2),
        quat::to_dual_quaternion(g.q3, g.v), quat::to_dual_quaternion(g.q4, g.v2)};
    std::vector<dual_quaternion<T>> targets;
    for (const dual_quaternion<T>& h : hands)
        targets.push_back(quat::normalize(quat::inverse(h * g.dq) * g.dq2));
    for (int side = 0; side < 2; ++side)
        for_each_bad<T>(side == 0 ? "hands[1]" : "targets[1]", hands[1],
                        [&](const dual_quaternion<T>& m, const std::string& where) {
                            std::vector<dual_quaternion<T>> h = hands, s = targets;
                            (side == 0 ? h : s)[1] = m;
                            const auto r = quat::hand_eye_from_poses(h, s);
                            EXPECT_ALL_NAN(
                                "hand_eye_from_poses (doc: NaN in every component) with " << where,
                                r);
                            CHECK_FALSE(r.calibration.unique);
                            CHECK_FALSE(r.refined);
                            EXPECT_EMPTY("try_hand_eye_from_poses with " << where,
                                         quat::try_hand_eye_from_poses(h, s));
                        });
}

}  // namespace test_hostile_estimation
