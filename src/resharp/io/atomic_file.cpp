#include "resharp/io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "resharp/core/errors.h"

namespace resharp::io {
namespace {

// ".NAME.tmp-" and 16 random hex digits. Built with append: GCC 12 warns falsely (-Wrestrict)
// on chains of operator+ with literals.
std::string temporary_name(const std::filesystem::path& target) {
    thread_local std::mt19937_64 engine{std::random_device{}()};
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(engine()));
    std::string name(1, '.');
    name.append(target.filename().string()).append(".tmp-").append(hex);
    return name;
}

// Reserves a fresh name beside `target` with O_EXCL, so two writers never share a temporary.
std::filesystem::path create_temporary(const std::filesystem::path& target) {
    const std::filesystem::path directory = target.parent_path();
    int error = 0;
    for (int attempt = 0; attempt < 16; ++attempt) {
        const std::filesystem::path candidate = directory / temporary_name(target);
        const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return candidate;
        }
        error = errno;
        if (error != EEXIST) break;
    }
    throw WriteError(target.string(), std::string("cannot create a temporary file beside it: ") +
                                          std::strerror(error));
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(std::move(target)), temporary_(create_temporary(target_)) {
    stream_.open(temporary_, std::ios::binary | std::ios::trunc);
    if (!stream_) fail("cannot open the temporary file " + temporary_.string());
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::discard() noexcept {
    if (is_done_) return;
    is_done_ = true;
    stream_.close();
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
}

void AtomicFile::fail(const std::string& reason) {
    discard();
    throw WriteError(target_.string(), reason);
}

void AtomicFile::commit() {
    if (is_done_) throw WriteError(target_.string(), "file already committed or discarded");
    stream_.flush();
    if (!stream_) fail("write failed (disk full?)");
    stream_.close();
    if (stream_.fail()) fail("closing the file failed (disk full?)");
    std::error_code ec;
    std::filesystem::rename(temporary_, target_, ec);
    if (ec) fail("cannot move the temporary file into place: " + ec.message());
    is_done_ = true;
}

}  // namespace resharp::io
