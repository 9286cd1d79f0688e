// Forward-mode differentiation through quat: with a dual-number scalar
// (tests/support/dual_number.hpp)
// and with ceres::Jet, every function below gives finite derivatives that agree with central
// differences in long double, at fixed-seed random points and where closed forms would divide a
// zero
// by a zero: the identity, zero rotation vectors, tiny angles (1e-12 rad), the switch to the
// small-angle series, and near half turns (pi - 1e-8).
//
// The reference: central differences of the long double function, Richardson-extrapolated twice
// over steps h, h/2, h/4 (error O(h^6)). Errors are relative to the largest entry of the Jacobian.
// Where the function is smooth only within delta of the point (a half turn, beyond which q and -q
// swap), the step must stay below delta and long double's rounding, about 1e-19 / h relative,
// limits the reference: those points say so and use a tolerance from that bound (as does
// rotation_between of nearly opposite directions, where the result amplifies roundings 1e8 times).
// QUAT_DIFFERENTIATION_REPORT=1 in the environment prints every measured error.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <limits>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include <ceres/jet.h>
#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>
#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/dual_number.hpp"
#include "support/random.hpp"

namespace test_differentiation {

namespace {

using namespace quat;
using quat::test::dual;

template <class T>
struct is_jet : std::false_type {};
template <class T, int N>
struct is_jet<ceres::Jet<T, N>> : std::true_type {};

/// Input number i of N with value v, as scalar S (a dual or a Jet).
template <class S>
S variable(double v, int i) {
    if constexpr (is_jet<S>::value) return S(v, i);
    else return S::variable(v, static_cast<std::size_t>(i));
}
// Partial i of output y. Not named partial: quat::test::partial (support/bspline_checks.hpp), found
// by argument-dependent lookup for a dual, would make the call ambiguous in a unity build.
template <std::size_t N>
double derivative(const dual<double, N>& y, int i) {
    return y.d[static_cast<std::size_t>(i)];
}
template <int N>
double derivative(const ceres::Jet<double, N>& y, int i) {
    return y.v[i];
}

template <class F, std::size_t In>
constexpr std::size_t outputs_of =
    std::tuple_size_v<decltype(std::declval<F>()(std::array<double, In>{}))>;

template <std::size_t In, std::size_t Out>
using jacobian = std::array<std::array<long double, In>, Out>;

/// The Jacobian of f at x by forward-mode differentiation with scalar S.
template <class S, std::size_t In, class F>
jacobian<In, outputs_of<F, In>> autodiff(F f, const std::array<double, In>& x) {
    std::array<S, In> input{};
    for (std::size_t i = 0; i < In; ++i) input[i] = variable<S>(x[i], static_cast<int>(i));
    const auto y = f(input);
    jacobian<In, outputs_of<F, In>> result{};
    for (std::size_t r = 0; r < y.size(); ++r)
        for (std::size_t i = 0; i < In; ++i) result[r][i] = derivative(y[r], static_cast<int>(i));
    return result;
}

/// The Jacobian of f at x by central differences in long double, Richardson-extrapolated twice.
template <std::size_t In, class F>
jacobian<In, outputs_of<F, In>> central_differences(F f, const std::array<double, In>& x,
                                                    long double h) {
    constexpr std::size_t out = outputs_of<F, In>;
    jacobian<In, out> result{};
    for (std::size_t i = 0; i < In; ++i) {
        std::array<std::array<long double, 3>, out> estimate{};
        for (std::size_t k = 0; k < 3; ++k) {
            const long double step = h / static_cast<long double>(1 << k);
            std::array<long double, In> plus{}, minus{};
            for (std::size_t j = 0; j < In; ++j) plus[j] = minus[j] = x[j];
            plus[i] += step;
            minus[i] -= step;
            const long double width = plus[i] - minus[i];  // 2 step as rounded: exact
            const auto up = f(plus), down = f(minus);
            for (std::size_t r = 0; r < out; ++r) estimate[r][k] = (up[r] - down[r]) / width;
        }
        for (std::size_t r = 0; r < out; ++r) {
            const long double first = (4 * estimate[r][1] - estimate[r][0]) / 3;
            const long double second = (4 * estimate[r][2] - estimate[r][1]) / 3;
            result[r][i] = (16 * second - first) / 15;
        }
    }
    return result;
}

/// max |got - reference| / max |reference|, or Inf when got has a NaN or infinite entry.
template <std::size_t In, std::size_t Out>
double relative_error(const jacobian<In, Out>& got, const jacobian<In, Out>& reference) {
    long double largest = 0, error = 0;
    for (std::size_t r = 0; r < Out; ++r) {
        for (std::size_t i = 0; i < In; ++i) {
            if (!std::isfinite(got[r][i])) return std::numeric_limits<double>::infinity();
            largest = std::max(largest, std::abs(reference[r][i]));
            error = std::max(error, std::abs(got[r][i] - reference[r][i]));
        }
    }
    return static_cast<double>(largest > 0 ? error / largest : error);
}

/// Both scalars' derivatives of f at x are finite and within `tolerance` of the reference
/// (steps from h).
template <std::size_t In, class F>
void check_derivatives(const std::string& name, F f, const std::array<double, In>& x,
                       long double h = 1e-3L, double tolerance = 1e-12) {
    const auto reference = central_differences<In>(f, x, h);
    const double dual_error = relative_error(autodiff<dual<double, In>, In>(f, x), reference);
    const double jet_error =
        relative_error(autodiff<ceres::Jet<double, static_cast<int>(In)>, In>(f, x), reference);
    if (std::getenv("QUAT_DIFFERENTIATION_REPORT") != nullptr)
        std::printf("%-48s dual %.2e  Jet %.2e\n", name.c_str(), dual_error, jet_error);
    INFO(name);
    CHECK(dual_error <= tolerance);
    CHECK(jet_error <= tolerance);
}

// The functions, with inputs and outputs as flat arrays of any scalar S.
template <class S, std::size_t N>
quaternion<S> quat_at(const std::array<S, N>& a, std::size_t i = 0) {
    return {a[i], a[i + 1], a[i + 2], a[i + 3]};
}
/// For functions of unit quaternions: derivatives along the sphere, which the input's
/// normalization projects onto (off the sphere, where the precondition fails, the formulas may
/// differ from their shortcuts in the radial direction: slerp(a, b, 0) is a, the formula a / |a|).
template <class S, std::size_t N>
quaternion<S> unit_at(const std::array<S, N>& a, std::size_t i = 0) {
    return normalize(quat_at(a, i));
}
template <class S, std::size_t N>
vec3<S> vec_in(const std::array<S, N>& a, std::size_t i) {
    return {a[i], a[i + 1], a[i + 2]};
}
template <class S>
std::array<S, 4> flat(const quaternion<S>& q) {
    return {q.w, q.x, q.y, q.z};
}
template <class S>
std::array<S, 3> flat(const vec3<S>& v) {
    return {v.x, v.y, v.z};
}

/// The inputs of a function, concatenated.
template <std::size_t N>
std::array<double, N> inputs(std::initializer_list<double> values) {
    REQUIRE(values.size() == N);
    std::array<double, N> result{};
    std::size_t i = 0;
    for (const double v : values) result[i++] = v;
    return result;
}

std::array<double, 4> flat_q(const quatd& q) { return {q.w, q.x, q.y, q.z}; }

/// name and a number, for the report.
std::string label(const char* name, double value) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "%s %.3g", name, value);
    return buffer;
}

