// Specification of align.hpp: rotation_between (shortest arc) and look_rotation (camera), against a
// high-precision reference computed here, Eigen and GLM.
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Geometry>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>

#include <quat/align.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"
#include "support/wide_float.hpp"

namespace test_align {

using quat::quaternion;
using quat::vec3;
using quat::test::eps;

// Compile time: the exact cases, and the compensated cross product's constant-evaluation branch.
static_assert(quat::rotation_between(vec3<double>{2, 0, 0}, vec3<double>{-0.5, 0, 0}) ==
              quaternion<double>{0, 0, 0, 1});
static_assert(quat::rotation_between(vec3<double>{0, 3, 0}, vec3<double>{0, 3, 0}) ==
              quat::quatd::identity());
static_assert(quat::rotation_between(vec3<float>{0, 0, 1}, vec3<float>{0, 1, 0}).x < -0.7071f);
static_assert(quat::look_rotation(vec3<double>{0, 0, -5}, vec3<double>{0, 2, 0}) ==
              quat::quatd::identity());
static_assert(!quat::try_look_rotation(vec3<double>{0, 0, -1}, vec3<double>{0, 0, 3}));
static_assert(!quat::try_rotation_between(vec3<double>{0, 0, 0}, vec3<double>{0, 0, 3}));
// 1 + 2^-30 and 1 - 2^-30 squared differ from 1 only beyond double's precision: the naive
// a b - c d gives 0, Kahan's algorithm the exact -2^-60.
static_assert(quat::detail::difference_of_products(1 - 0x1p-30, 1 + 0x1p-30, 1.0, 1.0) == -0x1p-60);

namespace {

// support/wide_float.hpp: 113 bits (__float128 on x86-64, long double on AArch64), where a product
// of two doubles is exact. Where only 64 bits are available: enough for float, and for double away
// from parallel and opposite; near opposite the reference cross product of doubles would cancel
// like the naive one.
using quat::test::wide;

wide wide_sqrt(wide x) {
    if (!(x > 0)) return 0;
    wide y = std::sqrt(static_cast<long double>(x));
    for (int i = 0; i < 2; ++i) y = (y + x / y) / 2;  // Newton, each step doubles the bits
    return y;
}

vec3<wide> widen(const vec3<float>& v) { return {wide(v.x), wide(v.y), wide(v.z)}; }
vec3<wide> widen(const vec3<double>& v) { return {wide(v.x), wide(v.y), wide(v.z)}; }
wide wide_norm(const vec3<wide>& v) { return wide_sqrt(quat::dot(v, v)); }

// Independent reference for rotation_between: the half angle from the chords of the unit vectors,
// |a^ + b^| = 2 cos(angle / 2) and |a^ - b^| = 2 sin(angle / 2) (both accurate at their small end),
// and the axis from a x b formed in `wide`, where each product of two inputs is exact.
template <class T>
quaternion<wide> reference_between(const vec3<T>& from, const vec3<T>& to) {
    const vec3<wide> a = widen(from), b = widen(to);
    const vec3<wide> ua = a / wide_norm(a), ub = b / wide_norm(b);
    const vec3<wide> c = quat::cross(a, b);
    const vec3<wide> axis = c / wide_norm(c);
    const wide cosine = wide_norm(ua + ub) / 2, sine = wide_norm(ua - ub) / 2;
    return {cosine, sine * axis.x, sine * axis.y, sine * axis.z};
}

// Independent reference for look_rotation: the frame (right, up', back) in `wide`, and its
// quaternion from whichever of 4 w^2, 4 x^2, 4 y^2, 4 z^2 is largest.
template <class T>
quaternion<wide> reference_look(const vec3<T>& forward_in, const vec3<T>& up_in) {
    const vec3<wide> f = widen(forward_in), up = widen(up_in);
    const vec3<wide> c = quat::cross(f, up);
    const vec3<wide> x = c / wide_norm(c), z = f / -wide_norm(f);
    const vec3<wide> y = quat::cross(z, x);
    const wide m00 = x.x, m11 = y.y, m22 = z.z;
    const wide m01 = y.x, m02 = z.x, m10 = x.y, m12 = z.y, m20 = x.z, m21 = y.z;
    const wide w4 = 1 + m00 + m11 + m22, x4 = 1 + m00 - m11 - m22, y4 = 1 - m00 + m11 - m22,
               z4 = 1 - m00 - m11 + m22;
    if (w4 >= x4 && w4 >= y4 && w4 >= z4) {
        const wide w = wide_sqrt(w4) / 2;
        return {w, (m21 - m12) / (4 * w), (m02 - m20) / (4 * w), (m10 - m01) / (4 * w)};
    }
    if (x4 >= y4 && x4 >= z4) {
        const wide s = wide_sqrt(x4) / 2;
        return {(m21 - m12) / (4 * s), s, (m01 + m10) / (4 * s), (m02 + m20) / (4 * s)};
    }
    if (y4 >= z4) {
        const wide s = wide_sqrt(y4) / 2;
        return {(m02 - m20) / (4 * s), (m01 + m10) / (4 * s), s, (m12 + m21) / (4 * s)};
    }
    const wide s = wide_sqrt(z4) / 2;
    return {(m10 - m01) / (4 * s), (m02 + m20) / (4 * s), (m12 + m21) / (4 * s), s};
}

// Rotation angle from q to the reference r, both normalized in long double, from the chord:
// |q - r| = 2 sin(angle / 4) for unit q, r on the same side (q . r >= 0). In eps of T.
template <class T>
long double angle_error(const quaternion<T>& q_in, const quaternion<wide>& r_in) {
    using L = long double;
    const quaternion<L> q = quat::normalize(quaternion<L>{q_in});
    quaternion<L> r = quat::normalize(quaternion<L>{L(r_in.w), L(r_in.x), L(r_in.y), L(r_in.z)});
    if (quat::dot(q, r) < 0) r = -r;
    return 4 * std::asin(quat::norm(q - r) / 2) / L(eps<T>);
}

// b is a turned by `angle` about a random axis perpendicular to a, rounded once to T.
template <class T>
vec3<T> turned(quat::test::random_rotations& random, const vec3<T>& a, long double angle) {
    using L = long double;
    const vec3<L> al{a};
    const vec3<L> axis = quat::normalize(quat::cross(al, vec3<L>{random.unit_vector<double>()}));
    const quaternion<L> q{std::cos(angle / 2), std::sin(angle / 2) * axis.x,
                          std::sin(angle / 2) * axis.y, std::sin(angle / 2) * axis.z};
    return vec3<T>{quat::rotate(q, al)};
}

// Length 10^e, e uniform in [-30, 30]: the random magnitudes of every family.
template <class T>
T random_length(quat::test::random_rotations& random) {
    return T(std::pow(10.0, random.uniform<double>(-30, 30)));
}

// Largest angle error of rotation_between over a family: pairs from make(random, i).
template <class T, class Make>
long double worst_between(int count, Make make) {
    quat::test::random_rotations random;
    long double worst = 0;
    for (int i = 0; i < count; ++i) {
        const auto [from, to] = make(random, i);
        const long double e =
            angle_error(quat::rotation_between(from, to), reference_between(from, to));
        CAPTURE(i, from.x, from.y, from.z, to.x, to.y, to.z);
        REQUIRE(e == e);
        worst = e > worst ? e : worst;
    }
    return worst;
}

template <class T>
struct family_pair {
    vec3<T> from, to;
};

}  // namespace

TEMPLATE_TEST_CASE("rotation_between is within 4 eps of the exact rotation", "[align][sweep]",
                   float, double) {
    using T = TestType;
    auto random_pair = [](quat::test::random_rotations& r, int) {
        return family_pair<T>{r.unit_vector<T>() * random_length<T>(r),
                              r.unit_vector<T>() * random_length<T>(r)};
    };
    // k = 1..15 cycles; each angle 10^-k, or pi - 10^-k when opposite.
    auto near = [](bool opposite) {
        return [opposite](quat::test::random_rotations& r, int i) {
            const vec3<T> a = r.unit_vector<T>();
            const long double delta = std::pow(10.0L, -(1 + i % 15));
            const long double angle = opposite ? 3.14159265358979323846L - delta : delta;
            return family_pair<T>{a * random_length<T>(r),
                                  turned(r, a, angle) * random_length<T>(r)};
        };
    };
    // Measured (g++ 12, __float128 reference): see the comments at each CHECK.
    const long double random = worst_between<T>(20000, random_pair);
    const long double parallel = worst_between<T>(20000, near(false));
    const long double opposite = worst_between<T>(20000, near(true));
    CAPTURE(random, parallel, opposite);
    CHECK(random <= 4);    // measured float 2.49, double 2.31 (largest near 90-110 degrees)
    CHECK(parallel <= 4);  // measured float 0.47, double 0.48
    CHECK(opposite <= 4);  // measured float 1.97, double 1.91
}

TEMPLATE_TEST_CASE("rotation_between returns a unit quaternion that maps from onto to", "[align]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int i = 0; i < 5000; ++i) {
        const vec3<T> from = random.unit_vector<T>() * random_length<T>(random);
        const vec3<T> to = random.unit_vector<T>() * random_length<T>(random);
        const quaternion<T> q = quat::rotation_between(from, to);
        CAPTURE(i);
        CHECK(std::abs(quat::norm(q) - 1) <= 2 * eps<T>);
        const vec3<T> moved = quat::rotate(q, quat::normalize(from));
        CHECK(quat::norm(moved - quat::normalize(to)) <= 8 * eps<T>);
        CHECK(q.w >= 0);  // the shortest arc: angle <= pi
    }
}

