#pragma once
/// One file through `resharp restore`: read, restore, write every output. The single-file form
/// and each item of a batch call this same function.

#include <string>

#include "resharp/io/format.h"
#include "resharp/pipeline/options.h"
#include "resharp/pipeline/report.h"

namespace resharp::cli {

/// The files one restore reads and writes; an empty path is not written.
struct RestoreTargets {
    std::string input;     ///< mesh to restore
    std::string output;    ///< restored mesh (format from its extension)
    std::string report;    ///< every count and stage time as JSON
    std::string segments;  ///< the segmentation as PLY colours (must end in .ply)
    std::string html;      ///< the viewer page (builds with the viewer only)
};

/// Reads `targets.input`, restores it with `options` (keep_segmentation is set as the targets
/// need) and writes the outputs in `encoding`, each through an atomic file, committed together:
/// on any failure none of them is left. Gives the report.
/// \throws ReadError, ParseError or InvalidInput for bad input, WriteError for an output that
/// cannot be written (an output path with an unknown extension fails before any work).
RestoreReport restore_file(const RestoreTargets& targets, RestoreOptions options,
                           io::Encoding encoding);

}  // namespace resharp::cli
