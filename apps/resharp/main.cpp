#include <cstdio>

#include "commands.h"
#include "exit_status.h"

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
#ifdef RESHARP_HAS_VIEWER
    add_view_command(app);
#endif

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kSuccess : kUsageError;
    } catch (const ExitWith& e) {
        return e.code;
    } catch (...) {
        const Failure failure = current_failure();
        return fail(failure.code, failure.message.c_str());
    }
    return kSuccess;
}
