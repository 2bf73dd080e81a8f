#include <memory>
#include <optional>
#include <string>

#include "commands.h"
#include "report_json.h"
#include "resharp/core/errors.h"
#include "resharp/io/mesh_io.h"
#include "resharp/pipeline/restore.h"
#include "segments.h"
#include "viewer/page.h"

namespace resharp::cli {
namespace {

struct ViewArguments {
    std::string input;
    std::string restored;
    std::string segments;
    std::string output;
};

nlohmann::json mesh_numbers(const Mesh& mesh) {
    return {{"vertices", mesh.vertex_count()}, {"triangles", mesh.face_count()}};
}

void run_view(const ViewArguments& args) {
    if (!args.segments.empty() && io::format_from_path(args.segments) != io::MeshFormat::Ply) {
        throw ReadError(args.segments,
                        "segments are read from PLY: use the .ply file that "
                        "resharp restore --segments wrote");
    }
    const Mesh input = weld(io::read_mesh(args.input));
    std::optional<RestoreResult> result;
    Mesh restored;
    nlohmann::json numbers;
    if (args.restored.empty()) {  // restore here with the default options
        result = restore(input, {.keep_segmentation = true});
        numbers = report_to_json(result->report);
    } else {
        restored = weld(io::read_mesh(args.restored));
        numbers = {{"input", mesh_numbers(input)}, {"restored", mesh_numbers(restored)}};
    }
    std::optional<SegmentLayers> layers;
    if (!args.segments.empty())
        layers = read_segment_layers(args.segments, input);
    else if (result)
        layers = segment_layers(result->segmentation);

    io::write_atomically(args.output, [&](std::ostream& out) {
        viewer::write_page(out, {.title = args.input,
                                 .input = &input,
                                 .restored = result ? &result->mesh : &restored,
                                 .segments = layers ? &*layers : nullptr,
                                 .numbers = numbers});
    });
}

}  // namespace

void add_view_command(CLI::App& app) {
    auto args = std::make_shared<ViewArguments>();
    CLI::App* command = app.add_subcommand(
        "view",
        "Write one self-contained HTML page showing a mesh before and after restoration side by "
        "side (linked cameras: drag to orbit, right-drag to pan, wheel to zoom), the restored "
        "sharp edges as lines, what was detected as colours to toggle, a wireframe and the "
        "report's numbers. Opens in any browser with WebGL, with no network.");
    command->add_option("input", args->input, "the mesh as it went in")->required();
    command->add_option("restored", args->restored,
                        "the restored mesh; if left out, the input is restored here with the "
                        "default options, and its report and segmentation are shown");
    command->add_option("--segments", args->segments,
                        "colour the input with the segmentation of 'resharp restore --segments' "
                        "(a PLY file of the same input)");
    command->add_option("-o,--output", args->output, "the page to write (.html)")->required();
    command->callback([args] { run_view(*args); });
}

}  // namespace resharp::cli
