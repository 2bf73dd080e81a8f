#include "batch.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "commands.h"
#include "exit_status.h"
#include "malloc_tuning.h"
#include "resharp/core/errors.h"
#include "resharp/io/format.h"

namespace resharp::cli {
namespace {

namespace fs = std::filesystem;

/// One file of the batch.
struct Item {
    fs::path input;     ///< as the command line names it, or under the folder it names
    fs::path relative;  ///< its name under the output folders
};

struct ItemResult {
    Failure failure;  ///< code 0: restored
    RestoreReport report;
    double seconds = 0;
};

/// The mesh files in `folder` (and its subfolders when `recursive`), sorted by path so the
/// order does not depend on the file system. Symbolic links to folders are not followed, so the
/// walk ends.
std::vector<Item> files_in(const fs::path& folder, bool recursive) {
    std::vector<fs::path> found;
    auto take = [&](const fs::directory_entry& entry) {
        if (entry.is_regular_file() && io::format_from_path(entry.path()))
            found.push_back(entry.path());
    };
    if (recursive) {
        for (const auto& entry : fs::recursive_directory_iterator(folder)) take(entry);
    } else {
        for (const auto& entry : fs::directory_iterator(folder)) take(entry);
    }
    std::sort(found.begin(), found.end());
    std::vector<Item> items;
    for (const fs::path& path : found) items.push_back({path, path.lexically_relative(folder)});
    return items;
}

bool same_or_inside(const fs::path& inner, const fs::path& outer) {
    const fs::path relative = fs::weakly_canonical(inner).lexically_relative(fs::canonical(outer));
    return !relative.empty() && *relative.begin() != "..";
}

/// The items in command-line order; refuses an output folder equal to an input folder (or, with
/// --recursive, inside it, where the next run would restore the outputs again).
std::vector<Item> collect(const std::vector<std::string>& inputs, const fs::path& output,
                          bool recursive) {
    std::vector<Item> items;
    for (const std::string& input : inputs) {
        if (!fs::is_directory(input)) {
            items.push_back({input, fs::path(input).filename()});
            continue;
        }
        if (fs::weakly_canonical(output) == fs::canonical(input) ||
            (recursive && same_or_inside(output, input))) {
            throw CLI::ValidationError(
                "--output", "the output folder " + output.string() + " is the input folder " +
                                input + (recursive ? " or inside it" : "") + ": choose another");
        }
        const std::vector<Item> found = files_in(input, recursive);
        items.insert(items.end(), found.begin(), found.end());
    }
    if (items.empty()) {
        throw InvalidInput("no .stl, .obj, .ply or .off file in the inputs given to restore");
    }
    return items;
}

/// Where the item's files go: the mesh keeps its name, the extras take NAME.json,
/// NAME.segments.ply and NAME.html (NAME without the mesh extension).
RestoreTargets targets_for(const Item& item, const RestoreTargets& folders) {
    auto beside = [&](const std::string& folder, const std::string& suffix) {
        if (folder.empty()) return std::string();
        fs::path name = item.relative;
        name.replace_extension();
        return (fs::path(folder) / name).string() + suffix;
    };
    return {.input = item.input.string(),
            .output = (fs::path(folders.output) / item.relative).string(),
            .report = beside(folders.report, ".json"),
            .segments = beside(folders.segments, ".segments.ply"),
            .html = beside(folders.html, ".html")};
}

/// Refuses two items writing one file, or an item writing over an input; makes the folders the
/// outputs go to (before any work, so each item's files appear whole or not at all).
void prepare_outputs(const std::vector<Item>& items, const std::vector<RestoreTargets>& targets) {
    std::map<fs::path, std::string> writer;  // output path -> the input it comes from
    for (const Item& item : items) writer.emplace(fs::weakly_canonical(item.input), "");
    for (std::size_t i = 0; i < items.size(); ++i) {
        for (const std::string* path :
             {&targets[i].output, &targets[i].report, &targets[i].segments, &targets[i].html}) {
            if (path->empty()) continue;
            const auto [at, is_new] =
                writer.emplace(fs::weakly_canonical(*path), items[i].input.string());
            if (is_new) continue;
            throw CLI::ValidationError(
                "--output", *path + " would be written for " + items[i].input.string() +
                                (at->second.empty() ? " over an input" : " and for " + at->second));
        }
    }
    for (const auto& [path, input] : writer) {
        if (input.empty()) continue;
        std::error_code error;
        fs::create_directories(path.parent_path(), error);
        if (error) throw WriteError(path.parent_path().string(), error.message());
    }
}

/// A bar on stderr, redrawn as files finish, when stderr is a terminal.
class Progress {
public:
    Progress(std::size_t total, bool is_shown) : total_(total), is_shown_(is_shown) { draw(); }
    void finished(bool is_failure) {
        const std::lock_guard lock(mutex_);
        ++done_;
        if (is_failure) ++failed_;
        draw();
    }
    void clear() const {
        if (is_shown_) std::fputs("\r\033[K", stderr);
    }

private:
    void draw() const {
        if (!is_shown_) return;
        constexpr std::size_t kWidth = 30;
        const std::size_t filled = done_ * kWidth / total_;
        std::fprintf(stderr, "\rresharp: [%s%s] %zu/%zu files, %zu failed",
                     std::string(filled, '#').c_str(), std::string(kWidth - filled, '.').c_str(),
                     done_, total_, failed_);
        std::fflush(stderr);
    }

