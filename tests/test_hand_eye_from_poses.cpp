// Specification of registration/hand_eye.hpp's hand_eye_from_poses: the mount and the target's
// pose from absolute hand and target poses, against synthetic ground truth; agreement with
// hand_eye on the same motions; the refinement at least as accurate as the closed form on noisy
// poses; the answer independent of the unit of length; degenerate poses and bad input.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <quat/registration/hand_eye.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_hand_eye_from_poses {

using quat::dual_quaternion;
using quat::quaternion;
using quat::vec3;
using quat::test::eps;

namespace {

template <class T>
struct poses {
    std::vector<dual_quaternion<T>> hands, targets;
    dual_quaternion<T> world;  // the target in the base
};

/// The hand at `count` random poses (turns of 0.1 to 2 rad about random axes, translations of
/// standard deviation 0.5), the sensor on it at `mount`, a fixed target 2 m away in the base:
/// S_j = X^-1 H_j^-1 W, each measured with an error of up to 2 `angle` radians and 2 `offset`
/// (uniform) in random directions.
template <class T>
poses<T> poses_for(quat::test::random_rotations& random, const dual_quaternion<T>& mount,
                   std::size_t count, double angle = 0, double offset = 0) {
    poses<T> p;
    p.world = random.rigid_motion<T>(2.0);
    for (std::size_t j = 0; j < count; ++j) {
        const vec3<T> axis = random.unit_vector<T>();  // one statement each: a fixed order
        const T turned = random.uniform<T>(0.1, 2.0);
        const vec3<T> translation = random.vector<T>(0.5);
        const dual_quaternion<T> hand =
            quat::to_dual_quaternion(quat::from_rotation_vector(axis * turned), translation);
        p.hands.push_back(hand);
        dual_quaternion<T> s = quat::normalize(quat::inverse(hand * mount) * p.world);
        if (angle > 0 || offset > 0) {
            const vec3<T> turn_axis = random.unit_vector<T>();
            const T turn = random.uniform<T>(0.0, 2 * angle);
            const vec3<T> way = random.unit_vector<T>();
            const T moved = random.uniform<T>(0.0, 2 * offset);
            s = quat::to_dual_quaternion(
                quat::from_rotation_vector(turn_axis * turn) * quat::rotation_of(s),
                quat::translation_of(s) + way * moved);
        }
        p.targets.push_back(s);
    }
    return p;
}

/// The motions between consecutive poses, as docs/rigid-motions.md forms them for hand_eye.
template <class T>
void consecutive_motions(const poses<T>& p, std::vector<dual_quaternion<T>>& a,
                         std::vector<dual_quaternion<T>>& b) {
    for (std::size_t j = 0; j + 1 < p.hands.size(); ++j) {
        a.push_back(quat::normalize(quat::inverse(p.hands[j + 1]) * p.hands[j]));
        b.push_back(quat::normalize(p.targets[j + 1] * quat::inverse(p.targets[j])));
    }
}

template <class T>
double rotation_error(const dual_quaternion<T>& x, const dual_quaternion<T>& truth) {
    return double(quat::angle_between(x.real, truth.real));
}

template <class T>
double translation_error(const dual_quaternion<T>& x, const dual_quaternion<T>& truth) {
    return double(quat::norm(quat::translation_of(x) - quat::translation_of(truth)));
}

template <class T>
bool all_nan(const quat::hand_eye_with_target<T>& r) {
    const quat::hand_eye_calibration<T>& c = r.calibration;
    const T parts[] = {c.mount.real.w,    c.mount.real.x,  c.mount.real.y,  c.mount.real.z,
                       c.mount.dual.w,    c.mount.dual.x,  c.mount.dual.y,  c.mount.dual.z,
                       r.target.real.w,   r.target.real.z, r.target.dual.x, c.rotation_rms,
                       c.translation_rms, c.ambiguity};
    for (const T part : parts)
        if (!std::isnan(part)) return false;
    return !c.unique && !r.refined;
}

}  // namespace

