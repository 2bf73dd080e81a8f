#include <charconv>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "batch.h"
#include "commands.h"
#include "malloc_tuning.h"
#include "report_json.h"
#include "resharp/core/errors.h"
#include "resharp/pipeline/option_table.h"
#include "restore_file.h"

namespace resharp::cli {
namespace {

struct RestoreArguments {
    std::vector<std::string> inputs;
    RestoreTargets targets;  ///< input unset; folders in a batch
    BatchSettings batch;
    bool ascii = false;
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
                std::string flags = "--" + std::string(info.name);
                if (!info.cli_alias.empty()) flags += ",--" + std::string(info.cli_alias);
                return add_table_option(command, flags, std::string(info.help), f, o);
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

/// --grid PITCH[,X,Y,Z] into `vertices`: the grid's pitch and, where given, its origin.
void bind_grid_option(CLI::App& command, VertexOptions& vertices) {
    auto parse = [&vertices](const std::string& text) {
        std::vector<double> numbers;
        const char* at = text.data();
        const char* const end = text.data() + text.size();
        // Bound: each pass reads at least one character or throws.
        while (at < end) {
            double x = 0.0;
            const auto [next, error] = std::from_chars(at, end, x);
            if (error != std::errc() || !std::isfinite(x) || (next != end && *next != ','))
                throw CLI::ValidationError("--grid", "not a number list: '" + text + "'");
            numbers.push_back(x);
            at = next == end ? end : next + 1;
        }
        try {
            set_grid(vertices, numbers);
        } catch (const InvalidInput& e) {
            throw CLI::ValidationError("--grid", std::string(e.what()) + ": '" + text + "'");
        }
    };
    command
        .add_option_function<std::string>("--" + std::string(kGridOptionName), parse,
                                          std::string(kGridOptionHelp))
        ->group(kMethodGroup);
}

void run_restore(const RestoreArguments& args, const CLI::App& command) {
    const RestoreOptions options = args.paper ? paper_variant(args.options) : args.options;
    const io::Encoding encoding = args.ascii ? io::Encoding::Ascii : io::Encoding::Binary;
    if (is_batch(args.inputs, args.targets.output)) {
        run_batch(args.inputs, args.targets, args.batch, options, encoding, command);
        return;
    }
    check_single_file(command);
    tune_malloc(1);
    RestoreTargets targets = args.targets;
    targets.input = args.inputs.front();
    const RestoreReport report = restore_file(targets, options, encoding);
    if (!args.batch.quiet) std::cerr << summarize(report, targets.input, targets.output);
}

}  // namespace

void add_restore_command(CLI::App& app) {
    auto args = std::make_shared<RestoreArguments>();
    CLI::App* command = app.add_subcommand(
        "restore",
        "Restore sharp edges and corners of a mesh made by grid-based machining "
        "simulation. Formats from the extension: .stl (binary or ASCII), .obj, .ply, "
        ".off.");
    command->footer(std::string(kBatchHelp) + "\n\n" + app.get_footer());
    command->add_option("input", args->inputs, "mesh to restore; several, or folders: a batch")
        ->required();
    command->add_option("-o,--output", args->targets.output, "restored mesh; a folder in a batch")
        ->required();
    command->add_option("--report", args->targets.report,
                        "write every count and stage time as JSON (a folder in a batch)");
    command->add_option("--segments", args->targets.segments,
                        "write the input as PLY with vertex colours (red: edge vertices) and face "
                        "colours (one per feature patch; yellow: edge triangles; magenta: corner "
                        "triangles); a folder in a batch");
#ifdef RESHARP_HAS_VIEWER
    command->add_option("--html", args->targets.html,
                        "write the viewer page: input and restored mesh side by side (a folder "
                        "in a batch)");
#endif
    command->add_flag("--ascii", args->ascii, "write STL and PLY as text instead of binary");
    command->add_flag("-q,--quiet", args->batch.quiet,
                      "print no summary (a batch still prints each failure)");
    add_batch_options(*command, args->batch);
    bind_options(*command, args->options, args->paper);
    bind_grid_option(*command, args->options.vertices);
    command->callback([args, command] { run_restore(*args, *command); });
}

}  // namespace resharp::cli
