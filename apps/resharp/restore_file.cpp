#include "restore_file.h"

#include <optional>

#include "report_json.h"
#include "resharp/core/errors.h"
#include "resharp/io/atomic_file.h"
#include "resharp/io/mesh_io.h"
#include "resharp/pipeline/restore.h"
#include "segments.h"
#ifdef RESHARP_HAS_VIEWER
#include "viewer/page.h"
#endif

namespace resharp::cli {
namespace {

/// The output files, opened before the work starts (a bad path fails at once) and committed
/// together at the end: a run that fails anywhere leaves none of them.
struct Outputs {
    io::AtomicFile mesh;
    std::optional<io::AtomicFile> segments;
    std::optional<io::AtomicFile> report;
    std::optional<io::AtomicFile> html;

    explicit Outputs(const RestoreTargets& targets) : mesh(checked(targets.output)) {
        if (!targets.segments.empty()) {
            if (io::format_for_writing(targets.segments) != io::MeshFormat::Ply) {
                throw WriteError(targets.segments,
                                 "segments are written as vertex and face "
                                 "colours, which only PLY stores: use .ply");
            }
            segments.emplace(targets.segments);
        }
        if (!targets.report.empty()) report.emplace(targets.report);
        if (!targets.html.empty()) html.emplace(targets.html);
    }
    void commit_all() {
        mesh.commit();
        if (segments) segments->commit();
        if (report) report->commit();
        if (html) html->commit();
    }

private:
    static const std::string& checked(const std::string& path) {
        io::format_for_writing(path);
        return path;
    }
};

void write_html(io::AtomicFile& file, const std::string& title, const Mesh& input,
                const RestoreResult& result) {
#ifdef RESHARP_HAS_VIEWER
    const SegmentLayers layers = segment_layers(result.segmentation);
    viewer::write_page(file.stream(), {.title = title,
                                       .input = &input,
                                       .restored = &result.mesh,
                                       .segments = &layers,
                                       .numbers = report_to_json(result.report)});
#else
    (void)title, (void)input, (void)result;
    throw WriteError(file.target().string(), "this resharp was built without the viewer");
#endif
}

}  // namespace

RestoreReport restore_file(const RestoreTargets& targets, RestoreOptions options,
                           io::Encoding encoding) {
    Mesh input = weld(io::read_mesh(targets.input));
    Outputs outputs(targets);
    // The segments file and the page show the input beside the result; else restore() may
    // take it (peak memory).
    const bool input_read_after = outputs.segments.has_value() || outputs.html.has_value();
    options.keep_segmentation = input_read_after;
    const RestoreResult result =
        input_read_after ? restore(input, options) : restore(std::move(input), options);

    const io::WriteOptions write_options{.encoding = encoding};
    io::write_mesh(outputs.mesh, result.mesh, write_options);
    if (outputs.segments) {
        const SegmentColors colors = color_segments(segment_layers(result.segmentation));
        io::write_mesh(*outputs.segments, input, write_options,
                       {.vertex_colors = colors.vertex, .face_colors = colors.face});
    }
    if (outputs.report) outputs.report->stream() << report_to_json(result.report).dump(2) << "\n";
    if (outputs.html) write_html(*outputs.html, targets.input, input, result);
    outputs.commit_all();
    return result.report;
}

}  // namespace resharp::cli
