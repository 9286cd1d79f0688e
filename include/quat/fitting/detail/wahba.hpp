// Wahba's problem solved: Davenport's q-method over accessors to the pairs and their weights, with
// the scaling that makes any finite sizes give the same rotation, the Newton polish for spread
// weights, the uniqueness test and scipy's sensitivity matrix. fitting/align_vectors.hpp calls it
// on two arrays; registration/align_points.hpp on the points less their centroids.
#ifndef QUAT_FITTING_DETAIL_WAHBA_HPP_INCLUDED
#define QUAT_FITTING_DETAIL_WAHBA_HPP_INCLUDED

#include <cstddef>

#include "../../align.hpp"
#include "../../conversions.hpp"
#include "../../detail/math.hpp"
#include "../../detail/power_of_two.hpp"
#include "../../matrix.hpp"
#include "../../quaternion.hpp"
#include "../../rotation_matrix.hpp"
#include "../../vec3.hpp"
#include "../nearest_rotation.hpp"
#include "symmetric_eigen.hpp"

namespace quat {

template <class T>
struct alignment;  // fitting/align_vectors.hpp; complete wherever a solution is made

#include "../../detail/isa_namespace.inc"
namespace detail {

template <class T>
struct wahba_solution {
    alignment<T> result;
    rotation_matrix<T> profile;    // Davenport's B = sum w_i t_i s_i^T of the scaled data
    T total_weight;                // sum w_i of the scaled weights
    T target_scale, source_scale;  // B of the data: profile times these and the weights' scale
    bool infinite;                 // a weight was infinite (no sensitivity matrix)
    bool negative;                 // a weight was negative (the callers' debug check)
};

// 1 where x is zero or lies within [min()^(1/4), max()^(1/4)], where every product of three such
// sizes stays a normal number; otherwise a power of two p with x / p in [1, 2). Dividing by a power
// of two is exact, so scaled data is the same data (bar what underflows beside the largest).
template <class T>
[[nodiscard]] constexpr T scale_of(T x) noexcept {
    const T high = detail::sqrt(detail::sqrt(detail::largest<T>()));
    const T low = detail::sqrt(detail::sqrt(detail::smallest_normal<T>()));
    if (!(x > high || (x < low && x > T(0)))) return T(1);
    return binade_of(x);
}

// max |component|, or infinity for a NaN or infinite component.
template <class T>
[[nodiscard]] constexpr T largest_component(const vec3<T>& v) noexcept {
    if (!detail::is_finite(v)) return detail::infinity<T>();
    return detail::largest_magnitude(v);
}

// Whether the non-zero vectors v(i) of the pairs used(i) all lie within `tolerance` radians of one
// line through 0 (true for none or one): B's rank is then at most one.
template <class T, class Vector, class Used>
[[nodiscard]] constexpr bool collinear(std::size_t count, Vector v, Used used) noexcept {
    vec3<T> reference{T(0), T(0), T(0)};
    T reference_norm = T(0);
    for (std::size_t i = 0; i < count; ++i)
        if (used(i) && norm(v(i)) > reference_norm) {
            reference = v(i);
            reference_norm = norm(reference);
        }
    const T tolerance = T(64) * detail::epsilon<T>();
    for (std::size_t i = 0; i < count; ++i)
        if (used(i) && norm(cross(v(i), reference)) > tolerance * norm(v(i)) * reference_norm)
            return false;
    return true;
}

// Newton's method on the rotation: with c_i = R s_i and R <- exp(phi) R, sum w t . exp(phi) c is
// sum w t . c + phi . g - phi^T H phi / 2 to second order, g = sum w c x t and
// H = sum w ((t . c) I - (t c^T + c t^T) / 2), so the step is phi = H^-1 g. The eigenvector of K
// is only as accurate as eps over K's relative eigen-gap 2 (s1 + s2) / max |B(i, j)|: weights
// spread over 1e10 leave the rotation about the heavy pairs' direction to about 1e-6. Each step
// divides that error by about 1 / (eps spread) (H's rounding relative to its smallest eigenvalue),
// because g is summed from cross products accurate to their own size, not B's. A step that is not
// a descent (H not positive definite) or implausibly large is not taken. At most `steps` steps:
// where the error's floor lies above eps (a small gap), the loop would otherwise run them all.
template <class T, class Target, class Source, class Weight>
[[nodiscard]] constexpr quaternion<T> newton_refine(quaternion<T> q, std::size_t count,
                                                    Target target, Source source, Weight weight,
                                                    int steps = 8) noexcept {
    for (int step = 0; step < steps; ++step) {
        const rotation_matrix<T> r = to_matrix(q);
        T g[3] = {}, h[3][3] = {}, tau = T(0);
        for_each_block(count, [&](std::size_t start, std::size_t end) {
            T block_g[3] = {}, block_s[3][3] = {}, block_tau = T(0);
            for (std::size_t i = start; i < end; ++i) {
                const T w = weight(i);
                if (!(w > T(0))) continue;
                const vec3<T> t = target(i), c = rotate(r, source(i));
                // c x t accurate to its own size (align.hpp): for a pair already aligned it is
                // tiny, and the plain formula's rounding (eps |c| |t| in every direction) times a
                // large weight would swamp the small weights' pull about that pair.
                const vec3<T> gradient = accurate_cross(c, t) * w, wt = t * w;
                const T tc[3] = {wt.x, wt.y, wt.z}, cc[3] = {c.x, c.y, c.z};
                block_g[0] += gradient.x;
                block_g[1] += gradient.y;
                block_g[2] += gradient.z;
                block_tau += dot(wt, c);
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b) block_s[a][b] += tc[a] * cc[b] + tc[b] * cc[a];
            }
            tau += block_tau;
            for (int a = 0; a < 3; ++a) {
                g[a] += block_g[a];
                for (int b = 0; b < 3; ++b) h[a][b] -= block_s[a][b] / T(2);
            }
        });
        for (int a = 0; a < 3; ++a) h[a][a] += tau;
        T phi[3] = {};
        if (!detail::solve_positive_definite3(h, g, phi)) break;
        const vec3<T> turn{phi[0], phi[1], phi[2]};
        const T size = norm(turn);
        if (!(size <= T(0.125))) break;
        q = normalize(from_rotation_vector(turn) * q);
        if (size <= detail::epsilon<T>()) break;
    }
    return q.w < T(0) ? -q : q;
}

// One Newton step of newton_refine's kind from B alone: with N = B R^T = sum w t (R s)^T,
// g = vee(N - N^T) and H = trace(N) I - (N + N^T) / 2. The eigenvector (or FOAM's closed form) is
// good to about eps / gap in relative terms, an error the step removes down to B's own rounding,
// which is where an SVD's answer lies too (measured by quat_accuracy's align_points rows).
template <class T>
[[nodiscard]] constexpr quaternion<T> polish_with_profile(const quaternion<T>& q,
                                                          const T (&b)[3][3]) noexcept {
    const rotation_matrix<T> n = rotation_matrix<T>{b} * transpose(to_matrix(q));
    const T g[3] = {n(2, 1) - n(1, 2), n(0, 2) - n(2, 0), n(1, 0) - n(0, 1)};
    const T trace = n(0, 0) + n(1, 1) + n(2, 2);
    T h[3][3] = {};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) h[i][j] = (i == j ? trace : T(0)) - (n(i, j) + n(j, i)) / T(2);
    T phi[3] = {};
    if (!detail::solve_positive_definite3(h, g, phi)) return q;
    const quaternion<T> p = normalize(from_rotation_vector(vec3<T>{phi[0], phi[1], phi[2]}) * q);
    return p.w < T(0) ? -p : p;
}

