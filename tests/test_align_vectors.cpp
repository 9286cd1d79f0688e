// Specification of fitting/align_vectors.hpp: Wahba's problem against scipy 1.10 (committed
// reference data, tools/scipy_reference.py), Eigen's SVD (Kabsch), exact data and long double
// residuals.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Dense>
#include <quat/align.hpp>
#include <quat/fitting/align_vectors.hpp>

#include "data/scipy_reference.hpp"
#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_align_vectors {

using quat::quaternion;
using quat::vec3;
using quat::test::eps;

namespace {

template <class T>
struct vector_pairs {
    std::vector<vec3<T>> targets, sources;
    std::vector<T> weights;
};

template <class T>
vector_pairs<T> from_scipy(const quat::test::scipy::align_case& c) {
    vector_pairs<T> p;
    for (std::size_t i = 0; i < c.count; ++i) {
        p.targets.push_back(vec3<T>{T(c.targets[i][0]), T(c.targets[i][1]), T(c.targets[i][2])});
        p.sources.push_back(vec3<T>{T(c.sources[i][0]), T(c.sources[i][1]), T(c.sources[i][2])});
        p.weights.push_back(T(c.weights[i]));
    }
    return p;
}

// Wahba's cost sum w |t - R s|^2 in long double, R from the quaternion q (normalized first).
template <class T>
long double cost(const vector_pairs<T>& p, const quaternion<T>& q) {
    const quaternion<long double> r = quat::normalize(quaternion<long double>(q));
    long double sum = 0;
    for (std::size_t i = 0; i < p.sources.size(); ++i) {
        const vec3<long double> d =
            vec3<long double>(p.targets[i]) - quat::rotate(r, vec3<long double>(p.sources[i]));
        sum += static_cast<long double>(p.weights[i]) * quat::squared_norm(d);
    }
    return sum;
}

// sqrt(sum w (|t|^2 + |s|^2)): the size of the data, what rounding errors in rssd scale with.
template <class T>
long double data_size(const vector_pairs<T>& p) {
    long double sum = 0;
    for (std::size_t i = 0; i < p.sources.size(); ++i)
        sum += static_cast<long double>(p.weights[i]) *
               (quat::squared_norm(vec3<long double>(p.targets[i])) +
                quat::squared_norm(vec3<long double>(p.sources[i])));
    return std::sqrt(sum);
}

// The Kabsch answer from Eigen's SVD: R = U diag(1, 1, det(U V^T)) V^T for B = U S V^T.
quaternion<double> kabsch(const vector_pairs<double>& p) {
    Eigen::Matrix3d b = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < p.sources.size(); ++i)
        b += p.weights[i] * Eigen::Vector3d(p.targets[i].x, p.targets[i].y, p.targets[i].z) *
             Eigen::Vector3d(p.sources[i].x, p.sources[i].y, p.sources[i].z).transpose();
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(b, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Vector3d d(1, 1, (svd.matrixU() * svd.matrixV().transpose()).determinant());
    const Eigen::Matrix3d r = svd.matrixU() * d.asDiagonal() * svd.matrixV().transpose();
    quat::rotation_matrix<double> m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = r(i, j);
    return quat::to_quaternion(m);
}

template <class T>
quaternion<T> to_quaternion(const double (&wxyz)[4]) {
    return {T(wxyz[0]), T(wxyz[1]), T(wxyz[2]), T(wxyz[3])};
}

}  // namespace

