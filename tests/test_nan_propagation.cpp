// NaN in, NaN out: every public function, given a NaN or an infinite component, returns something
// visibly bad (a NaN or infinite component, false, or an empty optional), never a finite value that
// looks like an answer. Each check names the function it covers.
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include <quat/lie/geodesic_mean.hpp>
#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>
#include <quat/quat.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>

#include "support/catch.hpp"

namespace test_nan_propagation {

namespace {

using quat::axis_angle;
using quat::dual_quaternion;
using quat::quaternion;
using quat::rotation_matrix;
using quat::sequence;
using quat::vec3;

template <class T>
bool bad(T x) {
    return !std::isfinite(x);
}
template <class T>
bool bad(const vec3<T>& v) {
    return bad(v.x) || bad(v.y) || bad(v.z);
}
template <class T>
bool bad(const quaternion<T>& q) {
    return bad(q.w) || bad(q.x) || bad(q.y) || bad(q.z);
}
template <class T>
bool bad(const rotation_matrix<T>& m) {
    for (int i = 0; i < 3; ++i)
        if (bad(quat::row(m, i))) return true;
    return false;
}
template <class T>
bool bad(const axis_angle<T>& a) {
    return bad(a.axis) || bad(a.angle);
}
template <class T>
bool bad(const quat::screw<T>& s) {
    return bad(s.direction) || bad(s.moment) || bad(s.angle) || bad(s.displacement);
}
template <class T, sequence S, quat::frame F>
bool bad(const quat::euler<T, S, F>& e) {
    return bad(e[0]) || bad(e[1]) || bad(e[2]);
}
template <class T>
bool bad(const dual_quaternion<T>& dq) {
    return bad(dq.real) || bad(dq.dual);
}
template <class T, int R, int C>
bool bad(const quat::matrix<T, R, C>& m) {
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j)
            if (bad(m(i, j))) return true;
    return false;
}
template <class T>
bool bad(const quat::se3::twist<T>& t) {
    return bad(t.linear) || bad(t.angular);
}

// Inputs with one bad component in a position that is not multiplied by zero on the way.
template <class T>
struct inputs {
    T value;
    quaternion<T> q{T(0.5), value, T(0.5), T(0.5)};
    vec3<T> v{T(0.25), value, T(-0.5)};
    quaternion<T> unit = quat::normalize(quaternion<T>{T(0.9), T(0.1), T(-0.3), T(0.2)});
    vec3<T> good_vector{T(0.3), T(-0.2), T(0.7)};
    rotation_matrix<T> m = [this] {
        rotation_matrix<T> r = quat::to_matrix(unit);
        r(1, 2) = value;
        return r;
    }();
    quat::euler<T> e{T(0.3), value, T(-0.2)};
    axis_angle<T> rotation{quat::normalize(vec3<T>{T(1), T(2), T(2)}), value};
};

}  // namespace

