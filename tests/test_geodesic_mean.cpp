// Specification of lie/geodesic_mean.hpp: the Karcher mean of rotations and the bi-invariant mean
// of rigid motions against their definition (the weighted logarithms to the inputs sum to zero,
// checked in long double), closed forms (two inputs: slerp and sclerp halfway; rotations about one
// axis: the mean angle; translations: their mean), bi-invariance, and the uniqueness test.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include <quat/conversions.hpp>
#include <quat/lie/geodesic_mean.hpp>
#include <quat/lie/se3.hpp>
#include <quat/paths/interpolation.hpp>
#include <quat/rigid/sclerp.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_geodesic_mean {

using quat::dual_quaternion;
using quat::quaternion;
using quat::vec3;

namespace {

// |sum w_i log(M^-1 R_i)| / sum w_i in long double: zero at the Karcher mean (its gradient).
template <class T>
long double gradient_norm(const std::vector<quaternion<T>>& rotations,
                          const std::vector<T>& weights, const quaternion<T>& m) {
    const quaternion<long double> back =
        quat::conjugate(quat::normalize(quaternion<long double>(m)));
    vec3<long double> sum{0, 0, 0};
    long double total = 0;
    for (std::size_t i = 0; i < rotations.size(); ++i) {
        const long double w = weights[i];
        sum = sum + quat::to_rotation_vector(
                        back * quat::normalize(quaternion<long double>(rotations[i]))) *
                        w;
        total += w;
    }
    return quat::norm(sum) / total;
}

template <class T>
std::vector<quaternion<T>> cluster(quat::test::random_rotations& random, std::size_t n,
                                   double spread) {
    const quaternion<double> center = random.unit_quaternion<double>();
    std::vector<quaternion<T>> out;
    for (std::size_t i = 0; i < n; ++i) {
        const vec3<double> axis = random.unit_vector<double>();
        const quaternion<double> q =
            center * quat::from_rotation_vector(axis * random.uniform<double>(0, spread));
        out.push_back(quaternion<T>(random.uniform<double>(0, 1) < 0.5 ? -q : q));  // any sign
    }
    return out;
}

double angle_between(const quaternion<double>& a, const quaternion<double>& b) {
    return quat::norm(quat::to_rotation_vector(quat::conjugate(a) * b));
}

}  // namespace

TEMPLATE_TEST_CASE("the weighted rotation vectors from the geodesic mean sum to zero",
                   "[geodesic_mean]", float, double, long double) {
    using T = TestType;
    // Measured: float 1.2e-7, double 3.4e-16, long double 1.1e-19 (rad; 1 to 2 eps), up to 1000
    // rotations spread to 1.5 rad: the rounding of the sum.
    const long double bound = 8 * static_cast<long double>(std::numeric_limits<T>::epsilon());
    quat::test::random_rotations random;
    for (const std::size_t n : {1u, 2u, 3u, 10u, 1000u})
        for (const double spread : {1e-6, 0.1, 1.0, 1.5}) {
            CAPTURE(n, spread);
            const std::vector<quaternion<T>> rotations = cluster<T>(random, n, spread);
            std::vector<T> ones(n, T(1)), weights;
            for (std::size_t i = 0; i < n; ++i) weights.push_back(random.uniform<T>(0.1, 3));
            const quaternion<T> plain = quat::geodesic_mean(rotations);
            const quaternion<T> weighted = quat::geodesic_mean(rotations, weights);
            CHECK(gradient_norm(rotations, ones, plain) <= bound);
            CHECK(gradient_norm(rotations, weights, weighted) <= bound);
            CHECK(plain.w >= T(0));
            CHECK(std::abs(quat::norm(plain) - T(1)) <= 2 * std::numeric_limits<T>::epsilon());
            // Within 1 rad of a center, all lie within pi/2 of the mean; spread 1.5 puts some
            // beyond it, where try_ refuses (the mean is then not known to be unique).
            const std::optional<quaternion<T>> tried = quat::try_geodesic_mean(rotations, weights);
            if (spread <= 1.0) REQUIRE(tried);
            if (tried) CHECK(*tried == weighted);
        }
}

