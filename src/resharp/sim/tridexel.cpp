#include "resharp/sim/tridexel.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

#include "resharp/core/errors.h"

namespace resharp::sim {

Ray GridSpec::ray(int axis, std::size_t index) const {
    const int b = (axis + 1) % 3;
    const int c = (axis + 2) % 3;
    const auto nb = static_cast<std::size_t>(counts[b]);
    Ray r;
    r.axis = axis;
    r.origin[axis] = 0.0;
    r.origin[b] = node(b, static_cast<int>(index % nb));
    r.origin[c] = node(c, static_cast<int>(index / nb));
    return r;
}

GridSpec grid_enclosing(const Box3& box, double pitch, const Vec3& anchor) {
    if (!(pitch > 0.0) || !std::isfinite(pitch)) throw InvalidInput("grid pitch must be positive");
    if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite()) {
        throw InvalidInput("grid box is empty or not finite");
    }
    GridSpec spec;
    spec.pitch = pitch;
    for (int a = 0; a < 3; ++a) {
        double first = std::floor((box.min()[a] - anchor[a]) / pitch);
        if (anchor[a] + first * pitch >= box.min()[a]) first -= 1.0;
        double last = std::ceil((box.max()[a] - anchor[a]) / pitch);
        if (anchor[a] + last * pitch <= box.max()[a]) last += 1.0;
        spec.origin[a] = anchor[a] + first * pitch;
        const double count = last - first + 1.0;
        if (count > 1e6) throw InvalidInput("grid too fine: more than a million nodes per axis");
        spec.counts[a] = static_cast<int>(count);
    }
    // Recheck with the node formula the mesher uses: rounding must not leave a node on the box.
    for (int a = 0; a < 3; ++a) {
        if (spec.node(a, 0) >= box.min()[a]) spec.origin[a] -= pitch, spec.counts[a] += 1;
        if (spec.node(a, spec.counts[a] - 1) <= box.max()[a]) spec.counts[a] += 1;
    }
    return spec;
}

GridSpec phased_grid(const Box3& box, double pitch, double phase) {
    const GridSpec spec = grid_enclosing(box, pitch, box.min().array() + phase * pitch);
    const double nodes = static_cast<double>(spec.counts[0]) * spec.counts[1] * spec.counts[2];
    if (nodes > 2147483647.0) throw InvalidInput("grid too fine: more than 2^31 nodes");
    return spec;
}

double pitch_for_cells(const Box3& box, double cells) {
    if (!(cells > 0.0) || !std::isfinite(cells)) throw InvalidInput("cells must be positive");
    if (box.isEmpty() || !box.sizes().allFinite()) throw InvalidInput("box is empty or not finite");
    return box.sizes().maxCoeff() / cells;
}

void subtract_intervals(RayIntervals& solid, std::span<const Interval> removed,
                        std::vector<Interval>& scratch) {
    // The remaining material is bounded by the removed volume, whose outward normal points into
    // the material: reverse it.
    const auto bounding = [](const Crossing& c) { return Crossing{c.t, -c.normal, c.surface}; };
    scratch.clear();
    std::size_t first_removed = 0;
    bool changed = false;
    for (const Interval& s : solid) {
        Crossing enter = s.enter;
        bool alive = true;
        for (std::size_t r = first_removed; r < removed.size(); ++r) {
            const Interval& cut = removed[r];
            if (cut.exit.t <= enter.t) {
                first_removed = r + 1;  // entirely before this and every later interval
                continue;
            }
            if (cut.enter.t >= s.exit.t) break;
            changed = true;
            if (cut.enter.t > enter.t) scratch.push_back({enter, bounding(cut.enter)});
            enter = bounding(cut.exit);
            if (enter.t >= s.exit.t) {
                alive = false;
                break;
            }
        }
        if (alive) scratch.push_back({enter, s.exit});
    }
    if (changed) solid.assign(scratch.data(), scratch.data() + scratch.size());
}