// The turn phi about the unit axis maximizing sum w_i y_i . rot(axis, phi) x_i, over the pairs with
// w_i > 0 other than `skip`: rot(axis, phi) x = x cos phi + (axis x x) sin phi + axis (axis . x) (1
// - cos phi), so the sum is A cos phi + S sin phi + const with S = sum w axis . (x x y) and A = sum
// w (x x axis) . (y x axis) (Lagrange's identity for x . y - (x . axis)(y . axis)), largest at
// atan2(S, A). Both from accurate cross products: a pair along the axis, however heavy, adds only
// its own rounding. Unique unless |A| and |S| are within 64 eps of sum w |x x axis| |y x axis|.
template <class T>
struct turn {
    T angle;
    bool unique;
};

template <class T, class X, class Y, class Weight>
[[nodiscard]] constexpr turn<T> best_turn(const vec3<T>& axis, std::size_t count, std::size_t skip,
                                          X x, Y y, Weight weight) noexcept {
    T sine = T(0), cosine = T(0), size = T(0);
    for (std::size_t i = 0; i < count; ++i) {
        const T w = weight(i);
        if (i == skip || !(w > T(0))) continue;
        const vec3<T> xi = x(i), yi = y(i);
        const vec3<T> x_across = accurate_cross(xi, axis), y_across = accurate_cross(yi, axis);
        sine += w * dot(axis, accurate_cross(xi, yi));
        cosine += w * dot(x_across, y_across);
        size += w * norm(x_across) * norm(y_across);
    }
    // max(|A|, |S|), not their hypotenuse: squares of tiny sums (weights 1e-300 beside one
    // of 1) would underflow.
    const bool unique =
        detail::max(detail::abs(sine), detail::abs(cosine)) > T(64) * detail::epsilon<T>() * size;
    return {unique ? detail::atan2(sine, cosine) : T(0), unique};
}

