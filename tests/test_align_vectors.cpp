// Specification of align_vectors.hpp: Wahba's problem against scipy 1.10 (committed reference
// data, tools/scipy_reference.py), Eigen's SVD (Kabsch), exact data and long double residuals.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <Eigen/Dense>
#include <quat/align.hpp>
#include <quat/align_vectors.hpp>

#include "data/scipy_reference.hpp"
#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

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
    CHECK(quat::approx_equal(both.rotation, quat::rotation_z(quat::pi), 4 * eps<double>));
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
    for (const auto& r :
         {quat::align_vectors(with_nan, sources), quat::align_vectors(sources, with_inf),
          quat::align_vectors(sources, sources, std::vector<double>{1, nan, 1}),
          quat::align_vectors(sources, sources, std::vector<double>{1, inf, 1})}) {
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
