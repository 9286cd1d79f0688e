// Specification of rigid/blend.hpp: dual-quaternion linear blending (Kavan et al. 2007), checked
// against its definition in long double and against the collapse of blended matrices it avoids.
#include <cmath>
#include <limits>
#include <vector>

#include <quat/rigid/blend.hpp>
#include <quat/rigid/homogeneous_matrix.hpp>
#include <quat/rigid/screw.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_blend {

using quat::dual_quaternion;
using quat::quaternion;
using quat::vec3;
using quat::test::eps;
using quat::test::max_difference;

namespace {

// The definition, in long double: sum of sign_i w_i dq_i, divided by |real|, dual made orthogonal.
template <class T>
dual_quaternion<long double> reference_blend(const std::vector<dual_quaternion<T>>& dqs,
                                             const std::vector<T>& weights) {
    quaternion<long double> real{0, 0, 0, 0}, dual{0, 0, 0, 0};
    for (std::size_t i = 0; i < dqs.size(); ++i) {
        const quaternion<long double> r(dqs[i].real), d(dqs[i].dual), r0(dqs[0].real);
        const long double w = quat::dot(r, r0) < 0 ? -(long double)weights[i] : weights[i];
        real += r * w;
        dual += d * w;
    }
    const long double n = std::sqrt(quat::dot(real, real));
    real = real / n;
    dual = dual / n;
    return {real, dual - real * quat::dot(real, dual)};
}

}  // namespace

TEMPLATE_TEST_CASE("blend is the normalized, hemisphere-aligned weighted sum", "[blend]", float,
                   double) {
    quat::test::random_rotations random;
    for (int i = 0; i < 200; ++i) {
        std::vector<dual_quaternion<TestType>> dqs;
        std::vector<TestType> weights;
        for (int k = 0; k < 4; ++k) {
            dqs.push_back(random.rigid_motion<TestType>());
            weights.push_back(random.uniform<TestType>(0.0, 1.0));
        }
        const auto ours = quat::blend(dqs, weights);
        const auto reference = reference_blend(dqs, weights);
        CHECK(max_difference(quaternion<long double>(ours.real), reference.real) <=
              8 * eps<TestType>);
        CHECK(max_difference(quaternion<long double>(ours.dual), reference.dual) <=
              16 * eps<TestType>);
        CHECK(std::abs(quat::dot(ours.real, ours.dual)) <= 8 * eps<TestType>);
        // Signs do not matter: -dq is the same motion.
        dqs[2] = -dqs[2];
        const auto flipped = quat::blend(dqs.data(), weights.data(), dqs.size());
        CHECK(max_difference(flipped.real, ours.real) <= 4 * eps<TestType>);
        CHECK(max_difference(flipped.dual, ours.dual) <= 8 * eps<TestType>);
    }
}

TEST_CASE("blend with one weight 1 and the rest 0 gives that transform", "[blend]") {
    quat::test::random_rotations random;
    const std::vector<dual_quaternion<double>> dqs{random.rigid_motion<double>(),
                                                   random.rigid_motion<double>()};
    const double first[] = {1, 0}, second[] = {0, 1};
    const auto a = quat::blend(dqs.data(), first, 2), b = quat::blend(dqs.data(), second, 2);
    CHECK(max_difference(a.real, dqs[0].real) <= 2 * eps<double>);
    CHECK(max_difference(quat::translation_of(b), quat::translation_of(dqs[1])) <= 8 * eps<double>);
    CHECK(quat::to_screw(quat::inverse(b) * dqs[1]).angle <= 4 * eps<double>);
}

TEST_CASE("blend keeps a twisted joint rigid where blended matrices collapse", "[blend]") {
    // Half way between no twist and a half turn about the bone (x axis): the blended matrix
    // flattens the cross-section to a line (the candy wrapper); the blend turns it by 90 degrees.
    const auto rest = quat::dual_quaterniond::identity();
    const auto twisted =
        quat::to_dual_quaternion(quat::rotation_x(quat::numbers::pi), vec3<double>{0, 0, 0});
    const std::vector<quat::dual_quaterniond> bones{rest, twisted};
    const std::vector<double> weights{0.5, 0.5};
    const auto blended = quat::blend(bones, weights);
    const vec3<double> p{0, 0.25, 0};  // on the cylinder's surface
    const vec3<double> moved = quat::transform(blended, p);
    CHECK(quat::norm(moved) == Approx(0.25).epsilon(1e-15));
    const auto a = quat::to_homogeneous(rest), b = quat::to_homogeneous(twisted);
    vec3<double> linear = quat::transform(a, p) * 0.5 + quat::transform(b, p) * 0.5;
    CHECK(quat::norm(linear) <= 1e-16);
}