namespace {

/// Rays of one family per tile side; a tile is the unit of parallel work.
constexpr int kTileSide = 16;

/// The rays of one family a volume's bounds reach: index ranges [b0, b1] x [c0, c1] and the
/// stretch [t0, t1] along the rays.
struct RayRange {
    int b0 = 0, b1 = -1, c0 = 0, c1 = -1;
    double t0 = 0.0, t1 = 0.0;
    bool empty() const { return b1 < b0 || c1 < c0; }
};

RayRange rays_reached(const GridSpec& spec, int axis, const Box3& bounds) {
    // A tolerance of 1e-9 pitch keeps a ray lying exactly on the bounds: under the perturbation
    // rule a volume may include its own boundary.
    constexpr double kSlack = 1e-9;
    const auto index_range = [&](int a, int& lo, int& hi) {
        const double from = (bounds.min()[a] - spec.origin[a]) / spec.pitch;
        const double to = (bounds.max()[a] - spec.origin[a]) / spec.pitch;
        lo = static_cast<int>(std::max(0.0, std::ceil(from - kSlack)));
        hi = static_cast<int>(std::min(spec.counts[a] - 1.0, std::floor(to + kSlack)));
    };
    RayRange r;
    if (bounds.isEmpty()) return r;
    index_range((axis + 1) % 3, r.b0, r.b1);
    index_range((axis + 2) % 3, r.c0, r.c1);
    const double slack = kSlack * spec.pitch;
    r.t0 = bounds.min()[axis] - slack;
    r.t1 = bounds.max()[axis] + slack;
    return r;
}

/// One tile of one ray family and the volumes that reach it, in program order.
struct Tile {
    int axis = 0;
    int b0 = 0, c0 = 0;  // first ray indices of the tile
};

class OrderedSubtraction {
public:
    OrderedSubtraction(DexelGrid& grid, std::span<const Solid* const> volumes)
        : grid_(grid), volumes_(volumes) {}

    void run(const std::function<void(std::size_t, std::size_t)>& on_progress) {
        bin_volumes_into_tiles();
        std::atomic<std::size_t> done{0};
        std::mutex progress_mutex;
        tbb::parallel_for(std::size_t{0}, tiles_.size(), [&](std::size_t t) {
            std::vector<Interval> removed;
            std::vector<Interval> scratch;
            process_tile(t, removed, scratch);
            const std::size_t finished = ++done;
            if (on_progress) {
                std::lock_guard lock(progress_mutex);
                on_progress(finished, tiles_.size());
            }
        });
    }

private:
    void bin_volumes_into_tiles() {
        const GridSpec& spec = grid_.spec;
        std::array<int, 3> tiles_b{}, tiles_c{}, first_tile{};
        for (int a = 0; a < 3; ++a) {
            tiles_b[a] = (spec.counts[(a + 1) % 3] + kTileSide - 1) / kTileSide;
            tiles_c[a] = (spec.counts[(a + 2) % 3] + kTileSide - 1) / kTileSide;
            first_tile[a] = static_cast<int>(tiles_.size());
            for (int tc = 0; tc < tiles_c[a]; ++tc) {
                for (int tb = 0; tb < tiles_b[a]; ++tb) {
                    tiles_.push_back({a, tb * kTileSide, tc * kTileSide});
                }
            }
        }
        ranges_.resize(3 * volumes_.size());
        const auto for_each_tile = [&](std::size_t v, auto&& visit) {
            for (int a = 0; a < 3; ++a) {
                const RayRange& r = ranges_[3 * v + a];
                if (r.empty()) continue;
                for (int tc = r.c0 / kTileSide; tc <= r.c1 / kTileSide; ++tc) {
                    for (int tb = r.b0 / kTileSide; tb <= r.b1 / kTileSide; ++tb) {
                        visit(static_cast<std::size_t>(first_tile[a] + tb + tiles_b[a] * tc));
                    }
                }
            }
        };
        tbb::parallel_for(std::size_t{0}, volumes_.size(), [&](std::size_t v) {
            const Box3 bounds = volumes_[v]->bounds();
            for (int a = 0; a < 3; ++a) ranges_[3 * v + a] = rays_reached(spec, a, bounds);
        });
        // Counting sort into CSR keeps each tile's volumes in program order.
        tile_offsets_.assign(tiles_.size() + 1, 0);
        for (std::size_t v = 0; v < volumes_.size(); ++v) {
            for_each_tile(v, [&](std::size_t t) { ++tile_offsets_[t + 1]; });
        }
        for (std::size_t t = 0; t < tiles_.size(); ++t) tile_offsets_[t + 1] += tile_offsets_[t];
        tile_volumes_.resize(tile_offsets_.back());
        std::vector<std::size_t> fill(tile_offsets_.begin(), tile_offsets_.end() - 1);
        for (std::size_t v = 0; v < volumes_.size(); ++v) {
            for_each_tile(v, [&](std::size_t t) { tile_volumes_[fill[t]++] = v; });
        }
    }