TEMPLATE_TEST_CASE("rotation_between of exactly parallel and opposite vectors", "[align]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int i = 0; i < 1000; ++i) {
        // Lengths 1e-20 .. 1e20 and a power of two k, so that a * k stays normal and exactly
        // parallel.
        const vec3<T> a =
            random.unit_vector<T>() * T(std::pow(10.0, random.uniform<double>(-20, 20)));
        const T k = T(std::ldexp(1.0, i % 60 - 30));
        // The identity up to the rounding of w = p / sqrt(p^2): within an ulp of 1.
        const quaternion<T> same = quat::rotation_between(a, a * k);
        CHECK((same.x == 0 && same.y == 0 && same.z == 0 && std::abs(same.w - 1) <= eps<T>));
        const quaternion<T> half = quat::rotation_between(a, a * -k);
        // A half turn about an axis perpendicular to a: w = 0, unit axis, axis . a = 0.
        CHECK(half.w == 0);
        CHECK(std::abs(quat::norm(half) - 1) <= 2 * eps<T>);
        CHECK(std::abs(quat::dot(vec3<T>{half.x, half.y, half.z}, quat::normalize(a))) <=
              2 * eps<T>);
    }
    // The documented axis: from x e, e the coordinate axis of from's smallest |component|.
    CHECK(quat::rotation_between(vec3<T>{1, 0, 0}, vec3<T>{-1, 0, 0}) == quaternion<T>{0, 0, 0, 1});
    CHECK(quat::rotation_between(vec3<T>{0, 1, 0}, vec3<T>{0, -1, 0}) ==
          quaternion<T>{0, 0, 0, -1});
    CHECK(quat::rotation_between(vec3<T>{0, 0, 1}, vec3<T>{0, 0, -1}) == quaternion<T>{0, 0, 1, 0});
    CHECK(quat::rotation_between(vec3<T>{0, 0, -1}, vec3<T>{0, 0, 1}) ==
          quaternion<T>{0, 0, -1, 0});
    // (2, -3, 1): smallest |z|, axis from x (0, 0, 1) = (-3, -2, 0) / sqrt(13).
    const quaternion<T> q = quat::rotation_between(vec3<T>{2, -3, 1}, vec3<T>{-4, 6, -2});
    const T s = T(1) / std::sqrt(T(13));
    CHECK(quat::angle_between(q, quaternion<T>{0, -3 * s, -2 * s, 0}) <= 4 * eps<T>);
}