template <class T>
[[nodiscard]] constexpr wahba_solution<T> nan_wahba(bool negative) noexcept {
    const T nan = detail::quiet_nan<T>();
    const rotation_matrix<T> profile{{{nan, nan, nan}, {nan, nan, nan}, {nan, nan, nan}}};
    return {{{nan, nan, nan, nan}, nan, false}, profile, nan, T(1), T(1), false, negative};
}

// One pair with infinite weight (scipy >= 1.11's "primary" pair): it is aligned exactly in
// direction, by the shortest arc P, then the finite pairs choose the turn about its target's
// direction (best_turn of P s_i onto t_i). Not unique when they have no pull about it.
template <class T, class Target, class Source, class Weight>
[[nodiscard]] constexpr alignment<T> align_with_primary(std::size_t count, std::size_t primary,
                                                        Target target, Source source,
                                                        Weight weight) noexcept {
    const vec3<T> tp = target(primary), sp = source(primary);
    const T nan = detail::quiet_nan<T>();
    if (!(squared_norm(tp) > T(0)) || !(squared_norm(sp) > T(0)))
        return {{nan, nan, nan, nan}, nan, false};  // infinity times a zero vector
    const quaternion<T> arc = rotation_between(sp, tp);
    const vec3<T> a = normalize(tp);
    const rotation_matrix<T> r = to_matrix(arc);
    const turn<T> best = best_turn(
        a, count, primary, [&](std::size_t i) { return rotate(r, source(i)); }, target, weight);
    if (!best.unique) return {arc, T(0), false};  // as for one pair: rotation_between itself
    const quaternion<T> q = normalize(from_rotation_vector(a * best.angle) * arc);
    return {q.w < T(0) ? -q : q, T(0), true};
}

// Davenport's B = sum w t s^T, summed in blocks of summation_block pairs, each block from zero:
// rounding errors then grow with the block length plus the number of blocks, not with the count.
// For 1e6 noisy pairs in float the plain running sums put the rotation 114 eps from its long
// double value; blocked, 2.7 eps (double: 16.6 and 2.5 eps). Returns sum w.
template <class T>
struct data_sizes {
    T target, source, weight, lowest;  // largest |component|, largest |w|, lowest w (or 0)
};

