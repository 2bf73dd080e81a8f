#pragma once
/// Orders that depend on where vertices lie, not on how the mesh numbers them: the segmentations
/// take their decisions in these orders, and ties elsewhere are broken by them, so renumbering
/// the vertices, reordering the faces or rotating a face's corners gives the same restoration
/// (issue 12).

#include <algorithm>
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "resharp/core/types.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

/// Lexicographic in (x, y, z): local ties (which of a few neighbours, which diagonal). A
/// similarity transform with positive scale keeps it, up to points its rounding makes equal.
inline bool lexicographically_less(const Vec3& a, const Vec3& b) {
    if (a.x() != b.x()) return a.x() < b.x();
    if (a.y() != b.y()) return a.y() < b.y();
    return a.z() < b.z();
}

/// Lexicographic in (z, y, x): the order in which a mesher sweeping its grid slab by slab meets
/// points, for decisions taken one after another across the part (which broken edge is bridged
/// first, which patch wins a tie of votes). Taken in this order they fall as they did in a
/// mesher's own numbering; with the ends of broken edges in (x, y, z) order the 3-cell cone of
/// smooth_solids_test got 86 phantom points where its bound allows 85.
inline bool sweep_less(const Vec3& a, const Vec3& b) {
    if (a.z() != b.z()) return a.z() < b.z();
    if (a.y() != b.y()) return a.y() < b.y();
    return a.x() < b.x();
}

/// Vertices ordered by position; coincident vertices by index (the only order they have).
inline bool vertex_before(const Mesh& mesh, Index a, Index b) {
    const Vec3 &pa = mesh.positions[a], &pb = mesh.positions[b];
    return pa != pb ? lexicographically_less(pa, pb) : a < b;
}

/// Vertices in sweep_less() order; coincident vertices by index.
inline bool vertex_swept_before(const Mesh& mesh, Index a, Index b) {
    const Vec3 &pa = mesh.positions[a], &pb = mesh.positions[b];
    return pa != pb ? sweep_less(pa, pb) : a < b;
}

/// Sorts vertex indices by vertex_before().
inline void sort_vertices(const Mesh& mesh, std::span<Index> vertices) {
    std::sort(vertices.begin(), vertices.end(),
              [&](Index a, Index b) { return vertex_before(mesh, a, b); });
}

/// The corners of face f sorted by vertex_swept_before(): faces compare by these, which neither the
/// face's index nor the rotation or orientation of its corners changes.
inline std::array<Index, 3> corners_in_sweep_order(const Mesh& mesh, Index f) {
    std::array<Index, 3> t = mesh.triangles[f];
    auto before = [&](Index a, Index b) { return vertex_swept_before(mesh, a, b); };
    if (before(t[1], t[0])) std::swap(t[0], t[1]);
    if (before(t[2], t[1])) std::swap(t[1], t[2]);
    if (before(t[1], t[0])) std::swap(t[0], t[1]);
    return t;
}

/// Faces f and g, given their corners_in_sweep_order() a and b, in sweep order: by their first
/// corners, then their second and third; the same three vertices (a duplicate face) by index.
inline bool face_swept_before(const Mesh& mesh, const std::array<Index, 3>& a,
                              const std::array<Index, 3>& b, Index f, Index g) {
    for (int k = 0; k < 3; ++k) {
        if (a[k] != b[k]) return vertex_swept_before(mesh, a[k], b[k]);
    }
    return f < g;
}

/// Faces handed out one by one in face_swept_before() order, skipping those a caller has taken
/// meanwhile, without sorting them all: the faces are dealt into slabs of z by their first
/// corner's z (a bucket pass), and a slab's faces are ordered a run at a time, when the last run
/// is handed out: the least kFirstRun of its faces still open and after that run, then twice as
/// many, and so on. A region growing from each face handed out takes most faces above it before
/// their slab comes, so few are ever sorted (std::sort of all of impeller's grown faces cost
/// 156 M instructions); and a flat face across the grid's z planes puts all its faces in one
/// slab, which its first face, a seed, then takes: a run keeps only its own faces (mech by
/// OpenVDB, a slab of 89,078 faces: sorted whole for one seed, and then kept whole, it cost
/// 5.7 ms of the regrowth's 14).
class FacesInSweepOrder {
public:
    /// Takes the faces to hand out (any order).
    FacesInSweepOrder(const Mesh& mesh, std::span<const Index> faces);