TEMPLATE_TEST_CASE("rotation_between keeps its accuracy from tiny to huge lengths", "[align]",
                   float, double) {
    using T = TestType;
    const T tiny = std::numeric_limits<T>::denorm_min(), huge = std::numeric_limits<T>::max();
    const vec3<T> a{1, 2, 3}, b{-3, 1, 2};
    const quaternion<wide> r = reference_between(a, b);
    for (const T s :
         {tiny, T(tiny * 64), std::numeric_limits<T>::min(), T(1e-30), T(1e30), T(huge / 4)}) {
        CAPTURE(s);
        CHECK(angle_error(quat::rotation_between(a * s, b), r) <= 2);
        CHECK(angle_error(quat::rotation_between(a, b * s), r) <= 2);
    }
    // Components of very different size: the largest sets the scale, the others still count.
    const vec3<T> mixed{huge / 4, T(3e-30) * huge / 4, 0};
    CHECK(angle_error(quat::rotation_between(mixed, b), reference_between(mixed, b)) <= 2);
}

TEMPLATE_TEST_CASE("rotation_between of zero or non-finite input", "[align]", float, double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    const vec3<T> good{1, 2, 3};
    for (const vec3<T> bad :
         {vec3<T>{0, 0, 0}, vec3<T>{nan, 0, 1}, vec3<T>{0, inf, 1}, vec3<T>{-inf, inf, 0}}) {
        CHECK_FALSE(quat::try_rotation_between(bad, good));
        CHECK_FALSE(quat::try_rotation_between(good, bad));
        // The unchecked function documents NaN in every component.
        const quaternion<T> q = quat::rotation_between(bad, good);
        CHECK((std::isnan(q.w) && std::isnan(q.x) && std::isnan(q.y) && std::isnan(q.z)));
        const quaternion<T> p = quat::rotation_between(good, bad);
        CHECK((std::isnan(p.w) && std::isnan(p.x) && std::isnan(p.y) && std::isnan(p.z)));
    }
    CHECK(quat::try_rotation_between(good, vec3<T>{3, 2, 1}) ==
          quat::rotation_between(good, vec3<T>{3, 2, 1}));
}

