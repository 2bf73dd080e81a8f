#pragma once
/// Rounding to an integer without a library call.

#include <cmath>
#include <cstdint>

namespace resharp {

/// Takes any double and gives std::round(x) to the bit: the nearest integer, halves away from
/// zero, the sign of x kept (-0.3 gives -0.0); x itself when it is already an integer (|x| of
/// 2^52 or more) or not finite. Inline: std::round() is a call into libm, and the grid search
/// (near/vertex_placement.cpp) rounds every shared coordinate in every pass of its fits.
inline double round_half_away(double x) {
    if (!(std::abs(x) < 0x1p52)) return x;
    double whole = static_cast<double>(static_cast<std::int64_t>(x));  // towards zero
    const double fraction = x - whole;  // exact: below 1 in size, within the bits of x
    if (fraction >= 0.5) {
        whole += 1.0;
    } else if (fraction <= -0.5) {
        whole -= 1.0;
    }
    return std::copysign(whole, x);
}

}  // namespace resharp
