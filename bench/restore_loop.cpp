// restore() of one mesh file called again and again in one process, as a simulator that links
// resharp calls it step after step: the first call pays the page faults of a fresh heap, the
// later ones find glibc's heap grown and measure the work alone (docs/benchmarks.md, "restore()
// in a program that leaves glibc's malloc alone"). The process leaves malloc's settings as they
// are, unlike the command line.
//
//   resharp_restore_loop MESH [THREADS [CALLS]]
//
// prints one line: the first call's time and the median of the others, in milliseconds. It uses
// only io::read_mesh(), weld() and restore(), which every build since b8e8ee5 has: to compare
// with an older build, compile this file against that build's libraries.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

#include "resharp/io/mesh_io.h"
#include "resharp/mesh/mesh.h"
#include "resharp/pipeline/restore.h"

namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 4) {
        std::fprintf(stderr, "usage: resharp_restore_loop MESH [THREADS [CALLS]]\n");
        return 2;
    }
    const int threads = argc > 2 ? std::atoi(argv[2]) : 0;
    const int calls = argc > 3 ? std::atoi(argv[3]) : 11;
    if (threads < 0 || calls < 2) {
        std::fprintf(stderr, "resharp_restore_loop: THREADS must be 0 or more, CALLS 2 or more\n");
        return 2;
    }
    try {
        const resharp::Mesh mesh = resharp::weld(resharp::io::read_mesh(argv[1]));
        resharp::RestoreOptions options;
        options.threads = threads;
        std::vector<double> times;
        for (int call = 0; call < calls; ++call) {  // Bound: CALLS
            const auto start = std::chrono::steady_clock::now();
            const resharp::RestoreResult result = resharp::restore(mesh, options);
            times.push_back(milliseconds_since(start));
        }
        std::vector<double> later(times.begin() + 1, times.end());
        const auto middle = later.begin() + static_cast<std::ptrdiff_t>(later.size() / 2);
        std::nth_element(later.begin(), middle, later.end());
        std::printf("first %.2f ms, later median %.2f ms (%d calls, %d threads)\n", times.front(),
                    *middle, calls, threads);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "resharp_restore_loop: %s\n", e.what());
        return 1;
    }
    return 0;
}