template <class T, class Target, class Source, class Weight>
constexpr T profile_of(T (&b)[3][3], data_sizes<T>& sizes, std::size_t count, Target target,
                       Source source, Weight weight) noexcept {
    T total = T(0);
    sizes = {T(0), T(0), T(0), T(0)};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) b[r][c] = T(0);
    for_each_block(count, [&](std::size_t start, std::size_t end) {
        T block[3][3] = {}, block_total = T(0);
        for (std::size_t i = start; i < end; ++i) {
            const T w = weight(i);
            const vec3<T> u = target(i), s = source(i), t = u * w;
            // Exact for finite B (a NaN or infinite component makes B so): no checks here.
            sizes.target = detail::max(
                sizes.target,
                detail::max(detail::abs(u.x), detail::max(detail::abs(u.y), detail::abs(u.z))));
            sizes.source = detail::max(
                sizes.source,
                detail::max(detail::abs(s.x), detail::max(detail::abs(s.y), detail::abs(s.z))));
            sizes.weight = detail::max(sizes.weight, detail::abs(w));
            sizes.lowest = w < sizes.lowest ? w : sizes.lowest;
            block[0][0] += t.x * s.x;
            block[0][1] += t.x * s.y;
            block[0][2] += t.x * s.z;
            block[1][0] += t.y * s.x;
            block[1][1] += t.y * s.y;
            block[1][2] += t.y * s.z;
            block[2][0] += t.z * s.x;
            block[2][1] += t.z * s.y;
            block[2][2] += t.z * s.z;
            block_total += w;
        }
        total += block_total;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) b[r][c] += block[r][c];
    });
    return total;
}

