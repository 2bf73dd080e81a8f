#pragma once
/// Output files that appear whole or not at all.

#include <filesystem>
#include <fstream>
#include <ostream>

namespace resharp::io {

/// A file written so that a failed or interrupted run never leaves a partial file: bytes go to
/// a temporary file beside the target (same directory, so the final rename is atomic), and
/// commit() renames it over the target. Destroyed without a successful commit(), for instance
/// while an exception unwinds, it removes the temporary and leaves any existing target as it
/// was. Guards against failed runs and concurrent readers, not power loss (no fsync).
///
///     AtomicFile file(path);
///     file.stream() << report;
///     file.commit();
class AtomicFile {
public:
    /// Creates the temporary file `.NAME.tmp-XXXXXXXX` beside `target`.
    /// \throws WriteError naming `target` if it cannot be created (missing or read-only
    /// directory).
    explicit AtomicFile(std::filesystem::path target);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// The stream to write to, in binary mode.
    std::ostream& stream() { return stream_; }

    /// Flushes and closes the stream, checks that every write succeeded, and renames the
    /// temporary file over the target.
    /// \throws WriteError naming the target if any step fails; the temporary is then removed.
    void commit();

    const std::filesystem::path& target() const { return target_; }
    const std::filesystem::path& temporary_path() const { return temporary_; }

private:
    [[noreturn]] void fail(const std::string& reason);
    void discard() noexcept;

    std::filesystem::path target_;
    std::filesystem::path temporary_;
    std::ofstream stream_;
    bool is_done_ = false;  ///< committed or discarded: nothing left to clean up
};

/// Writes `target` atomically: calls `write(std::ostream&)`, then commits. If `write` throws, no
/// file is created and the exception propagates.
/// \throws WriteError as AtomicFile, or whatever `write` throws.
template <class WriteFunction>
void write_atomically(const std::filesystem::path& target, WriteFunction&& write) {
    AtomicFile file(target);
    write(file.stream());
    file.commit();
}

}  // namespace resharp::io