TEMPLATE_TEST_CASE("align_vectors agrees with scipy 1.10 where scipy's answer is unique",
                   "[align_vectors]", float, double) {
    using T = TestType;
    // Measured (double): angle 1.2e-15, sensitivity 1.7e-15 relative, rssd 1.2e-15 relative to
    // the data's size against long double residuals. float: angle 1.5e-6 on the inputs rounded to
    // float, rssd 1.1e-7, sensitivity 7e-6 (both also measure the rounding of the inputs).
    const T angle_bound = std::is_same_v<T, float> ? T(1e-5) : T(1e-12);
    const T sensitivity_bound = std::is_same_v<T, float> ? T(1e-4) : T(1e-9);
    const T rssd_bound = 16 * eps<T>;
    for (const auto& c : quat::test::scipy::align_cases) {
        CAPTURE(c.name);
        const vector_pairs<T> p = from_scipy<T>(c);
        const auto result = quat::align_vectors_with_sensitivity(p.targets, p.sources, p.weights);
        CHECK(result.unique);
        CHECK(result.rotation.w >= 0);
        CHECK(quat::angle_between(result.rotation, to_quaternion<T>(c.rotation)) <= angle_bound);
        // rssd from the residuals, as a long double sum over the same rotation gives it.
        const long double reference = std::sqrt(cost(p, result.rotation));
        CHECK(std::abs(result.rssd - reference) <= rssd_bound * data_size(p));
        // scipy's rssd cancels: it agrees only to about sqrt(epsilon) of the data's size.
        const double scipy_rssd_bound = std::is_same_v<T, float> ? 1e-6 : 1e-7;
        CHECK(std::abs(double(result.rssd) - c.rssd) <= scipy_rssd_bound * double(data_size(p)));
        T largest = 0, difference = 0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                largest = std::max(largest, T(std::abs(c.sensitivity[i][j])));
                difference = std::max(difference,
                                      std::abs(result.sensitivity(i, j) - T(c.sensitivity[i][j])));
            }
        CHECK(difference <= sensitivity_bound * largest);
        // The plain call returns the same alignment.
        const quat::alignment<T> plain = quat::align_vectors(p.targets, p.sources, p.weights);
        CHECK(plain.rotation == result.rotation);
        CHECK(plain.rssd == result.rssd);
    }
}

TEST_CASE("exact data: the rotation within a few eps, rssd a few eps, not scipy's sqrt(eps)",
          "[align_vectors]") {
    // Rounding targets = R sources to double moves the optimum by about eps times the condition
    // number s0 / (s1 + s2) of B's singular values (the rotation about a nearly common direction is
    // weakly determined), so the bounds scale with it. Over 20000 such sets: angle at most
    // 3.66 eps (1 + condition), 3.6e5 eps for the worst-conditioned; rssd at most 2.96 eps
    // sqrt(1 + condition) of the data's size.
    quat::test::random_rotations random;
    for (int trial = 0; trial < 200; ++trial) {
        const quaternion<double> truth = random.unit_quaternion<double>();
        vector_pairs<double> p;
        Eigen::Matrix3d b = Eigen::Matrix3d::Zero();
        const std::size_t n = 2 + std::size_t(trial % 30);
        for (std::size_t i = 0; i < n; ++i) {
            const vec3<double> s = random.vector<double>(random.uniform<double>(0.1, 10));
            const vec3<double> t = quat::rotate(truth, s);
            p.sources.push_back(s);
            p.targets.push_back(t);
            p.weights.push_back(1);
            b += Eigen::Vector3d(t.x, t.y, t.z) * Eigen::Vector3d(s.x, s.y, s.z).transpose();
        }
        const Eigen::Vector3d singular = Eigen::JacobiSVD<Eigen::Matrix3d>(b).singularValues();
        const double condition = singular[0] / (singular[1] + singular[2]);
        const quat::alignment<double> result = quat::align_vectors(p.targets, p.sources);
        CAPTURE(trial, condition);
        CHECK(result.unique);
        CHECK(quat::angle_between(result.rotation, truth) <= 4 * eps<double> * (1 + condition));
        CHECK(result.rssd <= 4 * eps<double> * std::sqrt(1 + condition) * data_size(p));
    }

    // scipy's rssd, sqrt(sum (|a|^2 + |b|^2) - 2 sum s), on its own exact three-pair case:
    // 7.3e-08, where the residuals give 6.4e-16.
    const auto& three = quat::test::scipy::align_cases[1];
    REQUIRE(three.count == 3);
    const vector_pairs<double> p = from_scipy<double>(three);
    CHECK(three.rssd > 1e-8);
    CHECK(quat::align_vectors(p.targets, p.sources).rssd <= 4 * eps<double> * data_size(p));
}

TEST_CASE("reflected targets (Kabsch's det < 0 case, scipy #10444): the best proper rotation",
          "[align_vectors]") {
    quat::test::random_rotations random;
    for (int trial = 0; trial < 100; ++trial) {
        const quaternion<double> truth = random.unit_quaternion<double>();
        vector_pairs<double> p;
        for (int i = 0; i < 6; ++i) {
            p.sources.push_back(random.vector<double>());
            vec3<double> t = quat::rotate(truth, p.sources.back());
            t.z = -t.z;  // a mirror: no rotation maps sources onto targets
            p.targets.push_back(t + random.vector<double>(0.01 * (trial % 3)));
            p.weights.push_back(random.uniform<double>(0.5, 2));
        }
        const quat::alignment<double> result = quat::align_vectors(p.targets, p.sources, p.weights);
        CAPTURE(trial);
        CHECK(quat::determinant(quat::to_matrix(result.rotation)) == Approx(1));
        CHECK(quat::approx_equal(result.rotation, kabsch(p), 1e-12));  // measured 1.3e-15
        const long double best = cost(p, result.rotation);
        CHECK(std::abs(std::sqrt(best) - result.rssd) <= 1e-14 * data_size(p));
        for (int k = 0; k < 20; ++k) {
            const vec3<double> turn = random.unit_vector<double>() * (k < 10 ? 1e-3 : 0.1);
            const quaternion<double> other = result.rotation * quat::from_rotation_vector(turn);
            CHECK(cost(p, other) > best);
        }
    }
}