TEST_CASE("blend of cancelling or no weights is NaN", "[blend][nan]") {
    const auto a = quat::to_dual_quaternion(quat::rotation_z(0.3), vec3<double>{1, 0, 0});
    const std::vector<quat::dual_quaterniond> one{a, a};
    const std::vector<double> cancelling{1, -1};
    CHECK(std::isnan(quat::blend(one, cancelling).real.w));
    CHECK(std::isnan(quat::blend(one.data(), cancelling.data(), 0).real.w));
    const std::vector<double> nan_weight{1, std::numeric_limits<double>::quiet_NaN()};
    CHECK(std::isnan(quat::blend(one, nan_weight).dual.x));
}

TEST_CASE("blend is constexpr", "[blend][constexpr]") {
    constexpr quat::dual_quaterniond pair[] = {
        quat::dual_quaterniond::identity(),
        quat::to_dual_quaternion(quat::quatd::identity(), vec3<double>{2, 0, 0})};
    constexpr double weights[] = {0.5, 0.5};
    constexpr auto middle = quat::blend(pair, weights);
    STATIC_REQUIRE(middle.dual.x == 0.5);  // half of a translation by 1
}

// ---- Edges: weights of any finite size, mixed precisions ----

TEMPLATE_TEST_CASE("weights from subnormal to max() blend as their ratios", "[blend][edges]", float,
                   double) {
    // The weights are divided by the largest |weight| first, so these are the same sums bit for
    // bit. Unscaled sums overflow at max() (NaN) and lose the subnormals' digits.
    using T = TestType;
    quat::test::random_rotations random;
    const T max = std::numeric_limits<T>::max(), tiny = std::numeric_limits<T>::denorm_min();
    for (int trial = 0; trial < 50; ++trial) {
        const std::vector<dual_quaternion<T>> dqs{
            random.rigid_motion<T>(), random.rigid_motion<T>(), random.rigid_motion<T>()};
        const auto plain = quat::blend(dqs, std::vector<T>{4, 2, -1});
        const auto huge = quat::blend(dqs, std::vector<T>{max, max / 2, -max / 4});
        const auto small = quat::blend(dqs, std::vector<T>{4 * tiny, 2 * tiny, -tiny});
        CHECK(huge.real == plain.real);
        CHECK(huge.dual == plain.dual);
        CHECK(small.real == plain.real);
        CHECK(small.dual == plain.dual);
    }
}

TEST_CASE("mixed precisions: the transforms' precision, weights converted", "[blend][edges]") {
    // blend(vector<dual_quaternionf>, vector<double>) did not compile ("invalid static_cast").
    quat::test::random_rotations random;
    const std::vector<quat::dual_quaternionf> bones{random.rigid_motion<float>(),
                                                    random.rigid_motion<float>()};
    const std::vector<quat::dual_quaterniond> bones_d{random.rigid_motion<double>(),
                                                      random.rigid_motion<double>()};
    const std::vector<float> wf{0.25f, 0.75f};
    const std::vector<double> wd{0.25, 0.75};
    const quat::dual_quaternionf f = quat::blend(bones, wd);
    CHECK(f.real == quat::blend(bones, wf).real);
    CHECK(f.dual == quat::blend(bones, wf).dual);
    const quat::dual_quaterniond d = quat::blend(bones_d, wf);
    CHECK(d.real == quat::blend(bones_d, wd).real);
    CHECK(d.dual == quat::blend(bones_d.data(), wd.data(), 2).dual);
    CHECK(quat::blend(bones.data(), wd.data(), 2).dual == f.dual);  // pointers too
}

}  // namespace test_blend
