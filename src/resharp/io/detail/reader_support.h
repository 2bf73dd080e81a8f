#pragma once
/// Internal to resharp::io: what every reader does after parsing, shared so each format checks
/// the same things the same way.

#include <cstdint>
#include <span>

#include "resharp/mesh/mesh.h"

namespace resharp::io::detail {

/// Appends the fan (v0, v[i], v[i+1]) of a convex polygon with at least three corners.
void append_fan(std::span<const Index> polygon, std::vector<Triangle>& triangles);

/// Whether `count` records of at least `min_bytes` each fit in `available` bytes, computed
/// without overflow. Readers call this before reserving memory for a count read from a file.
bool fits(std::uint64_t count, std::uint64_t min_bytes, std::uint64_t available);

}  // namespace resharp::io::detail