TEST_CASE("the geodesic mean of two rotations is their slerp halfway, weighted by the weights",
          "[geodesic_mean]") {
    quat::test::random_rotations random;
    for (int trial = 0; trial < 200; ++trial) {
        const quaternion<double> a = random.unit_quaternion<double>();
        const quaternion<double> b = a * quat::from_rotation_vector(random.unit_vector<double>() *
                                                                    random.uniform<double>(0, 3));
        const double wa = random.uniform<double>(0.1, 1), wb = random.uniform<double>(0.1, 1);
        const std::vector<quaternion<double>> two{a, b};
        const quaternion<double> halfway = quat::slerp(a, b, 0.5);
        const quaternion<double> weighted = quat::slerp(a, b, wb / (wa + wb));
        CHECK(angle_between(quat::geodesic_mean(two), halfway) <= 2e-15);
        CHECK(angle_between(quat::geodesic_mean(two, std::vector<double>{wa, wb}), weighted) <=
              4e-16 * 8);
    }
}

TEST_CASE("about one axis the geodesic mean turns by the mean angle; the chordal mean does not",
          "[geodesic_mean]") {
    const vec3<double> z{0, 0, 1};
    const std::vector<double> angles{0.0, 0.1, 1.4, -0.3};
    std::vector<quaternion<double>> rotations;
    double sum = 0;
    for (const double a : angles) {
        rotations.push_back(quat::from_rotation_vector(z * a));
        sum += a;
    }
    const quaternion<double> expected = quat::from_rotation_vector(z * (sum / 4));
    CHECK(angle_between(quat::geodesic_mean(rotations), expected) <= 1e-15);
    CHECK(angle_between(quat::mean(rotations), expected) > 1e-3);  // the chordal mean differs
}

TEST_CASE("the geodesic mean is bi-invariant", "[geodesic_mean]") {
    quat::test::random_rotations random;
    const std::vector<quaternion<double>> rotations = cluster<double>(random, 50, 1.2);
    const quaternion<double> m = quat::geodesic_mean(rotations);
    const quaternion<double> g = random.unit_quaternion<double>();
    std::vector<quaternion<double>> left, right, inverted;
    for (const quaternion<double>& q : rotations) {
        left.push_back(g * q);
        right.push_back(q * g);
        inverted.push_back(quat::conjugate(q));
    }
    CHECK(angle_between(quat::geodesic_mean(left), g * m) <= 1e-14);
    CHECK(angle_between(quat::geodesic_mean(right), m * g) <= 1e-14);
    CHECK(angle_between(quat::geodesic_mean(inverted), quat::conjugate(m)) <= 1e-14);
}

TEST_CASE("try_geodesic_mean refuses what has no unique mean", "[geodesic_mean]") {
    const vec3<double> z{0, 0, 1};
    const quaternion<double> identity{1, 0, 0, 0};
    const std::vector<quaternion<double>> none;
    CHECK_FALSE(quat::try_geodesic_mean(none));
    CHECK(std::isnan(quat::geodesic_mean(none).w));
    // Three rotations 2.1 rad either side of the identity: the iteration stops at the identity,
    // a critical point, but two inputs lie beyond pi/2 of it.
    const std::vector<quaternion<double>> wide{identity, quat::from_rotation_vector(z * 2.1),
                                               quat::from_rotation_vector(z * -2.1)};
    CHECK_FALSE(quat::try_geodesic_mean(wide));
    CHECK(std::isfinite(quat::geodesic_mean(wide).w));
    const std::vector<quaternion<double>> narrow{identity, quat::from_rotation_vector(z * 1.5),
                                                 quat::from_rotation_vector(z * -1.5)};
    CHECK(quat::try_geodesic_mean(narrow));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<quaternion<double>> with_nan{identity, {nan, 0, 0, 0}};
    CHECK_FALSE(quat::try_geodesic_mean(with_nan));
    CHECK(std::isnan(quat::geodesic_mean(with_nan).w));
    const std::vector<quaternion<double>> long_one{identity, {2, 0, 0, 0}};
    CHECK_FALSE(quat::try_geodesic_mean(long_one));
    const std::vector<quaternion<double>> pair{identity, quat::from_rotation_vector(z)};
    CHECK_FALSE(quat::try_geodesic_mean(pair, std::vector<double>{1}));
    CHECK_FALSE(quat::try_geodesic_mean(pair, std::vector<double>{1, -1}));
    CHECK_FALSE(quat::try_geodesic_mean(pair, std::vector<double>{0, 0}));
    CHECK_FALSE(quat::try_geodesic_mean(pair, std::vector<double>{1, nan}));
    CHECK(std::isnan(quat::geodesic_mean(pair, std::vector<double>{0, 0}).w));
    const std::optional<quaternion<double>> one_weighted =
        quat::try_geodesic_mean(pair, std::vector<double>{0, 1});
    REQUIRE(one_weighted);
    CHECK(angle_between(*one_weighted, pair[1]) <= 1e-16);
}

