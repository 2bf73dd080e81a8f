#pragma once
/// Helpers shared by the resharp::io tests: scratch directories, byte builders for binary files,
/// a large closed mesh, and checks on ParseError messages.

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>

#include "resharp/core/errors.h"
#include "resharp/mesh/mesh.h"
#include "support/simple_meshes.h"

namespace resharp::test {

/// A fresh empty directory for the running test, removed at the start of the next run.
std::filesystem::path scratch_dir();

/// Every file in `dir`, by name, sorted.
std::vector<std::string> files_in(const std::filesystem::path& dir);

std::string read_bytes(const std::filesystem::path& path);
void write_bytes(const std::filesystem::path& path, const std::string& bytes);

/// A closed torus of 2 * nu * nv triangles; positions are irrational-looking doubles, so exact
/// round trips are a real test.
Mesh torus_mesh(int nu, int nv);

/// Appends `value` to `out` in byte order `order`.
template <class T>
void append(std::string& out, T value, std::endian order = std::endian::little) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (order != std::endian::native) std::reverse(bytes, bytes + sizeof(T));
    out.append(bytes, sizeof(T));
}

/// Checks that `read` throws ParseError whose what() holds `name`, `location` ("line 3",
/// "byte 84") and `reason`.
void expect_parse_error(const std::function<void()>& read, const std::string& name,
                        const std::string& location, const std::string& reason);

/// `p` rounded to float, as binary STL stores it.
Vec3 to_float_precision(const Vec3& p);

/// Checks that `soup`, welded, has the triangles of `mesh` corner by corner, each position
/// passed through `round` (identity for formats that keep doubles).
void expect_same_geometry(const TriangleSoup& soup, const Mesh& mesh,
                          const std::function<Vec3(const Vec3&)>& round);

}  // namespace resharp::test
