#pragma once
/// How a failure maps to an exit code and a message, shared by main() and the batch (which
/// reports each file's failure and goes on).

#include <string>

namespace resharp::cli {

/// An exit code (ExitCode in commands.h) and the message that explains it.
struct Failure {
    int code = 0;
    std::string message;
};

/// The exception being handled, as a Failure: ReadError, ParseError and InvalidInput give
/// kBadInput, WriteError kOutputFailed, bad_alloc and anything else kInternalError. Call only
/// inside a catch block.
Failure current_failure();

/// Thrown by a command that has already reported its outcome and wants main() to exit with
/// `code` (a batch: the worst of its files' codes).
struct ExitWith {
    int code = 0;
};

}  // namespace resharp::cli
