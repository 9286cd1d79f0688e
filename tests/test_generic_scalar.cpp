// The templates work with a user-defined scalar. This is the exact list of what quat asks of T:
// - construction from an integer or floating literal, explicit: T(2), T(0.5), T(3.14...L);
//   value initialization T{} and copying;
// - unary -, binary + - * /, compound += and -=, and the comparisons < <= > >= == != (returning
//   bool);
// - std::numeric_limits<T>: epsilon(), min(), max(), infinity(), quiet_NaN();
// - sqrt, sin, cos, atan2, asin and abs, found by argument-dependent lookup (or std:: for
//   built-ins);
//   exp and log as well, for exp(quaternion) and log(quaternion) only.
// Nothing needs to be constexpr: user::runtime_real below has no constexpr member at all.
// Operations
// must not throw (quat's functions are noexcept). The counting scalar of quat_bench is one such
// type.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <quat/quat.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>
#include <quat/trajectory.hpp>

#include "support/catch.hpp"

namespace test_generic_scalar {

namespace user {

/// A scalar that only offers what the list above promises: no implicit conversions at all.
struct real {
    double value;

    constexpr real() noexcept : value(0) {}
    constexpr explicit real(int v) noexcept : value(v) {}
    constexpr explicit real(double v) noexcept : value(v) {}
    constexpr explicit real(long double v) noexcept : value(static_cast<double>(v)) {}
};

constexpr real operator-(real a) noexcept { return real(-a.value); }
constexpr real operator+(real a, real b) noexcept { return real(a.value + b.value); }
constexpr real operator-(real a, real b) noexcept { return real(a.value - b.value); }
constexpr real operator*(real a, real b) noexcept { return real(a.value * b.value); }
constexpr real operator/(real a, real b) noexcept { return real(a.value / b.value); }
constexpr real& operator+=(real& a, real b) noexcept { return a = a + b; }
constexpr real& operator-=(real& a, real b) noexcept { return a = a - b; }
constexpr bool operator<(real a, real b) noexcept { return a.value < b.value; }
constexpr bool operator<=(real a, real b) noexcept { return a.value <= b.value; }
constexpr bool operator>(real a, real b) noexcept { return a.value > b.value; }
constexpr bool operator>=(real a, real b) noexcept { return a.value >= b.value; }
constexpr bool operator==(real a, real b) noexcept { return a.value == b.value; }
constexpr bool operator!=(real a, real b) noexcept { return a.value != b.value; }
inline real sqrt(real a) noexcept { return real(std::sqrt(a.value)); }
inline real sin(real a) noexcept { return real(std::sin(a.value)); }
inline real cos(real a) noexcept { return real(std::cos(a.value)); }
inline real atan2(real y, real x) noexcept { return real(std::atan2(y.value, x.value)); }
inline real asin(real a) noexcept { return real(std::asin(a.value)); }
inline real abs(real a) noexcept { return real(std::abs(a.value)); }
inline real exp(real a) noexcept { return real(std::exp(a.value)); }
inline real log(real a) noexcept { return real(std::log(a.value)); }

/// The same list with nothing constexpr: a type that is not a literal type (it has a
/// user-provided destructor), like an arbitrary-precision or automatic-differentiation scalar.
struct runtime_real {
    double value;

