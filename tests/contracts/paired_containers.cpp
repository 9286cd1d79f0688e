// Containers that must match (docs/conventions.md): every container overload called with a short
// and with a long partner, in a release build (NDEBUG, so QUAT_ASSERT checks nothing) under
// AddressSanitizer, which ends the program at the first read or write past a container. The
// containers are std::vectors sized exactly, so one element too far is a heap-buffer-overflow.
// Beyond "no overflow", each result is the documented one: the NaN result and unique = false for
// fits, NaN for averages, blends and keyframe paths, empty try_ forms, and the common length for
// batches (the elements past it untouched).
#ifndef NDEBUG
#error "paired_containers.cpp tests release builds: compile it with -DNDEBUG"
#endif

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <vector>

#include <quat/lie/geodesic_mean.hpp>
#include <quat/quat.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>
#include <quat/trajectory.hpp>

namespace {

using quat::dual_quaternion;
using quat::quaternion;
using quat::rotation_matrix;
using quat::vec3;

int failures = 0;

void check(bool condition, const char* what) {
    if (!condition) {
        ++failures;
        std::printf("FAILED: %s\n", what);
    }
}

bool is_nan(const quaternion<double>& q) {
    return std::isnan(q.w) && std::isnan(q.x) && std::isnan(q.y) && std::isnan(q.z);
}
bool is_nan(const dual_quaternion<double>& dq) { return is_nan(dq.real) && is_nan(dq.dual); }

// The element a batch leaves alone: a value no rotation of the inputs produces.
constexpr double untouched = 12345.0;

std::vector<vec3<double>> points(std::size_t n) {
    std::vector<vec3<double>> p;
    for (std::size_t i = 0; i < n; ++i)
        p.push_back({1.0 + double(i), 0.5 * double(i * i), 2.0 - double(i)});
    return p;
}

std::vector<quaternion<double>> rotations(std::size_t n) {
    std::vector<quaternion<double>> q;
    for (std::size_t i = 0; i < n; ++i)
        q.push_back(
            quat::from_rotation_vector(vec3<double>{0.1 * double(i), 0.3, -0.2 * double(i)}));
    return q;
}

std::vector<dual_quaternion<double>> motions(std::size_t n) {
    std::vector<dual_quaternion<double>> m;
    const std::vector<quaternion<double>> q = rotations(n);
    for (std::size_t i = 0; i < n; ++i)
        m.push_back(
            quat::to_dual_quaternion(q[i], vec3<double>{0.2 * double(i), 1.0, -0.5 * double(i)}));
    return m;
}

// Fits: the NaN result with unique = false, and an empty try_.
void fits(std::size_t a, std::size_t b) {
    const auto targets = points(a), sources = points(b);
    const std::vector<double> weights_a(a, 1.0), weights_b(b, 1.0);

    const auto v = quat::align_vectors(targets, sources);
    check(is_nan(v.rotation) && std::isnan(v.rssd) && !v.unique, "align_vectors");
    const auto vw = quat::align_vectors(targets, targets, weights_b);
    check(is_nan(vw.rotation) && std::isnan(vw.rssd) && !vw.unique, "align_vectors with weights");
    const auto vs = quat::align_vectors_with_sensitivity(targets, targets, weights_b);
    check(is_nan(vs.rotation) && !vs.unique && std::isnan(vs.sensitivity(0, 0)) &&
              std::isnan(vs.sensitivity(2, 1)),
          "align_vectors_with_sensitivity");
    check(!quat::try_align_vectors(targets, sources), "try_align_vectors");
    check(!quat::try_align_vectors(targets, targets, weights_b), "try_align_vectors with weights");

    const auto p = quat::align_points(targets, sources);
    check(is_nan(p.motion) && std::isnan(p.rms) && !p.unique, "align_points");
    const auto pw = quat::align_points(targets, targets, weights_b);
    check(is_nan(pw.motion) && std::isnan(pw.rms) && !pw.unique, "align_points with weights");
    const auto s = quat::align_points_with_scale(targets, sources);
    check(is_nan(s.motion) && std::isnan(s.rms) && std::isnan(s.scale) && !s.unique,
          "align_points_with_scale");
    const auto sw = quat::align_points_with_scale(targets, targets, weights_b);
    check(is_nan(sw.motion) && std::isnan(sw.scale) && !sw.unique,
          "align_points_with_scale with weights");
    check(!quat::try_align_points(targets, sources), "try_align_points");
    check(!quat::try_align_points(targets, targets, weights_b), "try_align_points with weights");
    check(!quat::try_align_points_with_scale(targets, sources), "try_align_points_with_scale");
    check(!quat::try_align_points_with_scale(targets, targets, weights_b),
          "try_align_points_with_scale with weights");
    static_cast<void>(weights_a);

    const auto hand = motions(a), eye = motions(b);
    for (const auto method :
         {quat::hand_eye_method::daniilidis, quat::hand_eye_method::rotation_first}) {
        const auto h = quat::hand_eye(hand, eye, method);
        check(is_nan(h.mount) && std::isnan(h.rotation_rms) && std::isnan(h.translation_rms) &&
                  !h.unique,
              "hand_eye");
        check(!quat::try_hand_eye(hand, eye, method), "try_hand_eye");
    }
    const auto poses = quat::hand_eye_from_poses(hand, eye);
    check(is_nan(poses.calibration.mount) && is_nan(poses.target) &&
              std::isnan(poses.calibration.rotation_rms) && !poses.calibration.unique &&
              !poses.refined,
          "hand_eye_from_poses");
    check(!quat::try_hand_eye_from_poses(hand, eye), "try_hand_eye_from_poses");
}

// Averages and blends with weights: NaN, and an empty try_.
void averages(std::size_t a, std::size_t b) {
    const auto q = rotations(a);
    const auto m = motions(a);
    const std::vector<double> w(b, 1.0);
    check(is_nan(quat::mean(q, w)), "mean with weights");
    check(!quat::try_mean(q, w), "try_mean with weights");
    check(is_nan(quat::geodesic_mean(q, w)), "geodesic_mean of rotations with weights");
    check(!quat::try_geodesic_mean(q, w), "try_geodesic_mean of rotations with weights");
    check(is_nan(quat::geodesic_mean(m, w)), "geodesic_mean of motions with weights");
    check(!quat::try_geodesic_mean(m, w), "try_geodesic_mean of motions with weights");
    check(is_nan(quat::blend(m, w)), "blend");
}

// Paths through keyframes: NaN at every time, and an empty try_make.
void paths(std::size_t a, std::size_t b) {
    std::vector<double> times;
    for (std::size_t i = 0; i < a; ++i) times.push_back(double(i));
    const auto q = rotations(b);
    for (const double t : {-1.0, 0.0, 0.5, 1.0, 1.5, 10.0}) {
        check(is_nan(quat::keyframe_slerp(times, q, t)), "keyframe_slerp");
        check(is_nan(quat::keyframe_squad(times, q, t)), "keyframe_squad");
    }
    const quat::rotation_spline<double> spline(times, q);
    check(is_nan(spline(0.5)) && is_nan(spline(1.0)), "rotation_spline");
    check(!quat::rotation_spline<double>::try_make(times, q), "rotation_spline::try_make");
    // Rigid paths through (time, pose) keyframes: NaN poses and states, an empty try_make.
    const auto poses = motions(b);
    const quat::split_keyframe_path<double> split(times, poses);
    const quat::se3_keyframe_path<double> screw(times, poses);
    for (const double t : {-1.0, 0.0, 0.5, 1.0, 10.0}) {
        check(is_nan(split(t)) && is_nan(split.state(t).pose), "split_keyframe_path");
        check(is_nan(screw(t)) && std::isnan(screw.state(t).velocity.x), "se3_keyframe_path");
    }
    check(!quat::split_keyframe_path<double>::try_make(times, poses),
          "split_keyframe_path::try_make");
    check(!quat::se3_keyframe_path<double>::try_make(times, poses), "se3_keyframe_path::try_make");
    // The split B-spline over a and b points: not valid, the NaN sample, an empty try_evaluate.
    const auto r = rotations(a);
    const auto p = points(b);
    const quat::split_bspline<double, 2> spline2(r, p, 0.0, 1.0);
    quat::split_bspline<double, 2>::jacobian_blocks J{};
    quat::split_bspline<double, 2>::jacobian_weights W{};
    check(!spline2.valid(), "split_bspline::valid");
    for (const double t : {0.0, 0.5, 1.0}) {
        check(is_nan(spline2.evaluate(t, &J, nullptr, nullptr, nullptr, &W).rotation) &&
                  std::isnan(J[0](0, 0)) && std::isnan(W[1]),
              "split_bspline::evaluate");
        check(!spline2.try_evaluate(t), "split_bspline::try_evaluate");
    }
}

// Batches: the common length, nothing written past it.
template <class Output>
bool untouched_from(const Output& output, std::size_t first) {
    for (std::size_t i = first; i < output.size(); ++i)
        if (!(output[i].x == untouched)) return false;
    return true;
}

void batches(std::size_t a, std::size_t b) {
    const quaternion<double> q = rotations(3)[2];
    const dual_quaternion<double> dq = motions(3)[2];
    const std::size_t common = a < b ? a : b;
    const auto input = points(a);
    const vec3<double> marker{untouched, untouched, untouched};

    std::vector<vec3<double>> output(b, marker);
    quat::rotate(q, input, output);
    check(untouched_from(output, common), "rotate by a quaternion");
    output.assign(b, marker);
    quat::rotate(quat::to_matrix(q), input, output);
    check(untouched_from(output, common), "rotate by a matrix");
    output.assign(b, marker);
    quat::transform(dq, input, output);
    check(untouched_from(output, common), "transform by a dual quaternion");
    output.assign(b, marker);
    quat::transform(quat::to_homogeneous(dq), input, output);
    check(untouched_from(output, common), "transform by a matrix");

    std::vector<double> ts(a, 0.25);
    std::vector<quaternion<double>> slerped(b, {untouched, untouched, untouched, untouched});
    quat::slerp(quaternion<double>::identity(), q, ts, slerped);
    check(untouched_from(slerped, common), "slerp over many t");

    // Element-wise: each of the three containers in turn is the short one.
    for (int shortest = 0; shortest < 3; ++shortest) {
        const std::size_t n0 = shortest == 0 ? common : a, n1 = shortest == 1 ? common : a,
                          n2 = shortest == 2 ? common : a;
        const std::size_t n = n0 < n1 ? (n0 < n2 ? n0 : n2) : (n1 < n2 ? n1 : n2);
        const auto r = rotations(n0);
        const auto p = points(n1);
        std::vector<vec3<double>> out(n2, marker);
        quat::rotate_each(r, p, out);
        check(untouched_from(out, n), "rotate_each");
        const auto other = rotations(n1);
        std::vector<quaternion<double>> composed(n2, {untouched, untouched, untouched, untouched});
        quat::compose_each(r, other, composed);
        check(untouched_from(composed, n), "compose_each");
    }
    const auto r = rotations(a);
    const double u = untouched;
    std::vector<rotation_matrix<double>> matrices(
        b, rotation_matrix<double>{{{u, u, u}, {u, u, u}, {u, u, u}}});
    quat::to_matrix_each(r, matrices);
    bool kept = true;
    for (std::size_t i = common; i < b; ++i) kept = kept && matrices[i](0, 0) == untouched;
    check(kept, "to_matrix_each");
    std::vector<rotation_matrix<double>> from(a, quat::to_matrix(q));
    std::vector<quaternion<double>> back(b, {untouched, untouched, untouched, untouched});
    quat::to_quaternion_each(from, back);
    check(untouched_from(back, common), "to_quaternion_each");

    if (a >= 2) {
        std::vector<double> times;
        for (std::size_t i = 0; i < a; ++i) times.push_back(double(i));
        const quat::rotation_spline<double> spline(times, rotations(a));
        std::vector<double> at(a, 0.5);
        std::vector<quaternion<double>> values(b, {untouched, untouched, untouched, untouched});
        spline.evaluate(at, values);
        check(untouched_from(values, common), "rotation_spline::evaluate");
        // The keyframe paths' evaluation over many times, into poses and into states.
        const quat::split_keyframe_path<double> split(times, motions(a));
        const quat::se3_keyframe_path<double> screw(times, motions(a));
        const dual_quaternion<double> marked{{untouched, untouched, untouched, untouched},
                                             {untouched, untouched, untouched, untouched}};
        std::vector<dual_quaternion<double>> poses(b, marked);
        quat::keyframe_path_state<double> marked_state{};
        marked_state.pose = marked;
        std::vector<quat::keyframe_path_state<double>> states(b, marked_state);
        const auto untouched_after = [&](const auto& out, const auto& pose_of) {
            for (std::size_t i = common; i < out.size(); ++i)
                if (!(pose_of(out[i]).real.x == untouched)) return false;
            return true;
        };
        const auto pose = [](const dual_quaternion<double>& x) { return x; };
        const auto state_pose = [](const quat::keyframe_path_state<double>& x) { return x.pose; };
        split.evaluate(at, poses);
        check(untouched_after(poses, pose), "split_keyframe_path::evaluate (poses)");
        split.evaluate(at, states);
        check(untouched_after(states, state_pose), "split_keyframe_path::evaluate (states)");
        poses.assign(b, marked);
        states.assign(b, marked_state);
        screw.evaluate(at, poses);
        check(untouched_after(poses, pose), "se3_keyframe_path::evaluate (poses)");
        screw.evaluate(at, states);
        check(untouched_after(states, state_pose), "se3_keyframe_path::evaluate (states)");
    }
}

}  // namespace

int main() {
    // Short and long partners, including an empty one.
    const std::size_t sizes[][2] = {{3, 5}, {5, 3}, {0, 4}, {4, 0}, {1, 2}, {7, 6}};
    for (const auto& size : sizes) {
        fits(size[0], size[1]);
        averages(size[0], size[1]);
        paths(size[0], size[1]);
        batches(size[0], size[1]);
    }
    if (failures != 0) {
        std::printf("%d checks failed\n", failures);
        return 1;
    }
    std::printf("every container overload stayed within its containers\n");
    return 0;
}
