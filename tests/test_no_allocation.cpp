// No path of the library allocates: every public operation runs here between two reads of a counter
// that every allocation of this test binary increments (support/allocation_counter.hpp).
#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

#include <quat/lie/geodesic_mean.hpp>
#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>
#include <quat/quat.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>
#include <quat/trajectory.hpp>

#include "support/allocation_counter.hpp"
#include "support/catch.hpp"
#include "support/random.hpp"

namespace test_no_allocation {

TEST_CASE("no operation allocates: scalar, checked and batch paths", "[allocation]") {
    quat::test::random_rotations random;
    const quat::quatf a = random.unit_quaternion<float>(), b = random.unit_quaternion<float>();
    const std::size_t n = 3000;  // beyond the 256-point blocks of the batch paths
    std::vector<quat::vec3<float>> points(n, quat::vec3<float>{1, 2, 3}), out(n);
    std::vector<float> xs(n, 1.0f), ys(n, 2.0f), zs(n, 3.0f), ox(n), oy(n), oz(n), ts(n, 0.25f);
    std::vector<quat::quatf> factors(n, a), slerped(n);
    std::vector<quat::dual_quaternionf> bones(n);
    // The streaming path (beyond 16 MiB) is its own branch; allocate its arrays before counting.
    const std::size_t big = (std::size_t(16) << 20) / sizeof(quat::vec3<float>) + 7;
    std::vector<quat::vec3<float>> big_points(big, quat::vec3<float>{1, 0, 0}), big_out(big);
    std::vector<quat::rotation_matrix<float>> matrices(n);

    // The counter must see a probe allocation, or the check below would prove nothing. (A direct
    // call of operator new, which unlike a new-expression the compiler may not leave out.)
    const long probe = allocations.load();
    ::operator delete(::operator new(16));
    const long probed = allocations.load();
    REQUIRE(probed == probe + 1);

    const long before = allocations.load();
    float sink = 0;
    const quat::rotation_matrix<float> m = quat::to_matrix(a);
    sink += quat::rotate(a, quat::vec3<float>{1, 2, 3}).x + quat::rotate(m, points[0]).y;
    sink += quat::to_quaternion(m).w + quat::to_axis_angle(a).angle + quat::to_axis_angle(m).angle;
    sink += quat::to_rotation_vector(a).x + quat::from_rotation_vector(points[0]).w;
    sink += quat::to_quaternion(quat::euler<float>{0.1f, 0.2f, 0.3f}).x;
    sink += quat::to_euler<quat::sequence::zxz, quat::frame::extrinsic>(a)[1];
    sink += quat::extract_euler<quat::sequence::xyz>(a).angles[0];
    sink += quat::slerp(a, b, 0.3f).w + quat::slerp(a, b, 1.7f).w + quat::nlerp(a, b, 0.3f).w;
    sink += quat::slerp_fast(a, b, 0.3f).w + quat::nearest_rotation(m)(0, 0);
    sink += quat::try_normalize(a)->w + quat::try_inverse(a)->w + quat::try_to_quaternion(m)->w;
    sink += quat::try_nearest_rotation(m).has_value() ? 1.0f : 0.0f;
    quat::rotate(a, points, out);
    quat::rotate(m, points, points);
    quat::rotate(a, quat::soa_points<const float>{xs.data(), ys.data(), zs.data(), n},
                 quat::soa_points<float>{ox.data(), oy.data(), oz.data(), n});
    quat::rotate(a, big_points, big_out);
    sink += quat::compose(factors).w;
    quat::slerp(a, b, ts, slerped);
    // Aligning, averaging, sampling and motion.
    const quat::vec3<float> u{1, 2, 3}, v{-3, 1, 2};
    sink += quat::rotation_between(u, v).w + quat::try_rotation_between(u, v)->w;
    sink += quat::look_rotation(u, v).w + quat::try_look_rotation(u, v)->w;
    sink += quat::align_vectors(points, out).rotation.w + quat::align_vectors(points, out, xs).rssd;
    sink += quat::align_vectors_with_sensitivity(points, out, xs).sensitivity(0, 0);
    sink += quat::mean(factors).w + quat::mean(factors, xs).w + quat::try_mean(factors, xs)->w;
    std::minstd_rand engine(7);
    sink += quat::random_rotation<float>(engine).w;
    sink += quat::swing_twist(a, u).twist.w + quat::pow(a, 0.3f).w;
    sink += quat::rotate_towards(a, b, 0.1f).w + quat::body_angular_velocity(a, b, 0.1f).x;
    sink += quat::integrate_world(a, u, 0.1f).w + quat::to_mrp(a).x + quat::from_mrp(u).w;
    sink += quat::to_euler(a, quat::euler<float>{0.1f, 0.2f, 0.3f})[0];
    // Rigid motions.
    const auto da = quat::to_dual_quaternion(a, u), db = quat::to_dual_quaternion(b, v);
    sink += (da * db).dual.x + quat::inverse(da).dual.y + quat::normalize(db).dual.z;
    sink += quat::try_normalize(da)->real.w + quat::transform(da, u).x;
    sink += quat::to_dual_quaternion(quat::to_homogeneous(da)).real.w;
    sink += quat::try_to_dual_quaternion(quat::to_homogeneous(db))->dual.w;
    sink += quat::from_screw(quat::to_screw(da)).dual.x + quat::sclerp(da, db, 0.3f).dual.y;
    for (quat::dual_quaternionf& bone : bones) bone = da;
    sink += quat::blend(bones, xs).real.w + quat::compose(bones).real.x;
    quat::transform(da, points, out);
    quat::transform(quat::to_homogeneous(db), big_points, big_out);
    quat::transform(da, quat::soa_points<const float>{xs.data(), ys.data(), zs.data(), n},
                    quat::soa_points<float>{ox.data(), oy.data(), oz.data(), n});
    // Per-element batches (batch/elementwise.hpp).
    quat::rotate_each(factors, points, out);
    quat::rotate_each(factors.data(), points.data(), points.data(), n);
    quat::rotate_each(
        quat::soa_quaternions<const float>{xs.data(), ys.data(), zs.data(), ts.data(), n},
        quat::soa_points<const float>{xs.data(), ys.data(), zs.data(), n},
        quat::soa_points<float>{ox.data(), oy.data(), oz.data(), n});
    quat::compose_each(factors, factors, slerped);
    quat::compose_each(factors.data(), slerped.data(), slerped.data(), n);
    quat::to_matrix_each(factors, matrices);
    quat::to_quaternion_each(matrices.data(), slerped.data(), n);
    sink += out[1].x + ox[2] + slerped[3].w + matrices[4](0, 0);
    const long after = allocations.load();

    CHECK(after == before);
    CHECK(std::isfinite(sink));  // every result above is finite (and kept alive)
}

TEST_CASE("keyframe paths allocate only when a rotation_spline is built", "[allocation]") {
    std::vector<float> times(40), ts(500);
    std::vector<quat::quatf> keyframes(40), out(500);
    for (std::size_t i = 0; i < times.size(); ++i) {
        times[i] = 0.25f * float(i) + 0.01f * float(i % 3);
        keyframes[i] = quat::from_rotation_vector(quat::vec3<float>{0.3f * float(i), 0.1f, 0.0f});
    }
    for (std::size_t k = 0; k < ts.size(); ++k) ts[k] = 0.02f * float(k) - 0.5f;
    const long start = allocations.load();
    const quat::rotation_spline<float> spline(times, keyframes);
    const long built = allocations.load();
    CHECK(built - start == 4);  // the documented three kept arrays and one temporary

    float sink = 0;
    const quat::quatf a = keyframes[1], b = keyframes[2], c = keyframes[3], d = keyframes[4];
    sink += quat::squad(a, quat::squad_control(a, b, c), quat::squad_control(b, c, d), d, 0.4f).w;
    sink += quat::keyframe_slerp(times, keyframes, 3.3f).w;
    sink += spline(2.2f).w + spline.angular_velocity(2.2f).x + spline.angular_acceleration(2.2f).y;
    spline.evaluate(ts, out);
    sink += out[100].w;
    CHECK(allocations.load() == built);
    CHECK(std::isfinite(sink));
}

TEST_CASE("the estimation families allocate nothing: Lie groups, means, registration, hand-eye",
          "[allocation]") {
    quat::test::random_rotations random;
    const std::size_t n = 600;  // beyond the registration's blocks of 256 pairs
    std::vector<quat::vec3<double>> sources(n), targets(n);
    std::vector<quat::quatd> rotations(n);
    std::vector<quat::dual_quaterniond> motions(n), hand(8), eye(8);
    std::vector<double> weights(n, 1.5);
    const quat::dual_quaterniond mount = quat::to_dual_quaternion(
        random.unit_quaternion<double>(), quat::vec3<double>{0.1, 0.2, 0.3});
    for (std::size_t i = 0; i < n; ++i) {
        sources[i] = quat::vec3<double>{double(i % 7), double(i % 11) - 5.0, double(i % 5) * 0.5};
        targets[i] = quat::transform(mount, sources[i]);
        rotations[i] = quat::slerp(quat::quatd::identity(), random.unit_quaternion<double>(), 0.2);
        motions[i] = quat::to_dual_quaternion(rotations[i], sources[i]);
    }
    for (std::size_t i = 0; i < hand.size(); ++i) {
        hand[i] = quat::to_dual_quaternion(random.unit_quaternion<double>(), sources[i]);
        eye[i] = quat::inverse(mount) * hand[i] * mount;
    }
    const quat::quatd a = rotations[1], b = rotations[2];
    const quat::dual_quaterniond x = motions[3], y = motions[4];
    const quat::vec3<double> w{0.3, -0.2, 0.5};
    const quat::se3::twist<double> t{{0.1, 0.2, -0.3}, w};

    const long before = allocations.load();
    double sink = 0;
    quat::matrix<double, 3, 3> j3{}, k3{};
    quat::matrix<double, 6, 6> j6{}, k6{};
    quat::matrix<double, 3, 6> j36{};
    sink += quat::so3::exp(w, &j3).w + quat::so3::log(a, &j3).x + j3(1, 2);
    sink += quat::so3::plus(a, w, &j3, &k3).y + quat::so3::minus(b, a, &j3, &k3).z;
    sink += quat::so3::plus_left(a, w, &k3, &j3).w + quat::so3::minus_left(b, a, &j3, &k3).x;
    sink += quat::so3::compose(a, b, &j3, &k3).w + quat::so3::inverse(a, &j3).x;
    sink += quat::so3::act(a, w, &j3, &k3).y + quat::so3::between(a, b, &j3, &k3).z;
    sink += quat::so3::right_jacobian_inverse(w)(0, 0) + quat::so3::left_jacobian(w)(1, 1);
    sink += quat::so3::adjoint(a)(2, 2) + quat::so3::vee(quat::so3::hat(w)).x;
    sink += quat::se3::exp(t, &j6).real.w + quat::se3::log(x, &j6).linear.x + j6(5, 5);
    sink += quat::se3::log(quat::to_homogeneous(x), &j6).angular.y;
    sink += quat::se3::plus(x, t, &j6, &k6).dual.x + quat::se3::minus(y, x, &j6, &k6).angular.z;
    sink += quat::se3::plus_left(x, t, &k6, &j6).real.x;
    sink += quat::se3::minus_left(y, x, &j6, &k6).linear.y;
    sink += quat::se3::compose(x, y, &j6, &k6).real.y + quat::se3::inverse(x, &j6).dual.z;
    sink += quat::se3::act(x, w, &j36, &j3).z + quat::se3::between(x, y, &j6, &k6).real.z;
    sink += quat::se3::adjoint(x)(3, 3) + quat::se3::right_jacobian_inverse(t)(4, 4);
    sink += quat::geodesic_mean(rotations).w + quat::geodesic_mean(rotations, weights).x;
    sink += quat::try_geodesic_mean(rotations)->y + quat::geodesic_mean(motions).dual.x;
    sink += quat::try_geodesic_mean(motions, weights)->real.w;
    sink += quat::align_points(targets, sources).rms +
            quat::align_points(targets, sources, weights).rms;
    sink += quat::align_points_with_scale(targets, sources).scale;
    sink += quat::try_align_points(targets, sources)->motion.real.w;
    sink += quat::try_align_points_with_scale(targets, sources, weights)->scale;
    sink += quat::hand_eye(hand, eye).mount.real.w;
    sink += quat::hand_eye(hand, eye, quat::hand_eye_method::rotation_first).rotation_rms;
    sink += quat::try_hand_eye(hand, eye)->translation_rms;
    const long after = allocations.load();

    CHECK(after == before);
    CHECK(std::isfinite(sink));
}

TEST_CASE("keyframe paths of rigid motions allocate nothing when evaluated", "[allocation]") {
    std::vector<double> times(20), ts(300);
    std::vector<quat::dual_quaterniond> keyframes(20), poses(300);
    std::vector<quat::keyframe_path_state<double>> states(300);
    for (std::size_t i = 0; i < times.size(); ++i) {
        times[i] = 0.25 * double(i) + 0.01 * double(i % 3);
        keyframes[i] = quat::to_dual_quaternion(
            quat::from_rotation_vector(quat::vec3<double>{0.3 * double(i), 0.1, 0.0}),
            quat::vec3<double>{double(i), 0.5 * double(i % 2), 0.0});
    }
    for (std::size_t k = 0; k < ts.size(); ++k) ts[k] = 0.02 * double(k) - 0.5;
    const quat::split_keyframe_path<double> split(times, keyframes);
    const quat::se3_keyframe_path<double> coupled(times, keyframes);
    const long built = allocations.load();
    double sink = split(2.2).real.w + split.state(2.2).acceleration.x + coupled(2.2).dual.x +
                  coupled.state(2.2).body_angular_acceleration.y;
    split.evaluate(ts, poses);
    split.evaluate(ts, states);
    sink += poses[100].real.w + states[200].velocity.x;
    coupled.evaluate(ts, poses);
    coupled.evaluate(ts, states);
    sink += poses[100].real.w + states[200].velocity.x;
    CHECK(allocations.load() == built);
    CHECK(std::isfinite(sink));
}

}  // namespace test_no_allocation