    runtime_real() noexcept : value(0) {}
    explicit runtime_real(int v) noexcept : value(v) {}
    explicit runtime_real(double v) noexcept : value(v) {}
    explicit runtime_real(long double v) noexcept : value(static_cast<double>(v)) {}
    runtime_real(const runtime_real&) noexcept = default;
    runtime_real& operator=(const runtime_real&) noexcept = default;
    ~runtime_real() {}  // NOLINT(modernize-use-equals-default): makes the type non-literal
};

inline runtime_real operator-(runtime_real a) noexcept { return runtime_real(-a.value); }
inline runtime_real operator+(runtime_real a, runtime_real b) noexcept {
    return runtime_real(a.value + b.value);
}
inline runtime_real operator-(runtime_real a, runtime_real b) noexcept {
    return runtime_real(a.value - b.value);
}
inline runtime_real operator*(runtime_real a, runtime_real b) noexcept {
    return runtime_real(a.value * b.value);
}
inline runtime_real operator/(runtime_real a, runtime_real b) noexcept {
    return runtime_real(a.value / b.value);
}
inline runtime_real& operator+=(runtime_real& a, runtime_real b) noexcept { return a = a + b; }
inline runtime_real& operator-=(runtime_real& a, runtime_real b) noexcept { return a = a - b; }
inline bool operator<(runtime_real a, runtime_real b) noexcept { return a.value < b.value; }
inline bool operator<=(runtime_real a, runtime_real b) noexcept { return a.value <= b.value; }
inline bool operator>(runtime_real a, runtime_real b) noexcept { return a.value > b.value; }
inline bool operator>=(runtime_real a, runtime_real b) noexcept { return a.value >= b.value; }
inline bool operator==(runtime_real a, runtime_real b) noexcept { return a.value == b.value; }
inline bool operator!=(runtime_real a, runtime_real b) noexcept { return a.value != b.value; }
inline runtime_real sqrt(runtime_real a) noexcept { return runtime_real(std::sqrt(a.value)); }
inline runtime_real sin(runtime_real a) noexcept { return runtime_real(std::sin(a.value)); }
inline runtime_real cos(runtime_real a) noexcept { return runtime_real(std::cos(a.value)); }
inline runtime_real atan2(runtime_real y, runtime_real x) noexcept {
    return runtime_real(std::atan2(y.value, x.value));
}
inline runtime_real asin(runtime_real a) noexcept { return runtime_real(std::asin(a.value)); }
inline runtime_real abs(runtime_real a) noexcept { return runtime_real(std::abs(a.value)); }
inline runtime_real exp(runtime_real a) noexcept { return runtime_real(std::exp(a.value)); }
inline runtime_real log(runtime_real a) noexcept { return runtime_real(std::log(a.value)); }

}  // namespace user

}  // namespace test_generic_scalar

// Specializations of std:: templates: at global scope, outside the file's namespace.
template <>
struct std::numeric_limits<test_generic_scalar::user::real> {
    static constexpr bool is_specialized = true;
    static constexpr test_generic_scalar::user::real epsilon() noexcept {
        return test_generic_scalar::user::real(std::numeric_limits<double>::epsilon());
    }
    static constexpr test_generic_scalar::user::real min() noexcept {
        return test_generic_scalar::user::real(std::numeric_limits<double>::min());
    }
    static constexpr test_generic_scalar::user::real max() noexcept {
        return test_generic_scalar::user::real(std::numeric_limits<double>::max());
    }
    static constexpr test_generic_scalar::user::real infinity() noexcept {
        return test_generic_scalar::user::real(std::numeric_limits<double>::infinity());
    }
    static constexpr test_generic_scalar::user::real quiet_NaN() noexcept {
        return test_generic_scalar::user::real(std::numeric_limits<double>::quiet_NaN());
    }
};

template <>
struct std::numeric_limits<test_generic_scalar::user::runtime_real> {
    static constexpr bool is_specialized = true;
    static test_generic_scalar::user::runtime_real epsilon() noexcept {
        return test_generic_scalar::user::runtime_real(std::numeric_limits<double>::epsilon());
    }
    static test_generic_scalar::user::runtime_real min() noexcept {
        return test_generic_scalar::user::runtime_real(std::numeric_limits<double>::min());
    }
    static test_generic_scalar::user::runtime_real max() noexcept {
        return test_generic_scalar::user::runtime_real(std::numeric_limits<double>::max());
    }
    static test_generic_scalar::user::runtime_real infinity() noexcept {
        return test_generic_scalar::user::runtime_real(std::numeric_limits<double>::infinity());
    }
    static test_generic_scalar::user::runtime_real quiet_NaN() noexcept {
        return test_generic_scalar::user::runtime_real(std::numeric_limits<double>::quiet_NaN());
    }
};