/// A unit quaternion turning by `angle` about the unit `axis`, in double.
quatd turn(const vec3<double>& axis, double angle) {
    return to_quaternion(axis_angle<double>{axis, angle});
}

constexpr double tiny = 1e-12;
constexpr double near_half_turn = 3.14159265358979323846 - 1e-8;
// from_rotation_vector switches to its series at |v| = 2 epsilon^(1/4), to_rotation_vector at
// tan(angle / 2) = epsilon^(1/4): just below and above both.
const double series_switch = 2 * std::pow(std::numeric_limits<double>::epsilon(), 0.25);

}  // namespace

TEST_CASE(
    "from_rotation_vector and to_rotation_vector differentiate at zero, tiny and near-half-turn "
    "angles") {
    const auto from = [](const auto& x) { return flat(from_rotation_vector(vec_in(x, 0))); };
    const auto to = [](const auto& x) { return flat(to_rotation_vector(quat_at(x))); };
    quat::test::random_rotations random;
    const vec3<double> axis = random.unit_vector<double>();
    for (const double angle :
         {0.0, tiny, 0.9 * series_switch, 1.1 * series_switch, 0.7, 2.5, near_half_turn}) {
        const vec3<double> v = axis * angle;
        check_derivatives<3>(label("from_rotation_vector |v|", angle), from, {v.x, v.y, v.z});
    }
    for (const double angle : {0.0, tiny, 0.9 * series_switch, 1.1 * series_switch, 0.7, 2.5}) {
        check_derivatives<4>(label("to_rotation_vector angle", angle), to,
                             flat_q(turn(axis, angle)));
    }
    // Within 1e-8 of a half turn, q's sign flips (and the rotation vector jumps) 5e-9 away: the
    // step stays below that, and long double's rounding over it limits the reference to ~1e-10.
    check_derivatives<4>("to_rotation_vector near a half turn", to,
                         flat_q(turn(axis, near_half_turn)), 1e-9L, 1e-9);
    for (int i = 0; i < 20; ++i) {
        const vec3<double> v = random.vector<double>(1.0);
        check_derivatives<3>("from_rotation_vector random", from, {v.x, v.y, v.z});
        check_derivatives<4>("to_rotation_vector random", to,
                             flat_q(random.unit_quaternion<double>()));
    }
}

