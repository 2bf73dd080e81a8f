#pragma once
/// `resharp restore` on many files: `restore A.stl B.stl ... -o OUTDIR/` and
/// `restore INDIR/ -o OUTDIR/`. Every file goes through restore_file(), several at once.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "restore_file.h"

namespace resharp::cli {

/// What only a batch uses.
struct BatchSettings {
    int jobs = 0;            ///< files restored at once, one thread each; 0 for all cores
    bool recursive = false;  ///< also restore the files in subfolders of a folder input
    bool quiet = false;      ///< no summary (a batch still prints each failure)
};

/// The batch form, for `resharp restore --help`.
inline constexpr const char* kBatchHelp =
    "Batch: 'resharp restore A.stl B.obj ... -o OUTDIR/' or 'resharp restore INDIR/ -o OUTDIR/' "
    "restores every .stl, .obj, .ply and .off file named or in the folder (extensions in any "
    "letter case; --recursive descends into subfolders), --jobs at once with one thread each. "
    "Each output keeps its input's name and subfolder under OUTDIR; --report, --segments and "
    "--html (in builds with the viewer) then name folders too and receive NAME.json, "
    "NAME.segments.ply and NAME.html. An output folder equal to an input folder is refused. A "
    "file that fails is reported with its reason, nothing is written for it, and the batch goes "
    "on; a table in input order ends the run, and the exit code is the worst of the files' (2 if "
    "any input was bad).";

/// Adds --jobs and --recursive.
void add_batch_options(CLI::App& command, BatchSettings& settings);

/// Whether the command line asks for a batch: several inputs, a folder among them, or an output
/// that names a folder (ends in '/' or is an existing folder).
bool is_batch(const std::vector<std::string>& inputs, const std::string& output);

/// Refuses the batch-only flags on the single-file form. \throws CLI::ValidationError
void check_single_file(const CLI::App& command);

/// Restores every mesh file `inputs` names into the folder `folders.output` (the other fields of
/// `folders`, if set, name the folders of the reports, segments and pages), with
/// `options.threads` = 1 per file. Prints a progress bar while stderr is a terminal and a
/// summary table at the end. Returns if every file was restored.
/// \throws CLI::ValidationError for a command line it refuses (output folder equal to an input
/// folder, two inputs with one output, --threads); InvalidInput if the inputs hold no mesh
/// file; WriteError if an output folder cannot be made; ExitWith the worst file's exit code
/// after the summary if any file failed.
void run_batch(const std::vector<std::string>& inputs, const RestoreTargets& folders,
               const BatchSettings& settings, RestoreOptions options, io::Encoding encoding,
               const CLI::App& command);

}  // namespace resharp::cli
