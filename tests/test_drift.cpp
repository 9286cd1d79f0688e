// Drift of chained products: 10^6 products of unit quaternions in float. Each product of two unit
// quaternions is unit only up to a few eps, and the errors add up like a random walk (or worse, a
// drift), so the library's documented policy is: renormalize a chained orientation every N
// products (N = 16 here: measured max ||q| - 1| = 8.0 eps over 10^6 products; N = 64 gave 18 eps).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_drift {

namespace {

constexpr std::size_t chain_length = 1000000;
constexpr std::size_t renormalize_every = 16;

struct drift_result {
    double max_norm_error;     // max over the chain of ||q| - 1|, measured in double
    double final_angle_error;  // rotation angle between the float chain and a double chain
};

/// Multiplies `chain_length` random unit steps (a fixed set of 1024, cycled) into q, renormalizing
/// every `every` products (0 = never), and tracks the same chain in double as the reference.
drift_result run_chain(std::size_t every) {
    quat::test::random_rotations rng;
    std::vector<quat::quatf> steps;
    for (int i = 0; i < 1024; ++i) steps.push_back(quat::normalize(rng.unit_quaternion<float>()));
    quat::quatf q = quat::quatf::identity();
    quat::quatd reference = quat::quatd::identity();
    double max_norm_error = 0;
    for (std::size_t i = 0; i < chain_length; ++i) {
        const quat::quatf& s = steps[i % steps.size()];
        q = s * q;
        reference = quat::normalize(quat::quatd{s.w, s.x, s.y, s.z} * reference);
        if (every != 0 && (i + 1) % every == 0) q = quat::normalize(q);
        const double n = quat::norm(quat::quatd{q.w, q.x, q.y, q.z});
        max_norm_error = std::max(max_norm_error, std::abs(n - 1));
    }
    const quat::quatd qd{q.w, q.x, q.y, q.z};
    return {max_norm_error, double(quat::angle_between(quat::normalize(qd), reference))};
}

}  // namespace

TEST_CASE("10^6 chained float products, renormalized every 16, stay within 16 eps of unit norm",
          "[drift]") {
    const drift_result r = run_chain(renormalize_every);
    const double eps = double(std::numeric_limits<float>::epsilon());
    INFO("max ||q| - 1| = " << r.max_norm_error / eps << " eps; final angle error "
                            << r.final_angle_error << " rad");
    // Between renormalizations the error grows by at most a few eps per product (random-walk-like).
    CHECK(r.max_norm_error <= 16 * eps);
    // The orientation itself accumulates rounding like any float integration: bounded loosely.
    CHECK(r.final_angle_error <= 1e-2);
}

TEST_CASE("without renormalization the norm of a 10^6-product chain drifts", "[drift]") {
    // Documents why the policy exists: the unrenormalized chain is measurably worse.
    const drift_result never = run_chain(0);
    const drift_result policy = run_chain(renormalize_every);
    INFO("never: " << never.max_norm_error << ", every 16: " << policy.max_norm_error);
    CHECK(never.max_norm_error > policy.max_norm_error);
}

}  // namespace test_drift
