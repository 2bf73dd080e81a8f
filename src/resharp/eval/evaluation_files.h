#pragma once
/// What `resharp evaluate` reads beside the input mesh: the simulator's oracle PLY, a restored
/// mesh, and the face roles of a `resharp restore --segments` PLY, each matched to the input.
/// Each comes as a function of the parsed file (for tests) and one of its path.

#include <filesystem>
#include <string>
#include <vector>

#include "resharp/eval/ideal_points.h"
#include "resharp/io/attributes.h"
#include "resharp/io/ply.h"
#include "resharp/pipeline/restore.h"

namespace resharp::eval {

/// The face colours `resharp restore --segments` gives edge and corner triangles.
inline constexpr io::Rgb kEdgeTriangleColor{255, 210, 0};
inline constexpr io::Rgb kCornerTriangleColor{230, 0, 230};

/// Takes the oracle `ply` (vertex properties nx, ny, nz, surface, and sx, sy, sz for the
/// off-surface meshers; docs/oracle.md) read from `name` and the input mesh; gives the oracle's
/// normal (normalised), surface and surface point (if given) for each of the input's #V
/// vertices, matched by position (PositionIndex).
/// \throws ReadError if a property is missing, InvalidInput (naming the first vertex) if an
/// input vertex is not in the oracle.
Oracle match_oracle(const io::PlyMesh& ply, const std::string& name, const Mesh& input);
/// As above, reading the PLY at `path`. \throws also what read_ply_with_properties throws.
Oracle read_oracle(const std::filesystem::path& path, const Mesh& input);

/// Takes a restored mesh `read` (welded) from `name` and the input; gives it renumbered so that
/// it starts with the input's #V vertices (matched by position, positions the input's) and its
/// new vertices follow in their order in `read`; the triangles are `read`'s, renumbered.
/// \throws InvalidInput (naming the first one) if an input vertex is missing from `read`.
Mesh match_restored(const Mesh& read, const std::string& name, const Mesh& input);
/// Whether `written`, an indexed mesh as its file holds it, begins with the input's #V vertices
/// in input order, some moved, as restore() writes a near-surface restoration (issue 14) whose
/// moved vertices no position can find: some moved, and every vertex found in the input by
/// position found at its own index. (The evaluation then bounds how far each moved.)
bool starts_with_moved_input(const Mesh& written, const Mesh& input);
/// As above, reading and welding the mesh file at `path`; a file that starts_with_moved_input()
/// is taken as it is. \throws also what read_mesh throws.
Mesh read_restored(const std::filesystem::path& path, const Mesh& input);

/// Takes a `--segments` `ply` read from `name` and the input's face count #F; gives #F roles
/// decoded from the face colours: kEdgeTriangleColor is Edge, kCornerTriangleColor Corner,
/// any other None.
/// \throws ReadError if the face colours are missing, InvalidInput if their count is not #F.
std::vector<BandRole> decode_segment_roles(const io::PlyMesh& ply, const std::string& name,
                                           std::size_t face_count);
/// As above, reading the PLY at `path`. \throws also what read_ply_with_properties throws.
std::vector<BandRole> read_segment_roles(const std::filesystem::path& path, std::size_t face_count);

}  // namespace resharp::eval
