#pragma once
/// The exceptions resharp throws. Input problems are always reported by exception, never by
/// assert; asserts (core/assert.h) guard internal invariants only.

#include <cstdint>
#include <stdexcept>
#include <string>

namespace resharp {

/// Base of every resharp exception.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The mesh or the options cannot be processed (empty mesh, NaN coordinate, bad option value).
class InvalidInput : public Error {
public:
    using Error::Error;
};

/// restore() was asked to stop (RestoreOptions::stop). restore() itself never lets it out: it
/// returns the input unchanged; the lower-level stage sequences (pipeline/restore.h) throw it.
class Cancelled : public Error {
public:
    using Error::Error;
};

/// A file could not be opened, read or written. what() starts with the path.
/// Readers throw ReadError or ParseError, writers WriteError.
class IoError : public Error {
public:
    IoError(std::string path, const std::string& reason);
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

/// An input file could not be opened or read (missing, unreadable, unknown format, empty).
class ReadError : public IoError {
public:
    using IoError::IoError;
};

/// An output file could not be written or moved into place.
class WriteError : public IoError {
public:
    using IoError::IoError;
};

/// Where in a file a parse error was found.
struct FileLocation {
    enum class Kind { Line, Byte };
    Kind kind = Kind::Line;
    std::uint64_t value = 0;  ///< 1-based line number, or 0-based byte offset

    static FileLocation line(std::uint64_t number) { return {Kind::Line, number}; }
    static FileLocation byte(std::uint64_t offset) { return {Kind::Byte, offset}; }
};

/// A file is malformed. what() reads "PATH: line N: REASON" or "PATH: byte N: REASON".
class ParseError : public ReadError {
public:
    ParseError(std::string path, FileLocation location, const std::string& reason);
    FileLocation location() const { return location_; }

private:
    FileLocation location_;
};

}  // namespace resharp