    /// The first face in sweep order not yet handed out for which open(f) holds, or kNoIndex when
    /// none is left. open must stay false for a face once it is false.
    template <typename Open>
    Index next(Open&& open) {
        // Bound: each call moves the cursor past each face at most once over all calls; a slab
        // of n faces takes at most log2(n / kFirstRun + 1) + 1 runs, each a pass over it.
        while (true) {
            while (cursor_ < run_faces_.size()) {
                const Index f = run_faces_[cursor_++].face;
                if (open(f)) return f;
            }
            if (slab_has_more_) {
                order_next_run(open);
            } else if (slab_ + 1 < slab_start_.size()) {
                ++slab_;
                run_faces_.clear();
                cursor_ = 0;
                run_ = kFirstRun;
                slab_has_more_ = true;
            } else {
                return kNoIndex;
            }
        }
    }

private:
    static constexpr std::size_t kFirstRun = 16;

    /// A face with its corners_in_sweep_order() and the position of the first, (z, y, x): most
    /// comparisons end at that position, and the rest (faces sharing their first corner, about
    /// two per vertex) go on to the corners kept.
    struct KeyedFace {
        std::array<double, 3> first_corner;
        std::array<Index, 3> corners;
        Index face;
    };
    KeyedFace keyed(Index f) const;
    /// face_swept_before() of the two.
    bool before(const KeyedFace& a, const KeyedFace& b) const;

    /// Replaces the run handed out by the least run_ faces of the slab (slab_ - 1) that are open
    /// and come after it, in order, and doubles run_. Bound: one pass over the slab.
    template <typename Open>
    void order_next_run(Open& open) {
        const std::optional<KeyedFace> after =
            run_faces_.empty() ? std::nullopt : std::optional(run_faces_.back());
        const auto in_order = [&](const KeyedFace& a, const KeyedFace& b) { return before(a, b); };
        // A heap whose front is the latest of the least run_ met so far.
        run_faces_.clear();
        for (std::size_t i = slab_start_[slab_ - 1]; i < slab_start_[slab_]; ++i) {
            const Index f = by_slab_[i];
            if (!open(f)) continue;
            const KeyedFace k = keyed(f);
            if (after && !before(*after, k)) continue;
            if (run_faces_.size() == run_) {
                if (!before(k, run_faces_.front())) continue;
                std::pop_heap(run_faces_.begin(), run_faces_.end(), in_order);
                run_faces_.back() = k;
            } else {
                run_faces_.push_back(k);
            }
            std::push_heap(run_faces_.begin(), run_faces_.end(), in_order);
        }
        std::sort_heap(run_faces_.begin(), run_faces_.end(), in_order);
        slab_has_more_ = run_faces_.size() == run_;
        cursor_ = 0;
        run_ *= 2;
    }

    const Mesh& mesh_;
    std::vector<Index> by_slab_;           // the faces, slab after slab
    std::vector<std::size_t> slab_start_;  // slab s is by_slab_[slab_start_[s], slab_start_[s + 1])
    std::size_t slab_ = 0;                 // slabs [0, slab_) are taken; slab_ - 1 is handed out
    bool slab_has_more_ = false;        // whether slab_ - 1 may hold faces after the run handed out
    std::vector<KeyedFace> run_faces_;  // the run handed out, in order
    std::size_t cursor_ = 0;            // run_faces_[0, cursor_) are handed out
    std::size_t run_ = kFirstRun;       // how many the next run of the slab takes
};

}  // namespace resharp
