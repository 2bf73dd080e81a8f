#pragma once
/// Running the real `resharp` executable from a test, through the shell, in a scratch folder.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace resharp::cli {

struct CliRun {
    int exit_code = -1;
    std::string stderr_text;
};

/// `path` in single quotes for the shell. Built with append: GCC 12 warns falsely (-Wrestrict)
/// on "'" + string.
inline std::string quoted(const std::filesystem::path& path) {
    std::string text(1, '\'');
    text.append(path.string()).push_back('\'');
    return text;
}

/// Runs `command` (a shell line, without redirection) with its stderr sent to `stderr_file`;
/// gives the exit code (-1 if it did not exit normally) and what it wrote on stderr.
inline CliRun run_shell(const std::string& command, const std::filesystem::path& stderr_file) {
    const std::string line = command + " 2>" + quoted(stderr_file);
    const int status = std::system(line.c_str());
    CliRun run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(stderr_file);
    std::stringstream text;
    text << in.rdbuf();
    run.stderr_text = text.str();
    return run;
}

/// An empty directory of the running test's own, removed again by the destructor. Flat (one
/// per test, named after the process and the test): ctest runs each test in a process of its
/// own, and a per-process parent directory would be left behind.
class ScratchDir {
public:
    explicit ScratchDir(const std::string& prefix) {
        std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        std::replace(name.begin(), name.end(), '/', '_');  // parameterised tests
        path_ = std::filesystem::temp_directory_path() /
                (prefix + "_" + std::to_string(::getpid()) + "_" + name);
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() { std::filesystem::remove_all(path_); }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

#ifdef RESHARP_SOURCE_DIR
/// The shipped example part (examples/bracket.stl).
inline std::filesystem::path example_mesh() {
    return std::filesystem::path(RESHARP_SOURCE_DIR) / "examples" / "bracket.stl";
}
#endif

/// A test with a ScratchDir of its own (named after its suite) and `resharp` to run in it.
/// Needs RESHARP_CLI, the path of the executable.
class CliTest : public ::testing::Test {
protected:
    /// Runs `resharp ARGS` through the shell (so `prefix` can set limits).
    CliRun resharp(const std::string& args, const std::string& prefix = "") const {
        return run_shell(prefix + std::string(RESHARP_CLI) + " " + args, dir_ / "stderr.txt");
    }
    CliRun restore(const std::string& args, const std::string& prefix = "") const {
        return resharp("restore " + args, prefix);
    }
    /// The scratch file `name`, quoted for the shell.
    std::string path(const std::string& name) const { return quoted(dir_ / name); }
    /// Every file in the scratch folder except the captured stderr.
    std::vector<std::string> outputs() const {
        std::vector<std::string> names;
        for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
            if (entry.path().filename() != "stderr.txt") names.push_back(entry.path().filename());
        }
        return names;
    }
    static std::string bytes_of(const std::filesystem::path& file) {
        std::ifstream in(file, std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }

    ScratchDir scratch_{::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name()};
    std::filesystem::path dir_ = scratch_.path();
};

}  // namespace resharp::cli
