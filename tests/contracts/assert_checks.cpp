// The debug checks behind QUAT_ASSERT, one precondition per run: `quat_assert_checks NAME` breaks
// precondition NAME and must stop with the message naming it (CTest matches the message), and
// `quat_assert_checks valid` feeds every checked function input that meets its precondition,
// including what users actually pass (renormalized products, NaN, in-place batches), and must
// finish without any check firing. The handler below is the documented way to route the checks
// elsewhere: it prints the message and ends the process (it must not return), in every build type.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#define QUAT_ASSERT(condition, message) \
    ((condition) ? void(0)              \
                 : (std::fprintf(stderr, "%s\n", message), std::fflush(stderr), std::_Exit(3)))

#include <quat/lie/geodesic_mean.hpp>
#include <quat/quat.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>
#include <quat/trajectory.hpp>

namespace {

using quat::quatd;
using quat::vec3;

int valid() {
    const quatd unit = quat::normalize(quatd{1, 2, 3, 4});
    const vec3<double> v{1, 2, 3};
    quatd drifted = unit;
    for (int i = 0; i < 100000; ++i) drifted = drifted * unit;  // rounding accumulates, unchecked
    volatile double sink = quat::rotate(drifted, v).x + quat::to_matrix(drifted)(0, 0);
    const quatd nan{std::numeric_limits<double>::quiet_NaN(), 0, 0, 0};
    const quatd inf{std::numeric_limits<double>::infinity(), 0, 0, 0};
    sink = sink + quat::rotate(nan, v).x + quat::rotate(inf, v).x;  // NaN in, NaN out: not checked
    sink = sink + quat::slerp(unit, nan, 0.5).w + quat::to_matrix(inf)(0, 0);
    const quat::quatf single = quat::normalize(quat::quatf{0.1f, 0.2f, 0.3f, 0.4f});
    sink = sink + static_cast<double>(quat::slerp(single, quat::rotation_x(1.0f), 0.5).w);
    sink = sink + quat::to_quaternion(quat::axis_angle<double>{{0, 0.6, 0.8}, 1}).w;
    quat::euler<double> e{0.1, 0.2, 0.3};
    sink = sink + e[2];
    std::vector<vec3<double>> points(300, v), out(300);
    const std::vector<double> weights(300, 0.5);
    const std::vector<quat::dual_quaterniond> motions{
        quat::to_dual_quaternion(unit, v), quat::to_dual_quaternion(quat::rotation_x(1.0), v)};
    sink = sink + quat::hand_eye(motions, motions).rotation_rms;
    sink = sink + quat::hand_eye_from_poses(motions, motions).calibration.rotation_rms;
    sink = sink + quat::align_points(points, points, weights).rms +
           quat::align_points_with_scale(points, points).scale +
           quat::align_vectors(points, points, weights).rssd;
    quat::rotate(unit, points, points);                           // in place
    quat::rotate(unit, points, out);                              // disjoint
    quat::rotate(unit, points.data(), points.data() + 150, 150);  // adjacent halves
    std::vector<double> x(64, 1), y(64, 2), z(64, 3);
    quat::rotate(unit, quat::soa_points<const double>{x.data(), y.data(), z.data(), 64},
                 quat::soa_points<double>{x.data(), y.data(), z.data(), 64});  // each in place
    const quatd turned = quat::rotation_y(0.3) * drifted;
    sink = sink + quat::pow(drifted, 0.3).w + quat::rotate_towards(drifted, turned, 0.1).w;
    sink = sink + quat::body_angular_velocity(drifted, turned, 0.1).x +
           quat::world_angular_velocity(drifted, turned, 0.1).x;
    sink =
        sink + quat::integrate_body(drifted, v, 0.1).w + quat::integrate_world(drifted, v, 0.1).w;
    sink =
        sink + quat::swing_twist(drifted, v).twist.w + quat::try_swing_twist(drifted, v)->swing.w;
    sink = sink + quat::mean(std::vector<quatd>{drifted, turned}, std::vector<double>{0, 2}).w;
    std::vector<double> t(32, 0.25);
    std::vector<quatd> slerped(32);
    quat::slerp(unit, quatd::identity(), t, slerped);
    sink = sink + slerped[3].w;
    // Rigid motions: a drifted real part, in-place and adjacent batches, matching sizes.
    const auto motion = quat::to_dual_quaternion(drifted, v);
    const auto other = quat::to_dual_quaternion(turned, vec3<double>{0, 1, 0});
    sink = sink + quat::transform(motion, v).x + quat::sclerp(motion, other, 0.3).dual.x;
    const std::vector<quat::dual_quaterniond> bones{motion, other};
    sink = sink + quat::blend(bones, std::vector<double>{0.5, 0.5}).dual.y;
    sink = sink + quat::inverse(quat::to_homogeneous(drifted, v))(0, 3) + v[2];
    quat::transform(motion, points, points);
    quat::transform(quat::to_homogeneous(other), points.data(), points.data() + 150, 150);
    quat::transform(motion, quat::soa_points<const double>{x.data(), y.data(), z.data(), 64},
                    quat::soa_points<double>{x.data(), y.data(), z.data(), 64});
    sink = sink + quat::to_homogeneous(motion)(3, 3);
    // Per-element batches: drifted rotations, in place, adjacent halves, each SoA array in place.
    const std::vector<quatd> rotations(300, drifted);
    quat::rotate_each(rotations, points, points);
    quat::rotate_each(rotations.data(), points.data(), points.data() + 150, 150);
    std::vector<quatd> products = rotations;
    quat::compose_each(products, rotations, products);
    quat::compose_each(rotations, products, products);
    quat::compose_each(products.data(), products.data(), products.data() + 150, 150);
    std::vector<double> w(64, 1), zero(64, 0);
    quat::rotate_each(
        quat::soa_quaternions<const double>{w.data(), zero.data(), zero.data(), zero.data(), 64},
        quat::soa_points<const double>{x.data(), y.data(), z.data(), 64},
        quat::soa_points<double>{x.data(), y.data(), z.data(), 64});
    std::vector<quat::rotation_matrix<double>> matrices(300);
    quat::to_matrix_each(products, matrices);
    quat::to_quaternion_each(matrices, products);
    sink = sink + points[7].x + products[9].w;
    // Keyframe paths: drifted keyframes at increasing times, t before, inside and after them.
    const std::vector<double> key_times{0, 1, 2.5};
    const std::vector<quatd> keys{drifted, turned, unit};
    for (const double at : {-1.0, 0.0, 0.7, 2.5, 3.0})
        sink = sink + quat::keyframe_slerp(key_times, keys, at).w +
               quat::keyframe_squad(key_times, keys, at).w +
               quat::rotation_spline<double>(key_times, keys)(at).w;
    sink = sink + quat::squad(drifted, quat::squad_control(drifted, drifted, turned),
                              quat::squad_control(drifted, turned, unit), turned, 0.4)
                      .w;
    // Trajectories: drifted control points and keyframes, matching sizes, t before, inside and
    // after the domain (the B-splines have no debug check of their own: NaN outside).
    const std::vector<quatd> controls{drifted, turned, unit, drifted, turned};
    std::vector<vec3<double>> positions(5, v);
    std::vector<quat::dual_quaterniond> motions_in;
    for (const quatd& q : controls) motions_in.push_back(quat::to_dual_quaternion(q, v));
    quat::so3_bspline<double, 4>::jacobian_blocks J3{};
    quat::se3_bspline<double, 4>::jacobian_blocks J6{};
    for (const double at : {-1.0, 0.0, 0.7, 2.0, 3.0}) {
        sink = sink +
               quat::so3_bspline<double, 4>(controls, 0.0, 1.0)
                   .evaluate(at, &J3, &J3, &J3, &J3)
                   .rotation.w +
               quat::se3_bspline<double, 4>(motions_in, 0.0, 1.0)
                   .evaluate(at, &J6, &J6, &J6, &J6)
                   .motion.real.w +
               quat::split_bspline<double, 4>(controls, positions, 0.0, 1.0)
                   .evaluate(at)
                   .body_velocity.linear.x;
    }
    const std::vector<double> pose_times{0, 1, 2.5, 4, 4.5};
    const quat::split_keyframe_path<double> split_path(pose_times, motions_in);
    const quat::se3_keyframe_path<double> se3_path(pose_times, motions_in);
    std::vector<quat::keyframe_path_state<double>> states(2);
    std::vector<quat::dual_quaterniond> poses_out(2);
    split_path.evaluate(std::vector<double>{0.5, 3.0}, states);
    se3_path.evaluate(std::vector<int>{1, 4}, poses_out);
    for (const double at : {-1.0, 0.0, 0.7, 2.5, 5.0})
        sink = sink + split_path.state(at).velocity.x + se3_path(at).real.w;
    sink = sink + states[1].pose.real.w + poses_out[1].dual.x;
    std::printf("no assertion fired (%g)\n", static_cast<double>(sink));
    return 0;
}

int run(const char* name) {
    const quatd not_unit{1, 1, 0, 0};
    const vec3<double> v{1, 2, 3};
    volatile double sink = 0;
    std::vector<vec3<double>> points(64, v);
    std::vector<double> x(64, 1), y(64, 2), z(64, 3);
    if (std::strcmp(name, "rotate") == 0) sink = quat::rotate(not_unit, v).x;
    if (std::strcmp(name, "to_matrix") == 0) sink = quat::to_matrix(not_unit)(0, 0);
    if (std::strcmp(name, "slerp") == 0) sink = quat::slerp(quatd::identity(), not_unit, 0.5).w;
    if (std::strcmp(name, "axis_angle") == 0)
        sink = quat::to_quaternion(quat::axis_angle<double>{{0, 0, 2}, 1}).w;
    if (std::strcmp(name, "pow") == 0) sink = quat::pow(not_unit, 0.5).w;
    if (std::strcmp(name, "rotate_towards") == 0)
        sink = quat::rotate_towards(quatd::identity(), not_unit, 0.1).w;
    if (std::strcmp(name, "body_angular_velocity") == 0)
        sink = quat::body_angular_velocity(not_unit, quatd::identity(), 0.1).x;
    if (std::strcmp(name, "world_angular_velocity") == 0)
        sink = quat::world_angular_velocity(quatd::identity(), not_unit, 0.1).x;
    if (std::strcmp(name, "integrate_body") == 0) sink = quat::integrate_body(not_unit, v, 0.1).w;
    if (std::strcmp(name, "integrate_world") == 0) sink = quat::integrate_world(not_unit, v, 0.1).w;
    if (std::strcmp(name, "swing_twist") == 0) sink = quat::swing_twist(not_unit, v).twist.w;
    if (std::strcmp(name, "to_matrix_overflowing") == 0)  // |q|^2 overflows, yet q is finite
        sink = quat::to_matrix(quatd{1e200, 1, 0, 0})(0, 0);
    if (std::strcmp(name, "axis_angle_matrix") == 0)
        sink = quat::to_matrix(quat::axis_angle<double>{{0, 0, 0}, 1})(0, 0);
    if (std::strcmp(name, "slerp_fast") == 0)
        sink = quat::slerp_fast(quatd::identity(), not_unit, 0.5).w;
    if (std::strcmp(name, "corrected_nlerp") == 0)
        sink = quat::corrected_nlerp(not_unit, quatd::identity(), 0.5).w;
    if (std::strcmp(name, "transform_vector") == 0)
        sink = quat::transform_vector(quat::dual_quaterniond{not_unit, quatd{0, 0, 0, 0}}, v).x;
    if (std::strcmp(name, "homogeneous_to_dual_quaternion") == 0) {
        quat::homogeneous_matrix<double> sheared =
            quat::to_homogeneous(quat::to_dual_quaternion(quatd::identity(), v));
        sheared(0, 1) = 0.5;
        sink = quat::to_dual_quaternion(sheared).real.w;
    }
    const std::vector<quatd> cluster{quatd::identity(), quat::rotation_x(0.5)};
    if (std::strcmp(name, "mean") == 0)
        sink = quat::mean(std::vector<quatd>{quatd::identity(), not_unit}).w;
    if (std::strcmp(name, "mean_negative_weight") == 0)
        sink = quat::mean(cluster, std::vector<double>{1, -1}).w;
    if (std::strcmp(name, "mean_weights_size") == 0)
        sink = quat::mean(cluster, std::vector<double>{1}).w;
    if (std::strcmp(name, "geodesic_mean") == 0)
        sink = quat::geodesic_mean(std::vector<quatd>{quatd::identity(), not_unit}).w;
    if (std::strcmp(name, "geodesic_mean_negative_weight") == 0)
        sink = quat::geodesic_mean(cluster, std::vector<double>{1, -1}).w;
    if (std::strcmp(name, "geodesic_mean_weights_size") == 0)
        sink = quat::geodesic_mean(cluster, std::vector<double>{1}).w;
    const std::vector<vec3<double>> pair{v, {0, 0, 1}};
    if (std::strcmp(name, "align_vectors_size") == 0)
        sink = quat::align_vectors(pair, std::vector<vec3<double>>{v}).rssd;
    if (std::strcmp(name, "align_vectors_negative_weight") == 0)
        sink = quat::align_vectors(pair, pair, std::vector<double>{1, -1}).rssd;
    if (std::strcmp(name, "hand_eye_size") == 0)
        sink = quat::hand_eye(std::vector<quat::dual_quaterniond>(2),
                              std::vector<quat::dual_quaterniond>(3))
                   .rotation_rms;
    if (std::strcmp(name, "hand_eye_not_unit") == 0) {
        const std::vector<quat::dual_quaterniond> twice{{quatd{2, 0, 0, 0}, quatd{0, 0, 0, 0}}};
        sink = quat::hand_eye(twice, twice).rotation_rms;
    }
    if (std::strcmp(name, "hand_eye_from_poses_size") == 0)
        sink = quat::hand_eye_from_poses(std::vector<quat::dual_quaterniond>(2),
                                         std::vector<quat::dual_quaterniond>(3))
                   .calibration.rotation_rms;
    if (std::strcmp(name, "hand_eye_from_poses_not_unit") == 0) {
        const std::vector<quat::dual_quaterniond> twice{{quatd{2, 0, 0, 0}, quatd{0, 0, 0, 0}}};
        sink = quat::hand_eye_from_poses(twice, twice).calibration.rotation_rms;
    }
    if (std::strcmp(name, "align_points_size") == 0)
        sink = quat::align_points(pair, std::vector<vec3<double>>{v}).rms;
    if (std::strcmp(name, "align_points_negative_weight") == 0)
        sink = quat::align_points_with_scale(pair, pair, std::vector<double>{1, -1}).rms;
    if (std::strcmp(name, "squad_control") == 0)
        sink = quat::squad_control(quatd::identity(), not_unit, quatd::identity()).w;
    const std::vector<double> unsorted{0, 2, 1};
    const std::vector<quatd> three{quatd::identity(), quat::rotation_x(0.5), quat::rotation_x(1.0)};
    if (std::strcmp(name, "keyframe_slerp_size") == 0)
        sink = quat::keyframe_slerp(std::vector<double>{0, 1}, three, 0.5).w;
    if (std::strcmp(name, "keyframe_slerp_unsorted") == 0)
        sink = quat::keyframe_slerp(std::vector<double>{0, 3, 1, 4},
                                    std::vector<quatd>(4, quatd::identity()), 3.5)
                   .w;
    if (std::strcmp(name, "rotation_spline_size") == 0)
        sink = quat::rotation_spline<double>(std::vector<double>{0},
                                             std::vector<quatd>{quatd::identity()})(0.5)
                   .w;
    if (std::strcmp(name, "rotation_spline_unsorted") == 0)
        sink = quat::rotation_spline<double>(unsorted, three)(0.5).w;
    const double nan_time = std::numeric_limits<double>::quiet_NaN();
    if (std::strcmp(name, "keyframe_slerp_nan_time") == 0)  // sorted around t, NaN elsewhere
        sink = quat::keyframe_slerp(std::vector<double>{0, 1, nan_time}, three, 0.5).w;
    if (std::strcmp(name, "keyframe_slerp_not_unit") == 0)
        sink = quat::keyframe_slerp(std::vector<double>{0, 1},
                                    std::vector<quatd>{quatd::identity(), not_unit}, 0.5)
                   .w;
    if (std::strcmp(name, "keyframe_squad_size") == 0)
        sink = quat::keyframe_squad(std::vector<double>{0, 1}, three, 0.5).w;
    if (std::strcmp(name, "keyframe_squad_unsorted") == 0)
        sink = quat::keyframe_squad(std::vector<double>{0, 3, 1, 4},
                                    std::vector<quatd>(4, quatd::identity()), 3.5)
                   .w;
    if (std::strcmp(name, "keyframe_squad_nan_time") == 0)  // sorted around t, NaN elsewhere
        sink = quat::keyframe_squad(std::vector<double>{0, 1, nan_time}, three, 0.5).w;
    if (std::strcmp(name, "keyframe_squad_not_unit") == 0)  // only a control point's neighbour
        sink = quat::keyframe_squad(std::vector<double>{0, 1, 2, 3},
                                    std::vector<quatd>{quatd::identity(), quatd::identity(),
                                                       quatd::identity(), not_unit},
                                    1.5)
                   .w;
    if (std::strcmp(name, "rotation_spline_infinite_time") == 0)
        sink = quat::rotation_spline<double>(
                   std::vector<double>{0, 1, std::numeric_limits<double>::infinity()}, three)(0.5)
                   .w;
    if (std::strcmp(name, "squad") == 0)  // before slerp's check inside, which names slerp
        sink =
            quat::squad(quatd::identity(), not_unit, quatd::identity(), quatd::identity(), 0.5).w;
    if (std::strcmp(name, "euler_index") == 0) {
        const quat::euler<double> e{0.1, 0.2, 0.3};
        sink = e[static_cast<std::size_t>(3 + sink)];
    }
    if (std::strcmp(name, "matrix_index") == 0) {
        const auto m = quat::rotation_matrix<double>::identity();
        sink = m(3 + static_cast<int>(sink), 0);
    }
    if (std::strcmp(name, "batch_overlap") == 0)
        quat::rotate(quat::to_matrix(quatd::identity()), points.data(), points.data() + 1, 63);
    if (std::strcmp(name, "batch_soa_overlap") == 0)
        quat::rotate(quatd::identity(),
                     quat::soa_points<const double>{x.data(), y.data(), z.data(), 60},
                     quat::soa_points<double>{x.data() + 2, y.data(), z.data(), 60});
    if (std::strcmp(name, "batch_short_output") == 0) {
        std::vector<vec3<double>> out(10);
        quat::rotate(quatd::identity(), points, out);
    }
    if (std::strcmp(name, "batch_slerp_overlap") == 0) {
        std::vector<quatd> out(8);
        quat::slerp(quatd::identity(), quat::rotation_z(1.0), &out[0].x, out.data(), 8);
    }
    if (std::strcmp(name, "batch_slerp_unit") == 0) {
        // t in [0, 1]: the polynomial path, which never calls the scalar slerp and its check.
        const double t[3] = {0.0, 0.5, 1.0};
        quatd out[3];
        quat::slerp(quatd{1, 1, 0, 0}, quat::rotation_z(1.0), t, out);
    }
    const auto bad_motion = quat::to_dual_quaternion(not_unit, v);
    const auto motion = quat::to_dual_quaternion(quatd::identity(), v);
    if (std::strcmp(name, "transform") == 0) sink = quat::transform(bad_motion, v).x;
    if (std::strcmp(name, "sclerp") == 0) sink = quat::sclerp(motion, bad_motion, 0.5).dual.x;
    if (std::strcmp(name, "blend_size") == 0)
        sink =
            quat::blend(std::vector<quat::dual_quaterniond>{motion, motion}, std::vector<double>{1})
                .real.w;
    if (std::strcmp(name, "blend_unit") == 0)
        sink = quat::blend(std::vector<quat::dual_quaterniond>{motion, bad_motion},
                           std::vector<double>{0.5, 0.5})
                   .real.w;
    if (std::strcmp(name, "homogeneous_index") == 0)
        sink = quat::to_homogeneous(motion)(0, 4 + static_cast<int>(sink));
    if (std::strcmp(name, "vec3_index") == 0) {
        const quat::vec3<double> p{1, 2, 3};
        sink = p[static_cast<std::size_t>(3 + sink)];
    }
    if (std::strcmp(name, "homogeneous_inverse") == 0) {
        quat::homogeneous_matrix<double> scaled = quat::to_homogeneous(motion);
        scaled(0, 0) *= 2;
        sink = quat::inverse(scaled)(0, 0);
    }
    if (std::strcmp(name, "rigid_batch_overlap") == 0)
        quat::transform(motion, points.data(), points.data() + 1, 63);
    if (std::strcmp(name, "rigid_batch_soa_overlap") == 0)
        quat::transform(motion, quat::soa_points<const double>{x.data(), y.data(), z.data(), 60},
                        quat::soa_points<double>{x.data(), y.data() + 1, z.data(), 60});
    if (std::strcmp(name, "rigid_batch_short_output") == 0) {
        std::vector<vec3<double>> out(10);
        quat::transform(motion, points, out);
    }
    const std::vector<quatd> rotations(64, quatd::identity());
    std::vector<quatd> products(64, quatd::identity());
    if (std::strcmp(name, "rotate_each_overlap") == 0)
        quat::rotate_each(rotations.data(), points.data(), points.data() + 1, 63);
    if (std::strcmp(name, "rotate_each_short_output") == 0) {
        std::vector<vec3<double>> out(10);
        quat::rotate_each(rotations, points, out);
    }
    if (std::strcmp(name, "rotate_each_size") == 0)
        quat::rotate_each(std::vector<quatd>(3, quatd::identity()), points, points);
    if (std::strcmp(name, "rotate_each_soa_overlap") == 0)
        quat::rotate_each(
            quat::soa_quaternions<const double>{x.data(), y.data(), z.data(), x.data(), 60},
            quat::soa_points<const double>{x.data(), y.data(), z.data(), 60},
            quat::soa_points<double>{x.data(), y.data(), z.data() + 3, 60});
    if (std::strcmp(name, "compose_each_overlap") == 0)
        quat::compose_each(rotations.data(), products.data(), products.data() + 1, 63);
    if (std::strcmp(name, "compose_each_short_output") == 0) {
        std::vector<quatd> out(10);
        quat::compose_each(rotations, products, out);
    }
    if (std::strcmp(name, "to_matrix_each_overlap") == 0) {
        std::vector<quat::rotation_matrix<double>> matrices(64);
        quat::to_matrix_each(reinterpret_cast<const quatd*>(matrices.data()), matrices.data(), 8);
    }
    // Keyframe paths: sizes, times, and the sizes of a batch evaluation.
    const std::vector<quat::dual_quaterniond> poses(3,
                                                    quat::to_dual_quaternion(quatd::identity(), v));
    const std::vector<double> in_order{0, 1, 2}, out_of_order{0, 2, 1};
    std::vector<quat::dual_quaterniond> short_out(1);
    if (std::strcmp(name, "split_keyframe_path_size") == 0)
        sink = quat::split_keyframe_path<double>(std::vector<double>{0, 1}, poses)(0.5).real.w;
    if (std::strcmp(name, "split_keyframe_path_unsorted") == 0)
        sink = quat::split_keyframe_path<double>(out_of_order, poses)(0.5).real.w;
    if (std::strcmp(name, "split_keyframe_path_evaluate_size") == 0)
        quat::split_keyframe_path<double>(in_order, poses).evaluate(in_order, short_out);
    if (std::strcmp(name, "se3_keyframe_path_size") == 0)
        sink = quat::se3_keyframe_path<double>(std::vector<double>{0},
                                               std::vector<quat::dual_quaterniond>(1))(0.5)
                   .real.w;
    if (std::strcmp(name, "se3_keyframe_path_unsorted") == 0)
        sink = quat::se3_keyframe_path<double>(
                   std::vector<double>{0, 1, std::numeric_limits<double>::quiet_NaN()}, poses)(0.5)
                   .real.w;
    if (std::strcmp(name, "se3_keyframe_path_evaluate_size") == 0)
        quat::se3_keyframe_path<double>(in_order, poses).evaluate(in_order, short_out);
    std::printf("no assertion fired for '%s' (%g)\n", name, static_cast<double>(sink));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: quat_assert_checks valid|rotate|to_matrix|...\n");
        return 2;
    }
    return std::strcmp(argv[1], "valid") == 0 ? valid() : run(argv[1]);
}