TEST_CASE("the naive formula fails near opposite where rotation_between succeeds", "[align]") {
    // normalize(|a| |b| + a . b, a x b): both parts cancel when a ~ -b, so the half angle and the
    // axis keep only rounding noise. Measured at pi - 1e-9 in double: naive 3.6e9 eps, ours 1.5.
    quat::test::random_rotations random;
    long double naive_worst = 0, ours_worst = 0;
    for (int i = 0; i < 200; ++i) {
        const vec3<double> a = random.unit_vector<double>() * 3;
        const vec3<double> b = turned(random, a, 3.14159265358979323846L - 1e-9L) * 0.25;
        const vec3<double> c = quat::cross(a, b);
        const quaternion<double> naive = quat::normalize(
            quaternion<double>{quat::norm(a) * quat::norm(b) + quat::dot(a, b), c.x, c.y, c.z});
        const quaternion<wide> r = reference_between(a, b);
        naive_worst = std::max(naive_worst, angle_error(naive, r));
        ours_worst = std::max(ours_worst, angle_error(quat::rotation_between(a, b), r));
    }
    CAPTURE(naive_worst, ours_worst);
    CHECK(naive_worst > 1000);
    CHECK(ours_worst <= 4);
}

TEMPLATE_TEST_CASE("rotation_between agrees with Eigen's FromTwoVectors and GLM's rotation",
                   "[align]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int i = 0; i < 2000; ++i) {
        // Well-conditioned: at least 0.45 rad from parallel and opposite, where Eigen's and GLM's
        // sqrt(2 (1 + cos)) has not yet lost more than a few eps to cancellation.
        const vec3<T> a = random.unit_vector<T>(), b = random.unit_vector<T>();
        const T cosine = quat::dot(a, b);
        if (std::abs(cosine) > T(0.9)) continue;
        const quaternion<T> q = quat::rotation_between(a * T(3), b * T(0.5));
        // Eigen::Quaternion(w, x, y, z); FromTwoVectors normalizes its inputs itself.
        Eigen::Quaternion<T> e;
        e.setFromTwoVectors(Eigen::Matrix<T, 3, 1>(a.x * 3, a.y * 3, a.z * 3),
                            Eigen::Matrix<T, 3, 1>(b.x / 2, b.y / 2, b.z / 2));
        CHECK(quat::angle_between(q, quaternion<T>{e.w(), e.x(), e.y(), e.z()}) <=
              quat::test::tolerance<T>::glm);
        // glm::quat(w, x, y, z) (its memory order is x, y, z, w); glm::rotation wants unit vectors.
        const glm::qua<T> g =
            glm::rotation(glm::vec<3, T>(a.x, a.y, a.z), glm::vec<3, T>(b.x, b.y, b.z));
        CHECK(quat::angle_between(q, quaternion<T>{g.w, g.x, g.y, g.z}) <=
              quat::test::tolerance<T>::glm);
    }
}

// ---- look_rotation --------------------------------------------------------------------------