namespace test_generic_scalar {

namespace {

// The same computation in double and in the user scalar must agree: the user scalar performs
// exactly the double operations, but an optimizer may constant-fold one side's <cmath> calls, so
// allow 4 eps.
template <class Q, class D>
void check_same(const Q& got, const D& expected) {
    const double tol = 4 * std::numeric_limits<double>::epsilon();
    CHECK(got.w.value == Approx(expected.w).epsilon(tol).margin(tol));
    CHECK(got.x.value == Approx(expected.x).epsilon(tol).margin(tol));
    CHECK(got.y.value == Approx(expected.y).epsilon(tol).margin(tol));
    CHECK(got.z.value == Approx(expected.z).epsilon(tol).margin(tol));
}

template <class R>
bool same(const R& got, double expected) {
    return std::abs(got.value - expected) <=
           4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(expected));
}

}  // namespace

TEMPLATE_TEST_CASE("every operation instantiates with a user-defined scalar and matches double",
                   "[generic]", user::real, user::runtime_real) {
    using namespace quat;
    using R = TestType;
    const auto r = [](double v) { return R(v); };
    const quaternion<R> a = normalize(quaternion<R>{r(0.3), r(-0.2), r(0.9), r(0.1)});
    const quaternion<R> b{r(0.5), r(0.5), r(-0.5), r(0.5)};
    const quatd ad = normalize(quatd{0.3, -0.2, 0.9, 0.1}), bd{0.5, 0.5, -0.5, 0.5};
    check_same(a, ad);
    check_same(a * b, ad * bd);
    check_same(a + b - a * r(2.0) / r(3.0), ad + bd - ad * 2.0 / 3.0);
    quaternion<R> accumulated = a;
    accumulated *= b;
    accumulated += a;
    accumulated -= b;
    accumulated *= r(0.5);
    accumulated /= r(3);
    check_same(accumulated, ((ad * bd + ad - bd) * 0.5) / 3.0);
    check_same(conjugate(a), conjugate(ad));
    check_same(inverse(a), inverse(ad));
    check_same(*try_inverse(a), *try_inverse(ad));
    check_same(*try_normalize(b), *try_normalize(bd));
    CHECK(same(norm(a), norm(ad)));
    CHECK(same(dot(a, b), dot(ad, bd)));
    CHECK(same(angle_between(a, b), angle_between(ad, bd)));
    CHECK(approx_equal(a, -a, r(1e-9)));
    CHECK(is_unit(a, r(1e-9)));
    check_same(rotation_x(r(0.7)), rotation_x(0.7));
    check_same(rotation_y(r(0.7)), rotation_y(0.7));
    check_same(rotation_z(r(0.7)), rotation_z(0.7));
    check_same(quaternion<R>{quat::quatf{ad}}, quatd{quat::quatf{ad}});
    CHECK(a == a);
    CHECK(a != b);

    vec3<R> v{r(1), r(2), r(3)};
    const vec3<double> vd{1, 2, 3};
    CHECK(same(rotate(a, v).y, rotate(ad, vd).y));
    CHECK(same(normalize(v).z, normalize(vd).z));
    CHECK(try_normalize(v).has_value());
    CHECK(same(cross(v, v * r(2)).x, 0));
    v += v;
    v -= vec3<R>{r(1), r(1), r(1)};
    v *= r(3);
    v /= r(2);
    CHECK(same(v.z, (3.0 * 2 - 1) * 3 / 2));

    const rotation_matrix<R> m = to_matrix(a);
    const rotation_matrix<double> md = to_matrix(ad);
    CHECK(same(m(1, 2), md(1, 2)));
    CHECK(same(rotate(m * transpose(m), v).x,
               rotate(md * transpose(md), vec3<double>{1.5, 4.5, 7.5}).x));
    CHECK(same(determinant(m), determinant(md)));
    CHECK(same(orthogonality_error(m), orthogonality_error(md)));
    check_same(to_quaternion(m), to_quaternion(md));
    check_same(*try_to_quaternion(m), *try_to_quaternion(md));
    CHECK(same(nearest_rotation(m)(0, 1), nearest_rotation(md)(0, 1)));
    CHECK(try_nearest_rotation(m).has_value());

    const axis_angle<R> aa = to_axis_angle(a);
    const axis_angle<double> aad = to_axis_angle(ad);
    CHECK(same(aa.angle, aad.angle));
    check_same(to_quaternion(aa), to_quaternion(aad));
    check_same(*try_to_quaternion(aa), *try_to_quaternion(aad));
    CHECK(same(to_matrix(aa)(2, 0), to_matrix(aad)(2, 0)));
    CHECK(same(to_axis_angle(m).angle, to_axis_angle(md).angle));

    check_same(from_rotation_vector(v), from_rotation_vector(vec3<double>{1.5, 4.5, 7.5}));
    CHECK(same(to_rotation_vector(a).x, to_rotation_vector(ad).x));

    const euler<R, sequence::xzx, frame::extrinsic> e{r(0.1), r(0.2), r(0.3)};
    const euler<double, sequence::xzx, frame::extrinsic> ed{0.1, 0.2, 0.3};
    const auto [e0, e1, e2] = e;
    CHECK((same(e0, 0.1) && same(e1, 0.2) && same(e2, 0.3)));
    check_same(to_quaternion(e), to_quaternion(ed));
    CHECK(same(to_matrix(e)(0, 2), to_matrix(ed)(0, 2)));
    CHECK(same(to_axis_angle(e).angle, to_axis_angle(ed).angle));
    CHECK(same(to_euler<sequence::zyx>(a)[1], to_euler<sequence::zyx>(ad)[1]));
    CHECK(same(to_euler<sequence::zyx>(m)[0], to_euler<sequence::zyx>(md)[0]));
    CHECK(same(to_euler<sequence::yzy>(aa)[2], to_euler<sequence::yzy>(aad)[2]));
    CHECK(same(to_euler<sequence::zyx>(e)[2], to_euler<sequence::zyx>(ed)[2]));
    CHECK(same(to_euler(a, euler<R, sequence::zyx>{r(3), r(0.1), r(-3)})[0],
               to_euler(ad, euler<double, sequence::zyx>{3, 0.1, -3})[0]));
    CHECK(extract_euler<sequence::xyz>(a).gimbal_lock ==
          extract_euler<sequence::xyz>(ad).gimbal_lock);
    CHECK(same(extract_euler<sequence::zxz>(a).angles[1],
               extract_euler<sequence::zxz>(ad).angles[1]));

    check_same(slerp(a, b, r(0.3)), slerp(ad, bd, 0.3));
    check_same(slerp(a, b, r(1.7)), slerp(ad, bd, 1.7));
    check_same(nlerp(a, b, r(0.3)), nlerp(ad, bd, 0.3));
    check_same(slerp_fast(a, b, r(0.3)), slerp_fast(ad, bd, 0.3));
    check_same(corrected_nlerp(a, b, r(0.3)), corrected_nlerp(ad, bd, 0.3));
    check_same(pow(a, r(0.3)), pow(ad, 0.3));
    check_same(rotate_towards(a, b, r(0.2)), rotate_towards(ad, bd, 0.2));
    CHECK(same(to_mrp(a).y, to_mrp(ad).y));
    check_same(from_mrp(vec3<R>{r(0.1), r(-0.2), r(0.3)}), from_mrp(vec3<double>{0.1, -0.2, 0.3}));

    const vec3<R> omega = body_angular_velocity(a, b, r(0.5));
    const vec3<double> omega_d = body_angular_velocity(ad, bd, 0.5);
    CHECK(same(omega.z, omega_d.z));
    CHECK(same(world_angular_velocity(a, b, r(0.5)).x, world_angular_velocity(ad, bd, 0.5).x));
    check_same(integrate_body(a, omega, r(0.5)), integrate_body(ad, omega_d, 0.5));
    check_same(integrate_world(a, omega, r(0.5)), integrate_world(ad, omega_d, 0.5));
    const vec3<R> from{r(1), r(-2), r(0.5)}, to{r(-0.3), r(0.1), r(2)};
    const vec3<double> from_d{1, -2, 0.5}, to_d{-0.3, 0.1, 2};
    check_same(rotation_between(from, to), rotation_between(from_d, to_d));
    check_same(*try_rotation_between(from, to), *try_rotation_between(from_d, to_d));
    check_same(look_rotation(from, to), look_rotation(from_d, to_d));
    check_same(*try_look_rotation(from, to), *try_look_rotation(from_d, to_d));
    const std::vector<vec3<R>> sources{from, to, cross(from, to)};
    const std::vector<vec3<double>> sources_d{from_d, to_d, cross(from_d, to_d)};
    std::vector<vec3<R>> targets;
    std::vector<vec3<double>> targets_d;
    for (const auto& s : sources) targets.push_back(rotate(a, s));
    for (const auto& s : sources_d) targets_d.push_back(rotate(ad, s));
    check_same(align_vectors(targets, sources).rotation,
               align_vectors(targets_d, sources_d).rotation);
    check_same(align_vectors(targets, sources, std::vector<R>{r(1), r(2), r(3)}).rotation,
               align_vectors(targets_d, sources_d, std::vector<double>{1, 2, 3}).rotation);
    CHECK(same(align_vectors_with_sensitivity(targets, sources, std::vector<R>{r(1), r(2), r(3)})
                   .sensitivity(0, 1),
               align_vectors_with_sensitivity(targets_d, sources_d, std::vector<double>{1, 2, 3})
                   .sensitivity(0, 1)));
    const std::vector<quaternion<R>> cluster{a, b, slerp(a, b, r(0.2))};
    const std::vector<quatd> cluster_d{ad, bd, slerp(ad, bd, 0.2)};
    check_same(mean(cluster), mean(cluster_d));
    check_same(*try_mean(cluster, std::vector<R>{r(1), r(2), r(0.5)}),
               *try_mean(cluster_d, std::vector<double>{1, 2, 0.5}));
    const vec3<R> twist_axis{r(0), r(2), r(1)};
    const vec3<double> twist_axis_d{0, 2, 1};
    check_same(swing_twist(a, twist_axis).twist, swing_twist(ad, twist_axis_d).twist);
    check_same(try_swing_twist(a, twist_axis)->swing, try_swing_twist(ad, twist_axis_d)->swing);
    // Keyframe paths.
    const quaternion<R> c = slerp(a, b, r(0.7));
    const quatd cd = slerp(ad, bd, 0.7);
    check_same(squad(a, squad_control(a, a, b), squad_control(a, b, c), b, r(0.4)),
               squad(ad, squad_control(ad, ad, bd), squad_control(ad, bd, cd), bd, 0.4));
    const std::vector<R> key_times{r(0), r(1), r(2.5), r(3)};
    const std::vector<double> key_times_d{0, 1, 2.5, 3};
    const std::vector<quaternion<R>> keys{a, b, c, a};
    const std::vector<quatd> keys_d{ad, bd, cd, ad};
    check_same(keyframe_slerp(key_times, keys, r(1.7)), keyframe_slerp(key_times_d, keys_d, 1.7));
    check_same(keyframe_squad(key_times, keys, r(1.7)), keyframe_squad(key_times_d, keys_d, 1.7));
    const rotation_spline<R> spline(key_times, keys);
    const rotation_spline<double> spline_d(key_times_d, keys_d);
    check_same(spline(r(1.7)), spline_d(1.7));
    CHECK(same(spline.angular_acceleration(r(1.7)).y, spline_d.angular_acceleration(1.7).y));

    // The batch functions take the plain loops (no vector polynomial) for a user scalar.
    std::vector<vec3<R>> points(5, vec3<R>{r(1), r(2), r(3)}), rotated(5);
    rotate(a, points, rotated);
    CHECK(same(rotated[4].y, rotate(ad, vd).y));
    std::vector<R> xs(5, r(1)), ys(5, r(2)), zs(5, r(3)), ox(5), oy(5), oz(5);
    rotate(a, soa_points<const R>{xs.data(), ys.data(), zs.data(), 5},
           soa_points<R>{ox.data(), oy.data(), oz.data(), 5});
    CHECK(same(oy[2], rotate(ad, vd).y));
    const std::vector<quaternion<R>> factors(20, a);
    const std::vector<quatd> factors_d(20, ad);
    check_same(compose(factors), compose(factors_d));
    const std::vector<R> ts{r(0), r(0.3), r(1)};
    std::vector<quaternion<R>> slerped(3);
    slerp(a, b, ts, slerped);
    check_same(slerped[1], slerp(ad, bd, 0.3));

    // Rigid motions.
    const dual_quaternion<R> da = to_dual_quaternion(a, vec3<R>{r(1), r(-2), r(0.5)});
    const dual_quaternion<R> db = to_dual_quaternion(b, vec3<R>{r(0.3), r(0), r(2)});
    const dual_quaterniond dad = to_dual_quaternion(ad, vec3<double>{1, -2, 0.5});
    const dual_quaterniond dbd = to_dual_quaternion(bd, vec3<double>{0.3, 0, 2});
    check_same((da * db).dual, (dad * dbd).dual);
    check_same(inverse(da).dual, inverse(dad).dual);
    check_same(normalize(da).dual, normalize(dad).dual);
    CHECK(same(transform(da, vec3<R>{r(1), r(2), r(3)}).z, transform(dad, vd).z));
    CHECK(same(translation_of(to_homogeneous(da)).y, translation_of(to_homogeneous(dad)).y));
    check_same(to_dual_quaternion(to_homogeneous(db)).dual,
               to_dual_quaternion(to_homogeneous(dbd)).dual);
    CHECK(same(to_screw(da).displacement, to_screw(dad).displacement));
    check_same(from_screw(to_screw(db)).dual, from_screw(to_screw(dbd)).dual);
    check_same(sclerp(da, db, r(0.3)).dual, sclerp(dad, dbd, 0.3).dual);
    const std::vector<dual_quaternion<R>> bones{da, db};
    const std::vector<dual_quaterniond> bones_d{dad, dbd};
    check_same(blend(bones, std::vector<R>{r(0.3), r(0.7)}).dual,
               blend(bones_d, std::vector<double>{0.3, 0.7}).dual);
    check_same(compose(bones).dual, compose(bones_d).dual);
    // Registration and hand-eye calibration.
    const std::vector<vec3<R>> cloud{from, to, cross(from, to), vec3<R>{r(0.2), r(0.4), r(-1)}};
    const std::vector<vec3<double>> cloud_d{from_d, to_d, cross(from_d, to_d), {0.2, 0.4, -1}};
    std::vector<vec3<R>> moved;
    std::vector<vec3<double>> moved_d;
    for (const vec3<R>& p : cloud) moved.push_back(transform(da, p) + p * r(0.01));
    for (const vec3<double>& p : cloud_d) moved_d.push_back(transform(dad, p) + p * 0.01);
    check_same(align_points(moved, cloud).motion.dual, align_points(moved_d, cloud_d).motion.dual);
    CHECK(same(align_points_with_scale(moved, cloud, std::vector<R>{r(1), r(2), r(1), r(3)}).scale,
               align_points_with_scale(moved_d, cloud_d, std::vector<double>{1, 2, 1, 3}).scale));
    const std::vector<dual_quaternion<R>> hand{da, db, da * db};
    const std::vector<dual_quaterniond> hand_d{dad, dbd, dad * dbd};
    const dual_quaternion<R> mount = normalize(sclerp(da, db, r(0.4)));
    const dual_quaterniond mount_d = normalize(sclerp(dad, dbd, 0.4));
    std::vector<dual_quaternion<R>> eye;
    std::vector<dual_quaterniond> eye_d;
    for (const dual_quaternion<R>& h : hand) eye.push_back(inverse(mount) * h * mount);
    for (const dual_quaterniond& h : hand_d) eye_d.push_back(inverse(mount_d) * h * mount_d);
    check_same(hand_eye(hand, eye).mount.dual, hand_eye(hand_d, eye_d).mount.dual);
    check_same(try_hand_eye(hand, eye)->mount.real, try_hand_eye(hand_d, eye_d)->mount.real);
    check_same(hand_eye(hand, eye, hand_eye_method::rotation_first).mount.dual,
               hand_eye(hand_d, eye_d, hand_eye_method::rotation_first).mount.dual);
    transform(da, points, rotated);
    CHECK(same(rotated[1].x, transform(dad, vd).x));
}

