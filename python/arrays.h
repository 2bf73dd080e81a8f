#pragma once
/// numpy arrays to and from resharp's containers. An input array is read through its strides
/// (any memory layout) into resharp's vector: one copy, every element checked on the way. An
/// output vector is handed to numpy, which then owns it: no copy.

#include <pybind11/numpy.h>

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "resharp/core/types.h"
#include "resharp/restoration/band_classification.h"

namespace resharp::python {

namespace py = pybind11;

/// The most rows an array may have: face and patch indices are handed back as int32.
inline constexpr std::size_t kMaxRows = 0x7fffffff;

/// `array`, a (#V, 3) numpy array of float32 or float64, as #V positions.
/// \throws InvalidInput naming `name` and the element if `array` is not a numpy array, has
///         another shape or dtype (byte order included), more than kMaxRows rows, or a NaN or
///         infinite coordinate.
std::vector<Vec3> positions_from(py::handle array, std::string_view name);

/// `array`, a (#F, 3) numpy array of int32, int64, uint32 or uint64, as #F triangles.
/// \throws InvalidInput naming `name` and the element if `array` is not a numpy array, has
///         another shape or dtype, more than kMaxRows rows, or an index outside
///         [0, vertex_count).
std::vector<Triangle> triangles_from(py::handle array, std::string_view name,
                                     std::size_t vertex_count);

/// Positions as a (#V, 3) float64 array over the vector's own storage.
py::array positions_to(std::vector<Vec3>&& positions);
/// Triangles as a (#F, 3) int32 array over the vector's own storage (indices below kMaxRows).
py::array triangles_to(std::vector<Triangle>&& triangles);
/// Indices as an (n,) int32 array over the vector's own storage; kNoIndex reads -1.
py::array indices_to(std::vector<Index>&& indices);
/// 0/1 flags as an (n,) bool array over the vector's own storage.
py::array flags_to(std::vector<std::uint8_t>&& flags);
/// Band roles as an (n,) uint8 array over the vector's own storage: 0 none, 1 edge, 2 corner.
py::array roles_to(std::vector<BandRole>&& roles);

}  // namespace resharp::python