TEST_CASE("antiparallel pairs give the half turn (scipy #20555 returned the identity)",
          "[align_vectors]") {
    // x -> -x and y -> -y: half a turn about z.
    const std::vector<vec3<double>> sources{{1, 0, 0}, {0, 1, 0}}, targets{{-1, 0, 0}, {0, -3, 0}};
    const quat::alignment<double> both = quat::align_vectors(targets, sources);
    CHECK(both.unique);
    CHECK(quat::approx_equal(both.rotation, quat::rotation_z(quat::numbers::pi), 4 * eps<double>));
    // One antiparallel pair: the half turn rotation_between chooses; it maps the source onto the
    // target's direction, and any half turn about an axis across it would do, so not unique.
    quat::test::random_rotations random;
    for (int trial = 0; trial < 100; ++trial) {
        const vec3<double> s = random.vector<double>();
        const std::vector<vec3<double>> one_source{s}, one_target{s * -2.5};
        const quat::alignment<double> one = quat::align_vectors(one_target, one_source);
        CHECK_FALSE(one.unique);
        CHECK(one.rotation == quat::rotation_between(s, s * -2.5));
        CHECK(quat::test::max_difference(quat::rotate(one.rotation, s), -s) <=
              8 * eps<double> * quat::norm(s));
        CHECK(one.rssd == Approx(1.5 * quat::norm(s)).epsilon(1e-14));  // |-2.5 s - (-s)|
    }
}

TEST_CASE("one pair: rotation_between(source, target), not unique", "[align_vectors]") {
    quat::test::random_rotations random;
    for (int trial = 0; trial < 200; ++trial) {
        const std::vector<vec3<double>> s{random.vector<double>(random.uniform<double>(0.01, 100))},
            t{random.vector<double>(random.uniform<double>(0.01, 100))};
        const std::vector<double> w{random.uniform<double>(0.1, 10)};
        const quat::alignment<double> result = quat::align_vectors(t, s, w);
        CHECK_FALSE(result.unique);
        CHECK(result.rotation == quat::rotation_between(s[0], t[0]));
        const double expected =
            std::sqrt(w[0]) * quat::norm(t[0] - quat::normalize(t[0]) * quat::norm(s[0]));
        CHECK(result.rssd == Approx(expected).epsilon(1e-12).margin(1e-13));
    }
}

TEST_CASE("collinear vectors: not unique; the shortest arc between the two directions",
          "[align_vectors]") {
    quat::test::random_rotations random;
    for (int trial = 0; trial < 100; ++trial) {
        const vec3<double> from = random.unit_vector<double>(), to = random.unit_vector<double>();
        vector_pairs<double> p;
        for (int i = 0; i < 5; ++i) {
            const double a = random.uniform<double>(0.5, 3), sign = i == 2 ? -1.0 : 1.0;
            p.sources.push_back(from * (sign * a));
            p.targets.push_back(to * (sign * a * random.uniform<double>(0.5, 2)));
        }
        const quat::alignment<double> result = quat::align_vectors(p.targets, p.sources);
        CHECK_FALSE(result.unique);
        // Measured 7.0 eps (1.6e-15 rad) from the one-pair answer.
        CHECK(quat::angle_between(result.rotation, quat::rotation_between(from, to)) <=
              16 * eps<double>);
    }
}