TEST_CASE(
    "integrate_body and integrate_world differentiate at a zero rate, tiny and near-half-turn "
    "steps") {
    // Inputs: q0 (4), omega (3), dt.
    const auto body = [](const auto& x) {
        return flat(integrate_body(unit_at(x), vec_in(x, 4), x[7]));
    };
    const auto world = [](const auto& x) {
        return flat(integrate_world(unit_at(x), vec_in(x, 4), x[7]));
    };
    quat::test::random_rotations random;
    const vec3<double> axis = random.unit_vector<double>();
    const quatd q0 = random.unit_quaternion<double>();
    for (const quatd& start : {quatd::identity(), q0}) {
        for (const double angle : {0.0, tiny, series_switch, 1.0, near_half_turn}) {
            const vec3<double> omega = axis * (angle / 0.1);
            const auto x =
                inputs<8>({start.w, start.x, start.y, start.z, omega.x, omega.y, omega.z, 0.1});
            check_derivatives<8>(label("integrate_body angle", angle), body, x);
            check_derivatives<8>(label("integrate_world angle", angle), world, x);
        }
    }
}

TEST_CASE("The angular velocities differentiate at equal orientations and tiny turns") {
    // Inputs: q0 (4), q1 (4), dt.
    const auto body = [](const auto& x) {
        return flat(body_angular_velocity(unit_at(x), unit_at(x, 4), x[8]));
    };
    const auto world = [](const auto& x) {
        return flat(world_angular_velocity(unit_at(x), unit_at(x, 4), x[8]));
    };
    quat::test::random_rotations random;
    const vec3<double> axis = random.unit_vector<double>();
    for (const quatd& q0 : {quatd::identity(), random.unit_quaternion<double>()}) {
        for (const double angle : {0.0, tiny, series_switch, 1.0, 2.5}) {
            const quatd q1 = q0 * turn(axis, angle);
            const auto x = inputs<9>({q0.w, q0.x, q0.y, q0.z, q1.w, q1.x, q1.y, q1.z, 0.25});
            check_derivatives<9>(label("body_angular_velocity angle", angle), body, x);
            check_derivatives<9>(label("world_angular_velocity angle", angle), world, x);
        }
        // q1's sign flips 5e-9 away (the reference's limit: see the top of the file).
        const quatd q1 = q0 * turn(axis, near_half_turn);
        const auto x = inputs<9>({q0.w, q0.x, q0.y, q0.z, q1.w, q1.x, q1.y, q1.z, 0.25});
        check_derivatives<9>("body_angular_velocity near a half turn", body, x, 1e-9L, 1e-9);
        check_derivatives<9>("world_angular_velocity near a half turn", world, x, 1e-9L, 1e-9);
    }
}