TEMPLATE_TEST_CASE("every function gives a visibly bad result for NaN and infinite input", "[nan]",
                   float, double) {
    using T = TestType;
    for (const T value : {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                          -std::numeric_limits<T>::infinity()}) {
        INFO("bad component: " << value);
        const inputs<T> in{value};
        const auto& q = in.q;
        const auto& v = in.v;
        const auto& m = in.m;
        const auto& unit = in.unit;

        // vec3.hpp
        CHECK(bad(-v));
        CHECK(bad(v + in.good_vector));
        CHECK(bad(v - in.good_vector));
        CHECK(bad(in.good_vector * value));
        CHECK(bad(in.good_vector / (value == value ? T(0) : value)));  // x / 0 and x / NaN
        CHECK(bad(quat::dot(v, in.good_vector)));
        CHECK(bad(quat::cross(v, in.good_vector)));
        CHECK(bad(quat::squared_norm(v)));
        CHECK(bad(quat::norm(v)));
        CHECK(bad(quat::normalize(v)));
        CHECK_FALSE(quat::try_normalize(v).has_value());

        // quaternion.hpp
        CHECK(bad(-q));
        CHECK(bad(q + unit));
        CHECK(bad(q - unit));
        CHECK(bad(q * unit));
        CHECK(bad(unit * q));
        CHECK(bad(unit * value));
        CHECK(bad(quat::conjugate(q)));
        CHECK(bad(quat::dot(q, unit)));
        CHECK(bad(quat::squared_norm(q)));
        CHECK(bad(quat::norm(q)));
        CHECK(bad(quat::normalize(q)));
        CHECK_FALSE(quat::try_normalize(q).has_value());
        CHECK(bad(quat::inverse(q)));
        CHECK_FALSE(quat::try_inverse(q).has_value());
        CHECK(bad(quat::rotate(q, in.good_vector)));
        CHECK(bad(quat::rotate(unit, v)));
        CHECK(bad(quat::angle_between(q, unit)));
        CHECK(bad(quat::angle_between(unit, q)));
        CHECK_FALSE(quat::approx_equal(q, unit, T(10)));
        CHECK_FALSE(quat::is_unit(q, T(10)));
        CHECK(bad(quat::rotation_x(value)));
        CHECK(bad(quat::rotation_y(value)));
        CHECK(bad(quat::rotation_z(value)));
        if (value != value) CHECK_FALSE(q == q);

        // rotation_matrix.hpp
        CHECK(bad(m * quat::to_matrix(unit)));
        CHECK(bad(quat::to_matrix(unit) * m));
        CHECK(bad(quat::rotate(m, in.good_vector)));
        CHECK(bad(quat::rotate(quat::to_matrix(unit), v)));
        CHECK(bad(quat::transpose(m)));
        CHECK(bad(quat::determinant(m)));
        CHECK(bad(quat::orthogonality_error(m)));

        // conversions.hpp
        CHECK(bad(quat::to_matrix(q)));
        CHECK(bad(quat::to_quaternion(m)));
        CHECK_FALSE(quat::try_to_quaternion(m).has_value());
        CHECK(bad(quat::to_quaternion(in.rotation)));
        CHECK_FALSE(quat::try_to_quaternion(in.rotation).has_value());
        CHECK_FALSE(quat::try_to_quaternion(axis_angle<T>{v, T(1)}).has_value());
        CHECK(bad(quat::to_axis_angle(q)));
        CHECK(bad(quat::to_axis_angle(quaternion<T>{value, T(0), T(0), T(0)})));
        CHECK(bad(quat::to_axis_angle(m)));
        CHECK(bad(quat::to_matrix(in.rotation)));
        CHECK(bad(quat::from_rotation_vector(v)));
        CHECK(bad(quat::to_rotation_vector(q)));

        // euler.hpp
        CHECK(bad(quat::to_quaternion(in.e)));
        CHECK(bad(quat::to_matrix(in.e)));
        CHECK(bad(quat::to_axis_angle(in.e)));
        CHECK(bad(quat::extract_euler<sequence::zyx>(q).angles));
        CHECK(bad(quat::extract_euler<sequence::zxz, quat::frame::extrinsic>(q).angles));
        CHECK(bad(quat::to_euler<sequence::xyz>(q)));
        CHECK(bad(quat::to_euler<sequence::xyz>(m)));
        CHECK(bad(quat::to_euler<sequence::xyz>(in.rotation)));
        CHECK(bad(quat::to_euler<sequence::yzy>(in.e)));

        // continuous_euler.hpp
        CHECK(bad(quat::to_euler(q, quat::euler<T>{T(0.1), T(0.2), T(0.3)})));
        CHECK(bad(quat::to_euler(unit, in.e)));

        // fitting/nearest_rotation.hpp
        CHECK(bad(quat::nearest_rotation(m)));
        CHECK_FALSE(quat::try_nearest_rotation(m).has_value());

        // paths/interpolation.hpp and paths/slerp_fast.hpp: a bad end point or a bad parameter
        const quaternion<T> other = quat::normalize(quaternion<T>{T(0.2), T(0.7), T(0.1), T(-0.4)});
        for (const T t : {T(0), T(0.25), T(1), T(2)}) {
            CHECK(bad(quat::slerp(unit, q, t)));
            CHECK(bad(quat::slerp(q, unit, t)));
            CHECK(bad(quat::nlerp(unit, q, t)));
            CHECK(bad(quat::slerp_fast(q, unit, t)));
            CHECK(bad(quat::corrected_nlerp(q, unit, t)));
        }
        CHECK(bad(quat::slerp(unit, other, value)));
        CHECK(bad(quat::slerp(unit, unit, value)));  // no motion to scale, but t is still bad
        CHECK(bad(quat::nlerp(unit, other, value)));
        CHECK(bad(quat::slerp_fast(unit, other, value)));
        CHECK(bad(quat::corrected_nlerp(unit, other, value)));

        // paths/interpolation.hpp: powers and bounded steps
        CHECK(bad(quat::pow(q, T(0.5))));
        CHECK(bad(quat::pow(unit, value)));
        CHECK(bad(quat::rotate_towards(q, unit, T(0.1))));
        CHECK(bad(quat::rotate_towards(unit, q, T(0.1))));
        if (value != value) CHECK(bad(quat::rotate_towards(unit, other, value)));

        // conversions.hpp: modified Rodrigues parameters
        CHECK(bad(quat::to_mrp(q)));
        CHECK(bad(quat::from_mrp(v)));

        // kinematics.hpp
        CHECK(bad(quat::body_angular_velocity(unit, q, T(0.1))));
        CHECK(bad(quat::world_angular_velocity(q, unit, T(0.1))));
        if (value != value) CHECK(bad(quat::body_angular_velocity(unit, other, value)));  // inf: 0
        CHECK(bad(quat::integrate_body(unit, v, T(0.1))));
        CHECK(bad(quat::integrate_world(q, in.good_vector, T(0.1))));
        CHECK(bad(quat::integrate_world(unit, in.good_vector, value)));

        // paths/keyframe_squad.hpp: a bad keyframe beyond the segment feeds its control point; a
        // NaN t
        const std::vector<T> key_times{T(0), T(1), T(2), T(4)};
        const std::vector<quaternion<T>> keys{unit, other, unit, q};
        CHECK(bad(quat::keyframe_squad(key_times, keys, T(1.5))));
        if (value != value) CHECK(bad(quat::keyframe_squad(key_times, keys, value)));  // inf: held

        // swing_twist.hpp
        const auto parts = quat::swing_twist(q, in.good_vector);
        CHECK((bad(parts.swing) || bad(parts.twist)));
        const auto about_bad_axis = quat::swing_twist(unit, v);
        CHECK((bad(about_bad_axis.swing) || bad(about_bad_axis.twist)));
        CHECK_FALSE(quat::try_swing_twist(q, in.good_vector).has_value());
        CHECK_FALSE(quat::try_swing_twist(unit, v).has_value());

        // align.hpp
        CHECK(bad(quat::rotation_between(v, in.good_vector)));
        CHECK(bad(quat::rotation_between(in.good_vector, v)));
        CHECK_FALSE(quat::try_rotation_between(v, in.good_vector).has_value());
        CHECK(bad(quat::look_rotation(v, in.good_vector)));
        CHECK(bad(quat::look_rotation(in.good_vector, v)));
        CHECK_FALSE(quat::try_look_rotation(in.good_vector, v).has_value());

        // fitting/align_vectors.hpp
        const std::vector<vec3<T>> sources{in.good_vector, vec3<T>{T(1), T(0), T(0)}};
        const std::vector<vec3<T>> targets{v, vec3<T>{T(0), T(1), T(0)}};
        const auto aligned = quat::align_vectors(targets, sources);
        CHECK((bad(aligned.rotation) && bad(aligned.rssd) && !aligned.unique));
        CHECK(bad(quat::align_vectors(sources, targets, std::vector<T>{T(1), T(2)}).rotation));
        // One infinite weight is a primary pair, aligned exactly (as scipy does); two, or a NaN
        // weight, give NaN.
        CHECK(bad(
            quat::align_vectors(sources, sources, std::vector<T>{std::abs(value), std::abs(value)})
                .rssd));
        CHECK(bad(quat::align_vectors_with_sensitivity(targets, sources, std::vector<T>{T(1), T(1)})
                      .rotation));

        // registration/align_points.hpp
        const std::vector<vec3<T>> cloud{in.good_vector, vec3<T>{T(1), T(0), T(0)},
                                         vec3<T>{T(0), T(0), T(2)}};
        const std::vector<vec3<T>> bad_cloud{v, vec3<T>{T(0), T(1), T(0)},
                                             vec3<T>{T(0), T(0), T(1)}};
        const auto registered = quat::align_points(bad_cloud, cloud);
        CHECK((bad(registered.motion.real) && bad(registered.motion.dual) && bad(registered.rms) &&
               !registered.unique));
        CHECK(bad(quat::align_points_with_scale(cloud, bad_cloud).scale));
        CHECK_FALSE(quat::try_align_points(cloud, bad_cloud).has_value());

        // registration/hand_eye.hpp
        const dual_quaternion<T> hand_motion = quat::to_dual_quaternion(other, in.good_vector);
        const std::vector<dual_quaternion<T>> hands{hand_motion, hand_motion * hand_motion};
        const std::vector<dual_quaternion<T>> eyes{quat::to_dual_quaternion(other, v), hand_motion};
        const auto calibrated = quat::hand_eye(hands, eyes);
        CHECK((bad(calibrated.mount.real) && bad(calibrated.mount.dual) &&
               bad(calibrated.rotation_rms) && !calibrated.unique));
        CHECK_FALSE(quat::try_hand_eye(hands, eyes).has_value());
        const auto first = quat::hand_eye(hands, eyes, quat::hand_eye_method::rotation_first);
        CHECK((bad(first.mount.real) && bad(first.mount.dual) && !first.unique));

        // fitting/mean.hpp
        const std::vector<quaternion<T>> cluster{unit, other, q};
        CHECK(bad(quat::mean(cluster)));
        CHECK_FALSE(quat::try_mean(cluster).has_value());
        const std::vector<quaternion<T>> good_cluster{unit, other};
        const T weight = std::abs(value);  // a negative weight is a precondition violation
        CHECK(bad(quat::mean(good_cluster, std::vector<T>{T(1), weight})));
        CHECK_FALSE(quat::try_mean(good_cluster, std::vector<T>{weight, T(1)}).has_value());

        // batch/rotations.hpp
        std::vector<vec3<T>> points(40, in.good_vector), rotated(40);
        points[7] = v;
        quat::rotate(unit, points, rotated);
        CHECK(bad(rotated[7]));
        CHECK_FALSE(bad(rotated[8]));  // the others are untouched by it
        quat::rotate(m, points.data(), rotated.data(), points.size());
        CHECK(bad(rotated[0]));
        std::vector<T> x(40, T(1)), y(40, T(2)), z(40, T(3)), ox(40), oy(40), oz(40);
        y[3] = value;
        quat::rotate(unit, quat::soa_points<const T>{x.data(), y.data(), z.data(), 40},
                     quat::soa_points<T>{ox.data(), oy.data(), oz.data(), 40});
        CHECK(bad(vec3<T>{ox[3], oy[3], oz[3]}));
        std::vector<quaternion<T>> factors(20, unit);
        factors[11] = q;
        CHECK(bad(quat::compose(factors)));
        std::vector<T> ts(20, T(0.5));
        ts[5] = value;
        std::vector<quaternion<T>> slerped(20);
        quat::slerp(unit, other, ts, slerped);
        CHECK(bad(slerped[5]));
        quat::slerp(unit, q, ts.data(), slerped.data(), 4);
        CHECK(bad(slerped[0]));

        // rigid/dual_quaternion.hpp, rigid/homogeneous_matrix.hpp, rigid/screw.hpp,
        // rigid/sclerp.hpp, rigid/blend.hpp, batch/rigid_motions.hpp
        const auto motion = quat::to_dual_quaternion(unit, in.good_vector);
        const auto bad_rotation = quat::to_dual_quaternion(q, in.good_vector);
        const auto bad_translation = quat::to_dual_quaternion(unit, v);
        CHECK(bad(quat::translation_of(bad_translation)));
        CHECK(bad(quat::translation_of(bad_rotation)));
        CHECK(bad((motion * bad_translation).dual));
        CHECK(bad((bad_rotation * motion).real));
        CHECK(bad(quat::inverse(bad_rotation).real));
        CHECK(bad(quat::normalize(bad_translation).dual));
        CHECK(bad(quat::normalize(bad_rotation).real));
        CHECK_FALSE(quat::try_normalize(bad_translation).has_value());
        CHECK(bad(quat::transform(motion, v)));
        CHECK(bad(quat::transform(bad_translation, in.good_vector)));
        CHECK(bad(quat::transform_vector(motion, v)));
        const quat::homogeneous_matrix<T> h = quat::to_homogeneous(bad_translation);
        CHECK(bad(quat::transform(h, in.good_vector)));
        CHECK(bad(quat::translation_of(quat::to_dual_quaternion(h))));
        CHECK_FALSE(quat::try_to_dual_quaternion(h).has_value());
        CHECK(bad(quat::to_screw(bad_translation)));
        CHECK(bad(quat::to_screw(bad_rotation)));
        CHECK(bad(quat::from_screw(quat::screw<T>{in.good_vector, v, T(1), T(2)}).dual));
        CHECK(bad(quat::sclerp(motion, bad_translation, T(0.5)).dual));
        CHECK(bad(quat::sclerp(motion, bad_translation, T(0)).dual));
        CHECK(bad(quat::sclerp(bad_translation, motion, T(1)).dual));
        CHECK(bad(quat::sclerp(motion, motion, value).real));
        const std::vector<quat::dual_quaternion<T>> bones{motion, bad_translation};
        CHECK(bad(quat::blend(bones, std::vector<T>{T(0.5), T(0.5)}).dual));
        const std::vector<quat::dual_quaternion<T>> good_bones{motion, motion};
        CHECK(bad(quat::blend(good_bones, std::vector<T>{T(0.5), value}).real));
        quat::transform(motion, points, rotated);
        CHECK(bad(rotated[7]));
        CHECK_FALSE(bad(rotated[8]));
        quat::transform(h, quat::soa_points<const T>{x.data(), y.data(), z.data(), 40},
                        quat::soa_points<T>{ox.data(), oy.data(), oz.data(), 40});
        CHECK(bad(vec3<T>{ox[0], oy[0], oz[0]}));
        std::vector<quat::dual_quaternion<T>> chain(20, motion);
        chain[13] = bad_rotation;
        CHECK(bad(quat::compose(chain).real));

        // batch/elementwise.hpp: the bad element only
        std::vector<quaternion<T>> rotations(40, unit);
        rotations[9] = q;
        quat::rotate_each(rotations, points, rotated);
        CHECK(bad(rotated[7]));  // the bad point
        CHECK(bad(rotated[9]));  // the bad rotation
        CHECK_FALSE(bad(rotated[8]));
        std::vector<T> w(40, T(1)), zero(40, T(0));
        quat::rotate_each(
            quat::soa_quaternions<const T>{w.data(), zero.data(), zero.data(), zero.data(), 40},
            quat::soa_points<const T>{x.data(), y.data(), z.data(), 40},
            quat::soa_points<T>{ox.data(), oy.data(), oz.data(), 40});
        CHECK(bad(vec3<T>{ox[3], oy[3], oz[3]}));
        CHECK_FALSE(bad(vec3<T>{ox[4], oy[4], oz[4]}));
        std::vector<quaternion<T>> products(40);
        quat::compose_each(rotations, std::vector<quaternion<T>>(40, other), products);
        CHECK(bad(products[9]));
        CHECK_FALSE(bad(products[10]));
        std::vector<rotation_matrix<T>> matrices(40);
        quat::to_matrix_each(rotations, matrices);
        CHECK(bad(matrices[9]));
        CHECK_FALSE(bad(matrices[10]));
        matrices[10] = m;
        std::vector<quaternion<T>> converted(40);
        quat::to_quaternion_each(matrices, converted);
        CHECK(bad(converted[10]));
        CHECK_FALSE(bad(converted[11]));
    }
}