namespace {

// sum w_i log(M^-1 X_i) / sum w_i in long double: {|angular part|, |linear part|}.
std::pair<long double, long double> rigid_gradient(const std::vector<dual_quaternion<double>>& xs,
                                                   const std::vector<double>& weights,
                                                   const dual_quaternion<double>& m) {
    const dual_quaternion<long double> back =
        quat::se3::inverse(quat::normalize(dual_quaternion<long double>(m)));
    const vec3<long double> zero{0, 0, 0};
    quat::se3::twist<long double> sum{zero, zero};
    long double total = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        sum = sum + quat::se3::log(back * quat::normalize(dual_quaternion<long double>(xs[i]))) *
                        static_cast<long double>(weights[i]);
        total += weights[i];
    }
    return {quat::norm(sum.angular) / total, quat::norm(sum.linear) / total};
}

double distance(const dual_quaternion<double>& a, const dual_quaternion<double>& b) {
    const quat::se3::twist<double> t = quat::se3::minus(b, a);
    return std::max(quat::norm(t.angular), quat::norm(t.linear));
}

}  // namespace

TEST_CASE("the weighted twists from the rigid mean sum to zero", "[geodesic_mean]") {
    // Measured: angular 1.8e-16, linear 1.9e-15 (translations up to about 10 units).
    quat::test::random_rotations random;
    for (const std::size_t n : {1u, 2u, 5u, 200u})
        for (const double spread : {1e-7, 0.3, 1.2}) {
            CAPTURE(n, spread);
            const dual_quaternion<double> center = random.rigid_motion<double>();
            std::vector<dual_quaternion<double>> xs;
            std::vector<double> weights;
            for (std::size_t i = 0; i < n; ++i) {
                const vec3<double> omega =
                    random.unit_vector<double>() * random.uniform<double>(0, spread);
                const vec3<double> rho = random.vector<double>(3.0);
                const dual_quaternion<double> x =
                    center * quat::se3::exp(quat::se3::twist<double>{rho, omega});
                xs.push_back(random.uniform<double>(0, 1) < 0.5 ? -x : x);
                weights.push_back(random.uniform<double>(0.1, 2));
            }
            const dual_quaternion<double> m = quat::geodesic_mean(xs, weights);
            const auto [angular, linear] = rigid_gradient(xs, weights, m);
            CHECK(angular <= 8 * 2.3e-16);
            CHECK(linear <= 8 * 2.3e-16 * 10);
            CHECK(m.real.w >= 0);
            // Its rotation is the rotations' geodesic mean.
            std::vector<quaternion<double>> rotations;
            for (const auto& x : xs) rotations.push_back(x.real);
            CHECK(angle_between(m.real, quat::geodesic_mean(rotations, weights)) <= 1e-15);
            const std::optional<dual_quaternion<double>> tried =
                quat::try_geodesic_mean(xs, weights);
            REQUIRE(tried);
            CHECK(*tried == m);
        }
}

