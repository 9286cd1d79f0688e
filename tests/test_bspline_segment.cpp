// Where a time falls on a uniform B-spline (quat/trajectory/bspline_segment.hpp): every spline's
// segment_at(t) names the segment evaluate(t) uses, and the offset from which a spline over that
// segment's K points alone, starting at 0, gives the same sample: what the Ceres residuals of
// interop/ceres_trajectory.hpp rely on. Outside the domain, and for views that cannot be
// evaluated, it is empty.
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include <quat/quat.hpp>
#include <quat/trajectory.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"

namespace test_bspline_segment {

namespace {

using namespace quat;

constexpr double t0 = -0.75, dt = 0.4;

/// Times across the range of a spline of `count` points: every knot, points between them, the
/// ends, and the ends' neighbours inside.
template <std::size_t K>
std::vector<double> times_of(std::size_t count) {
    const double end = t0 + static_cast<double>(count - K + 1) * dt;
    std::vector<double> times{t0, std::nextafter(t0, end), std::nextafter(end, t0), end};
    for (std::size_t m = 0; m <= count - K + 1; ++m) {
        const double knot = t0 + static_cast<double>(m) * dt;
        times.push_back(knot);
        if (m <= count - K) times.push_back(knot + 0.3 * dt);
    }
    return times;
}

template <std::size_t K>
void check_so3_and_se3() {
    test::random_rotations random;
    const std::vector<quaternion<double>> rotations = test::random_walk<double>(random, 9, 1.0);
    std::vector<dual_quaternion<double>> motions;
    std::vector<vec3<double>> positions;
    for (const quaternion<double>& q : rotations) {
        const vec3<double> p = random.vector<double>(2.0);
        motions.push_back(to_dual_quaternion(q, p));
        positions.push_back(p);
    }
    const so3_bspline<double, K> so3(rotations, t0, dt);
    const se3_bspline<double, K> se3(motions, t0, dt);
    const euclidean_bspline<double, K> points(positions, t0, dt);
    const split_bspline<double, K> split(rotations, positions, t0, dt);
    for (const double t : times_of<K>(rotations.size())) {
        INFO("K = " << K << ", t = " << t);
        const std::optional<bspline_segment<double>> at = so3.segment_at(t);
        REQUIRE(at.has_value());
        CHECK(at->first == so3.evaluate(t).first);
        CHECK(at->offset >= 0);
        CHECK(at->offset <= dt);
        // The same segment and offset from every form of the spline.
        for (const std::optional<bspline_segment<double>>& other :
             {se3.segment_at(t), points.segment_at(t), split.segment_at(t)}) {
            REQUIRE(other.has_value());
            CHECK(other->first == at->first);
            CHECK(other->offset == at->offset);
        }
        // The segment's K points alone, from time 0, give the sample at the offset (up to the
        // rounding of t - t0 - first dt).
        const so3_bspline<double, K> local(rotations.data() + at->first, K, 0.0, dt);
        CHECK(norm(so3::minus(local(at->offset), so3(t))) < 1e-14);
        const se3_bspline<double, K> local_motion(motions.data() + at->first, K, 0.0, dt);
        CHECK(norm(se3::minus(local_motion(at->offset), se3(t)).linear) < 1e-14);
    }
}

}  // namespace

TEST_CASE("bspline_segment: segment_at names evaluate's segment and the offset into it") {
    check_so3_and_se3<4>();
    check_so3_and_se3<5>();
    check_so3_and_se3<6>();
}

TEST_CASE("bspline_segment: empty outside the domain and for views that cannot be evaluated") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<quaternion<double>> rotations(6, quaternion<double>::identity());
    const std::vector<vec3<double>> positions(6, vec3<double>{1, 2, 3});
    const so3_bspline<double, 4> spline(rotations, 1.0, 0.5);  // [1, 2.5]
    for (const double t : {std::nextafter(1.0, 0.0), std::nextafter(2.5, 3.0), -inf, inf, nan}) {
        INFO("t = " << t);
        CHECK(!spline.segment_at(t).has_value());
    }
    CHECK(spline.segment_at(2.5)->first == 2);  // the end belongs to the last segment
    CHECK(spline.segment_at(2.5)->offset == 0.5);
    CHECK(!so3_bspline<double, 4>(rotations.data(), 3, 1.0, 0.5).segment_at(1.0).has_value());
    CHECK(!so3_bspline<double, 4>(rotations, 1.0, 0.0).segment_at(1.0).has_value());
    CHECK(!so3_bspline<double, 4>(rotations, nan, 0.5).segment_at(1.0).has_value());
    CHECK(!so3_bspline<double, 4>(nullptr, 6, 1.0, 0.5).segment_at(1.0).has_value());
    // A split spline's rotations and positions must be as many.
    const std::vector<vec3<double>> fewer(5, vec3<double>{1, 2, 3});
    CHECK(split_bspline<double, 4>(rotations, positions, 1.0, 0.5).segment_at(1.2).has_value());
    CHECK(!split_bspline<double, 4>(rotations, fewer, 1.0, 0.5).segment_at(1.2).has_value());
}

}  // namespace test_bspline_segment