TEST_CASE("the zero quaternion has no axis: to_axis_angle gives NaN", "[nan]") {
    CHECK(bad(quat::to_axis_angle(quat::quatd{0, 0, 0, 0})));
    CHECK(quat::to_axis_angle(quat::quatd{2, 0, 0, 0}).angle == 0.0);  // any positive scale of 1
}

TEMPLATE_TEST_CASE("the first-use spellings give a visibly bad result for NaN and infinite input",
                   "[nan][first-use]", float, double) {
    using T = TestType;
    for (const T value : {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                          -std::numeric_limits<T>::infinity()}) {
        INFO("bad component: " << value);
        const inputs<T> in{value};
        const vec3<T> p = in.good_vector;
        // vec3.hpp, constants.hpp
        CHECK(bad(in.v[1]));
        CHECK(bad(quat::lerp(in.v, p, T(0.5))));
        CHECK(bad(quat::lerp(p, in.v, T(0.5))));
        CHECK(bad(quat::lerp(p, p * T(2), value)));
        CHECK(bad(quat::radians(value)));
        CHECK(bad(quat::degrees(value)));
        // quaternion.hpp, rotation_matrix.hpp, conversions.hpp, paths/interpolation.hpp
        CHECK(bad(in.unit * in.v));
        CHECK(bad(in.m * p));
        CHECK(bad(quat::angle(in.q)));
        CHECK(bad(quat::axis(in.q)));
        CHECK(bad(quat::exp(in.q)));
        // e^-Inf is 0: exp((-Inf, 0)) = (0, 0) is the answer, not a bad one.
        if (!(value < 0)) CHECK(bad(quat::exp(quaternion<T>{value, 0, 0, 0})));
        CHECK(bad(quat::log(in.q)));
        CHECK(bad(quat::log(quaternion<T>{value, 0, 0, 0})));
        // rigid/dual_quaternion.hpp, rigid/homogeneous_matrix.hpp
        const auto dq = quat::to_dual_quaternion(in.unit, in.v);
        CHECK(bad(quat::to_dual_quaternion(in.unit) * in.v));
        CHECK(bad(quat::dual_quaternion<T>::from_translation(in.v) * p));
        CHECK(bad((dq * T(2)).dual));
        CHECK(bad((T(2) * dq).dual));
        CHECK(bad((dq / T(2)).dual));
        CHECK(bad((quat::to_dual_quaternion(in.unit, p) * value).real));
        const quat::homogeneous_matrix<T> h = quat::to_homogeneous(in.unit, in.v);
        CHECK(bad(h * p));
        CHECK(bad(quat::translation_of(quat::inverse(h))));
        CHECK(bad(quat::to_homogeneous(in.m, p) * p));
        CHECK(bad(quat::to_homogeneous(in.m) * p));
        CHECK(bad(quat::homogeneous_matrix<T>::from_translation(in.v) * p));
    }
}

