#pragma once
/// A box kept in floats for a quick test that never misses, its exact answer left to the box of
/// doubles it holds.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "resharp/restoration/clearance.h"

namespace resharp {

/// A box of floats holding a box of doubles, its bounds rounded outward: half the memory (the
/// harm check keeps one per split face, and on a midpoint mesh every face is split or moved: 16
/// of 145 MB at the peak). It may meet a box the box it holds does not; the exact answer is the
/// held box's.
class OuterBox {
public:
    OuterBox() = default;  ///< empty
    explicit OuterBox(const Box3& box) {
        for (int k = 0; k < 3; ++k) {
            min_[k] = rounded(box.min()[k], -kInfinity);
            max_[k] = rounded(box.max()[k], kInfinity);
        }
    }

    /// The box of doubles that holds the floats' bounds (and so the box it was made from).
    Box3 box() const {
        return Box3(Vec3(min_[0], min_[1], min_[2]), Vec3(max_[0], max_[1], max_[2]));
    }

    bool may_meet(const Box3& box) const {
        for (int k = 0; k < 3; ++k) {
            if (max_[k] < box.min()[k] || box.max()[k] < min_[k]) return false;
        }
        return true;
    }

private:
    static constexpr float kInfinity = std::numeric_limits<float>::infinity();

    /// The float nearest x, moved one step towards `outward` if that passed x. Clamped first:
    /// a double beyond the floats' range does not convert.
    static float rounded(double x, float outward) {
        constexpr double kLargest = std::numeric_limits<float>::max();
        const float f = static_cast<float>(std::clamp(x, -kLargest, kLargest));
        const bool inside = outward > 0 ? f < x : f > x;
        return inside ? std::nextafter(f, outward) : f;
    }

    std::array<float, 3> min_{kInfinity, kInfinity, kInfinity};
    std::array<float, 3> max_{-kInfinity, -kInfinity, -kInfinity};
};

}  // namespace resharp