TEMPLATE_TEST_CASE(
    "hand_eye_from_poses: exact poses give the mount and the target within a few "
    "eps",
    "[hand_eye][poses]", float, double) {
    using T = TestType;
    quat::test::random_rotations random(51);
    double worst[4] = {};
    for (int k = 0; k < 50; ++k) {
        const dual_quaternion<T> mount = random.rigid_motion<T>(0.2);
        const poses<T> p = poses_for(random, mount, 7);
        const quat::hand_eye_with_target<T> r = quat::hand_eye_from_poses(p.hands, p.targets);
        CHECK(r.calibration.unique);
        // Rotations in eps, translations in eps of the scene's size (about 2).
        const double errors[4] = {rotation_error(r.calibration.mount, mount) / double(eps<T>),
                                  translation_error(r.calibration.mount, mount) / double(eps<T>),
                                  rotation_error(r.target, p.world) / double(eps<T>),
                                  translation_error(r.target, p.world) / 2 / double(eps<T>)};
        for (int i = 0; i < 4; ++i) worst[i] = std::max(worst[i], errors[i]);
        CHECK(r.calibration.rotation_rms <= 64 * eps<T>);
    }
    CAPTURE(worst[0], worst[1], worst[2], worst[3]);
    for (const double w : worst) CHECK(w <= 32);
}

TEST_CASE("hand_eye_from_poses agrees with hand_eye on exact poses", "[hand_eye][poses]") {
    quat::test::random_rotations random(52);
    for (int k = 0; k < 20; ++k) {
        const dual_quaternion<double> mount = random.rigid_motion<double>(0.2);
        const poses<double> p = poses_for(random, mount, 6);
        std::vector<dual_quaternion<double>> a, b;
        consecutive_motions(p, a, b);
        for (const auto method :
             {quat::hand_eye_method::daniilidis, quat::hand_eye_method::rotation_first}) {
            const auto relative = quat::hand_eye(a, b, method);
            const auto absolute = quat::hand_eye_from_poses(p.hands, p.targets);
            CHECK(rotation_error(relative.mount, absolute.calibration.mount) <= 32 * eps<double>);
            CHECK(translation_error(relative.mount, absolute.calibration.mount) <=
                  32 * eps<double>);
            CHECK(absolute.calibration.unique == relative.unique);
            CHECK(absolute.calibration.rotation_rms <= 64 * eps<double>);
            CHECK(absolute.calibration.translation_rms <= 256 * eps<double>);
        }
    }
}

TEST_CASE("hand_eye_from_poses: noisy poses give a mount at least as accurate as the closed form",
          "[hand_eye][poses]") {
    // 1 degree and 10 mm of error on every measured target pose (the target about 2 m away), 4, 11
    // and 51 poses, 40 sets each: the refinement's RMS errors against those of hand_eye's
    // rotation_first on the consecutive motions of the same poses (the closed form it starts from).
    const double degree = quat::numbers::pi / 180;
    for (const std::size_t count : {4, 11, 51}) {
        quat::test::random_rotations random(53 + count);
        double closed[2] = {}, refined[2] = {};
        int improved = 0;
        for (int k = 0; k < 40; ++k) {
            const dual_quaternion<double> mount = random.rigid_motion<double>(0.2);
            const poses<double> p = poses_for(random, mount, count, degree, 0.01);
            std::vector<dual_quaternion<double>> a, b;
            consecutive_motions(p, a, b);
            const auto x = quat::hand_eye(a, b, quat::hand_eye_method::rotation_first);
            const auto r = quat::hand_eye_from_poses(p.hands, p.targets);
            improved += r.refined ? 1 : 0;
            closed[0] += std::pow(rotation_error(x.mount, mount), 2);
            closed[1] += std::pow(translation_error(x.mount, mount), 2);
            refined[0] += std::pow(rotation_error(r.calibration.mount, mount), 2);
            refined[1] += std::pow(translation_error(r.calibration.mount, mount), 2);
        }
        CAPTURE(count, improved, std::sqrt(closed[0] / 40), std::sqrt(refined[0] / 40),
                std::sqrt(closed[1] / 40), std::sqrt(refined[1] / 40));
        CHECK(improved >= 38);
        CHECK(refined[0] <= closed[0]);
        CHECK(refined[1] <= closed[1]);
    }
}

/// The sums of squared residuals of the model (docs/rigid-motions.md), sum |r_j|^2 and sum |e_j|^2,
/// in long double, for X = (exp(a) R_X, t_X + b) and W = (exp(c) R_W, t_W + d) with
/// at = (a, b, c, d).
struct residual_sums {
    long double rotation, translation;
};

