#include "io/bad_file_manifest.h"

#include <cctype>
#include <fstream>
#include <sstream>

namespace resharp::test {

std::filesystem::path bad_files_dir() {
    return std::filesystem::path(RESHARP_TEST_DATA_DIR) / "bad";
}

std::vector<BadFileExpectation> load_bad_file_manifest() {
    std::vector<BadFileExpectation> rows;
    std::ifstream in(bad_files_dir() / "MANIFEST.tsv");
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        BadFileExpectation e;
        std::getline(fields, e.file, '\t');
        std::getline(fields, e.kind, '\t');
        std::getline(fields, e.location, '\t');
        std::getline(fields, e.reason);
        rows.push_back(e);
    }
    return rows;
}

std::string test_name_for(const std::string& file) {
    std::string name = file;
    for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    }
    return name;
}

}  // namespace resharp::test