TEST_CASE("a zero weight drops its pair; scaling every weight changes nothing", "[align_vectors]") {
    quat::test::random_rotations random;
    for (int trial = 0; trial < 100; ++trial) {
        const quaternion<double> truth = random.unit_quaternion<double>();
        vector_pairs<double> all, kept;
        for (int i = 0; i < 8; ++i) {
            const vec3<double> s = random.vector<double>(),
                               t = quat::rotate(truth, s) + random.vector<double>(0.1);
            const double w = i % 3 == 1 ? 0.0 : random.uniform<double>(0.1, 2);
            all.sources.push_back(s);
            all.targets.push_back(t);
            all.weights.push_back(w);
            if (w > 0) {
                kept.sources.push_back(s);
                kept.targets.push_back(t);
                kept.weights.push_back(w);
            }
        }
        const quat::alignment<double> a =
            quat::align_vectors(all.targets, all.sources, all.weights);
        const quat::alignment<double> b =
            quat::align_vectors(kept.targets, kept.sources, kept.weights);
        CHECK(a.rotation == b.rotation);  // the same sums, in the same order
        CHECK(a.rssd == b.rssd);
        // A power of two scales every sum exactly; K is scaled back, so nothing changes at all.
        std::vector<double> scaled = all.weights;
        for (double& w : scaled) w *= 0.25;
        const quat::alignment<double> c = quat::align_vectors(all.targets, all.sources, scaled);
        CHECK(c.rotation == a.rotation);
        CHECK(c.rssd == a.rssd * 0.5);
        // Another factor rounds each weight: measured at most 39.6 eps over 10000 such sets.
        for (double& w : scaled) w *= 37.25 / 0.25;
        const quat::alignment<double> d = quat::align_vectors(all.targets, all.sources, scaled);
        CHECK(quat::angle_between(d.rotation, a.rotation) <= 64 * eps<double>);
        CHECK(d.rssd == Approx(a.rssd * std::sqrt(37.25)).epsilon(1e-14));
    }
}

