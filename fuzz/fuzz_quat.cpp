// libFuzzer harness: raw bytes become doubles (so NaN, Inf, subnormals and huge values all occur)
// and drive to_euler, to_quaternion(matrix), slerp, nearest_rotation and the try_* variants. Any
// broken invariant aborts with a message, which libFuzzer reports as a crash with the input saved.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <quat/quat.hpp>

namespace {

using quat::frame;
using quat::sequence;

// Generous bounds in double: every check passes by orders of magnitude on correct code.
constexpr double unit_tolerance = 1e-12;
constexpr double round_trip_tolerance = 1e-10;

void require(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "invariant broken: %s\n", what);
        std::abort();
    }
}

bool finite(const quat::quatd& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}
bool finite(const quat::rotation_matrix<double>& m) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (!std::isfinite(m(i, j))) return false;
    return true;
}
bool is_unit(const quat::quatd& q) { return std::abs(quat::norm(q) - 1) <= unit_tolerance; }
bool is_rotation(const quat::rotation_matrix<double>& m) {
    return quat::orthogonality_error(m) <= unit_tolerance &&
           std::abs(quat::determinant(m) - 1) <= unit_tolerance;
}

/// Euler extraction of a unit quaternion: finite, canonical and reproducing the rotation.
template <sequence S, frame F>
void check_euler(const quat::quatd& unit) {
    const auto extraction = quat::extract_euler<S, F>(unit);
    const auto& e = extraction.angles;
    require(std::isfinite(e[0]) && std::isfinite(e[1]) && std::isfinite(e[2]),
            "to_euler: finite in, finite out");
    require(std::abs(e[0]) <= M_PI && std::abs(e[2]) <= M_PI,
            "to_euler: first/third angle in [-pi, pi]");
    require(quat::angle_between(quat::to_quaternion(e), unit) <= round_trip_tolerance,
            "to_euler: round trip");
    require(!extraction.gimbal_lock || e[2] == 0, "to_euler: third angle 0 at gimbal lock");
}

void check_quaternion(const quat::quatd& q) {
    const std::optional<quat::quatd> unit = quat::try_normalize(q);
    require(unit.has_value() == (finite(q) && (q.w != 0 || q.x != 0 || q.y != 0 || q.z != 0)),
            "try_normalize: empty exactly for zero or non-finite input");
    if (!unit) return;
    require(finite(*unit) && is_unit(*unit), "try_normalize: unit output");
    check_euler<sequence::zyx, frame::intrinsic>(*unit);
    check_euler<sequence::xyz, frame::extrinsic>(*unit);
    check_euler<sequence::zxz, frame::intrinsic>(*unit);
    check_euler<sequence::yxy, frame::extrinsic>(*unit);
    // quaternion -> matrix -> quaternion.
    const quat::rotation_matrix<double> m = quat::to_matrix(*unit);
    require(is_rotation(m), "to_matrix: rotation");
    const quat::quatd back = quat::to_quaternion(m);
    require(is_unit(back) && back.w >= 0, "to_quaternion(matrix): unit, w >= 0");
    require(quat::angle_between(back, *unit) <= round_trip_tolerance,
            "to_quaternion(matrix): round trip");
    require(quat::try_to_quaternion(m).has_value(), "try_to_quaternion: accepts a rotation");
    // exp/log round trip.
    require(quat::angle_between(quat::from_rotation_vector(quat::to_rotation_vector(*unit)),
                                *unit) <= round_trip_tolerance,
            "rotation vector round trip");
}

void check_slerp(const quat::quatd& a_raw, const quat::quatd& b_raw, double t_raw) {
    const auto a = quat::try_normalize(a_raw), b = quat::try_normalize(b_raw);
    if (!a || !b || !std::isfinite(t_raw)) return;
    const double t = std::fmod(t_raw, 3.0);  // extrapolation in (-3, 3)
    const quat::quatd r = quat::slerp(*a, *b, t);
    require(finite(r), "slerp: finite in, finite out");
    require(std::abs(quat::norm(r) - 1) <= 1e-10, "slerp: unit output");
    if (t == 0) require(r == *a, "slerp: exact at t = 0");
}

void check_matrix(const quat::rotation_matrix<double>& m) {
    const std::optional<quat::quatd> q = quat::try_to_quaternion(m);
    if (q) require(finite(*q) && is_unit(*q), "try_to_quaternion: unit output");
    const std::optional<quat::rotation_matrix<double>> r = quat::try_nearest_rotation(m);
    if (!finite(m)) {
        require(!q && !r, "try_*: non-finite matrix gives empty optional");
        return;
    }
    if (r) require(finite(*r) && is_rotation(*r), "try_nearest_rotation: rotation output");
    const quat::rotation_matrix<double> n = quat::nearest_rotation(m);
    require(finite(n) && is_rotation(n), "nearest_rotation: finite in, rotation out");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    double v[9] = {};
    std::memcpy(v, data, size < sizeof v ? size : sizeof v);
    const quat::quatd a{v[0], v[1], v[2], v[3]}, b{v[4], v[5], v[6], v[7]};
    check_quaternion(a);
    check_slerp(a, b, v[8]);
    check_matrix(quat::rotation_matrix<double>::from_rows({v[0], v[1], v[2]}, {v[3], v[4], v[5]},
                                                          {v[6], v[7], v[8]}));
    return 0;
}