residual_sums sums_at(const poses<double>& p, const dual_quaternion<double>& mount,
                      const dual_quaternion<double>& world, const long double (&at)[12]) {
    using L = long double;
    const auto moved = [&at](const dual_quaternion<double>& m, int first) {
        const quaternion<L> turn =
            quat::from_rotation_vector(vec3<L>{at[first], at[first + 1], at[first + 2]});
        const dual_quaternion<L> wide(m);
        const vec3<L> shift{at[first + 3], at[first + 4], at[first + 5]};
        return quat::to_dual_quaternion(turn * quat::rotation_of(wide),
                                        quat::translation_of(wide) + shift);
    };
    const dual_quaternion<L> x = moved(mount, 0), w = moved(world, 6);
    residual_sums s{0, 0};
    for (std::size_t j = 0; j < p.hands.size(); ++j) {
        const dual_quaternion<L> predicted =
            quat::inverse(x) * quat::inverse(dual_quaternion<L>(p.hands[j])) * w;
        const dual_quaternion<L> measured(p.targets[j]);
        const vec3<L> r = quat::to_rotation_vector(quat::rotation_of(measured) *
                                                   quat::conjugate(quat::rotation_of(predicted)));
        const vec3<L> e = quat::translation_of(measured) - quat::translation_of(predicted);
        s.rotation += quat::dot(r, r);
        s.translation += quat::dot(e, e);
    }
    return s;
}

TEST_CASE("hand_eye_from_poses: a stationary point of the weighted cost, by finite differences",
          "[hand_eye][poses]") {
    // The gradients of sum |r|^2 and sum |e|^2 over the 12 unknowns by central differences in
    // long double, independent of the refinement's Jacobians, each component times the noise of
    // its kind / sqrt(poses) (so in units of the answer's uncertainty). At the answer of a weighted
    // least-squares fit they are opposite: g_r + lambda g_t = 0 for the weight lambda it used.
    // With many poses that weight is the variance ratio of the answer's own residuals and the
    // answer the maximum of the likelihood with the variances unknown, where the concentrated cost
    // log(sum |r|^2) + log(sum |e|^2) is stationary (checked against the closed form's gradient).
    // With few poses that likelihood has no maximum (it grows without bound as one kind of
    // residual goes to 0); the second round's weight, from the first round's residuals, then
    // differs from the final residuals' ratio (measured: up to 22x at 4 poses, 2.6x at 11).
    const double degree = quat::numbers::pi / 180;
    for (const std::size_t count : {4, 11, 51}) {
        quat::test::random_rotations random(59 + count);
        double worst_opposite = 0, worst_ratio = 1, worst_ml = 0, closed_ml = 1e300;
        for (int k = 0; k < 10; ++k) {
            const dual_quaternion<double> mount = random.rigid_motion<double>(0.2);
            const poses<double> p = poses_for(random, mount, count, degree, 0.01);
            const auto r = quat::hand_eye_from_poses(p.hands, p.targets);
            REQUIRE(r.refined);
            std::vector<dual_quaternion<double>> a, b;
            consecutive_motions(p, a, b);
            const auto closed = quat::hand_eye(a, b, quat::hand_eye_method::rotation_first);
            const double units[2] = {degree / std::sqrt(double(count)),
                                     0.01 / std::sqrt(double(count))};
            for (int which = 0; which < 2; ++which) {
                const dual_quaternion<double> x = which == 0 ? r.calibration.mount : closed.mount;
                const dual_quaternion<double> w =
                    which == 0 ? r.target : quat::normalize(p.hands[0] * x * p.targets[0]);
                const long double zero[12] = {};
                const residual_sums at = sums_at(p, x, w, zero);
                long double gr[12], gt[12];
                for (int i = 0; i < 12; ++i) {
                    const long double h = 1e-6L;
                    long double up[12] = {}, down[12] = {};
                    up[i] = h;
                    down[i] = -h;
                    const residual_sums u = sums_at(p, x, w, up), d = sums_at(p, x, w, down);
                    gr[i] = (u.rotation - d.rotation) / (2 * h) * units[i % 6 < 3 ? 0 : 1];
                    gt[i] = (u.translation - d.translation) / (2 * h) * units[i % 6 < 3 ? 0 : 1];
                }
                long double rt = 0, tt = 0, rr = 0, ml = 0;
                for (int i = 0; i < 12; ++i) {
                    rt += gr[i] * gt[i];
                    tt += gt[i] * gt[i];
                    rr += gr[i] * gr[i];
                    ml = std::max(ml, std::abs(gr[i] / at.rotation + gt[i] / at.translation));
                }
                if (which == 1) {
                    closed_ml = std::min(closed_ml, double(ml));
                    continue;
                }
                worst_ml = std::max(worst_ml, double(ml));
                const long double lambda = -rt / tt;
                long double off = 0;
                for (int i = 0; i < 12; ++i) off += std::pow(gr[i] + lambda * gt[i], 2.0L);
                worst_opposite = std::max(worst_opposite, double(std::sqrt(off / rr)));
                // lambda against the variance ratio of the answer's residuals, as a factor >= 1.
                const double ratio = double(lambda / (at.rotation / at.translation));
                worst_ratio = std::max(worst_ratio, std::max(ratio, 1 / ratio));
            }
        }
        CAPTURE(count, worst_opposite, worst_ratio, worst_ml, closed_ml);
        // The rounds end at steps below 2^-10 of the noise: sqrt(poses) / 1024 of the uncertainty.
        CHECK(worst_opposite <= 1e-2);
        if (count > 50) {
            CHECK(worst_ratio <= 1.1);
            CHECK(worst_ml * 100 <= closed_ml);
        }
    }
}