TEMPLATE_TEST_CASE("the element-wise batches give a user scalar the scalar functions' results",
                   "[generic][elementwise]", user::real, user::runtime_real) {
    using R = TestType;
    const std::size_t n = 9;
    std::vector<quat::quaternion<R>> q, products(n), back(n);
    std::vector<quat::vec3<R>> p, out(n);
    std::vector<quat::rotation_matrix<R>> m(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double s = static_cast<double>(i);
        q.push_back(
            quat::normalize(quat::quaternion<R>{R(1.0 + s), R(0.3 - s), R(0.2 * s), R(-0.7)}));
        p.push_back(quat::vec3<R>{R(s), R(2.0 - s), R(0.5)});
    }
    quat::rotate_each(q, p, out);
    quat::compose_each(q, q, products);
    quat::to_matrix_each(q, m);
    quat::to_quaternion_each(m, back);
    for (std::size_t i = 0; i < n; ++i) {
        const quat::vec3<R> rotated = quat::rotate(q[i], p[i]);
        CHECK((same(out[i].x, rotated.x.value) && same(out[i].y, rotated.y.value) &&
               same(out[i].z, rotated.z.value)));
        const quat::quaternion<R> product = q[i] * q[i];
        CHECK((same(products[i].w, product.w.value) && same(products[i].x, product.x.value) &&
               same(products[i].y, product.y.value) && same(products[i].z, product.z.value)));
        const quat::rotation_matrix<R> matrix = quat::to_matrix(q[i]);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) CHECK(same(m[i](r, c), matrix(r, c).value));
        const quat::quaternion<R> converted = quat::to_quaternion(m[i]);
        CHECK((same(back[i].w, converted.w.value) && same(back[i].x, converted.x.value) &&
               same(back[i].y, converted.y.value) && same(back[i].z, converted.z.value)));
    }
}