TEMPLATE_TEST_CASE("look_rotation: -z along forward, y toward up, x along forward x up", "[align]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    long double worst = 0;
    for (int i = 0; i < 20000; ++i) {
        const vec3<T> forward = random.unit_vector<T>() * random_length<T>(random);
        const vec3<T> up = random.unit_vector<T>() * random_length<T>(random);
        const quaternion<T> q = quat::look_rotation(forward, up);
        CAPTURE(i);
        const vec3<T> f = quat::normalize(forward), u = quat::normalize(up);
        const vec3<T> image_up = quat::rotate(q, vec3<T>{0, 1, 0});
        CHECK(quat::norm(quat::rotate(q, vec3<T>{0, 0, -1}) - f) <= 8 * eps<T>);
        CHECK(quat::dot(image_up, u) > 0);
        CHECK(std::abs(quat::dot(image_up, f)) <= 8 * eps<T>);
        CHECK(std::abs(quat::norm(q) - 1) <= 2 * eps<T>);
        worst = std::max(worst, angle_error(q, reference_look(forward, up)));
    }
    // Against the frame built in `wide`: measured float 1.95, double 2.26 eps.
    CAPTURE(worst);
    CHECK(worst <= 4);
}

TEMPLATE_TEST_CASE("look_rotation stays accurate as up approaches forward", "[align]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    long double worst = 0;
    for (int i = 0; i < 4000; ++i) {
        const vec3<T> forward = random.unit_vector<T>();
        // Angles 10^-1 .. 10^-6 (float) or 10^-14 (double), toward forward or backward.
        const int k = 1 + i % (sizeof(T) == sizeof(float) ? 6 : 14);
        const long double delta = std::pow(10.0L, -k);
        const vec3<T> up = turned(random, forward, i % 2 ? delta : 3.14159265358979323846L - delta);
        CAPTURE(i, k);
        REQUIRE(quat::try_look_rotation(forward * T(4), up));
        worst = std::max(worst, angle_error(quat::look_rotation(forward * T(4), up),
                                            reference_look(forward, up)));
    }
    // Measured float 1.86, double 2.05 eps.
    CAPTURE(worst);
    CHECK(worst <= 4);
}

TEMPLATE_TEST_CASE("look_rotation agrees with glm::quatLookAtRH", "[align]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int i = 0; i < 2000; ++i) {
        const vec3<T> forward = random.unit_vector<T>() * T(7), up = random.unit_vector<T>();
        if (quat::norm(quat::cross(quat::normalize(forward), up)) < T(0.1)) continue;
        const quaternion<T> q = quat::look_rotation(forward, up);
        // GLM wants a unit direction; glm::qua<T>(w, x, y, z).
        const vec3<T> f = quat::normalize(forward);
        const glm::qua<T> g =
            glm::quatLookAtRH(glm::vec<3, T>(f.x, f.y, f.z), glm::vec<3, T>(up.x, up.y, up.z));
        CHECK(quat::angle_between(q, quaternion<T>{g.w, g.x, g.y, g.z}) <=
              quat::test::tolerance<T>::glm);
    }
}

TEMPLATE_TEST_CASE("look_rotation with up parallel to forward falls back to rotation_between",
                   "[align]", float, double) {
    using T = TestType;
    const vec3<T> minus_z{0, 0, -1};
    quat::test::random_rotations random;
    for (int i = 0; i < 500; ++i) {
        const vec3<T> forward = random.unit_vector<T>() * T(3);
        for (const T k : {T(2), T(-0.5)}) {
            CHECK(quat::look_rotation(forward, forward * k) ==
                  quat::rotation_between(minus_z, forward));
            CHECK_FALSE(quat::try_look_rotation(forward, forward * k));
        }
    }
    // Straight down and straight up the y axis with y up: the shortest arc from -z.
    CHECK(quat::look_rotation(vec3<T>{0, -1, 0}, vec3<T>{0, 1, 0}) ==
          quat::rotation_between(minus_z, vec3<T>{0, -1, 0}));
    // The threshold |forward x up| <= eps |forward| |up|: half of it falls back, twice does not.
    const T e = eps<T>;
    CHECK_FALSE(quat::try_look_rotation(vec3<T>{0, 0, -1}, vec3<T>{e / 2, 0, 1}));
    CHECK_FALSE(quat::try_look_rotation(vec3<T>{0, 0, -1}, vec3<T>{0, 0, 1}));
    REQUIRE(quat::try_look_rotation(vec3<T>{0, 0, -1}, vec3<T>{0, 2 * e, 1}));
    // Even there the result is the exact frame: up' = y (the tiny y component of up).
    CHECK(*quat::try_look_rotation(vec3<T>{0, 0, -1}, vec3<T>{0, 2 * e, 1}) ==
          quaternion<T>::identity());
}

