// trajectory/so3_bspline.hpp and se3_bspline.hpp: one evaluation of the value, the body velocity
// and its derivative with the Jacobians of all three with respect to the K control points
// (jacobian/quat/<spline>_k<K>/double: the analytic O(K) recurrences) against the same three
// Jacobians by automatic differentiation with ceres::Jet (jacobian/jet/<spline>_k<K>/double: the
// spline evaluated on Jets over the 3K (SO(3)) or 6K (SE(3)) right-tangent perturbations of the
// control points, the value's derivatives read into its tangent as bench_lie.cpp does), for K = 4,
// 5, 6; and evaluation over 1024 sorted times of a 64-point spline, the value alone and with every
// Jacobian (bspline_batch/quat/<spline>_k<K>_{value,jacobians}/double/1024: items are times).
#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <ceres/jet.h>

#include <quat/trajectory/se3_bspline.hpp>
#include <quat/trajectory/so3_bspline.hpp>

#include "common.hpp"

namespace bench {
namespace {

using quat::matrix;
using quat::quatd;
using quat::vec3;
using dq = quat::dual_quaternion<double>;
template <int N>
using jet = ceres::Jet<double, N>;

/// K control points of one segment (t0 = 0, dt = 1, the domain [0, 1]) and a time in it. Each
/// point is a small random step from the previous one, as a fitted trajectory's are.
template <class Point, std::size_t K>
struct segment {
    std::array<Point, K> points;
    double t;
};
quatd step_rotation(random_source& r, const quatd& from) {
    return from * quat::from_rotation_vector(quat::normalize(r.vector()) * r.uniform(0.05, 0.8));
}
template <std::size_t K>
segment<quatd, K> rotations(random_source& r) {
    segment<quatd, K> s{};
    s.points[0] = r.rotation();
    for (std::size_t m = 1; m < K; ++m) s.points[m] = step_rotation(r, s.points[m - 1]);
    s.t = r.uniform(0, 1);
    return s;
}
template <std::size_t K>
segment<dq, K> motions(random_source& r) {
    const segment<quatd, K> q = rotations<K>(r);
    segment<dq, K> s{};
    vec3<double> p = r.vector();
    for (std::size_t m = 0; m < K; ++m) {
        s.points[m] = quat::to_dual_quaternion(q.points[m], p);
        p += r.vector() * 0.3;
    }
    s.t = q.t;
    return s;
}

/// x (1, d/2): the first-order right plus of SO(3), d Jets at 0 from variable `first`.
template <int N>
quat::quaternion<jet<N>> first_order_plus(const quatd& x, int first) {
    const quat::quaternion<jet<N>> step{jet<N>(1), jet<N>(0, first) * 0.5,
                                        jet<N>(0, first + 1) * 0.5, jet<N>(0, first + 2) * 0.5};
    return quat::quaternion<jet<N>>(x) * step;
}
/// x ((1, omega/2) + eps (0, rho/2)): SE(3)'s, rho from variable `first`, omega after it.
template <int N>
quat::dual_quaternion<jet<N>> first_order_plus(const dq& x, int first) {
    const quat::dual_quaternion<jet<N>> step{
        {jet<N>(1), jet<N>(0, first + 3) * 0.5, jet<N>(0, first + 4) * 0.5,
         jet<N>(0, first + 5) * 0.5},
        {jet<N>(0), jet<N>(0, first) * 0.5, jet<N>(0, first + 1) * 0.5,
         jet<N>(0, first + 2) * 0.5}};
    return quat::dual_quaternion<jet<N>>(x) * step;
}
/// The derivatives of a unit quaternion of Jets read into the tangent: 2 vec(q^-1 dq / dd_i).
template <int N>
matrix<double, 3, N> tangent(const quat::quaternion<jet<N>>& q) {
    const quatd inverse{q.w.a, -q.x.a, -q.y.a, -q.z.a};
    matrix<double, 3, N> m{};
    for (int i = 0; i < N; ++i) {
        const quatd d = inverse * quatd{q.w.v[i], q.x.v[i], q.y.v[i], q.z.v[i]};
        m(0, i) = 2 * d.x;
        m(1, i) = 2 * d.y;
        m(2, i) = 2 * d.z;
    }
    return m;
}
/// The same for a unit dual quaternion of Jets: X^-1 dX = (0, omega/2) + eps (0, rho/2).
template <int N>
matrix<double, 6, N> tangent(const quat::dual_quaternion<jet<N>>& x) {
    const dq inverse{{x.real.w.a, -x.real.x.a, -x.real.y.a, -x.real.z.a},
                     {x.dual.w.a, -x.dual.x.a, -x.dual.y.a, -x.dual.z.a}};
    matrix<double, 6, N> m{};
    for (int i = 0; i < N; ++i) {
        const dq d = inverse * dq{{x.real.w.v[i], x.real.x.v[i], x.real.y.v[i], x.real.z.v[i]},
                                  {x.dual.w.v[i], x.dual.x.v[i], x.dual.y.v[i], x.dual.z.v[i]}};
        const double column[6] = {d.dual.x, d.dual.y, d.dual.z, d.real.x, d.real.y, d.real.z};
        for (int r = 0; r < 6; ++r) m(r, i) = 2 * column[r];
    }
    return m;
}
/// The derivatives of a vector of Jets, one row per component.
template <int N>
matrix<double, 3, N> partials(const vec3<jet<N>>& v) {
    matrix<double, 3, N> m{};
    for (int i = 0; i < N; ++i) {
        m(0, i) = v.x.v[i];
        m(1, i) = v.y.v[i];
        m(2, i) = v.z.v[i];
    }
    return m;
}
template <int N>
matrix<double, 6, N> partials(const quat::se3::twist<jet<N>>& t) {
    const matrix<double, 3, N> l = partials(t.linear), a = partials(t.angular);
    matrix<double, 6, N> m{};
    for (int i = 0; i < N; ++i)
        for (int r = 0; r < 3; ++r) {
            m(r, i) = l(r, i);
            m(r + 3, i) = a(r, i);
        }
    return m;
}

/// A sample and its three Jacobians, returned whole so that nothing is optimized away.
template <class Sample, class Blocks>
struct sample_with_jacobians {
    Sample sample;
    Blocks J_value, J_velocity, J_acceleration;
};
template <class Value, class Rate>
struct jet_jacobians {
    Value J_value;
    Rate J_velocity, J_acceleration;
};

template <class Make, class F>
void add(const std::string& name, Make make, F f) {
    benchmark::RegisterBenchmark(name.c_str(),
                                 [make, f](benchmark::State& state) { cycle(state, make, f); });
}

template <std::size_t K>
void register_order() {
    const std::string k = "_k" + std::to_string(K);
    constexpr int N3 = 3 * K, N6 = 6 * K;
    using so3 = quat::so3_bspline<double, K>;
    using se3 = quat::se3_bspline<double, K>;
    add("jacobian/quat/so3_bspline" + k + "/double", rotations<K>, [](const segment<quatd, K>& s) {
        sample_with_jacobians<quat::so3_bspline_sample<double>, typename so3::jacobian_blocks> r{};
        r.sample = so3(s.points.data(), K, 0.0, 1.0)
                       .evaluate(s.t, &r.J_value, &r.J_velocity, &r.J_acceleration);
        return r;
    });
    add("jacobian/jet/so3_bspline" + k + "/double", rotations<K>, [](const segment<quatd, K>& s) {
        std::array<quat::quaternion<jet<N3>>, K> points;
        for (int m = 0; m < static_cast<int>(K); ++m)
            points[static_cast<std::size_t>(m)] =
                first_order_plus<N3>(s.points[static_cast<std::size_t>(m)], 3 * m);
        const auto sample = quat::so3_bspline<jet<N3>, K>(points.data(), K, jet<N3>(0), jet<N3>(1))
                                .evaluate(jet<N3>(s.t));
        return jet_jacobians<matrix<double, 3, N3>, matrix<double, 3, N3>>{
            tangent(sample.rotation), partials(sample.angular_velocity),
            partials(sample.angular_acceleration)};
    });
    add("jacobian/quat/se3_bspline" + k + "/double", motions<K>, [](const segment<dq, K>& s) {
        sample_with_jacobians<quat::se3_bspline_sample<double>, typename se3::jacobian_blocks> r{};
        r.sample = se3(s.points.data(), K, 0.0, 1.0)
                       .evaluate(s.t, &r.J_value, &r.J_velocity, &r.J_acceleration);
        return r;
    });
    add("jacobian/jet/se3_bspline" + k + "/double", motions<K>, [](const segment<dq, K>& s) {
        std::array<quat::dual_quaternion<jet<N6>>, K> points;
        for (int m = 0; m < static_cast<int>(K); ++m)
            points[static_cast<std::size_t>(m)] =
                first_order_plus<N6>(s.points[static_cast<std::size_t>(m)], 6 * m);
        const auto sample = quat::se3_bspline<jet<N6>, K>(points.data(), K, jet<N6>(0), jet<N6>(1))
                                .evaluate(jet<N6>(s.t));
        return jet_jacobians<matrix<double, 6, N6>, matrix<double, 6, N6>>{
            tangent(sample.motion), partials(sample.velocity), partials(sample.acceleration)};
    });
}

/// 64 control points in a chain of small steps, and 1024 sorted times over the whole domain.
template <class Point>
struct batch_input {
    std::vector<Point> points;
    std::vector<double> times;
};
template <class Point, std::size_t K>
batch_input<Point> make_batch(random_source& r) {
    constexpr std::size_t count = 64, times = 1024;
    batch_input<Point> b;
    quatd q = r.rotation();
    vec3<double> p = r.vector();
    for (std::size_t i = 0; i < count; ++i) {
        if constexpr (std::is_same_v<Point, quatd>) b.points.push_back(q);
        else b.points.push_back(quat::to_dual_quaternion(q, p));
        q = step_rotation(r, q);
        p += r.vector() * 0.3;
    }
    const double end = double(count - K + 1);
    for (std::size_t i = 0; i < times; ++i) b.times.push_back(r.uniform(0, end));
    std::sort(b.times.begin(), b.times.end());
    return b;
}

template <template <class, std::size_t> class Spline, class Point, std::size_t K>
void register_batch(const std::string& spline_name) {
    const std::string prefix = "bspline_batch/quat/" + spline_name + "_k" + std::to_string(K);
    benchmark::RegisterBenchmark(
        (prefix + "_value/double/1024").c_str(), [](benchmark::State& state) {
            random_source random;
            const batch_input<Point> b = make_batch<Point, K>(random);
            const Spline<double, K> spline(b.points, 0.0, 1.0);
            for (auto _ : state) {
                for (const double t : b.times) {
                    auto value = spline(t);
                    benchmark::DoNotOptimize(value);
                }
            }
            state.SetItemsProcessed(state.iterations() *
                                    static_cast<benchmark::IterationCount>(b.times.size()));
        });
    benchmark::RegisterBenchmark(
        (prefix + "_jacobians/double/1024").c_str(), [](benchmark::State& state) {
            random_source random;
            const batch_input<Point> b = make_batch<Point, K>(random);
            const Spline<double, K> spline(b.points, 0.0, 1.0);
            typename Spline<double, K>::jacobian_blocks J_value{}, J_velocity{}, J_acceleration{};
            for (auto _ : state) {
                for (const double t : b.times) {
                    auto sample = spline.evaluate(t, &J_value, &J_velocity, &J_acceleration);
                    benchmark::DoNotOptimize(sample);
                    benchmark::DoNotOptimize(J_value);
                    benchmark::DoNotOptimize(J_velocity);
                    benchmark::DoNotOptimize(J_acceleration);
                }
            }
            state.SetItemsProcessed(state.iterations() *
                                    static_cast<benchmark::IterationCount>(b.times.size()));
        });
}

}  // namespace

void register_trajectory() {
    register_order<4>();
    register_order<5>();
    register_order<6>();
    register_batch<quat::so3_bspline, quatd, 4>("so3");
    register_batch<quat::se3_bspline, dq, 4>("se3");
    register_batch<quat::so3_bspline, quatd, 6>("so3");
    register_batch<quat::se3_bspline, dq, 6>("se3");
}

}  // namespace bench
