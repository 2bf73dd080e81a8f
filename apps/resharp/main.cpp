#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
    CLI::App app{"resharp: restores sharp machined edges on grid-simulated meshes"};
    app.require_subcommand(1);
    CLI11_PARSE(app, argc, argv);
    return 0;
}