    void process_tile(std::size_t t, std::vector<Interval>& removed,
                      std::vector<Interval>& scratch) {
        const Tile& tile = tiles_[t];
        const GridSpec& spec = grid_.spec;
        const int a = tile.axis;
        const int nb = spec.counts[(a + 1) % 3];
        const int nc = spec.counts[(a + 2) % 3];
        std::vector<RayIntervals>& rays = grid_.rays[a];
        for (std::size_t k = tile_offsets_[t]; k < tile_offsets_[t + 1]; ++k) {
            const std::size_t v = tile_volumes_[k];
            const RayRange& r = ranges_[3 * v + a];
            const int c_end = std::min({r.c1, tile.c0 + kTileSide - 1, nc - 1});
            const int b_end = std::min({r.b1, tile.b0 + kTileSide - 1, nb - 1});
            for (int c = std::max(r.c0, tile.c0); c <= c_end; ++c) {
                for (int b = std::max(r.b0, tile.b0); b <= b_end; ++b) {
                    const std::size_t index =
                        static_cast<std::size_t>(b) + static_cast<std::size_t>(nb) * c;
                    RayIntervals& solid = rays[index];
                    // Most rays a volume's box reaches hold no material there (air above the
                    // stock, a pocket already cut): skip them before the exact intersection.
                    if (solid.empty() || solid.back().exit.t < r.t0 ||
                        solid.front().enter.t > r.t1) {
                        continue;
                    }
                    removed.clear();
                    volumes_[v]->intersect(spec.ray(a, index), removed);
                    if (!removed.empty()) subtract_intervals(solid, removed, scratch);
                }
            }
        }
    }

    DexelGrid& grid_;
    std::span<const Solid* const> volumes_;
    std::vector<Tile> tiles_;
    std::vector<RayRange> ranges_;           // per volume, per family
    std::vector<std::size_t> tile_offsets_;  // CSR over tiles_
    std::vector<std::size_t> tile_volumes_;
};

}  // namespace

DexelGrid sample_solid(const GridSpec& spec, const Solid& solid) {
    DexelGrid grid;
    grid.spec = spec;
    const Box3 bounds = solid.bounds();
    for (int a = 0; a < 3; ++a) {
        grid.rays[a].resize(spec.ray_count(a));
        const RayRange range = rays_reached(spec, a, bounds);
        if (range.empty()) continue;
        const int nb = spec.counts[(a + 1) % 3];
        tbb::parallel_for(range.c0, range.c1 + 1, [&](int c) {
            std::vector<Interval> found;
            for (int b = range.b0; b <= range.b1; ++b) {
                const std::size_t index =
                    static_cast<std::size_t>(b) + static_cast<std::size_t>(nb) * c;
                found.clear();
                solid.intersect(spec.ray(a, index), found);
                grid.rays[a][index].assign(found.data(), found.data() + found.size());
            }
        });
    }
    return grid;
}

void subtract(DexelGrid& grid, const Solid& volume) {
    const Solid* volumes[] = {&volume};
    subtract_in_order(grid, volumes);
}

void subtract_in_order(DexelGrid& grid, std::span<const Solid* const> volumes,
                       const std::function<void(std::size_t, std::size_t)>& on_progress) {
    OrderedSubtraction(grid, volumes).run(on_progress);
}

}  // namespace resharp::sim
