// Specification of fitting/mean.hpp: the chordal L2 mean against scipy 1.10 (committed reference
// data, tools/scipy_reference.py), Eigen's symmetric eigensolver in long double, and its
// definition.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Dense>
#include <quat/conversions.hpp>
#include <quat/fitting/mean.hpp>

#include "data/scipy_reference.hpp"
#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_mean {

using quat::quaternion;
using quat::test::eps;

namespace {

// The chordal cost sum w_i |M - R_i|_F^2 in long double.
template <class T>
long double chordal_cost(const std::vector<quaternion<T>>& rotations, const std::vector<T>& weights,
                         const quaternion<T>& m) {
    const quat::rotation_matrix<long double> a =
        quat::to_matrix(quat::normalize(quaternion<long double>(m)));
    long double sum = 0;
    for (std::size_t i = 0; i < rotations.size(); ++i) {
        const quat::rotation_matrix<long double> b =
            quat::to_matrix(quat::normalize(quaternion<long double>(rotations[i])));
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                sum += static_cast<long double>(weights[i]) * (a(r, c) - b(r, c)) *
                       (a(r, c) - b(r, c));
    }
    return sum;
}

// The top eigenvector of sum w q q^T by Eigen's SelfAdjointEigenSolver in long double.
quaternion<double> eigen_mean(const std::vector<quaternion<double>>& rotations,
                              const std::vector<double>& weights) {
    using matrix = Eigen::Matrix<long double, 4, 4>;
    using vector = Eigen::Matrix<long double, 4, 1>;
    matrix k = matrix::Zero();
    for (std::size_t i = 0; i < rotations.size(); ++i) {
        const vector q(rotations[i].w, rotations[i].x, rotations[i].y, rotations[i].z);
        k += static_cast<long double>(weights[i]) * q * q.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<matrix> solver(k);
    const vector v = solver.eigenvectors().col(3);  // eigenvalues ascend
    const quaternion<double> q{double(v[0]), double(v[1]), double(v[2]), double(v[3])};
    return q.w < 0 ? -q : q;
}

// Rotations spread by up to `spread` radians about a random center.
std::vector<quaternion<double>> cluster(quat::test::random_rotations& random, std::size_t n,
                                        double spread) {
    const quaternion<double> center = random.unit_quaternion<double>();
    std::vector<quaternion<double>> out;
    for (std::size_t i = 0; i < n; ++i)
        out.push_back(center * quat::from_rotation_vector(random.unit_vector<double>() *
                                                          random.uniform<double>(0, spread)));
    return out;
}

}  // namespace

TEMPLATE_TEST_CASE("mean agrees with scipy 1.10's Rotation.mean", "[mean]", float, double) {
    using T = TestType;
    // Measured 2.4e-15 rad (double); float 3.0e-7 on the inputs rounded to float.
    const T bound = std::is_same_v<T, float> ? T(2e-6) : T(1e-12);
    for (const auto& c : quat::test::scipy::mean_cases) {
        CAPTURE(c.name);
        std::vector<quaternion<T>> rotations;
        std::vector<T> weights;
        for (std::size_t i = 0; i < c.count; ++i) {
            const auto& q = c.rotations[i];
            rotations.push_back(quaternion<T>{T(q[0]), T(q[1]), T(q[2]), T(q[3])});
            weights.push_back(T(c.weights[i]));
        }
        const quaternion<T> expected{T(c.mean[0]), T(c.mean[1]), T(c.mean[2]), T(c.mean[3])};
        const quaternion<T> m = quat::mean(rotations, weights);
        CHECK(m.w >= 0);
        CHECK(quat::angle_between(m, expected) <= bound);
        const std::optional<quaternion<T>> checked = quat::try_mean(rotations, weights);
        REQUIRE(checked.has_value());
        CHECK(*checked == m);
    }
}

TEST_CASE("mean is the top eigenvector of sum w q q^T and minimizes the chordal cost", "[mean]") {
    // The eigenvector is determined to about eps over the relative gap between the two largest
    // eigenvalues; over 20000 such sets the angle to Eigen's stayed below 6.67 eps / gap (24.6 eps
    // at most, for widely spread rotations).
    quat::test::random_rotations random;
    for (int trial = 0; trial < 200; ++trial) {
        const std::vector<quaternion<double>> rotations =
            cluster(random, 3 + std::size_t(trial % 40), trial % 2 ? 0.3 : 2.5);
        std::vector<double> weights;
        Eigen::Matrix4d k = Eigen::Matrix4d::Zero();
        double total = 0;
        for (const quaternion<double>& q : rotations) {
            weights.push_back(random.uniform<double>(0, 3));
            total += weights.back();
            const Eigen::Vector4d v(q.w, q.x, q.y, q.z);
            k += weights.back() * v * v.transpose();
        }
        const Eigen::Vector4d values =
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(k).eigenvalues();
        const double gap = (values[3] - values[2]) / total;
        const quaternion<double> m = quat::mean(rotations, weights);
        CAPTURE(trial, gap);
        CHECK(quat::angle_between(m, eigen_mean(rotations, weights)) <= 8 * eps<double> / gap);
        const long double best = chordal_cost(rotations, weights, m);
        for (int n = 0; n < 10; ++n) {
            const quaternion<double> other =
                m * quat::from_rotation_vector(random.unit_vector<double>() * 1e-4);
            CHECK(chordal_cost(rotations, weights, other) > best);
        }
    }
}

TEST_CASE("the signs of the inputs do not matter; the result has w >= 0", "[mean]") {
    quat::test::random_rotations random;
    for (int trial = 0; trial < 100; ++trial) {
        const std::vector<quaternion<double>> rotations = cluster(random, 12, 1.0);
        std::vector<quaternion<double>> flipped = rotations;
        for (std::size_t i = 0; i < flipped.size(); i += 2) flipped[i] = -flipped[i];
        const quaternion<double> m = quat::mean(rotations);
        CHECK(quat::mean(flipped) == m);  // q q^T is the same product for -q, bit for bit
        CHECK(m.w >= 0);
    }
}

TEST_CASE("a naive component average is not the mean (the opencv #2553 mistake)", "[mean]") {
    // Two rotations 10 degrees apart about z, stored with opposite signs as any source may give
    // them. Adding the components (then normalizing) cancels them instead of averaging.
    const quaternion<double> a = quat::rotation_z(0.0),
                             b = -quat::rotation_z(10 * quat::numbers::pi / 180);
    const quaternion<double> naive = quat::normalize(a + b);
    CHECK(quat::angle_between(naive, quat::rotation_z(5 * quat::numbers::pi / 180)) >
          3);  // nearly a half turn
    const std::vector<quaternion<double>> both{a, b};
    CHECK(quat::angle_between(quat::mean(both), quat::rotation_z(5 * quat::numbers::pi / 180)) <=
          4 * eps<double>);
}

TEST_CASE("copies of one rotation average to it; symmetric pairs to their midpoint", "[mean]") {
    quat::test::random_rotations random;
    for (int trial = 0; trial < 100; ++trial) {
        const quaternion<double> q = random.unit_quaternion<double>();
        const std::vector<quaternion<double>> same(7, q);
        const quaternion<double> m = quat::mean(same);
        CHECK(quat::angle_between(m, q) <= 8 * eps<double>);  // 10000 trials: at most 4.0 eps
        // q offset both ways by up to 1 rad: q stays the mean while each pair's cos^2 of half its
        // angle outweighs sin^2 (beyond about 1.57 rad other rotations can win).
        std::vector<quaternion<double>> pairs;
        for (int k = 0; k < 3; ++k) {
            const quaternion<double> offset = quat::from_rotation_vector(
                random.unit_vector<double>() * random.uniform<double>(0, 1));
            pairs.push_back(q * offset);
            pairs.push_back(-(q * quat::conjugate(offset)));
        }
        CHECK(quat::angle_between(quat::mean(pairs), q) <= 16 * eps<double>);  // at most 6.4 eps
    }
}

TEST_CASE("ties, empty input, zero, negative and NaN weights: empty try_mean, NaN mean", "[mean]") {
    // Two rotations half a turn apart, equal weights: every rotation on the arc between them is a
    // mean. Unequal weights break the tie.
    const std::vector<quaternion<double>> opposite{quaternion<double>::identity(),
                                                   quat::rotation_x(quat::numbers::pi)};
    CHECK_FALSE(quat::try_mean(opposite).has_value());
    CHECK(quat::is_unit(quat::mean(opposite), 4 * eps<double>));
    CHECK_FALSE(quat::try_mean(opposite, std::vector<double>{2, 2}).has_value());
    const std::optional<quaternion<double>> heavier =
        quat::try_mean(opposite, std::vector<double>{1, 1.001});
    REQUIRE(heavier.has_value());
    CHECK(quat::angle_between(*heavier, opposite[1]) <= 4 * eps<double>);

    const std::vector<quaternion<double>> none;
    CHECK_FALSE(quat::try_mean(none).has_value());
    CHECK(std::isnan(quat::mean(none).w));

    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<quaternion<double>> three{quat::rotation_x(0.1), quat::rotation_y(0.2),
                                                quat::rotation_z(0.3)};
    for (const std::vector<double>& bad :
         {std::vector<double>{0, 0, 0}, std::vector<double>{1, -1, 1},
          std::vector<double>{1, nan, 1}, std::vector<double>{1, inf, 1}}) {
        CHECK_FALSE(quat::try_mean(three, bad).has_value());
    }
    CHECK(std::isnan(quat::mean(three, std::vector<double>{0, 0, 0}).w));
    CHECK(std::isnan(quat::mean(three, std::vector<double>{1, nan, 1}).w));
    CHECK(std::isnan(quat::mean(three, std::vector<double>{1, inf, 1}).w));
    std::vector<quaternion<double>> broken = three;
    broken[1].y = nan;
    CHECK(std::isnan(quat::mean(broken).w));
    CHECK_FALSE(quat::try_mean(broken).has_value());
    // A zero weight drops its rotation, bit for bit.
    const std::vector<quaternion<double>> two{three[0], three[2]};
    CHECK(quat::mean(three, std::vector<double>{1, 0, 2}) ==
          quat::mean(two, std::vector<double>{1, 2}));
}

TEST_CASE("float and long double means agree with double to their precision", "[mean]") {
    quat::test::random_rotations random;
    const std::vector<quaternion<double>> rotations = cluster(random, 50, 1.5);
    const quaternion<double> d = quat::mean(rotations);
    std::vector<quaternion<float>> f;
    std::vector<quaternion<long double>> l;
    for (const quaternion<double>& q : rotations) {
        f.emplace_back(q);
        l.emplace_back(q);
    }
    CHECK(quat::angle_between(quaternion<double>(quat::mean(f)), d) <= 1e-6);  // measured 6.6e-8
    CHECK(quat::angle_between(quaternion<double>(quat::mean(l)), d) <= 4 * eps<double>);
}

// mean runs at compile time: two quarter turns about z, one stored negated, average to an eighth.
constexpr std::array<quaternion<double>, 2> two_turns{
    quaternion<double>{1, 0, 0, 0},
    quaternion<double>{-0.70710678118654752, 0, 0, -0.70710678118654752}};
constexpr quaternion<double> eighth = quat::mean(two_turns);
static_assert(eighth.w - 0.92387953251128676 < 1e-15 && 0.92387953251128676 - eighth.w < 1e-15);

// ---- Edges: weights of any finite size, try_mean on any input, mixed precisions ----

TEST_CASE("weights from subnormal to max() give the mean of their ratios", "[mean][edges]") {
    // The weights are divided by the largest first, so these are the same sums bit for bit. Sums
    // of the raw weights would overflow to infinity at max() (NaN mean) and lose the subnormals'
    // digits.
    quat::test::random_rotations random;
    const double max = std::numeric_limits<double>::max();
    const double tiny = std::numeric_limits<double>::denorm_min();
    for (int trial = 0; trial < 50; ++trial) {
        const std::vector<quaternion<double>> rotations = cluster(random, 3, 2.0);
        const quaternion<double> plain = quat::mean(rotations, std::vector<double>{4, 2, 1});
        CHECK(quat::mean(rotations, std::vector<double>{max, max / 2, max / 4}) == plain);
        CHECK(quat::mean(rotations, std::vector<double>{4 * tiny, 2 * tiny, tiny}) == plain);
        CHECK(quat::try_mean(rotations, std::vector<double>{max, max / 2, max / 4}) ==
              quat::try_mean(rotations, std::vector<double>{4, 2, 1}));
        CHECK(quat::mean(rotations, std::vector<double>{max, max, max}) == quat::mean(rotations));
    }
    const std::vector<quaternion<float>> floats{quat::rotation_x(0.25f), quat::rotation_y(0.5f)};
    const float fmax = std::numeric_limits<float>::max();
    CHECK(quat::mean(floats, std::vector<float>{fmax, fmax}) == quat::mean(floats));
    CHECK(quat::mean(floats, std::vector<float>{1e-45f, 1e-45f}) == quat::mean(floats));
}

TEST_CASE("try_mean returns empty, never asserts, for any bad input", "[mean][edges]") {
    // Meaningful in a debug build, where mean's unit-quaternion and size checks are live: try_mean
    // must test its input before any of them can fire. Each bad value in each component of one
    // rotation.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<quaternion<double>> good{quat::rotation_x(0.1), quat::rotation_y(0.2),
                                               quat::rotation_z(0.3)};
    const std::vector<double> ones{1, 1, 1};
    for (const double bad : {nan, inf, -inf}) {
        for (int component = 0; component < 4; ++component) {
            std::vector<quaternion<double>> rotations = good;
            double* q[] = {&rotations[1].w, &rotations[1].x, &rotations[1].y, &rotations[1].z};
            *q[component] = bad;
            CAPTURE(bad, component);
            CHECK_FALSE(quat::try_mean(rotations).has_value());
            CHECK_FALSE(quat::try_mean(rotations, ones).has_value());
        }
        std::vector<double> weights = ones;
        weights[2] = bad;
        CHECK_FALSE(quat::try_mean(good, weights).has_value());
    }
    // Zero and non-unit rotations (|q|^2 off 1 by more than 1/4096, mean's debug check).
    for (const quaternion<double>& off : {quaternion<double>{0, 0, 0, 0}, good[1] * 2.0,
                                          good[1] * 0.99, quaternion<double>{1e-300, 0, 0, 0}}) {
        std::vector<quaternion<double>> rotations = good;
        rotations[1] = off;
        CHECK_FALSE(quat::try_mean(rotations).has_value());
        CHECK_FALSE(quat::try_mean(rotations, ones).has_value());
    }
    // Empty, differing sizes, negative, zero weights.
    const std::vector<quaternion<double>> none;
    CHECK_FALSE(quat::try_mean(none).has_value());
    CHECK_FALSE(quat::try_mean(none, std::vector<double>{}).has_value());
    CHECK_FALSE(quat::try_mean(good, std::vector<double>{1, 1}).has_value());
    CHECK_FALSE(quat::try_mean(good, std::vector<double>{1, 1, 1, 1}).has_value());
    CHECK_FALSE(quat::try_mean(good, std::vector<double>{1, -1, 1}).has_value());
    CHECK_FALSE(quat::try_mean(good, std::vector<double>{0, 0, 0}).has_value());
    CHECK_FALSE(quat::try_mean(good, std::vector<double>{-0.0, 0, 0}).has_value());
    // Within the tolerance: a value, unit, never NaN.
    std::vector<quaternion<double>> rounded = good;
    rounded[0] = rounded[0] * (1 + 1e-5);
    const std::optional<quaternion<double>> m = quat::try_mean(rounded);
    REQUIRE(m.has_value());
    CHECK(quat::is_unit(*m, 4 * eps<double>));
}

TEST_CASE("mixed precisions: float rotations with double weights and the reverse",
          "[mean][edges]") {
    quat::test::random_rotations random;
    const std::vector<quaternion<double>> rotations = cluster(random, 20, 1.0);
    std::vector<quaternion<float>> floats;
    std::vector<float> wf;
    for (const quaternion<double>& q : rotations) {
        floats.emplace_back(q);
        wf.push_back(random.uniform<float>(0.5f, 2.0f));
    }
    const std::vector<double> wd(wf.begin(), wf.end());  // the same values, exactly
    CHECK(quat::mean(floats, wd) == quat::mean(floats, wf));
    CHECK(quat::try_mean(floats, wd) == quat::try_mean(floats, wf));
    CHECK(quat::mean(rotations, wf) == quat::mean(rotations, wd));
    CHECK(quat::try_mean(rotations, wf) == quat::try_mean(rotations, wd));
}

}  // namespace test_mean