TEMPLATE_TEST_CASE(
    "the first-use spellings instantiate with a user-defined scalar and match double",
    "[generic][first-use]", user::real, user::runtime_real) {
    using namespace quat;
    using R = TestType;
    const auto r = [](double v) { return R(v); };
    const quaternion<R> a = normalize(quaternion<R>{r(0.3), r(-0.2), r(0.9), r(0.1)});
    const quatd ad = normalize(quatd{0.3, -0.2, 0.9, 0.1});
    vec3<R> v{r(1), r(2), r(3)};
    const vec3<double> vd{1, 2, 3};
    CHECK(same((a * v).y, (ad * vd).y));
    const rotation_matrix<R> m = to_matrix(a);
    const rotation_matrix<double> md = to_matrix(ad);
    CHECK(same((m * v).z, (md * vd).z));
    v[1] = r(-2);
    CHECK(same(v[1], -2));
    CHECK(same(lerp(v, vec3<R>{r(3), r(2), r(1)}, r(0.25)).x,
               lerp(vec3<double>{1, -2, 3}, vec3<double>{3, 2, 1}, 0.25).x));
    const dual_quaternion<R> dq = to_dual_quaternion(a, v);
    const dual_quaterniond dqd = to_dual_quaternion(ad, vec3<double>{1, -2, 3});
    CHECK(same((dq * v).x, (dqd * vec3<double>{1, -2, 3}).x));
    check_same(to_dual_quaternion(a).real, to_dual_quaternion(ad).real);
    check_same(dual_quaternion<R>::from_translation(v).dual,
               dual_quaterniond::from_translation(vec3<double>{1, -2, 3}).dual);
    dual_quaternion<R> scaled = r(2) * dq * r(3) / r(4);
    scaled *= r(0.5);
    scaled /= r(2);
    check_same(scaled.dual, ((2.0 * dqd * 3.0 / 4.0) * 0.5 / 2.0).dual);
    const homogeneous_matrix<R> h = to_homogeneous(a, v);
    const homogeneous_matrix<double> hd = to_homogeneous(ad, vec3<double>{1, -2, 3});
    CHECK(same((h * v).y, (hd * vec3<double>{1, -2, 3}).y));
    CHECK(same(inverse(h)(1, 3), inverse(hd)(1, 3)));
    CHECK(same(to_homogeneous(a)(2, 1), to_homogeneous(ad)(2, 1)));
    CHECK(same(to_homogeneous(m)(0, 2), to_homogeneous(md)(0, 2)));
    CHECK(same(to_homogeneous(m, v)(1, 3), -2));
    CHECK(same(homogeneous_matrix<R>::from_translation(v)(2, 3), 3));
    CHECK(same(angle(a), angle(ad)));
    CHECK(same(axis(a).z, axis(ad).z));
    const quaternion<R> q{r(0.5), r(0.1), r(-0.2), r(0.3)};
    const quatd qd{0.5, 0.1, -0.2, 0.3};
    check_same(exp(q), exp(qd));
    check_same(log(q), log(qd));
    CHECK(same(radians(r(90)), radians(90.0)));
    CHECK(same(degrees(r(1)), degrees(1.0)));
    check_same(rotation_y<R>(0.7), rotation_y(0.7));
}