TEMPLATE_TEST_CASE(
    "the Lie groups and the geodesic mean give a visibly bad result for NaN and "
    "infinite input",
    "[nan][lie]", float, double) {
    using T = TestType;
    for (const T value : {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                          -std::numeric_limits<T>::infinity()}) {
        INFO("bad component: " << value);
        const inputs<T> in{value};
        const quaternion<T> q{in.unit.w, value, in.unit.y, in.unit.z};
        const vec3<T>& w = in.v;
        const dual_quaternion<T> good = quat::to_dual_quaternion(in.unit, in.good_vector);
        const dual_quaternion<T> motion = quat::to_dual_quaternion(in.unit, w);
        const quat::se3::twist<T> t{w, in.good_vector};
        quat::matrix<T, 3, 3> j3{}, k3{};
        quat::matrix<T, 6, 6> j6{}, k6{};

        // lie/so3.hpp: the value, and each Jacobian that depends on the bad input
        CHECK(bad(quat::so3::exp(w, &j3)));
        CHECK(bad(j3));
        CHECK(bad(quat::so3::log(q, &j3)));
        CHECK(bad(j3));
        CHECK(bad(quat::so3::right_jacobian(w)));
        CHECK(bad(quat::so3::right_jacobian_inverse(w)));
        CHECK(bad(quat::so3::plus(in.unit, w, &j3, &k3)));
        CHECK(bad(quat::so3::minus(q, in.unit, &j3, &k3)));
        CHECK(bad(j3));
        CHECK(bad(quat::so3::act(q, in.good_vector, &j3, &k3)));
        CHECK(bad(quat::so3::compose(q, in.unit)));

        // lie/se3.hpp
        CHECK(bad(quat::se3::exp(t, &j6)));
        CHECK(bad(j6));
        CHECK(bad(quat::se3::log(motion, &j6)));
        CHECK(bad(j6));
        CHECK(bad(quat::se3::right_jacobian(t)));
        CHECK(bad(quat::se3::plus(good, t, &j6, &k6)));
        CHECK(bad(quat::se3::minus(motion, good, &j6, &k6)));
        CHECK(bad(quat::se3::act(good, w)));
        CHECK(bad(quat::se3::compose(motion, good)));

        // lie/geodesic_mean.hpp
        std::vector<quaternion<T>> rotations(5, in.unit);
        rotations[3] = q;
        CHECK(bad(quat::geodesic_mean(rotations)));
        CHECK_FALSE(quat::try_geodesic_mean(rotations).has_value());
        std::vector<dual_quaternion<T>> motions(5, good);
        motions[2] = motion;
        CHECK(bad(quat::geodesic_mean(motions)));
        CHECK_FALSE(quat::try_geodesic_mean(motions).has_value());
    }
}

}  // namespace test_nan_propagation