// sum w_i t_i . (R s_i) = trace(R^T B), so R is the rotation nearest to B: the eigenvector of the
// largest eigenvalue of Horn's (Davenport's) K of B (Davenport's q-method; Markley & Crassidis,
// Fundamentals of Spacecraft Attitude Determination and Control, 2014, ch. 5), polished by
// newton_refine where K's relative eigen-gap leaves it inaccurate. K's eigenvalues are
// s0 + s1 + s2 and s0 - s1 - s2, ... for B's singular values s0 >= s1 >= |s2| (s2 < 0 when
// det B < 0). The optimum is unique unless B has rank one or less (the used sources or the used
// targets collinear, see collinear()) or, where the top two eigenvalues nearly tie, best_turn finds
// no pull. Collinear data tie them to rounding, so the rank is only examined below sqrt(eps).
template <class T, class Target, class Source, class Weight>
[[nodiscard]] constexpr alignment<T> rotation_of_profile(const T (&b)[3][3], std::size_t count,
                                                         Target target, Source source,
                                                         Weight weight,
                                                         T as_is_gap = T(1)) noexcept {
    const rotation_matrix<T> scaled = unit_scaled(rotation_matrix<T>{b});
    // Few pairs: Newton steps over the pairs cost less than the eigen-solve, so FOAM serves down
    // to a gap bound of 1/1024, where its error (about eps / bound^2, at most about a million eps)
    // is well inside Newton's reach: as the error squares with each step, two bring it to the
    // floor of the pairs' rounding, a third confirms it (more only repeat that floor where it lies
    // above eps). Three random points fall below separated_gap() 71 % of the time (their B has
    // rank 2), four 46 %; over 20,000 random sets of 4 or 5 points the rotation's worst error fell
    // from 7.9 eps to 3.8 eps, and 3 double points took 0.72 us where they took 0.87 with a bound
    // of 1/32 and the eigen-solve below it. Newton's steps leave out pairs of weight <= 0, so a
    // negative weight (align_vectors' precondition, unchecked) keeps the eigen-solve, where it
    // counts against its pair. Where `as_is_gap` is below 1 (a wider type solving for a narrower
    // one, whose eps is far above eps / as_is_gap^2), FOAM's rotation is used as it is down to it.
    constexpr std::size_t few = 16;
    bool small = count <= few;
    for (std::size_t i = 0; small && i < count; ++i) small = weight(i) >= T(0);
    const T floor = small ? T(1) / T(1024) : separated_gap<T>();
    const horn_solution<T> separated = detail::foam(scaled, as_is_gap < floor ? as_is_gap : floor);
    // FOAM's error grows as its gap bound shrinks: above 1 (B's singular values within about a
    // factor 2 of each other) it is within a few eps as it is (as_is_gap's default), below that one polish; below
    // separated_gap(), Newton's method over the pairs, as for the eigenvector of a small gap (K's
    // gap 2 (s1 + s2) is at least the bound, so the optimum is unique).
    if (separated.eigenvalue_gap >= as_is_gap) return {separated.rotation, T(0), true};
    if (separated.eigenvalue_gap >= separated_gap<T>())
        return {polish_with_profile(separated.rotation, b), T(0), true};
    if (separated.eigenvalue_gap > T(0))
        return {newton_refine(separated.rotation, count, target, source, weight, 3), T(0), true};
    const symmetric_eigen4<T> eigen = detail::horn_eigen(scaled);
    const T gap = eigen.values[0] - eigen.values[1];
    const T tie = detail::sqrt(detail::epsilon<T>());
    bool unique = gap > tie;
    quaternion<T> q = eigen.vectors[0];
    if (!unique) {
        // One pair outweighing all others together by 1 / eps (w |t| |s|, what it adds to B)
        // leaves theirs below its rounding in B, in K and in Newton's H: it is then aligned first,
        // as an infinite weight is, and the others turn about it (what they move it by is below
        // eps). Such a pair ties K's top two eigenvalues, so it is only looked for here.
        T heaviest = T(0), others = T(0);
        std::size_t heavy = 0;
        for (std::size_t i = 0; i < count; ++i) {
            const T load = weight(i) * norm(target(i)) * norm(source(i));
            if (load > heaviest) {
                others += heaviest;
                heaviest = load;
                heavy = i;
            } else {
                others += load;
            }
        }
        if (count > 1 && others < detail::epsilon<T>() * heaviest)
            return align_with_primary<T>(count, heavy, target, source, weight);
        const auto used = [&](std::size_t i) {
            return weight(i) > T(0) && squared_norm(target(i)) > T(0) &&
                   squared_norm(source(i)) > T(0);
        };
        unique = !collinear<T>(count, source, used) && !collinear<T>(count, target, used);
    }
    if (unique && !(gap > tie)) {
        // The two best eigenvectors v0, v1 nearly tie (weights spread by 1e8 or more, or a
        // symmetric set): the optimum lies near the circle v0 (cos a + u sin a), u the vector part
        // of v0* v1, the rotations R(v0) rot(u, 2 a), and B's rounding leaves v0 anywhere on it.
        // best_turn finds the turn from the pairs themselves; none at all: not unique.
        const quaternion<T> v0 = eigen.vectors[0], between = conjugate(v0) * eigen.vectors[1];
        const vec3<T> u = normalize(vec3<T>{between.x, between.y, between.z});
        const turn<T> best = best_turn(
            u, count, count, source,
            [&](std::size_t i) { return rotate(conjugate(v0), target(i)); }, weight);
        unique = best.unique;
        if (unique) q = v0 * from_rotation_vector(u * best.angle);
    }
    if (unique) {
        q = normalize(q.w < T(0) ? -q : q);
        // The eigenvector is good to about eps / gap: polish it where that is coarse. Below
        // 64 eps, Newton's H is too coarse to converge (each step would cut the error by less
        // than 32); best_turn's answer is then already good to eps.
        if (gap < separated_gap<T>() && gap > T(64) * detail::epsilon<T>())
            q = newton_refine(q, count, target, source, weight);
        else if (gap >= separated_gap<T>()) q = polish_with_profile(q, b);
    } else if (count == 1 && eigen.values[0] > T(0)) {
        q = rotation_between(source(0), target(0));
    } else {
        // The optimal rotations span the eigenvectors tied with the largest; of those, the one
        // nearest the identity (the projection of 1 onto the span), which for collinear pairs
        // is the shortest arc, as for one pair, and for B = 0 (no data) the identity. When
        // every optimal rotation is a half turn, the projection is 0 and any of them will do.
        quaternion<T> nearest{T(0), T(0), T(0), T(0)};
        for (int n = 0; n < 4; ++n)
            if (eigen.values[0] - eigen.values[n] <= tie)
                nearest += eigen.vectors[n] * eigen.vectors[n].w;
        if (squared_norm(nearest) > T(0)) q = nearest;
        q = normalize(q.w < T(0) ? -q : q);
    }
    return {q, T(0), unique};
}