TEMPLATE_TEST_CASE("the keyframe paths of rigid motions take a user-defined scalar", "[generic]",
                   user::real, user::runtime_real) {
    // The user scalar takes the coefficients' series in n^2 where double takes closed forms, and
    // the se3 path's solve carries those roundings: measured 8 eps (1.6e-15 of 0.87) in its
    // linear acceleration, so 16 eps is allowed here.
    using namespace quat;
    using R = TestType;
    const auto r = [](double v) { return R(v); };
    const auto near = [](const R& got, double expected) {
        return std::abs(got.value - expected) <=
               16 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(expected));
    };
    const quatd a = normalize(quatd{0.3, -0.2, 0.9, 0.1}), b{0.5, 0.5, -0.5, 0.5};
    const std::vector<dual_quaterniond> poses_d{
        to_dual_quaternion(a, vec3<double>{1, -2, 0.5}),
        to_dual_quaternion(b, vec3<double>{0.3, 0, 2}),
        to_dual_quaternion(slerp(a, b, 0.7), vec3<double>{2, 1, 0}),
        to_dual_quaternion(a, vec3<double>{0, 0, 1})};
    std::vector<dual_quaternion<R>> poses;
    for (const dual_quaterniond& x : poses_d)
        poses.push_back({{r(x.real.w), r(x.real.x), r(x.real.y), r(x.real.z)},
                         {r(x.dual.w), r(x.dual.x), r(x.dual.y), r(x.dual.z)}});
    const std::vector<R> times{r(0), r(1), r(2.5), r(3)};
    const std::vector<double> times_d{0, 1, 2.5, 3};
    const split_keyframe_path<R> split(times, poses);
    const split_keyframe_path<double> split_d(times_d, poses_d);
    const se3_keyframe_path<R> coupled(times, poses);
    const se3_keyframe_path<double> coupled_d(times_d, poses_d);
    for (const double t : {0.4, 1.7, 2.9}) {
        const keyframe_path_state<R> s = split.state(r(t)), c = coupled.state(r(t));
        const keyframe_path_state<double> sd = split_d.state(t), cd = coupled_d.state(t);
        CHECK(near(split(r(t)).dual.x, split_d(t).dual.x));
        CHECK(near(s.acceleration.y, sd.acceleration.y));
        CHECK(near(s.body_angular_acceleration.z, sd.body_angular_acceleration.z));
        CHECK(near(coupled(r(t)).dual.x, coupled_d(t).dual.x));
        CHECK(near(c.acceleration.y, cd.acceleration.y));
        CHECK(near(c.body_angular_acceleration.z, cd.body_angular_acceleration.z));
    }
}

}  // namespace test_generic_scalar
