// Seeded random rotations and vectors for property tests: every run sees the same inputs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include <quat/quat.hpp>

namespace quat::test {

/// The seed every test starts from, so failures reproduce.
inline constexpr std::uint64_t seed = 20190501;

/// Random rotations, uniform on the sphere of unit quaternions (normalized 4D Gaussians).
class random_rotations {
public:
    explicit random_rotations(std::uint64_t s = seed) : engine_(s) {}

    template <class T>
    quaternion<T> unit_quaternion() {
        for (;;) {
            const double w = gauss_(engine_), x = gauss_(engine_), y = gauss_(engine_),
                         z = gauss_(engine_);
            const double n = std::sqrt(w * w + x * x + y * y + z * z);
            if (n > 1e-3) return {T(w / n), T(x / n), T(y / n), T(z / n)};
        }
    }

    template <class T>
    vec3<T> unit_vector() {
        for (;;) {
            const double x = gauss_(engine_), y = gauss_(engine_), z = gauss_(engine_);
            const double n = std::sqrt(x * x + y * y + z * z);
            if (n > 1e-3) return {T(x / n), T(y / n), T(z / n)};
        }
    }

    template <class T>
    vec3<T> vector(double scale = 1.0) {
        return {T(scale * gauss_(engine_)), T(scale * gauss_(engine_)), T(scale * gauss_(engine_))};
    }

    /// A random rigid motion: a uniform rotation, then a translation of Gaussian components of
    /// standard deviation `reach`.
    template <class T>
    dual_quaternion<T> rigid_motion(double reach = 2.0) {
        const quaternion<T> q = unit_quaternion<T>();  // one statement each: a fixed order
        const vec3<T> t = vector<T>(reach);
        return to_dual_quaternion(q, t);
    }

    /// Uniform in [low, high).
    template <class T>
    T uniform(double low, double high) {
        return T(std::uniform_real_distribution<double>(low, high)(engine_));
    }

private:
    std::mt19937_64 engine_;
    std::normal_distribution<double> gauss_;
};

/// Keyframes q_(i+1) = q_i exp(step_i), |step_i| <= max_angle, with random signs.
template <class T>
std::vector<quaternion<T>> random_walk(random_rotations& random, std::size_t count,
                                       double max_angle) {
    std::vector<quaternion<T>> keyframes{random.unit_quaternion<T>()};
    while (keyframes.size() < count) {
        const vec3<T> axis = random.unit_vector<T>();  // one statement each: a fixed order
        const vec3<T> step = axis * random.uniform<T>(0.0, max_angle);
        keyframes.push_back(normalize(keyframes.back() * from_rotation_vector(step)));
    }
    for (quaternion<T>& q : keyframes)
        if (random.uniform<double>(0.0, 1.0) < 0.5) q = -q;
    return keyframes;
}

/// Largest absolute element difference of two 3x3 matrices.
template <class T>
T max_difference(const rotation_matrix<T>& a, const rotation_matrix<T>& b) {
    T worst = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) worst = std::max(worst, std::abs(a(i, j) - b(i, j)));
    return worst;
}

/// Largest absolute component difference of two vectors.
template <class T>
T max_difference(const vec3<T>& a, const vec3<T>& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

/// Largest absolute component difference of two quaternions (sign-sensitive).
template <class T>
T max_difference(const quaternion<T>& a, const quaternion<T>& b) {
    return std::max(
        {std::abs(a.w - b.w), std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

}  // namespace quat::test