TEST_CASE("no pairs, NaN and infinity: documented results", "[align_vectors]") {
    const std::vector<vec3<double>> none;
    const quat::alignment<double> empty = quat::align_vectors(none, none);
    CHECK(empty.rotation == quaternion<double>::identity());
    CHECK(empty.rssd == 0);
    CHECK_FALSE(empty.unique);

    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<vec3<double>> sources{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::vector<vec3<double>> with_nan{{1, 0, 0}, {0, nan, 0}, {0, 0, 1}};
    const std::vector<vec3<double>> with_inf{{1, 0, 0}, {0, inf, 0}, {0, 0, 1}};
    // Infinite weights: one is a pair to meet exactly (see below); two or more, as scipy refuses
    // them, and one on a zero vector (infinity times zero) give NaN.
    const std::vector<vec3<double>> with_zero{{1, 0, 0}, {0, 0, 0}, {0, 0, 1}};
    for (const auto& r :
         {quat::align_vectors(with_nan, sources), quat::align_vectors(sources, with_inf),
          quat::align_vectors(sources, sources, std::vector<double>{1, nan, 1}),
          quat::align_vectors(sources, sources, std::vector<double>{inf, inf, 1}),
          quat::align_vectors(sources, with_zero, std::vector<double>{1, inf, 1}),
          quat::align_vectors(with_zero, sources, std::vector<double>{1, inf, 1})}) {
        CHECK(std::isnan(r.rotation.w));
        CHECK(std::isnan(r.rssd));
        CHECK_FALSE(r.unique);
    }
    // A single pair with a zero vector has no direction to align: the identity.
    const std::vector<vec3<double>> zero{{0, 0, 0}}, one{{1, 2, 3}};
    CHECK(quat::align_vectors(one, zero).rotation == quaternion<double>::identity());
}

TEST_CASE("long double gives the double answer to double precision", "[align_vectors]") {
    const vector_pairs<double> p = from_scipy<double>(quat::test::scipy::align_cases[6]);
    const quat::alignment<double> d = quat::align_vectors(p.targets, p.sources, p.weights);
    std::vector<vec3<long double>> targets, sources;
    for (std::size_t i = 0; i < p.sources.size(); ++i) {
        targets.emplace_back(p.targets[i]);
        sources.emplace_back(p.sources[i]);
    }
    const quat::alignment<long double> l = quat::align_vectors(targets, sources);
    CHECK(quat::angle_between(quaternion<double>(l.rotation), d.rotation) <= 4 * eps<double>);
    CHECK(double(l.rssd) == Approx(d.rssd).epsilon(1e-14));
}

// align_vectors runs at compile time (std::array's data() and size() are constexpr): x -> y and
// y -> -x is a quarter turn about z.
constexpr std::array<vec3<double>, 2> quarter_sources{vec3<double>{1, 0, 0}, vec3<double>{0, 1, 0}};
constexpr std::array<vec3<double>, 2> quarter_targets{vec3<double>{0, 1, 0},
                                                      vec3<double>{-1, 0, 0}};
constexpr quat::alignment<double> quarter = quat::align_vectors(quarter_targets, quarter_sources);
static_assert(quarter.unique && quarter.rssd < 1e-15);
static_assert(quarter.rotation.w - 0.70710678118654752 < 1e-15 &&
              0.70710678118654752 - quarter.rotation.z < 1e-15);

// ---- Edges: weights spread over hundreds of orders of magnitude, infinite weights, sizes from
// subnormal to huge ----

namespace {

// n pairs t = R s for random s and one weight of `heavy` (the first), the others near 1.
template <class T>
vector_pairs<T> exact_pairs(quat::test::random_rotations& random, const quaternion<T>& truth,
                            std::size_t n, T heavy) {
    vector_pairs<T> p;
    for (std::size_t i = 0; i < n; ++i) {
        p.sources.push_back(random.vector<T>());
        p.targets.push_back(quat::rotate(truth, p.sources.back()));
        p.weights.push_back(i == 0 ? heavy : random.uniform<T>(0.5, 2));
    }
    return p;
}

}  // namespace

TEST_CASE("one pair outweighing the others by 1e10: still their exact answer, unique",
          "[align_vectors][edges]") {
    // x -> y with weight 1e10 and (1, 1, 0) -> (0, 1, 1) with weight 1: the third of a turn about
    // (1, 1, 1) fits both exactly (cost 0). Davenport's K alone cannot tell its top two eigenvalues
    // apart at this spread (they differ by 2e-10 of the largest): a uniqueness rule read from that
    // gap alone calls it not unique and returns a quarter turn about z with cost 2.
    const std::vector<vec3<double>> targets{{0, 1, 0}, {0, 1, 1}}, sources{{1, 0, 0}, {1, 1, 0}};
    const quat::alignment<double> result =
        quat::align_vectors(targets, sources, std::vector<double>{1e10, 1});
    CHECK(result.unique);
    CHECK(quat::angle_between(result.rotation, quaternion<double>{0.5, 0.5, 0.5, 0.5}) <=
          4 * eps<double>);
    CHECK(result.rssd <= 1e5 * 8 * eps<double>);  // sqrt(1e10) times the rotation's rounding
}

TEMPLATE_TEST_CASE("exact data with one weight from 1e6 to 1e300 times the others: the truth",
                   "[align_vectors][edges]", float, double) {
    // Measured (double, 100 sets per spread, 2 to 5 pairs): at most 12.5 eps at every spread;
    // scipy 1.10 is 2.4e-6 off at 1e10.
    using T = TestType;
    const int top = std::numeric_limits<T>::max_exponent10 - 2;  // 36 for float, 306 for double
    quat::test::random_rotations random;
    for (int exponent = 6; exponent <= top; exponent += exponent < 20 ? 1 : 10) {
        for (int trial = 0; trial < 40; ++trial) {
            const quaternion<T> truth = random.unit_quaternion<T>();
            const T heavy = T(std::pow(10.0, exponent));
            const vector_pairs<T> p = exact_pairs(random, truth, 2 + std::size_t(trial % 4), heavy);
            const quat::alignment<T> result = quat::align_vectors(p.targets, p.sources, p.weights);
            CAPTURE(exponent, trial);
            CHECK(result.unique);
            CHECK(quat::angle_between(result.rotation, truth) <= 32 * eps<T>);
        }
    }
}

TEST_CASE("noisy data with one weight 1e2 to 1e40 times the others: the long double answer",
          "[align_vectors][edges]") {
    // No exact answer here; long double (64-bit significand on x86) carries 11 more bits through
    // the same steps. Measured at most 17.9 eps at 1e2, 5.2 eps from 1e4 on (100 sets per
    // spread).
    quat::test::random_rotations random;
    for (int exponent = 2; exponent <= 40; exponent += 2) {
        for (int trial = 0; trial < 40; ++trial) {
            const quaternion<double> truth = random.unit_quaternion<double>();
            vector_pairs<double> p =
                exact_pairs(random, truth, 3 + std::size_t(trial % 5), std::pow(10.0, exponent));
            for (vec3<double>& t : p.targets) t += random.vector<double>(0.1);
            std::vector<vec3<long double>> targets, sources;
            std::vector<long double> weights;
            for (std::size_t i = 0; i < p.targets.size(); ++i) {
                targets.emplace_back(p.targets[i]);
                sources.emplace_back(p.sources[i]);
                weights.push_back(p.weights[i]);
            }
            const quat::alignment<double> d = quat::align_vectors(p.targets, p.sources, p.weights);
            const quat::alignment<long double> l = quat::align_vectors(targets, sources, weights);
            CAPTURE(exponent, trial);
            CHECK(d.unique);
            CHECK(quat::angle_between(quaternion<long double>(d.rotation), l.rotation) <=
                  32 * eps<double>);
        }
    }
}

TEST_CASE("an infinite weight: its pair met exactly, the others turn about it (scipy 1.11)",
          "[align_vectors][edges]") {
    const double inf = std::numeric_limits<double>::infinity();
    // The example above with the heavy weight made infinite: the same answer, rssd without the
    // infinite pair (scipy >= 1.11 leaves it out; scipy 1.10 raised "SVD did not converge").
    const std::vector<vec3<double>> targets{{0, 1, 0}, {0, 1, 1}}, sources{{1, 0, 0}, {1, 1, 0}};
    const quat::alignment<double> exact =
        quat::align_vectors(targets, sources, std::vector<double>{inf, 1});
    CHECK(exact.unique);
    CHECK(quat::angle_between(exact.rotation, quaternion<double>{0.5, 0.5, 0.5, 0.5}) <=
          4 * eps<double>);
    CHECK(exact.rssd <= 4 * eps<double>);

    quat::test::random_rotations random;
    for (int trial = 0; trial < 100; ++trial) {
        // Noisy others: the infinite pair's direction is still met to rounding, and the turn
        // about it is the one the weight 1e200 gives (the limit of finite weights).
        const quaternion<double> truth = random.unit_quaternion<double>();
        vector_pairs<double> p = exact_pairs(random, truth, 6, inf);
        for (std::size_t i = 1; i < p.targets.size(); ++i)
            p.targets[i] += random.vector<double>(0.1);
        p.targets[0] = p.targets[0] * 3.0;  // lengths differ: only its direction is met
        const quat::alignment<double> result = quat::align_vectors(p.targets, p.sources, p.weights);
        CAPTURE(trial);
        CHECK(result.unique);
        CHECK(quat::norm(quat::cross(quat::rotate(result.rotation, p.sources[0]), p.targets[0])) <=
              8 * eps<double> * quat::norm(p.sources[0]) * quat::norm(p.targets[0]));
        std::vector<double> huge = p.weights;
        huge[0] = 1e200;
        const quat::alignment<double> limit = quat::align_vectors(p.targets, p.sources, huge);
        CHECK(quat::angle_between(result.rotation, limit.rotation) <= 8 * eps<double>);
        vector_pairs<double> others = p;
        others.weights[0] = 0;
        CHECK(result.rssd ==
              Approx(double(std::sqrt(cost(others, result.rotation)))).epsilon(1e-12));
        const auto with_sensitivity =
            quat::align_vectors_with_sensitivity(p.targets, p.sources, p.weights);
        CHECK(with_sensitivity.rotation == result.rotation);
        CHECK(std::isnan(with_sensitivity.sensitivity(0, 0)));  // scipy raises
    }
    // Nothing else pulls about the infinite pair's target: its shortest arc, not unique.
    const std::vector<vec3<double>> alone_t{{0, 0, 2}, {0, 0, 5}}, alone_s{{1, 0, 0}, {3, 0, 0}};
    const quat::alignment<double> alone =
        quat::align_vectors(alone_t, alone_s, std::vector<double>{inf, 1});
    CHECK_FALSE(alone.unique);
    CHECK(alone.rotation == quat::rotation_between(alone_s[0], alone_t[0]));
}

TEMPLATE_TEST_CASE("every size from subnormal to near max() gives the same rotation",
                   "[align_vectors][edges]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    // Noisy pairs of length up to 2, scaled by powers of ten: the inputs round, so the rotation
    // moves by a few eps; rssd scales with them. Unscaled sums (align_vectors scales the data by
    // powers of two) underflow at 1e-200 to the identity (unique false) and overflow at 1e200 to
    // NaN.
    const std::vector<double> scales =
        std::is_same_v<T, float>
            ? std::vector<double>{1e-38, 1e-30, 1e-20, 1e20, 1e30, 1e38}
            : std::vector<double>{1e-300, 1e-200, 1e-100, 1e-60, 1e60, 1e100, 1e200, 1e300};
    for (int trial = 0; trial < 20; ++trial) {
        const quaternion<T> truth = random.unit_quaternion<T>();
        vector_pairs<T> p = exact_pairs(random, truth, 5, T(1));
        for (vec3<T>& t : p.targets) t += random.vector<T>(T(0.05));
        const auto plain = quat::align_vectors_with_sensitivity(p.targets, p.sources, p.weights);
        REQUIRE(plain.unique);
        for (const double scale : scales) {
            vector_pairs<T> scaled = p;
            for (vec3<T>& t : scaled.targets) t = vec3<T>(vec3<double>(t) * scale);
            for (vec3<T>& s : scaled.sources) s = vec3<T>(vec3<double>(s) * scale);
            const auto r = quat::align_vectors_with_sensitivity(scaled.targets, scaled.sources,
                                                                scaled.weights);
            CAPTURE(trial, scale);
            CHECK(r.unique);
            // float at 1e-38 is subnormal: 2^-149 steps on components near 1e-38 (2^-23 relative).
            const T bound = scale < 1.2e-38 && std::is_same_v<T, float> ? T(2e-5) : 32 * eps<T>;
            CHECK(quat::angle_between(r.rotation, plain.rotation) <= bound);
            CHECK(double(r.rssd) == Approx(double(plain.rssd) * scale).epsilon(1e-4));
            // sensitivity ~ 1 / |B|: scale^-2 (representable for these scales in double only).
            if (std::is_same_v<T, double> && std::abs(std::log10(scale)) <= 100)
                CHECK(double(r.sensitivity(1, 1)) ==
                      Approx(double(plain.sensitivity(1, 1)) / (scale * scale)).epsilon(1e-6));
        }
        // Weights anywhere up to max(): only their ratios count.
        std::vector<T> heavy = p.weights, light = p.weights;
        for (T& w : heavy) w *= std::numeric_limits<T>::max() / 4;
        for (T& w : light) w *= std::numeric_limits<T>::min();
        CHECK(quat::angle_between(quat::align_vectors(p.targets, p.sources, heavy).rotation,
                                  plain.rotation) <= 32 * eps<T>);
        CHECK(quat::angle_between(quat::align_vectors(p.targets, p.sources, light).rotation,
                                  plain.rotation) <= 32 * eps<T>);
    }
}

TEST_CASE("subnormal vectors that are exact: exactly the unscaled answer",
          "[align_vectors][edges]") {
    // Small integers times 2^-1070 are exact subnormals; they are scaled by a power of two, so
    // the problem solved is the unscaled one bit for bit. Likewise times 2^1000.
    const std::vector<vec3<double>> sources{{1, 0, 0}, {0, 2, 0}, {1, 1, 3}};
    const std::vector<vec3<double>> targets{{0, 1, 0}, {0, 0, 2}, {3, 1, 1}};  // x->y->z->x
    const quat::alignment<double> plain = quat::align_vectors(targets, sources);
    for (const double scale :
         {std::ldexp(1.0, -1070), std::ldexp(1.0, -1040), std::ldexp(1.0, 1000)}) {
        std::vector<vec3<double>> t = targets, s = sources;
        for (vec3<double>& v : t) v = v * scale;
        for (vec3<double>& v : s) v = v * scale;
        const quat::alignment<double> r = quat::align_vectors(t, s);
        CAPTURE(scale);
        CHECK(r.unique);
        CHECK(r.rotation == plain.rotation);
        CHECK(quat::angle_between(r.rotation, quaternion<double>{0.5, 0.5, 0.5, 0.5}) <=
              4 * eps<double>);
    }
}

TEST_CASE("mixed precisions: weights of the other type convert", "[align_vectors][edges]") {
    quat::test::random_rotations random;
    const vector_pairs<double> p = exact_pairs(random, random.unit_quaternion<double>(), 6, 1.0);
    std::vector<vec3<float>> tf, sf;
    std::vector<float> wf;
    for (std::size_t i = 0; i < p.sources.size(); ++i) {
        tf.emplace_back(p.targets[i]);
        sf.emplace_back(p.sources[i]);
        wf.push_back(float(p.weights[i]));
    }
    std::vector<double> wd(wf.begin(), wf.end());
    CHECK(quat::align_vectors(tf, sf, wd).rotation == quat::align_vectors(tf, sf, wf).rotation);
    CHECK(quat::align_vectors_with_sensitivity(tf, sf, wd).rotation ==
          quat::align_vectors(tf, sf, wf).rotation);
    const std::vector<double> wd_exact(wf.begin(), wf.end());
    CHECK(quat::align_vectors(p.targets, p.sources, wf).rotation ==
          quat::align_vectors(p.targets, p.sources, wd_exact).rotation);
}

// The weight-spread path runs at compile time too: the example of "one pair outweighing the
// others by 1e10" (K's top eigenvalues 2e-10 apart: best_turn and its atan2, then Newton steps).
constexpr std::array<vec3<double>, 2> spread_targets{vec3<double>{0, 1, 0}, vec3<double>{0, 1, 1}};
constexpr std::array<vec3<double>, 2> spread_sources{vec3<double>{1, 0, 0}, vec3<double>{1, 1, 0}};
constexpr quat::alignment<double> spread =
    quat::align_vectors(spread_targets, spread_sources, std::array<double, 2>{1e10, 1});
static_assert(spread.unique && spread.rotation.w - 0.5 < 1e-15 && 0.5 - spread.rotation.w < 1e-15 &&
              spread.rotation.x - 0.5 < 1e-15 && 0.5 - spread.rotation.z < 1e-15);

TEST_CASE("try_align_vectors: the alignment, or empty for input it does not align",
          "[align_vectors]") {
    const std::vector<vec3<double>> sources{{1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
    const quaternion<double> turn = quat::normalize(quaternion<double>{0.9, 0.1, -0.3, 0.2});
    std::vector<vec3<double>> targets;
    for (const vec3<double>& s : sources) targets.push_back(quat::rotate(turn, s));
    const std::vector<double> weights{1, 2, 0.5};

    // Where the input is good, exactly the plain function's result.
    const auto checked = quat::try_align_vectors(targets, sources);
    REQUIRE(checked);
    const quat::alignment<double> plain = quat::align_vectors(targets, sources);
    CHECK(checked->rotation == plain.rotation);
    CHECK(checked->rssd == plain.rssd);
    CHECK(checked->unique);
    const auto weighted = quat::try_align_vectors(targets, sources, weights);
    REQUIRE(weighted);
    CHECK(weighted->rotation == quat::align_vectors(targets, sources, weights).rotation);

    // Non-unique is not bad input: one pair aligns, with unique = false.
    const std::vector<vec3<double>> one_target{targets[0]}, one_source{sources[0]};
    const auto one = quat::try_align_vectors(one_target, one_source);
    REQUIRE(one);
    CHECK_FALSE(one->unique);

    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<vec3<double>> none, with_nan{{1, 0, 0}, {0, nan, 0}, {0, 0, 1}};
    CHECK_FALSE(quat::try_align_vectors(none, none));
    CHECK_FALSE(quat::try_align_vectors(one_target, sources));
    CHECK_FALSE(quat::try_align_vectors(with_nan, sources));
    CHECK_FALSE(quat::try_align_vectors(targets, with_nan));
    CHECK_FALSE(quat::try_align_vectors(targets, sources, std::vector<double>{1, 2}));
    CHECK_FALSE(quat::try_align_vectors(targets, sources, std::vector<double>{1, -1, 1}));
    CHECK_FALSE(quat::try_align_vectors(targets, sources, std::vector<double>{1, nan, 1}));
    CHECK_FALSE(quat::try_align_vectors(targets, sources, std::vector<double>{0, 0, 0}));
    CHECK_FALSE(quat::try_align_vectors(targets, sources, std::vector<double>{inf, inf, 1}));
    // One infinite weight is scipy's (>= 1.11) exact pair, not bad input.
    CHECK(quat::try_align_vectors(targets, sources, std::vector<double>{inf, 1, 1}));
    // Vectors near max() that no rotation brings together: s and -s both onto t leave
    // rssd = 2 |t|, beyond max().
    const double huge = std::numeric_limits<double>::max();
    const std::vector<vec3<double>> far_targets{{huge, 0, 0}, {huge, 0, 0}};
    const std::vector<vec3<double>> far_sources{{huge, 0, 0}, {-huge, 0, 0}};
    CHECK(std::isinf(quat::align_vectors(far_targets, far_sources).rssd));
    CHECK_FALSE(quat::try_align_vectors(far_targets, far_sources));
}

TEST_CASE("alignment_with_sensitivity is an alignment with one more field", "[align_vectors]") {
    const std::vector<vec3<double>> sources{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
    const quaternion<double> turn = quat::normalize(quaternion<double>{0.5, 0.5, -0.1, 0.3});
    std::vector<vec3<double>> targets;
    for (const vec3<double>& s : sources)
        targets.push_back(quat::rotate(turn, s) + vec3<double>{1e-3, 0, 0});
    const std::vector<double> weights{1, 1, 2, 1};
    const quat::alignment_with_sensitivity<double> both =
        quat::align_vectors_with_sensitivity(targets, sources, weights);
    const quat::alignment<double>& fit = both;  // passes where an alignment is taken
    const quat::alignment<double> plain = quat::align_vectors(targets, sources, weights);
    CHECK(fit.rotation == plain.rotation);
    CHECK(fit.rssd == plain.rssd);
    CHECK(fit.unique == plain.unique);
    CHECK(both.sensitivity(0, 0) > 0);
}

}  // namespace test_align_vectors