// sqrt(sum w |t - R s|^2) from the residuals themselves: scipy's sum w (|t|^2 + |s|^2) -
// 2 trace(R^T B) cancels down to about sqrt(epsilon) times the vectors' length when they fit
// exactly. target, source and weight are the data divided by the powers of two in `scale`.
template <class T, class Target, class Source, class Weight>
[[nodiscard]] constexpr T rssd_of(const quaternion<T>& q, std::size_t count, Target target,
                                  Source source, Weight weight) noexcept {
    const rotation_matrix<T> r = to_matrix(q);
    T squares = T(0);
    for_each_block(count, [&](std::size_t start, std::size_t end) {
        T block = T(0);
        for (std::size_t i = start; i < end; ++i)
            block += weight(i) * squared_norm(target(i) - rotate(r, source(i)));
        squares += block;
    });
    return detail::sqrt(squares);
}

// The data are first summed as they are; only where that overflows, underflows (sizes outside
// [min()^(1/4), max()^(1/4)]), meets an infinite weight or NaN are they examined closely and
// divided by powers of two (scale_of), so sizes from subnormal to max() give the same rotation.
template <class T, class Target, class Source, class Weight>
[[nodiscard]] constexpr wahba_solution<T> solve_wahba(Target target, Source source,
                                                      std::size_t count, Weight weight) noexcept {
    T b[3][3] = {};
    data_sizes<T> sizes{};
    T total = profile_of(b, sizes, count, target, source, weight);
    bool plain = detail::is_finite(total);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) plain = plain && detail::is_finite(b[r][c]);
    T target_size = sizes.target, source_size = sizes.source, weight_size = sizes.weight,
      lowest = sizes.lowest;
    std::size_t infinite = 0, primary = 0;
    bool finite = true;
    plain = plain && scale_of(target_size) == T(1) && scale_of(source_size) == T(1) &&
            scale_of(weight_size) == T(1);
    if (!plain) {
        target_size = source_size = weight_size = lowest = T(0);
        for (std::size_t i = 0; i < count; ++i) {
            const T w = weight(i);
            lowest = w < lowest ? w : lowest;
            if (w == detail::infinity<T>()) {
                ++infinite;
                primary = i;
            } else {
                finite = finite && detail::is_finite(w);
                weight_size = detail::max(weight_size, detail::abs(w));
            }
            target_size = detail::max(target_size, largest_component(target(i)));
            source_size = detail::max(source_size, largest_component(source(i)));
        }
    }
    if (!finite || infinite > 1 || !detail::is_finite(target_size) ||
        !detail::is_finite(source_size))
        return nan_wahba<T>(lowest < T(0));
    if (plain) {
        alignment<T> result = rotation_of_profile(b, count, target, source, weight);
        result.rssd = rssd_of(result.rotation, count, target, source, weight);
        return {result, rotation_matrix<T>{b}, total, T(1), T(1), false, lowest < T(0)};
    }
    // Separate scales for the rotation (only B's direction counts), one for both in the residuals.
    const T pt = scale_of(target_size), ps = scale_of(source_size), pw = scale_of(weight_size);
    const T p = scale_of(detail::max(target_size, source_size));
    const auto scaled_target = [&](std::size_t i) { return target(i) / pt; };
    const auto scaled_source = [&](std::size_t i) { return source(i) / ps; };
    const auto scaled_weight = [&](std::size_t i) {
        const T w = weight(i);  // an infinite weight's pair is aligned apart, and not in rssd
        return w == detail::infinity<T>() ? T(0) : w / pw;
    };
    total = profile_of(b, sizes, count, scaled_target, scaled_source, scaled_weight);
    alignment<T> result =
        infinite == 1
            ? align_with_primary<T>(count, primary, scaled_target, scaled_source, scaled_weight)
            : rotation_of_profile(b, count, scaled_target, scaled_source, scaled_weight);
    // An infinite weight's pair is left out of rssd, as scipy does (its residual is the
    // difference of the lengths).
    result.rssd = rssd_of(
                      result.rotation, count, [&](std::size_t i) { return target(i) / p; },
                      [&](std::size_t i) { return source(i) / p; }, scaled_weight) *
                  detail::sqrt(pw) * p;
    return {result, rotation_matrix<T>{b}, total, pt, ps, infinite != 0, lowest < T(0)};
}