TEST_CASE("exp and log of quaternions differentiate on the real axis and near it") {
    const auto exp_q = [](const auto& x) { return flat(quat::exp(quat_at(x))); };
    const auto log_q = [](const auto& x) { return flat(quat::log(quat_at(x))); };
    quat::test::random_rotations random;
    const vec3<double> axis = random.unit_vector<double>();
    for (const double w : {0.0, 0.3, -1.5}) {
        // exp switches to its series at |v| = epsilon^(1/4), half the rotation vector's switch.
        for (const double length :
             {0.0, tiny, 0.45 * series_switch, 0.55 * series_switch, 0.8, near_half_turn}) {
            const vec3<double> v = axis * length;
            check_derivatives<4>(label("exp |v|", length), exp_q, inputs<4>({w, v.x, v.y, v.z}));
        }
    }
    for (const double w : {1.0, 2.0, 0.5}) {
        for (const double angle : {0.0, tiny, series_switch, 1.0, 2.5, near_half_turn}) {
            const quatd q = turn(axis, angle) * w;
            check_derivatives<4>(label("log angle", angle), log_q, flat_q(q));
        }
    }
    for (int i = 0; i < 10; ++i) {
        const vec3<double> v = random.vector<double>(1.0);
        const double w = random.uniform<double>(-1.0, 1.0);
        check_derivatives<4>("exp random", exp_q, inputs<4>({w, v.x, v.y, v.z}));
        check_derivatives<4>("log random", log_q, inputs<4>({w, v.x, v.y, v.z}));
    }
}

TEST_CASE("slerp and pow differentiate at equal ends, tiny angles and their exact ends in t") {
    // slerp's inputs: a (4), b (4), t; pow's: q (4), t.
    const auto slerp_f = [](const auto& x) { return flat(slerp(unit_at(x), unit_at(x, 4), x[8])); };
    const auto pow_f = [](const auto& x) { return flat(quat::pow(unit_at(x), x[4])); };
    quat::test::random_rotations random;
    const vec3<double> axis = random.unit_vector<double>();
    for (const quatd& a : {quatd::identity(), random.unit_quaternion<double>()}) {
        // slerp switches to its series at sin(angle / 4) = epsilon^(1/4), pow as
        // to_rotation_vector.
        for (const double angle :
             {0.0, tiny, 1e-6, series_switch, 1.9 * series_switch, 2.1 * series_switch, 1.0, 3.0}) {
            const quatd b = a * turn(axis, angle);
            for (const double t : {0.0, 0.3, 1.0, 1.7, -0.4}) {
                const std::string at = label(" at t", t);
                check_derivatives<9>(label("slerp angle", angle) + at, slerp_f,
                                     inputs<9>({a.w, a.x, a.y, a.z, b.w, b.x, b.y, b.z, t}));
                check_derivatives<5>(label("pow angle", angle) + at, pow_f,
                                     inputs<5>({b.w, b.x, b.y, b.z, t}));
            }
        }
        // b's sign (and pow's q's) flips 5e-9 away: the reference's limit.
        const quatd b = a * turn(axis, near_half_turn);
        check_derivatives<9>("slerp near a half turn", slerp_f,
                             inputs<9>({a.w, a.x, a.y, a.z, b.w, b.x, b.y, b.z, 0.3}), 1e-9L, 1e-9);
        check_derivatives<5>("pow near a half turn", pow_f, inputs<5>({b.w, b.x, b.y, b.z, 0.3}),
                             1e-9L, 1e-9);
    }
}

TEST_CASE(
    "rotation_between differentiates at parallel, nearly parallel and nearly opposite "
    "directions") {
    const auto between = [](const auto& x) {
        return flat(rotation_between(vec_in(x, 0), vec_in(x, 3)));
    };
    quat::test::random_rotations random;
    for (int i = 0; i < 5; ++i) {
        const vec3<double> from = random.vector<double>(1.0);
        const vec3<double> axis = normalize(cross(from, random.vector<double>(1.0)));
        for (const double angle : {0.0, tiny, 1e-6, 1.0, 2.0, 3.0, near_half_turn}) {
            const vec3<double> to = rotate(turn(axis, angle), from) * 1.5;
            // Near opposite the axis moves 1e8 times faster than the inputs, which amplifies every
            // rounding as much: there the reference varies by 1e-9 with its step, and a user scalar
            // gets the plain cross product (double gets a compensated one). Measured <= 7.4e-9.
            const bool opposite = angle > 3.1;
            check_derivatives<6>(label("rotation_between angle", angle), between,
                                 inputs<6>({from.x, from.y, from.z, to.x, to.y, to.z}),
                                 opposite ? 1e-10L : 1e-3L, opposite ? 3e-8 : 1e-12);
        }
    }
}

