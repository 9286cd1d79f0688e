// Specification of registration/align_points.hpp: point-set registration against exact data, a long
// double solution of the same least-squares problem, Eigen's umeyama (SVD), degenerate and
// far-from-origin sets, weights and bad input.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

// g++ 12 at -O3 reports a false -Warray-bounds (and, with AVX-512, -Wmaybe-uninitialized) inside
// Eigen::umeyama's packet loads of its 3-vector means; the reference is Eigen's code, not quat's.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <Eigen/Geometry>
#include <quat/registration/align_points.hpp>
#include <quat/rigid/homogeneous_matrix.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_align_points {

using quat::dual_quaternion;
using quat::quaternion;
using quat::vec3;
using quat::test::eps;

namespace {

template <class T>
struct point_pairs {
    std::vector<vec3<T>> targets, sources;
};

/// count points around `center` with Gaussian spread, and their images scale R p + t.
template <class T>
point_pairs<T> exact_pairs(quat::test::random_rotations& rng, const quaternion<T>& q,
                           const vec3<T>& t, T scale, vec3<T> center, double spread,
                           std::size_t count) {
    point_pairs<T> p;
    for (std::size_t i = 0; i < count; ++i) {
        const vec3<T> s = center + rng.vector<T>(spread);
        p.sources.push_back(s);
        p.targets.push_back(quat::rotate(q, s) * scale + t);
    }
    return p;
}

template <class T>
std::vector<vec3<long double>> widened(const std::vector<vec3<T>>& v) {
    return std::vector<vec3<long double>>(v.begin(), v.end());
}

/// Angle between a result's rotation and a long double one, in units of T's epsilon.
template <class T>
double angle_in_eps(const quaternion<T>& q, const quaternion<long double>& reference) {
    return double(quat::angle_between(quaternion<long double>(q), reference)) / double(eps<T>);
}

template <class T>
using eigen_points = Eigen::Matrix<T, 3, Eigen::Dynamic>;

template <class T>
eigen_points<T> to_eigen(const std::vector<vec3<T>>& v) {
    eigen_points<T> m(3, Eigen::Index(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) {
        const auto c = Eigen::Index(i);
        m(0, c) = v[i].x;
        m(1, c) = v[i].y;
        m(2, c) = v[i].z;
    }
    return m;
}

}  // namespace

TEMPLATE_TEST_CASE("exact data: the motion and scale of the long double solution within a few eps",
                   "[align_points]", float, double) {
    using T = TestType;
    quat::test::random_rotations rng(11);
    double worst_rigid = 0, worst_similarity = 0, worst_scale = 0;
    for (int k = 0; k < 100; ++k) {
        const quaternion<T> q = rng.unit_quaternion<T>();
        const vec3<T> t = rng.vector<T>(2.0);
        const T scale = rng.uniform<T>(0.1, 10.0);
        const point_pairs<T> rigid = exact_pairs(rng, q, t, T(1), vec3<T>{}, 1.0, 12);
        const point_pairs<T> similar = exact_pairs(rng, q, t, scale, vec3<T>{}, 1.0, 12);

        const quat::point_alignment<T> r = quat::align_points(rigid.targets, rigid.sources);
        const auto r_reference = quat::align_points(widened(rigid.targets), widened(rigid.sources));
        CHECK(r.unique);
        CHECK(r.rms < T(64) * eps<T> * (T(1) + quat::norm(t)));
        worst_rigid = std::max(worst_rigid, angle_in_eps(r.motion.real, r_reference.motion.real));
        CHECK(quat::norm(quat::translation_of(r.motion) - t) <=
              T(64) * eps<T> * (T(1) + quat::norm(t)));

        const quat::similarity_alignment<T> s =
            quat::align_points_with_scale(similar.targets, similar.sources);
        const auto s_reference =
            quat::align_points_with_scale(widened(similar.targets), widened(similar.sources));
        CHECK(s.unique);
        worst_similarity =
            std::max(worst_similarity, angle_in_eps(s.motion.real, s_reference.motion.real));
        worst_scale = std::max(worst_scale,
                               double(std::abs(s.scale - T(s_reference.scale)) / s.scale / eps<T>));
        CHECK(std::abs(s.scale - scale) <= T(64) * eps<T> * scale);
    }
    // Measured: rigid 2.0 eps (double) and 2.1 (float), similarity 2.3 and 2.2; scale 3.8 and
    // 2.9 eps (FOAM and a Newton polish from B; the Jacobi eigenvector alone gave 5.1 and 3.9).
    CHECK(worst_rigid <= 12);
    CHECK(worst_similarity <= 12);
    CHECK(worst_scale <= 12);
}

TEMPLATE_TEST_CASE("RANSAC sizes: 3 to 16 noisy pairs, the long double answer within a few eps",
                   "[align_points][sweep]", float, double) {
    // Few pairs take their own path (float solved in double, FOAM down to small eigen-gaps and
    // Newton steps over the pairs), so they are held to the long double solution of the same data.
    // Three points are as accurate as their triangle allows: a thin one (B of rank 2 with a small
    // second singular value) amplifies any method's rounding, so they are held to 64 eps in double.
    using T = TestType;
    quat::test::random_rotations rng(21);
    for (const std::size_t count : {3, 4, 5, 8, 16}) {
        double worst_angle = 0, worst_scale = 0;
        for (int k = 0; k < 2000; ++k) {
            const quaternion<T> q = rng.unit_quaternion<T>();
            point_pairs<T> p = exact_pairs(rng, q, rng.vector<T>(2.0), T(1), vec3<T>{}, 1.0, count);
            for (vec3<T>& target : p.targets) target += rng.vector<T>(0.01);
            const auto r = quat::align_points(p.targets, p.sources);
            const auto reference = quat::align_points(widened(p.targets), widened(p.sources));
            CHECK(r.unique);
            worst_angle = std::max(worst_angle, angle_in_eps(r.motion.real, reference.motion.real));
            const auto s = quat::align_points_with_scale(p.targets, p.sources);
            const auto s_reference =
                quat::align_points_with_scale(widened(p.targets), widened(p.sources));
            worst_scale = std::max(
                worst_scale, double(std::abs(s.scale - T(s_reference.scale)) / s.scale / eps<T>));
        }
        INFO(count << " pairs: worst rotation " << worst_angle << " eps, scale " << worst_scale);
        // Measured: float 0.8 eps at every size, its scale the same float as long double's;
        // double 26 eps at 3 pairs, 4.0 at 4, 2.5 to 2.9 from 5 to 16, its scale 4.0 to 6.0 eps.
        CHECK(worst_angle <= (sizeof(T) == sizeof(float) ? 2 : count == 3 ? 64 : 8));
        CHECK(worst_scale <= (sizeof(T) == sizeof(float) ? 2 : 8));
    }
}

TEST_CASE("far from the origin: 1e6 away with a spread of 1e-3, the long double answer",
          "[align_points]") {
    // The data are the rounded doubles; their exact least-squares solution (long double) is what
    // a careful method can reach. A one-pass centroid loses the spread's last digits.
    quat::test::random_rotations rng(12);
    double worst_angle = 0, worst_scale = 0;
    for (int k = 0; k < 100; ++k) {
        const quaternion<double> q = rng.unit_quaternion<double>();
        const vec3<double> t = rng.vector<double>(2.0);
        const vec3<double> center{1e6, -5e5, 3e5};
        const point_pairs<double> p = exact_pairs(rng, q, t, 1.0, center, 1e-3, 20);
        const auto r = quat::align_points(p.targets, p.sources);
        const auto reference = quat::align_points(widened(p.targets), widened(p.sources));
        worst_angle = std::max(worst_angle, angle_in_eps(r.motion.real, reference.motion.real));
        CHECK(quat::norm(quat::translation_of(r.motion) -
                         vec3<double>(quat::translation_of(reference.motion))) <= 1e-8);
        const auto s = quat::align_points_with_scale(p.targets, p.sources);
        const auto s_reference =
            quat::align_points_with_scale(widened(p.targets), widened(p.sources));
        worst_scale = std::max(worst_scale,
                               double(std::abs(s.scale - double(s_reference.scale)) / eps<double>));
    }
    // Measured: 1.7 eps (rotation) and 5.0 eps (scale); 4.8 and 4.2 with the Jacobi eigenvector.
    CHECK(worst_angle <= 16);
    CHECK(worst_scale <= 16);
}

TEMPLATE_TEST_CASE("noisy data: the same motion as Eigen's umeyama within their combined error",
                   "[align_points]", float, double) {
    using T = TestType;
    quat::test::random_rotations rng(13);
    for (int k = 0; k < 50; ++k) {
        const quaternion<T> q = rng.unit_quaternion<T>();
        const vec3<T> t = rng.vector<T>(2.0);
        point_pairs<T> p = exact_pairs(rng, q, t, T(1.5), vec3<T>{T(1), T(2), T(3)}, 1.0, 30);
        for (vec3<T>& target : p.targets) target += rng.vector<T>(0.01);

        for (const bool scaled : {false, true}) {
            const Eigen::Matrix<T, 4, 4> e =
                Eigen::umeyama(to_eigen(p.sources), to_eigen(p.targets), scaled);
            const quat::similarity_alignment<T> s =
                scaled
                    ? quat::align_points_with_scale(p.targets, p.sources)
                    : quat::similarity_alignment<T>{quat::align_points(p.targets, p.sources), T(1)};
            const quat::rotation_matrix<T> m = quat::to_matrix(s.motion.real);
            const vec3<T> translation = quat::translation_of(s.motion);
            const T tolerance = std::is_same_v<T, float> ? T(2e-5) : T(1e-12);
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    CHECK(std::abs(m(i, j) * s.scale - e(i, j)) <= tolerance);
            CHECK(std::abs(translation.x - e(0, 3)) <= tolerance * 8);
            CHECK(std::abs(translation.y - e(1, 3)) <= tolerance * 8);
            CHECK(std::abs(translation.z - e(2, 3)) <= tolerance * 8);
        }
    }
}

TEST_CASE("the residual is the weighted RMS of the residuals, never a reflection",
          "[align_points]") {
    // Mirrored targets (scipy #10444, Kabsch's det < 0): the best proper motion, not the mirror.
    const std::vector<vec3<double>> sources{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    std::vector<vec3<double>> targets;
    for (const vec3<double>& s : sources) targets.push_back({s.x, s.y, -s.z});
    const std::vector<double> weights{1, 2, 3, 0.5};
    const auto r = quat::align_points(targets, sources, weights);
    CHECK(quat::determinant(quat::to_matrix(r.motion.real)) > 0.99);
    long double squares = 0, total = 0;
    for (std::size_t i = 0; i < sources.size(); ++i) {
        const vec3<double> residual = targets[i] - quat::transform(r.motion, sources[i]);
        squares += weights[i] * quat::dot(residual, residual);
        total += weights[i];
    }
    CHECK(r.rms == Approx(double(std::sqrt(squares / total))).epsilon(1e-13));
    // A motion found with Eigen's umeyama on the same data has the same residual.
    CHECK(r.rms > 0.1);
}

TEST_CASE("degenerate sets: collinear, two points, all equal are not unique; coplanar is",
          "[align_points]") {
    const quaternion<double> q = quat::normalize(quaternion<double>{0.8, 0.2, -0.4, 0.1});
    const vec3<double> t{1, -2, 0.5};
    const auto image = [&](const std::vector<vec3<double>>& s) {
        std::vector<vec3<double>> out;
        for (const vec3<double>& p : s) out.push_back(quat::rotate(q, p) + t);
        return out;
    };
    const std::vector<vec3<double>> collinear{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {-3, -3, -3}};
    const std::vector<vec3<double>> two{{1, 0, 0}, {0, 1, 0}};
    const std::vector<vec3<double>> same{{1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
    const std::vector<vec3<double>> coplanar{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (const auto* set : {&collinear, &two, &same}) {
        const auto r = quat::align_points(image(*set), *set);
        CHECK_FALSE(r.unique);
        CHECK(r.rms <= 1e-14);  // one of the exact motions
        for (const vec3<double>& p : *set)
            CHECK(quat::norm(quat::transform(r.motion, p) - (quat::rotate(q, p) + t)) <= 1e-14);
    }
    const auto plane = quat::align_points(image(coplanar), coplanar);
    CHECK(plane.unique);
    CHECK(quat::angle_between(plane.motion.real, q) <= 8 * eps<double>);
    // All targets equal: no scale maps a spread onto a point except 0, so the scale is
    // undetermined.
    const std::vector<vec3<double>> spread{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const auto collapsed = quat::align_points_with_scale(same, spread);
    CHECK_FALSE(collapsed.unique);
    CHECK(collapsed.scale == 1);
}

TEST_CASE(
    "weights: zero drops a pair, only ratios count, one dominating by 1e12 is the long "
    "double answer",
    "[align_points]") {
    quat::test::random_rotations rng(14);
    const quaternion<double> q = rng.unit_quaternion<double>();
    point_pairs<double> p = exact_pairs(rng, q, vec3<double>{1, 2, 3}, 1.0, vec3<double>{}, 1.0, 8);
    for (vec3<double>& target : p.targets) target += rng.vector<double>(0.05);
    std::vector<double> weights(8, 1.0);
    weights[3] = 0;
    const auto dropped = quat::align_points(p.targets, p.sources, weights);
    point_pairs<double> without = p;
    without.targets.erase(without.targets.begin() + 3);
    without.sources.erase(without.sources.begin() + 3);
    const auto reference = quat::align_points(without.targets, without.sources);
    CHECK(quat::angle_between(dropped.motion.real, reference.motion.real) <= 8 * eps<double>);
    CHECK(dropped.rms == Approx(reference.rms).epsilon(1e-13));

    std::vector<double> scaled = weights;
    for (double& w : scaled) w *= 1e200;
    const auto big = quat::align_points(p.targets, p.sources, scaled);
    CHECK(quat::angle_between(big.motion.real, dropped.motion.real) <= 8 * eps<double>);
    CHECK(big.rms == Approx(dropped.rms).epsilon(1e-13));

    std::vector<double> dominant(8, 1.0);
    dominant[0] = 1e12;
    std::vector<long double> dominant_wide(dominant.begin(), dominant.end());
    const auto r = quat::align_points(p.targets, p.sources, dominant);
    const auto wide = quat::align_points(widened(p.targets), widened(p.sources), dominant_wide);
    CHECK(angle_in_eps(r.motion.real, wide.motion.real) <= 64);
    CHECK(quat::norm(quat::translation_of(r.motion) -
                     vec3<double>(quat::translation_of(wide.motion))) <= 1e-12);
}

TEST_CASE("bad input: NaN results, and try_ forms that return empty", "[align_points]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<vec3<double>> none, good{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::vector<vec3<double>> with_nan{{1, 0, 0}, {0, nan, 0}, {0, 0, 1}};
    const std::vector<vec3<double>> with_inf{{1, 0, 0}, {0, inf, 0}, {0, 0, 1}};

    const auto empty = quat::align_points(none, none);
    CHECK(empty.motion == dual_quaternion<double>::identity());
    CHECK(empty.rms == 0);
    CHECK_FALSE(empty.unique);
    for (const auto& r : {quat::align_points(with_nan, good), quat::align_points(good, with_inf)}) {
        CHECK(std::isnan(r.motion.real.w));
        CHECK(std::isnan(r.motion.dual.x));
        CHECK(std::isnan(r.rms));
        CHECK_FALSE(r.unique);
    }
    CHECK(std::isnan(quat::align_points_with_scale(with_nan, good).scale));

    CHECK(quat::try_align_points(good, good));
    CHECK(quat::try_align_points(good, good)->motion.real ==
          quat::align_points(good, good).motion.real);
    CHECK(quat::try_align_points_with_scale(good, good, std::vector<double>{1, 2, 3}));
    CHECK_FALSE(quat::try_align_points(none, none));
    CHECK_FALSE(quat::try_align_points(good, none));
    CHECK_FALSE(quat::try_align_points(with_nan, good));
    CHECK_FALSE(quat::try_align_points(good, with_inf));
    CHECK_FALSE(quat::try_align_points(good, good, std::vector<double>{1, 1}));
    CHECK_FALSE(quat::try_align_points(good, good, std::vector<double>{1, -1, 1}));
    CHECK_FALSE(quat::try_align_points(good, good, std::vector<double>{1, nan, 1}));
    CHECK_FALSE(quat::try_align_points(good, good, std::vector<double>{1, inf, 1}));
    CHECK_FALSE(quat::try_align_points(good, good, std::vector<double>{0, 0, 0}));
    CHECK_FALSE(quat::try_align_points_with_scale(with_nan, good));
    // Points near max() whose residual cannot be represented.
    const double huge = std::numeric_limits<double>::max() / 4;
    const std::vector<vec3<double>> far{{huge, 0, 0}, {-huge, 0, 0}}, near{{1, 0, 0}, {-1, 0, 0}};
    CHECK(quat::try_align_points(far, far));
    CHECK(quat::try_align_points(near, far));
}

TEST_CASE("the motion converts to the homogeneous matrix", "[align_points]") {
    const std::vector<vec3<float>> sources{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
    const quaternion<float> q = quat::normalize(quaternion<float>{0.6f, 0.2f, 0.7f, -0.3f});
    std::vector<vec3<float>> targets;
    for (const vec3<float>& s : sources)
        targets.push_back(quat::rotate(q, s) + vec3<float>{4, 5, 6});
    const auto r = quat::align_points(targets, sources);
    const quat::homogeneous_matrix<float> h = quat::to_homogeneous(r.motion);
    for (std::size_t i = 0; i < sources.size(); ++i)
        CHECK(quat::norm(quat::transform(h, sources[i]) - targets[i]) <= 1e-5f);
}

TEMPLATE_TEST_CASE("to_similarity applies the fitted scale; to_matrix4 is Eigen's umeyama matrix",
                   "[align_points]", float, double) {
    using T = TestType;
    quat::test::random_rotations rng(15);
    for (int k = 0; k < 50; ++k) {
        const quaternion<T> q = rng.unit_quaternion<T>();
        const vec3<T> t = rng.vector<T>(2.0);
        const T scale = rng.uniform<T>(0.1, 10.0);
        const point_pairs<T> exact = exact_pairs(rng, q, t, scale, vec3<T>{}, 1.0, 12);
        const quat::similarity<T> fit =
            quat::to_similarity(quat::align_points_with_scale(exact.targets, exact.sources));
        CHECK(fit.scale == quat::align_points_with_scale(exact.targets, exact.sources).scale);
        for (std::size_t i = 0; i < exact.sources.size(); ++i)
            CHECK(quat::norm(quat::transform(fit, exact.sources[i]) - exact.targets[i]) <=
                  T(64) * eps<T> * (T(1) + scale + quat::norm(t)));

        // Noisy data: the 4x4 matrix equals Eigen's umeyama with scaling, element by element.
        point_pairs<T> noisy = exact_pairs(rng, q, t, scale, vec3<T>{T(1), T(2), T(3)}, 1.0, 30);
        for (vec3<T>& target : noisy.targets) target += rng.vector<T>(0.01);
        const Eigen::Matrix<T, 4, 4> e =
            Eigen::umeyama(to_eigen(noisy.sources), to_eigen(noisy.targets), true);
        const quat::matrix<T, 4, 4> m = quat::to_matrix4(
            quat::to_similarity(quat::align_points_with_scale(noisy.targets, noisy.sources)));
        const T tolerance = (std::is_same_v<T, float> ? T(2e-5) : T(1e-12)) * scale;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                CHECK(std::abs(m(i, j) - e(i, j)) <= (j < 3 ? tolerance : tolerance * 8));
    }
}

}  // namespace test_align_points

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
