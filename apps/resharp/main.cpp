#include <cstdio>
#include <exception>
#include <new>

#include "commands.h"
#include "resharp/core/errors.h"

namespace {

constexpr const char* kExitCodeHelp =
    "Exit codes: 0 success; 1 bad command line; 2 unreadable or malformed input, or a mesh "
    "that cannot be processed; 3 an output file could not be written; 4 internal error or out "
    "of memory. On any failure no output file is left behind.";

int fail(int code, const char* message) {
    std::fprintf(stderr, "resharp: error: %s\n", message);
    return code;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace resharp::cli;
    CLI::App app{
        "resharp: restores the sharp machined edges and corners that grid-based "
        "machining simulation turns into chamfer bands."};
    app.footer(kExitCodeHelp);
    app.require_subcommand(1);
    add_restore_command(app);
    add_simulate_command(app);
    add_evaluate_command(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kSuccess : kUsageError;
    } catch (const resharp::ReadError& e) {  // includes ParseError
        return fail(kBadInput, e.what());
    } catch (const resharp::InvalidInput& e) {
        return fail(kBadInput, e.what());
    } catch (const resharp::WriteError& e) {
        return fail(kOutputFailed, e.what());
    } catch (const std::bad_alloc&) {
        return fail(kInternalError, "out of memory");
    } catch (const std::exception& e) {
        return fail(kInternalError, e.what());
    }
    return kSuccess;
}