TEST_CASE(
    "to_axis_angle differentiates where the axis is defined, Euler angles away from gimbal "
    "lock") {
    const auto axis_angle_f = [](const auto& x) {
        const auto r = to_axis_angle(quat_at(x));
        return std::array{r.axis.x, r.axis.y, r.axis.z, r.angle};
    };
    const auto from_euler = [](const auto& x) {
        using S = std::decay_t<decltype(x[0])>;
        return flat(to_quaternion(euler<S, sequence::zyx>{x[0], x[1], x[2]}));
    };
    const auto from_proper = [](const auto& x) {
        using S = std::decay_t<decltype(x[0])>;
        return flat(to_quaternion(euler<S, sequence::zxz, frame::extrinsic>{x[0], x[1], x[2]}));
    };
    const auto to_tait_bryan = [](const auto& x) {
        const auto e = to_euler<sequence::zyx>(unit_at(x));
        return std::array{e[0], e[1], e[2]};
    };
    const auto to_proper = [](const auto& x) {
        const auto e = to_euler<sequence::zxz, frame::extrinsic>(unit_at(x));
        return std::array{e[0], e[1], e[2]};
    };
    quat::test::random_rotations random;
    const vec3<double> axis = random.unit_vector<double>();
    // The axis turns 1e12 times faster than q at 1e-12 rad: a step of 1e-14 there.
    check_derivatives<4>("to_axis_angle angle 1e-12", axis_angle_f, flat_q(turn(axis, tiny)),
                         1e-15L);
    check_derivatives<4>("to_axis_angle angle 1e-6", axis_angle_f, flat_q(turn(axis, 1e-6)), 1e-9L);
    check_derivatives<4>("to_axis_angle near a half turn", axis_angle_f,
                         flat_q(turn(axis, near_half_turn)), 1e-9L, 1e-9);
    check_derivatives<3>("to_quaternion(euler zyx) at zero", from_euler, inputs<3>({0, 0, 0}));
    check_derivatives<4>("to_euler zyx at the identity", to_tait_bryan, flat_q(quatd::identity()));
    for (int i = 0; i < 10; ++i) {
        const quatd q = random.unit_quaternion<double>();
        check_derivatives<4>("to_axis_angle random", axis_angle_f, flat_q(q));
        check_derivatives<4>("to_euler zyx random", to_tait_bryan, flat_q(q));
        check_derivatives<4>("to_euler zxz extrinsic random", to_proper, flat_q(q));
        const auto angles =
            inputs<3>({random.uniform<double>(-3, 3), random.uniform<double>(-1.5, 1.5),
                       random.uniform<double>(-3, 3)});
        check_derivatives<3>("to_quaternion(euler zyx) random", from_euler, angles);
        check_derivatives<3>("to_quaternion(euler zxz extrinsic) random", from_proper, angles);
    }
}

TEST_CASE("sclerp differentiates at equal motions, pure translations and tiny turns") {
    // Inputs: a's rotation (4) and translation (3), b's, t.
    const auto sclerp_f = [](const auto& x) {
        const auto a = to_dual_quaternion(unit_at(x), vec_in(x, 4));
        const auto b = to_dual_quaternion(unit_at(x, 7), vec_in(x, 11));
        const auto r = sclerp(a, b, x[14]);
        return std::array{r.real.w, r.real.x, r.real.y, r.real.z,
                          r.dual.w, r.dual.x, r.dual.y, r.dual.z};
    };
    quat::test::random_rotations random;
    const vec3<double> axis = random.unit_vector<double>();
    const quatd qa = random.unit_quaternion<double>();
    const vec3<double> ta = random.vector<double>(1.0), tb = random.vector<double>(1.0);
    // sclerp's slide switches to its series near angle 0.0245 (for t in [0, 1]).
    for (const double angle : {0.0, tiny, 1e-6, series_switch, 0.024, 0.025, 1.0, 3.0}) {
        const quatd qb = qa * turn(axis, angle);
        for (const vec3<double>& t_b : {ta, tb}) {
            for (const double t : {0.0, 0.3, 1.0, 1.6}) {
                check_derivatives<15>(label("sclerp angle", angle) + label(" at t", t), sclerp_f,
                                      inputs<15>({qa.w, qa.x, qa.y, qa.z, ta.x, ta.y, ta.z, qb.w,
                                                  qb.x, qb.y, qb.z, t_b.x, t_b.y, t_b.z, t}));
            }
        }
    }
}

