#pragma once
/// The restore options by name, as the command line (`resharp restore --region-angle 8`) and the
/// Python module (`resharp.restore(V, F, region_angle=8)`) offer them: one entry per settable
/// field of RestoreOptions with its name and help text, written here once. A field added to
/// RestoreOptions is offered by both once it has an entry here.

#include <cstddef>
#include <span>
#include <string_view>
#include <utility>
#include <variant>

#include "resharp/pipeline/options.h"

namespace resharp {

/// A numeric field of RestoreOptions, reached through `field`.
template <class T>
struct ValueField {
    T& (*field)(RestoreOptions&);
};

/// A boolean field that giving the option sets to `when_given` (false for "no-..." options);
/// its default is the other value.
struct FlagField {
    bool& (*field)(RestoreOptions&);
    bool when_given = true;
};

/// An enumerated field, named by one of `choices` (lower case).
template <class E>
struct ChoiceField {
    E& (*field)(RestoreOptions&);
    std::span<const std::pair<std::string_view, E>> choices;
};

using OptionField =
    std::variant<ValueField<double>, ValueField<int>, ValueField<std::size_t>, FlagField,
                 ChoiceField<CurvatureFeature>, ChoiceField<NormalEstimate>,
                 ChoiceField<PointPlacement>, ChoiceField<VertexMode>>;

struct OptionInfo {
    /// The flag without its dashes ("region-angle"); Python writes '_' for '-' (region_angle).
    std::string_view name;
    std::string_view help;  ///< the --help text and the Python docstring
    OptionField field;
    /// paper_variant() sets this field, so the option and the paper's choices exclude each other.
    bool paper_choice = false;
    /// A second flag for the command line where the name a user looks for there clashes with
    /// Python's arguments ("vertices": restore(vertices, faces)); empty for none.
    std::string_view cli_alias = {};
};

/// Every option, in the order `resharp restore --help` lists them. Static storage.
std::span<const OptionInfo> restore_option_table();

/// The name and help of the switch that applies paper_variant() to the options.
inline constexpr std::string_view kPaperOptionName = "paper";
inline constexpr std::string_view kPaperOptionHelp =
    "the paper's choice wherever resharp makes another (docs/method.md): signed k-means, "
    "unlimited region growing, plain merging, borders confirmed by edge vertices only, eq. 5.1 "
    "normals, points on tangent planes (eq. 5.2 / 5.3)";

/// The name and help of the grid option (VertexOptions::grid): `--grid PITCH[,X,Y,Z]` on the
/// command line, `grid=pitch` or `grid=(pitch, x, y, z)` in Python; see set_grid().
inline constexpr std::string_view kGridOptionName = "grid";
inline constexpr std::string_view kGridOptionHelp =
    "the grid the mesher worked on: its pitch, or its pitch and a grid point x, y, z (mm); "
    "without it, inferred from the mesh. It bounds how far the near and midpoint vertex "
    "placements move a vertex";

/// The name of `value` among `field`'s choices.
template <class E>
std::string_view choice_name(const ChoiceField<E>& field, E value) {
    for (const auto& [name, choice] : field.choices) {
        if (choice == value) return name;
    }
    return {};
}

}  // namespace resharp