TEMPLATE_TEST_CASE("look_rotation of zero or non-finite input", "[align]", float, double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    const vec3<T> good{1, 2, 3}, up{0, 1, 0};
    for (const vec3<T> bad : {vec3<T>{0, 0, 0}, vec3<T>{nan, 0, 1}, vec3<T>{0, inf, 1}}) {
        CHECK_FALSE(quat::try_look_rotation(bad, up));
        CHECK_FALSE(quat::try_look_rotation(good, bad));
        const quaternion<T> q = quat::look_rotation(bad, up), p = quat::look_rotation(good, bad);
        CHECK((std::isnan(q.w) && std::isnan(q.x) && std::isnan(q.y) && std::isnan(q.z)));
        CHECK((std::isnan(p.w) && std::isnan(p.x) && std::isnan(p.y) && std::isnan(p.z)));
    }
    // Huge and tiny lengths are fine.
    const quaternion<T> r = quat::look_rotation(good, up);
    const T huge = std::numeric_limits<T>::max() / 8, tiny = std::numeric_limits<T>::denorm_min();
    CHECK(quat::angle_between(quat::look_rotation(good * huge, up * tiny), r) <= 4 * eps<T>);
    CHECK(quat::try_look_rotation(good, up) == r);
}

// ---- the other camera conventions of docs/conventions.md ------------------------------------

TEMPLATE_TEST_CASE("docs: +z forward, y up is look_rotation(f, up) * rotation_y(numbers::pi)",
                   "[align]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int i = 0; i < 1000; ++i) {
        const vec3<T> forward = random.unit_vector<T>(), up = random.unit_vector<T>();
        if (quat::norm(quat::cross(forward, up)) < T(0.1)) continue;
        const quaternion<T> q =
            quat::look_rotation(forward, up) * quat::rotation_y(quat::numbers::pi_v<T>);
        const vec3<T> image_up = quat::rotate(q, vec3<T>{0, 1, 0});
        CHECK(quat::norm(quat::rotate(q, vec3<T>{0, 0, 1}) - forward) <= 8 * eps<T>);
        CHECK(quat::dot(image_up, up) > 0);
        CHECK(std::abs(quat::dot(image_up, forward)) <= 8 * eps<T>);
        // x = y x z points left of forward, as right-handed axes with z forward must.
        CHECK(quat::dot(quat::rotate(q, vec3<T>{1, 0, 0}), quat::cross(forward, up)) < 0);
    }
    // Looking along +z with y up is the identity.
    CHECK(quat::angle_between(quat::look_rotation(vec3<T>{0, 0, 1}, vec3<T>{0, 1, 0}) *
                                  quat::rotation_y(quat::numbers::pi_v<T>),
                              quaternion<T>::identity()) <= 4 * eps<T>);
}

TEMPLATE_TEST_CASE(
    "docs: aerospace body axes (x forward, y right, z down) are look_rotation(f, up) * "
    "(1/2, 1/2, 1/2, -1/2)",
    "[align]", float, double) {
    using T = TestType;
    const quaternion<T> body{T(0.5), T(0.5), T(0.5), T(-0.5)};
    // The same constant as rotation_z(-pi/2) * rotation_y(pi/2).
    CHECK(quat::angle_between(body, quat::rotation_z(-quat::numbers::pi_v<T> / 2) *
                                        quat::rotation_y(quat::numbers::pi_v<T> / 2)) <=
          4 * eps<T>);
    quat::test::random_rotations random;
    for (int i = 0; i < 1000; ++i) {
        const vec3<T> forward = random.unit_vector<T>(), up = random.unit_vector<T>();
        if (quat::norm(quat::cross(forward, up)) < T(0.1)) continue;
        const quaternion<T> q = quat::look_rotation(forward, up) * body;
        const vec3<T> right = quat::normalize(quat::cross(forward, up));
        CHECK(quat::norm(quat::rotate(q, vec3<T>{1, 0, 0}) - forward) <= 8 * eps<T>);
        CHECK(quat::norm(quat::rotate(q, vec3<T>{0, 1, 0}) - right) <= 8 * eps<T>);
        CHECK(quat::dot(quat::rotate(q, vec3<T>{0, 0, 1}), up) < 0);  // z down
    }
    // North-east-down world, flying north level: the identity.
    CHECK(quat::angle_between(quat::look_rotation(vec3<T>{1, 0, 0}, vec3<T>{0, 0, -1}) * body,
                              quaternion<T>::identity()) <= 4 * eps<T>);
}

}  // namespace test_align