TEST_CASE("the rigid mean of two motions is their sclerp halfway; of translations, their mean",
          "[geodesic_mean]") {
    quat::test::random_rotations random;
    for (int trial = 0; trial < 100; ++trial) {
        const dual_quaternion<double> a = random.rigid_motion<double>();
        const dual_quaternion<double> b =
            a * quat::se3::exp(quat::se3::twist<double>{
                    random.vector<double>(2.0),
                    random.unit_vector<double>() * random.uniform<double>(0, 3)});
        const double wa = random.uniform<double>(0.1, 1), wb = random.uniform<double>(0.1, 1);
        const std::vector<dual_quaternion<double>> two{a, b};
        CHECK(distance(quat::geodesic_mean(two), quat::sclerp(a, b, 0.5)) <= 1e-14);
        CHECK(distance(quat::geodesic_mean(two, std::vector<double>{wa, wb}),
                       quat::sclerp(a, b, wb / (wa + wb))) <= 1e-14);
    }
    const std::vector<dual_quaternion<double>> moves{
        dual_quaternion<double>::from_translation({1, 0, 0}),
        dual_quaternion<double>::from_translation({0, 2, 0}),
        dual_quaternion<double>::from_translation({0, 0, -3})};
    const dual_quaternion<double> m = quat::geodesic_mean(moves);
    CHECK(m.real == quaternion<double>::identity());
    const vec3<double> t = quat::translation_of(m);
    CHECK(t.x == Approx(1.0 / 3).epsilon(1e-15));
    CHECK(t.y == Approx(2.0 / 3).epsilon(1e-15));
    CHECK(t.z == Approx(-1.0).epsilon(1e-15));
}

TEST_CASE("the rigid mean is bi-invariant", "[geodesic_mean]") {
    quat::test::random_rotations random;
    std::vector<dual_quaternion<double>> xs;
    for (int i = 0; i < 30; ++i)
        xs.push_back(quat::se3::exp(
            quat::se3::twist<double>{random.vector<double>(5.0),
                                     random.unit_vector<double>() * random.uniform<double>(0, 1)}));
    const dual_quaternion<double> m = quat::geodesic_mean(xs);
    const dual_quaternion<double> g = random.rigid_motion<double>(10.0);
    std::vector<dual_quaternion<double>> left, right, inverted;
    for (const auto& x : xs) {
        left.push_back(g * x);
        right.push_back(x * g);
        inverted.push_back(quat::se3::inverse(x));
    }
    CHECK(distance(quat::geodesic_mean(left), g * m) <= 1e-13);
    CHECK(distance(quat::geodesic_mean(right), m * g) <= 1e-13);
    CHECK(distance(quat::geodesic_mean(inverted), quat::se3::inverse(m)) <= 1e-13);
}

TEST_CASE("try_geodesic_mean of motions refuses what has no unique mean", "[geodesic_mean]") {
    const std::vector<dual_quaternion<double>> none;
    CHECK_FALSE(quat::try_geodesic_mean(none));
    CHECK(std::isnan(quat::geodesic_mean(none).real.w));
    const vec3<double> z{0, 0, 1}, t{1, 2, 3};
    const auto turn = [&](double angle) {
        return quat::to_dual_quaternion(quat::from_rotation_vector(z * angle), t);
    };
    const std::vector<dual_quaternion<double>> wide{turn(0), turn(2.1), turn(-2.1)};
    CHECK_FALSE(quat::try_geodesic_mean(wide));
    CHECK(std::isfinite(quat::geodesic_mean(wide).real.w));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<dual_quaternion<double>> with_nan{turn(0), turn(nan)};
    CHECK_FALSE(quat::try_geodesic_mean(with_nan));
    CHECK(std::isnan(quat::geodesic_mean(with_nan).real.w));
    const std::vector<dual_quaternion<double>> pair{turn(0), turn(1)};
    CHECK_FALSE(quat::try_geodesic_mean(pair, std::vector<double>{1}));
    CHECK_FALSE(quat::try_geodesic_mean(pair, std::vector<double>{1, -1}));
    CHECK_FALSE(quat::try_geodesic_mean(pair, std::vector<double>{0, 0}));
    const std::vector<dual_quaternion<double>> long_one{turn(0), turn(1) * 2.0};
    CHECK_FALSE(quat::try_geodesic_mean(long_one));
}

}  // namespace test_geodesic_mean
