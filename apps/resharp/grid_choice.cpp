#include "grid_choice.h"

namespace resharp::cli {

void add_grid_options(CLI::App& command, GridChoice& choice, const std::string& fallback) {
    CLI::Option* pitch =
        command
            .add_option("--pitch", choice.pitch, "grid pitch h in mm (default: " + fallback + ")")
            ->check(CLI::PositiveNumber);
    command
        .add_option("--cells", choice.cells,
                    "grid pitch as cells along the longest side of the stock or solid")
        ->check(CLI::PositiveNumber)
        ->excludes(pitch);
}

double resolve_pitch(const GridChoice& choice, const sim::Box3& box, double fallback) {
    if (choice.pitch > 0.0) return choice.pitch;
    if (choice.cells > 0.0) return sim::pitch_for_cells(box, choice.cells);
    return fallback > 0.0 ? fallback : sim::pitch_for_cells(box, kDefaultSolidCells);
}

}  // namespace resharp::cli
