#pragma once
/// e^(2 pi i x) without a library call, to a stated bound: for scans that only compare sums of
/// many such terms and take the library's value where a comparison is close.

#include <array>
#include <cfloat>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "resharp/core/rounding.h"

namespace resharp {

/// The bound on each component of approximate_turn_phasor(turns) - std::polar(1.0, angle), for
/// angle = 2 pi turns computed in double either way (the library's argument carries its own
/// rounding, of a few units in the last place of the angle; the polynomials' error is below
/// 1e-16): 8 units in the last place of (|angle| + 2).
inline double turn_phasor_error(double turns) {
    return 8.0 * DBL_EPSILON * (2.0 * std::numbers::pi * std::abs(turns) + 2.0);
}

namespace detail {

/// (-1)^k / (first + 2k)!, k = 0 .. count - 1: the Taylor coefficients of sine (first 1) and
/// cosine (first 0) in powers of a^2.
template <std::size_t count>
constexpr std::array<double, count> alternating_inverse_factorials(int first) {
    std::array<double, count> out{};
    double factorial = 1.0;
    for (int n = 2; n <= first; ++n) factorial *= n;
    for (std::size_t k = 0; k < count; ++k) {
        out[k] = (k % 2 == 0 ? 1.0 : -1.0) / factorial;
        const int n = first + 2 * static_cast<int>(k);
        factorial *= static_cast<double>(n + 1) * static_cast<double>(n + 2);
    }
    return out;
}

}  // namespace detail

inline constexpr auto kSineTaylor = detail::alternating_inverse_factorials<8>(1);    // to a^15
inline constexpr auto kCosineTaylor = detail::alternating_inverse_factorials<9>(0);  // to a^16

/// Takes x in turns and gives (cos 2 pi x, sin 2 pi x) within turn_phasor_error(x) per
/// component: the turn split into quarters (exact: a power-of-two multiple subtracted from a
/// value within a factor two of it) and the rest, at most an eighth of a turn, by Taylor
/// polynomials to degree 15 (sine) and 16 (cosine), whose next terms are below 1e-16 there.
/// Where |x| is 2^50 or more, or not finite, it is std::polar's value.
inline std::complex<double> approximate_turn_phasor(double turns) {
    if (!(std::abs(turns) < 0x1p50)) return std::polar(1.0, 2.0 * std::numbers::pi * turns);
    const double quarters = round_half_away(4.0 * turns);
    const double a = 2.0 * std::numbers::pi * (turns - 0.25 * quarters);  // |a| <= pi / 4
    const double a2 = a * a;
    double s = kSineTaylor.back(), c = kCosineTaylor.back();
    for (std::size_t k = kSineTaylor.size() - 1; k-- > 0;) s = s * a2 + kSineTaylor[k];
    for (std::size_t k = kCosineTaylor.size() - 1; k-- > 0;) c = c * a2 + kCosineTaylor[k];
    s *= a;
    switch (static_cast<std::int64_t>(quarters) & 3) {
        case 0:
            return {c, s};
        case 1:
            return {-s, c};
        case 2:
            return {-c, -s};
        default:
            return {s, -c};
    }
}

}  // namespace resharp