TEST_CASE("hand_eye_from_poses: the same answer in every unit of length", "[hand_eye][poses]") {
    quat::test::random_rotations random(54);
    const double degree = quat::numbers::pi / 180;
    const dual_quaternion<double> mount = random.rigid_motion<double>(0.2);
    const poses<double> p = poses_for(random, mount, 12, 0.5 * degree, 0.005);
    const auto x = quat::hand_eye_from_poses(p.hands, p.targets);
    REQUIRE(x.refined);
    for (const double scale : {1e-150, 1e-3, 0.3, 1e3, 1e150}) {
        poses<double> s = p;
        for (dual_quaternion<double>& h : s.hands) h.dual = h.dual * scale;
        for (dual_quaternion<double>& t : s.targets) t.dual = t.dual * scale;
        const auto y = quat::hand_eye_from_poses(s.hands, s.targets);
        CAPTURE(scale);
        CHECK(y.refined);
        CHECK(rotation_error(x.calibration.mount, y.calibration.mount) <= 1e-9);
        CHECK(quat::norm(quat::translation_of(y.calibration.mount) / scale -
                         quat::translation_of(x.calibration.mount)) <= 1e-9);
        CHECK(quat::norm(quat::translation_of(y.target) / scale - quat::translation_of(x.target)) <=
              1e-8);
    }
}

TEST_CASE("hand_eye_from_poses: deterministic", "[hand_eye][poses]") {
    quat::test::random_rotations random(55);
    const dual_quaternion<double> mount = random.rigid_motion<double>(0.2);
    const poses<double> p = poses_for(random, mount, 9, 0.01, 0.01);
    const auto x = quat::hand_eye_from_poses(p.hands, p.targets);
    const auto y = quat::hand_eye_from_poses(p.hands, p.targets);
    CHECK(x.calibration.mount == y.calibration.mount);
    CHECK(x.target == y.target);
}

TEST_CASE("hand_eye_from_poses: a hand turning about one axis keeps the closed form",
          "[hand_eye][poses]") {
    quat::test::random_rotations random(56);
    const dual_quaternion<double> mount = random.rigid_motion<double>(0.2);
    const vec3<double> axis = random.unit_vector<double>();
    const dual_quaternion<double> world = random.rigid_motion<double>(2.0);
    poses<double> p;
    for (int j = 0; j < 8; ++j) {
        const dual_quaternion<double> hand = quat::to_dual_quaternion(
            quat::from_rotation_vector(axis * random.uniform<double>(-2.0, 2.0)),
            random.vector<double>(0.5));
        p.hands.push_back(hand);
        p.targets.push_back(quat::normalize(quat::inverse(hand * mount) * world));
    }
    std::vector<dual_quaternion<double>> a, b;
    consecutive_motions(p, a, b);
    const auto relative = quat::hand_eye(a, b, quat::hand_eye_method::rotation_first);
    const auto r = quat::hand_eye_from_poses(p.hands, p.targets);
    CHECK_FALSE(r.calibration.unique);
    CHECK_FALSE(r.refined);
    CHECK(rotation_error(r.calibration.mount, relative.mount) <= 64 * eps<double>);
    CHECK(translation_error(r.calibration.mount, relative.mount) <= 64 * eps<double>);
}