TEST_CASE(
    "so3 and se3 exp, log, plus and minus differentiate at zero, tiny and near-half-turn "
    "tangents") {
    // The Lie-group forms with the tests' own dual number beside ceres::Jet (tests/test_so3.cpp
    // and tests/test_se3.cpp compare Jet with the analytic Jacobians).
    const auto so3_exp = [](const auto& x) { return flat(so3::exp(vec_in(x, 0))); };
    const auto so3_log = [](const auto& x) { return flat(so3::log(unit_at(x))); };
    const auto so3_plus = [](const auto& x) { return flat(so3::plus(unit_at(x), vec_in(x, 4))); };
    const auto so3_minus = [](const auto& x) {
        return flat(so3::minus(unit_at(x), unit_at(x, 4)));
    };
    const auto twist_at = [](const auto& x, std::size_t i) {
        using S = std::decay_t<decltype(x[0])>;
        return se3::twist<S>{vec_in(x, i), vec_in(x, i + 3)};
    };
    const auto flat_motion = [](const auto& m) {
        return std::array{m.real.w, m.real.x, m.real.y, m.real.z,
                          m.dual.w, m.dual.x, m.dual.y, m.dual.z};
    };
    const auto flat_twist = [](const auto& t) {
        return std::array{t.linear.x,  t.linear.y,  t.linear.z,
                          t.angular.x, t.angular.y, t.angular.z};
    };
    const auto se3_exp = [&](const auto& x) { return flat_motion(se3::exp(twist_at(x, 0))); };
    // log and minus at motions reached from a fixed one by a twist: derivatives along the group.
    quat::test::random_rotations random;
    const dual_quaternion<double> base = random.rigid_motion<double>();
    const auto se3_log = [&](const auto& x) {
        using S = std::decay_t<decltype(x[0])>;
        return flat_twist(se3::log(dual_quaternion<S>(base) * se3::exp(twist_at(x, 0))));
    };
    const auto se3_minus = [&](const auto& x) {
        using S = std::decay_t<decltype(x[0])>;
        const dual_quaternion<S> from(base);
        return flat_twist(se3::minus(se3::plus(from, twist_at(x, 0)), from));
    };
    const vec3<double> axis = random.unit_vector<double>(), rho = random.vector<double>(1.0);
    const quatd q = random.unit_quaternion<double>();
    for (const double angle : {0.0, tiny, 0.9 * series_switch, 1.1 * series_switch, 0.7, 2.5}) {
        const vec3<double> w = axis * angle;
        const quatd p = q * turn(axis, angle);
        check_derivatives<3>(label("so3::exp angle", angle), so3_exp, inputs<3>({w.x, w.y, w.z}));
        check_derivatives<4>(label("so3::log angle", angle), so3_log, flat_q(turn(axis, angle)));
        check_derivatives<7>(label("so3::plus angle", angle), so3_plus,
                             inputs<7>({q.w, q.x, q.y, q.z, w.x, w.y, w.z}));
        check_derivatives<8>(label("so3::minus angle", angle), so3_minus,
                             inputs<8>({p.w, p.x, p.y, p.z, q.w, q.x, q.y, q.z}));
        const std::array<double, 6> t = inputs<6>({rho.x, rho.y, rho.z, w.x, w.y, w.z});
        check_derivatives<6>(label("se3::exp angle", angle), se3_exp, t);
        check_derivatives<6>(label("se3::log angle", angle), se3_log, t);
        check_derivatives<6>(label("se3::minus angle", angle), se3_minus, t);
    }
    const std::array<double, 6> zero_twist{};
    check_derivatives<6>("se3::exp of the zero twist", se3_exp, zero_twist);
    check_derivatives<6>("se3::log at the zero twist", se3_log, zero_twist);
}

}  // namespace test_differentiation
