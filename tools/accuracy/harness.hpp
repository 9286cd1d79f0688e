// Accuracy tool plumbing: a seeded generator, error statistics and the markdown table.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "reference.hpp"

namespace accuracy {

/// splitmix64: a fixed, portable sequence, so every run measures the same inputs.
struct rng {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

    /// Uniformly distributed direction (rejection from the cube), in double.
    v3<double> unit_vector() {
        for (;;) {
            const v3<double> v{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
            const double n2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
            if (n2 > 1e-4 && n2 <= 1) {
                const double n = std::sqrt(n2);
                return {v[0] / n, v[1] / n, v[2] / n};
            }
        }
    }
    /// Uniformly distributed rotation (uniform on S^3), w >= 0, normalized in high precision and
    /// rounded once to T: the best unit quaternion T can hold, so input rounding stays below 1 eps.
    template <class T = double>
    q4<T> unit_quaternion() {
        for (;;) {
            const q4<double> q{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
            const double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
            if (n2 > 1e-4 && n2 <= 1) {
                hq h = normalized(widen(q));
                if (h[0] < 0) h = {-h[0], -h[1], -h[2], -h[3]};
                return {T(h[0]), T(h[1]), T(h[2]), T(h[3])};
            }
        }
    }
};

template <class T>
q4<T> narrow(const q4<double>& q) {
    return {T(q[0]), T(q[1]), T(q[2]), T(q[3])};
}
template <class T>
v3<T> narrow(const v3<double>& v) {
    return {T(v[0]), T(v[1]), T(v[2])};
}
template <class T>
q4<T> narrow(const hq& q) {
    return {T(q[0]), T(q[1]), T(q[2]), T(q[3])};
}

/// Max and RMS of a stream of errors (already in units of eps); NaN counts as infinite.
struct error_stats {
    double max = 0;
    double sum_squares = 0;
    long count = 0;
    long non_finite = 0;
    std::string worst_case;  // description of the input that produced `max`

    /// Records one error; true when it is the new maximum (the caller then sets worst_case).
    bool add(double e) {
        ++count;
        if (!std::isfinite(e)) {
            ++non_finite;
            e = std::numeric_limits<double>::infinity();
        } else {
            sum_squares += e * e;
        }
        if (count == 1 || e > max) {
            max = e;
            return true;
        }
        return false;
    }
    [[nodiscard]] double rms() const {
        const long finite = count - non_finite;
        return finite > 0 ? std::sqrt(sum_squares / double(finite)) : 0.0;
    }
    void merge(const error_stats& o) {
        if (o.max > max) {
            max = o.max;
            worst_case = o.worst_case;
        }
        sum_squares += o.sum_squares;
        count += o.count;
        non_finite += o.non_finite;
    }
};

/// Error in units of eps of T, from a high-precision difference.
template <class T>
double in_eps(real error) {
    return double(error / real(std::numeric_limits<T>::epsilon()));
}

/// One line of the table: an operation on one input family in one scalar type.
struct row {
    std::string operation;
    std::string inputs;
    std::string scalar;
    std::string unit;
    double target;  // quat's target in the unit above; NaN = no target
    std::optional<error_stats> quat, glm, eigen;
    // A miss explained in docs/accuracy.md (a rounding floor, not a defect) is tolerated up to this
    // ceiling by the exit status; NaN = no miss tolerated.
    double accepted = std::numeric_limits<double>::quiet_NaN();

    [[nodiscard]] bool missed() const {
        return quat && !std::isnan(target) && !(quat->max <= target);
    }
    [[nodiscard]] bool unexplained_miss() const { return missed() && !(quat->max <= accepted); }
};

inline std::string format_number(double v) {
    char buf[32];
    if (std::isinf(v)) return "inf";
    if (v != 0 && (v >= 1e5 || v < 1e-2)) std::snprintf(buf, sizeof buf, "%.1e", v);
    else std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

inline std::string format_cell(const std::optional<error_stats>& s) {
    if (!s) return "—";
    std::string cell = format_number(s->max) + " / " + format_number(s->rms());
    if (s->non_finite > 0)
        cell += std::string(" (") + std::to_string(s->non_finite) + "/" + std::to_string(s->count) +
                " non-finite)";
    return cell;
}

inline void print_table(const std::vector<row>& rows) {
    std::printf(
        "| operation | inputs | type | unit | quat target | quat max / rms | GLM max / rms | "
        "Eigen max / rms |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    for (const row& r : rows) {
        const std::string target =
            std::isnan(r.target)
                ? "—"
                : (std::string("≤ ") + format_number(r.target) + (r.missed() ? " **missed**" : ""));
        std::printf("| %s | %s | %s | %s | %s | %s | %s | %s |\n", r.operation.c_str(),
                    r.inputs.c_str(), r.scalar.c_str(), r.unit.c_str(), target.c_str(),
                    format_cell(r.quat).c_str(), format_cell(r.glm).c_str(),
                    format_cell(r.eigen).c_str());
    }
}

}  // namespace accuracy