TEST_CASE("hand_eye_from_poses: few poses, NaN, bad input", "[hand_eye][poses]") {
    quat::test::random_rotations random(57);
    const dual_quaternion<double> mount = random.rigid_motion<double>(0.2);
    const poses<double> p = poses_for(random, mount, 6);
    REQUIRE(quat::try_hand_eye_from_poses(p.hands, p.targets));
    CHECK(quat::try_hand_eye_from_poses(p.hands, p.targets)->calibration.mount ==
          quat::hand_eye_from_poses(p.hands, p.targets).calibration.mount);

    const std::vector<dual_quaternion<double>> none;
    const auto empty = quat::hand_eye_from_poses(none, none);
    CHECK(empty.calibration.mount == dual_quaternion<double>::identity());
    CHECK(empty.target == dual_quaternion<double>::identity());
    CHECK(empty.calibration.rotation_rms == 0);
    CHECK(empty.calibration.ambiguity == 1);
    CHECK_FALSE(empty.calibration.unique);
    CHECK_FALSE(quat::try_hand_eye_from_poses(none, none));

    const std::vector<dual_quaternion<double>> one_h{p.hands[0]}, one_t{p.targets[0]};
    const auto one = quat::hand_eye_from_poses(one_h, one_t);
    CHECK(one.calibration.mount == dual_quaternion<double>::identity());
    CHECK(translation_error(one.target, quat::normalize(p.hands[0] * p.targets[0])) == 0);
    CHECK_FALSE(one.calibration.unique);
    const std::vector<dual_quaternion<double>> two_h{p.hands[0], p.hands[1]},
        two_t{p.targets[0], p.targets[1]};
    CHECK_FALSE(quat::try_hand_eye_from_poses(two_h, two_t));

    const double nan = std::numeric_limits<double>::quiet_NaN();
    poses<double> bad = p;
    bad.targets[3].dual.y = nan;
    CHECK(all_nan(quat::hand_eye_from_poses(bad.hands, bad.targets)));
    CHECK_FALSE(quat::try_hand_eye_from_poses(bad.hands, bad.targets));
    poses<double> infinite = p;
    infinite.hands[0].real.x = std::numeric_limits<double>::infinity();
    CHECK(all_nan(quat::hand_eye_from_poses(infinite.hands, infinite.targets)));
    CHECK_FALSE(quat::try_hand_eye_from_poses(infinite.hands, infinite.targets));
    poses<double> scaled = p;
    scaled.hands[1].real = scaled.hands[1].real * 2.0;
    CHECK_FALSE(quat::try_hand_eye_from_poses(scaled.hands, scaled.targets));
    const std::vector<dual_quaternion<double>> fewer(p.targets.begin(), p.targets.end() - 1);
    CHECK_FALSE(quat::try_hand_eye_from_poses(p.hands, fewer));
}

#ifdef NDEBUG
// Debug builds stop at the precondition (tests/contracts).
TEST_CASE("a release-build hand_eye_from_poses of lists of different sizes is NaN",
          "[hand_eye][poses][nan]") {
    quat::test::random_rotations random(58);
    const dual_quaternion<double> mount = random.rigid_motion<double>(0.2);
    const poses<double> p = poses_for(random, mount, 6);
    const std::vector<dual_quaternion<double>> fewer(p.targets.begin(), p.targets.end() - 1);
    CHECK(all_nan(quat::hand_eye_from_poses(p.hands, fewer)));
    CHECK(all_nan(quat::hand_eye_from_poses(fewer, p.hands)));
}
#endif

}  // namespace test_hand_eye_from_poses