// scipy's sensitivity mean(w) / zeta (kappa I + B B^T), kappa = s0 s1 + s1 s2 + s2 s0 and
// zeta = (s0 + s1) (s1 + s2) (s2 + s0) for B's singular values signed as above, here without an
// SVD: with lambda = s0 + s1 + s2 = trace(R^T B), kappa = (lambda^2 - |B|_F^2) / 2 and
// zeta = lambda kappa - det B (Markley, "Attitude determination using vector observations: a fast
// optimal matrix algorithm", J. Astronaut. Sci. 41(2), 1993). B is scaled to a largest element of 1
// first, and the scale put back at the end (sensitivity scales as 1 / |B|).
template <class T>
[[nodiscard]] constexpr matrix3<T> wahba_sensitivity(const wahba_solution<T>& solution,
                                                     std::size_t count) noexcept {
    T scale = T(0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) scale = detail::max(scale, detail::abs(solution.profile(i, j)));
    if (!(scale > T(0))) scale = T(1);
    rotation_matrix<T> b{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) b(i, j) = solution.profile(i, j) / scale;
    const rotation_matrix<T> r = to_matrix(solution.result.rotation);
    T lambda = T(0), frobenius = T(0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            lambda += r(i, j) * b(i, j);
            frobenius += b(i, j) * b(i, j);
        }
    const T kappa = (lambda * lambda - frobenius) / T(2);
    const T zeta = lambda * kappa - determinant(b);
    const T factor =
        solution.total_weight / static_cast<T>(static_cast<double>(count)) / (scale * zeta);
    // The weights' scale cancels in mean(w) / |B|; the vectors' scales are divided out one at a
    // time, since their product may overflow where the quotient does not.
    const T nan = detail::quiet_nan<T>();
    matrix3<T> sensitivity{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            sensitivity(i, j) =
                solution.infinite ? nan
                                  : factor * ((i == j ? kappa : T(0)) + dot(row(b, i), row(b, j))) /
                                        solution.target_scale / solution.source_scale;
    return sensitivity;
}

// solve_wahba over two arrays.
template <class T, class Weight>
[[nodiscard]] constexpr wahba_solution<T> solve_wahba(const vec3<T>* targets,
                                                      const vec3<T>* sources, std::size_t count,
                                                      Weight weight) noexcept {
    return solve_wahba<T>([targets](std::size_t i) { return targets[i]; },
                          [sources](std::size_t i) { return sources[i]; }, count, weight);
}

}  // namespace detail
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_FITTING_DETAIL_WAHBA_HPP_INCLUDED
