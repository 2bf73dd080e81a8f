#pragma once
/// Per-vertex and per-face values written beside a mesh (PLY only).

#include <cstdint>
#include <span>

#include "resharp/core/types.h"

namespace resharp::io {

/// An 8-bit colour, as PLY's `uchar red, green, blue`.
struct Rgb {
    std::uint8_t red = 0;
    std::uint8_t green = 0;
    std::uint8_t blue = 0;
    bool operator==(const Rgb&) const = default;
};

/// Optional values written with a mesh, each either empty or one per element. Views only: the
/// caller keeps the data alive for the call. Only PLY stores them.
struct MeshAttributes {
    std::span<const Vec3> vertex_normals = {};           ///< #V, written as `double nx, ny, nz`
    std::span<const std::int32_t> vertex_surfaces = {};  ///< #V, written as `int surface`
    /// #V, written as `double sx, sy, sz` (the simulator's nearest exact surface point)
    std::span<const Vec3> vertex_surface_points = {};
    std::span<const Rgb> vertex_colors = {};  ///< #V, written as `uchar red, green, blue`
    std::span<const Rgb> face_colors = {};    ///< #F, written as `uchar red, green, blue`

    bool empty() const {
        return vertex_normals.empty() && vertex_surfaces.empty() && vertex_surface_points.empty() &&
               vertex_colors.empty() && face_colors.empty();
    }
};

}  // namespace resharp::io