    std::mutex mutex_;
    std::size_t total_;
    std::size_t done_ = 0;
    std::size_t failed_ = 0;
    bool is_shown_;
};

ItemResult restore_item(const RestoreTargets& targets, const RestoreOptions& options,
                        io::Encoding encoding) {
    const auto start = std::chrono::steady_clock::now();
    ItemResult result;
    try {
        result.report = restore_file(targets, options, encoding);
    } catch (...) {
        result.failure = current_failure();
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

/// The summary: one row per file in input order (file, triangles in, points inserted, time,
/// status), then the totals.
std::string summary_table(const std::vector<Item>& items, const std::vector<ItemResult>& results) {
    std::size_t width = 4;
    for (const Item& item : items) width = std::max(width, item.input.string().size());
    std::ostringstream table;
    table << std::left << std::setw(int(width)) << "file" << std::right << std::setw(11)
          << "triangles" << std::setw(9) << "points" << std::setw(9) << "time s"
          << "  status\n";
    std::size_t failed = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const ItemResult& r = results[i];
        table << std::left << std::setw(int(width)) << items[i].input.string() << std::right;
        if (r.failure.code == 0) {
            table << std::setw(11) << r.report.input_triangles << std::setw(9)
                  << r.report.edge_points_inserted + r.report.corner_points_inserted;
        } else {
            table << std::setw(11) << "-" << std::setw(9) << "-";
            ++failed;
        }
        table << std::setw(9) << std::fixed << std::setprecision(2) << r.seconds << "  "
              << (r.failure.code == 0 ? "ok"
                                      : "failed (exit " + std::to_string(r.failure.code) +
                                            "): " + r.failure.message)
              << "\n";
    }
    table << "resharp: " << items.size() << " files: " << items.size() - failed << " restored, "
          << failed << " failed\n";
    return table.str();
}

}  // namespace

void add_batch_options(CLI::App& command, BatchSettings& settings) {
    command
        .add_option("-j,--jobs", settings.jobs,
                    "batch: files restored at once, one thread each; 0 for all cores")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    command.add_flag("-r,--recursive", settings.recursive,
                     "batch: also restore the files in subfolders of a folder input");
}

bool is_batch(const std::vector<std::string>& inputs, const std::string& output) {
    return inputs.size() > 1 || fs::is_directory(inputs.front()) || output.ends_with('/') ||
           fs::is_directory(output);
}

void check_single_file(const CLI::App& command) {
    for (const char* flag : {"--jobs", "--recursive"}) {
        if (command.count(flag) > 0) {
            throw CLI::ValidationError(flag,
                                       "applies to a batch only (several inputs, a folder, or an "
                                       "output folder)");
        }
    }
}

void run_batch(const std::vector<std::string>& inputs, const RestoreTargets& folders,
               const BatchSettings& settings, RestoreOptions options, io::Encoding encoding,
               const CLI::App& command) {
    if (command.count("--threads") > 0) {
        throw CLI::ValidationError("--threads",
                                   "a batch restores each file on one thread: use --jobs");
    }
    const std::vector<Item> items = collect(inputs, folders.output, settings.recursive);
    std::vector<RestoreTargets> targets;
    for (const Item& item : items) targets.push_back(targets_for(item, folders));
    prepare_outputs(items, targets);

    options.threads = 1;
    const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t workers =
        std::min(items.size(), settings.jobs > 0 ? std::size_t(settings.jobs) : cores);
    tune_malloc(workers);
    std::vector<ItemResult> results(items.size());
    Progress progress(items.size(), !settings.quiet && ::isatty(STDERR_FILENO));
    std::atomic<std::size_t> next{0};
    auto work = [&] {  // each worker takes the next item until all are taken
        for (std::size_t i = next++; i < items.size(); i = next++) {
            results[i] = restore_item(targets[i], options, encoding);
            progress.finished(results[i].failure.code != 0);
        }
    };
    {
        std::vector<std::jthread> threads;
        for (std::size_t w = 1; w < workers; ++w) threads.emplace_back(work);
        work();
    }  // joins
    progress.clear();

    int worst = kSuccess;
    for (const ItemResult& r : results) {
        worst = std::max(worst, r.failure.code);
        if (settings.quiet && r.failure.code != 0)
            std::cerr << "resharp: error: " << r.failure.message << "\n";
    }
    if (!settings.quiet) std::cerr << summary_table(items, results);
    if (worst != kSuccess) throw ExitWith{worst};
}

}  // namespace resharp::cli
