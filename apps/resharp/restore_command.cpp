#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "commands.h"
#include "report_json.h"
#include "resharp/core/errors.h"
#include "resharp/io/atomic_file.h"
#include "resharp/io/mesh_io.h"
#include "resharp/pipeline/option_table.h"
#include "resharp/pipeline/restore.h"
#include "segments.h"

namespace resharp::cli {
namespace {

struct RestoreArguments {
    std::string input;
    std::string output;
    std::string report;
    std::string segments;
    bool ascii = false;
    bool quiet = false;
    bool paper = false;
    RestoreOptions options;
};

/// The --help group of the method's options (pipeline/option_table.h), apart from the files
/// and the run's own flags.
constexpr const char* kMethodGroup = "Method options";

CLI::Option* add_table_option(CLI::App& command, const std::string& flag, const std::string& help,
                              const FlagField& f, RestoreOptions& o) {
    return command.add_flag(f.when_given ? flag : "!" + flag, f.field(o), help);
}

template <class T>
CLI::Option* add_table_option(CLI::App& command, const std::string& flag, const std::string& help,
                              const ValueField<T>& f, RestoreOptions& o) {
    return command.add_option(flag, f.field(o), help)->capture_default_str();
}

template <class E>
CLI::Option* add_table_option(CLI::App& command, const std::string& flag, const std::string& help,
                              const ChoiceField<E>& f, RestoreOptions& o) {
    std::map<std::string, E> names;
    std::string text;
    for (const auto& [name, value] : f.choices) {
        names.emplace(name, value);
        text += (text.empty() ? "{" : ",") + std::string(name);
    }
    E& field = f.field(o);
    text += "}=" + std::string(choice_name(f, field));
    return command.add_option(flag, field, help)
        ->transform(CLI::CheckedTransformer(names, CLI::ignore_case))
        ->option_text(text);
}

/// One flag per entry of the option table, bound to its field, so that --help shows the
/// struct's own defaults; then --paper, which excludes the options of the paper's choices.
void bind_options(CLI::App& command, RestoreOptions& o, bool& paper) {
    std::vector<CLI::Option*> paper_choices;
    for (const OptionInfo& info : restore_option_table()) {
        CLI::Option* option = std::visit(
            [&](const auto& f) {
                return add_table_option(command, "--" + std::string(info.name),
                                        std::string(info.help), f, o);
            },
            info.field);
        option->group(kMethodGroup);
        if (info.paper_choice) paper_choices.push_back(option);
    }
    CLI::Option* paper_flag = command.add_flag("--" + std::string(kPaperOptionName), paper,
                                               std::string(kPaperOptionHelp));
    paper_flag->group(kMethodGroup);
    for (CLI::Option* choice : paper_choices) paper_flag->excludes(choice);
}

/// The output files, opened before the work starts (a bad path fails at once) and committed
/// together at the end: a run that fails anywhere leaves none of them.
struct Outputs {
    io::AtomicFile mesh;
    std::optional<io::AtomicFile> segments;
    std::optional<io::AtomicFile> report;

    explicit Outputs(const RestoreArguments& args) : mesh(checked(args.output)) {
        if (!args.segments.empty()) {
            if (io::format_for_writing(args.segments) != io::MeshFormat::Ply) {
                throw WriteError(args.segments,
                                 "segments are written as vertex and face "
                                 "colours, which only PLY stores: use .ply");
            }
            segments.emplace(args.segments);
        }
        if (!args.report.empty()) report.emplace(args.report);
    }
    void commit_all() {
        mesh.commit();
        if (segments) segments->commit();
        if (report) report->commit();
    }

private:
    static const std::string& checked(const std::string& path) {
        io::format_for_writing(path);
        return path;
    }
};

void run_restore(const RestoreArguments& args) {
    const Mesh input = weld(io::read_mesh(args.input));
    Outputs outputs(args);
    RestoreOptions options = args.paper ? paper_variant(args.options) : args.options;
    options.keep_segmentation = outputs.segments.has_value();
    const RestoreResult result = restore(input, options);

    const io::WriteOptions encoding{.encoding =
                                        args.ascii ? io::Encoding::Ascii : io::Encoding::Binary};
    io::write_mesh(outputs.mesh, result.mesh, encoding);
    if (outputs.segments) {
        const SegmentColors colors = color_segments(result.segmentation);
        io::write_mesh(*outputs.segments, input, encoding,
                       {.vertex_colors = colors.vertex, .face_colors = colors.face});
    }
    if (outputs.report) outputs.report->stream() << report_to_json(result.report).dump(2) << "\n";
    outputs.commit_all();
    if (!args.quiet) std::cerr << summarize(result.report, args.input, args.output);
}

}  // namespace

void add_restore_command(CLI::App& app) {
    auto args = std::make_shared<RestoreArguments>();
    CLI::App* command = app.add_subcommand(
        "restore",
        "Restore sharp edges and corners of a mesh made by grid-based machining "
        "simulation. Formats from the extension: .stl (binary or ASCII), .obj, .ply, "
        ".off.");
    command->add_option("input", args->input, "mesh to restore")->required();
    command->add_option("-o,--output", args->output, "restored mesh")->required();
    command->add_option("--report", args->report, "write every count and stage time as JSON");
    command->add_option("--segments", args->segments,
                        "write the input as PLY with vertex colours (red: edge vertices) and face "
                        "colours (one per feature patch; yellow: edge triangles; magenta: corner "
                        "triangles)");
    command->add_flag("--ascii", args->ascii, "write STL and PLY as text instead of binary");
    command->add_flag("-q,--quiet", args->quiet, "print no summary");
    bind_options(*command, args->options, args->paper);
    command->callback([args] { run_restore(*args); });
}

}  // namespace resharp::cli
