#include "resharp/eval/crease_losses.h"

#include <algorithm>
#include <map>

#include "resharp/core/errors.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/uniform_grid.h"

namespace resharp::eval {
namespace {

bool moved(const Mesh& input, const Mesh& output, Index v) {
    return v < input.vertex_count() && output.positions[v] != input.positions[v];
}

Origin origin_of_corners(const Mesh& input, const Mesh& output, std::span<const Index> corners) {
    bool any_moved = false;
    for (Index v : corners) {
        if (v >= input.vertex_count()) return Origin::Split;
        any_moved = any_moved || moved(input, output, v);
    }
    return any_moved ? Origin::Moves : Origin::Input;
}

/// The band faces of the input near a point, and what became of their points and moves.
class BandNeighbourhood {
public:
    BandNeighbourhood(const Mesh& input, const Mesh& output, const Segmentation& s, double reach)
        : input_(input),
          output_(output),
          s_(s),
          reach_(reach),
          faces_(detail::face_grid(input, reach)) {}

    /// The loss of a missed true piece at p, before asking whether an output crease is near.
    std::pair<CreaseLoss, MoveFate> judge(const Vec3& p) const {
        bool band = false, placed = false, harmed = false, inserted = false;
        bool planned = false, kept = false;
        faces_.for_each_near(p, reach_, [&](Index f) {
            if (s_.face_role[f] == BandRole::None ||
                detail::face_box(input_, f).exteriorDistance(p) > reach_)
                return;
            band = true;
            const PointFate fate = s_.point_fate[f];
            placed = placed || fate != PointFate::NotPlaced;
            harmed = harmed || fate == PointFate::UndoneByHarm;
            inserted = inserted || fate == PointFate::Inserted;
            for (Index v : input_.triangles[f]) {
                planned = planned || (!s_.move_planned.empty() && s_.move_planned[v]);
                kept = kept || moved(input_, output_, v);
            }
        });
        const MoveFate moves = kept ? MoveFate::Kept : planned ? MoveFate::Undone : MoveFate::None;
        const CreaseLoss loss = !band      ? CreaseLoss::NoBand
                                : inserted ? CreaseLoss::InsertedNoCrease
                                : harmed   ? CreaseLoss::UndoneByHarm
                                : placed   ? CreaseLoss::RefusedByGuard
                                           : CreaseLoss::NotPlaced;
        return {loss, moves};
    }

private:
    const Mesh& input_;
    const Mesh& output_;
    const Segmentation& s_;
    double reach_;
    detail::UniformGrid faces_;
};

}  // namespace

std::string_view crease_loss_name(CreaseLoss loss) {
    switch (loss) {
        case CreaseLoss::NoBand:
            return "no_band";
        case CreaseLoss::NotPlaced:
            return "not_placed";
        case CreaseLoss::RefusedByGuard:
            return "refused_by_guard";
        case CreaseLoss::UndoneByHarm:
            return "undone_by_harm_check";
        case CreaseLoss::InsertedNoCrease:
            return "inserted_no_sharp_edge";
        case CreaseLoss::InsertedOff:
            return "inserted_off_by_more_than_tau";
    }
    return "unknown";
}

std::string_view move_fate_name(MoveFate fate) {
    switch (fate) {
        case MoveFate::None:
            return "no_move_planned";
        case MoveFate::Undone:
            return "moves_undone";
        case MoveFate::Kept:
            return "moved";
    }
    return "unknown";
}

std::string_view origin_name(Origin origin) {
    switch (origin) {
        case Origin::Input:
            return "input";
        case Origin::Moves:
            return "moves";
        case Origin::Split:
            return "split";
    }
    return "unknown";
}

Origin face_origin(const Mesh& input, const Mesh& output, const Triangle& face) {
    return origin_of_corners(input, output, face);
}

CreaseLosses find_crease_losses(const Mesh& input, const Mesh& output,
                                const Segmentation& segmentation, const CurveSamples& exact,
                                double pitch, double sharp_angle_deg, double spacing,
                                const CreaseMetricsOptions& options) {
    if (output.vertex_count() < input.vertex_count())
        throw InvalidInput("crease losses: the output has fewer vertices than the input");
    if (segmentation.face_role.size() != input.face_count() ||
        segmentation.point_fate.size() != input.face_count())
        throw InvalidInput("crease losses: face roles and point fates of the input are needed");
    if (!(pitch > 0.0)) throw InvalidInput("crease losses: the pitch must be positive");
    const CurveSamples mesh = sample_mesh_creases(output, sharp_angle_deg, spacing);
    const std::vector<double> from_exact = crease_distances(exact, mesh);
    const std::vector<double> from_mesh = crease_distances(mesh, exact);
    const double tau = options.tolerance * options.unit;
    CreaseLosses losses;
    losses.true_length = exact.total_length() / options.unit;
    losses.mesh_length = mesh.total_length() / options.unit;
    const BandNeighbourhood near(input, output, segmentation, pitch);
    for (std::size_t i = 0; i < exact.size(); ++i) {
        if (from_exact[i] <= tau) continue;
        auto [loss, moves] = near.judge(exact.points[i]);
        if (loss == CreaseLoss::InsertedNoCrease && from_exact[i] <= pitch)
            loss = CreaseLoss::InsertedOff;
        losses.missed[std::size_t(loss)][std::size_t(moves)] += exact.weights[i] / options.unit;
    }
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        if (from_mesh[i] <= tau) continue;
        const Index h = mesh.half_edges[i];
        const std::array<Index, 2> ends{tail_vertex(output, h), head_vertex(output, h)};
        const std::size_t origin = std::size_t(origin_of_corners(input, output, ends));
        (from_mesh[i] <= pitch ? losses.false_beside : losses.false_stray)[origin] +=
            mesh.weights[i] / options.unit;
    }
    return losses;
}

std::array<std::size_t, kOriginCount> flipped_by_origin(
    const Mesh& input, const Mesh& output, std::span<const std::uint8_t> flipped,
    std::span<const std::uint8_t> flipped_in_input) {
    if (flipped.size() != output.face_count() || flipped_in_input.size() != input.face_count())
        throw InvalidInput("flipped by origin: one flag per face is needed");
    std::map<Triangle, Index> input_face;
    for (Index f = 0; f < input.face_count(); ++f) input_face.emplace(input.triangles[f], f);
    std::array<std::size_t, kOriginCount> counts{};
    for (Index f = 0; f < output.face_count(); ++f) {
        if (!flipped[f]) continue;
        const Triangle& t = output.triangles[f];
        Origin origin = face_origin(input, output, t);
        const auto same = input_face.find(t);
        if (origin == Origin::Moves && same != input_face.end() && flipped_in_input[same->second])
            origin = Origin::Input;
        ++counts[std::size_t(origin)];
    }
    return counts;
}

}  // namespace resharp::eval
