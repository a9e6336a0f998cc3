// modexlab-fuzz-replay: every fuzz target over its committed corpus (tests/fuzz/corpus/NAME, or
// the directory given), as `make test` runs it: the build has AddressSanitizer and
// UndefinedBehaviorSanitizer, so an input that once made a target read or write out of bounds,
// overflow or break a promise fails here. A target is a test: it passes when its corpus holds
// inputs and every one of them ran clean; a crash ends the program without its summary line.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/fuzz/registry.h"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    const fs::path root = argc > 1 ? fs::path(argv[1]) : fs::path(MODEXLAB_SOURCE_DIR) / "tests/fuzz/corpus";
    int passed = 0, failed = 0;
    auto targets = fuzz::targets();
    std::sort(targets.begin(), targets.end(), [](const fuzz::Entry& a, const fuzz::Entry& b) { return a.name < b.name; });
    for (const fuzz::Entry& t : targets) {
        const fs::path dir = root / t.name;
        std::vector<fs::path> inputs;
        if (fs::is_directory(dir))
            for (const auto& e : fs::directory_iterator(dir))
                if (e.is_regular_file()) inputs.push_back(e.path());
        std::sort(inputs.begin(), inputs.end());
        size_t bytes = 0;
        for (const fs::path& p : inputs) {
            std::ifstream in(p, std::ios::binary);
            const std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
            fuzz::current_input() = p.string();
            // a copy of exactly the input's size, as libFuzzer gives it: a read past the end is seen
            std::vector<uint8_t> exact(data.begin(), data.end());
            t.target(exact.data(), exact.size());
            bytes += data.size();
        }
        fuzz::current_input().clear();
        if (inputs.empty()) {
            std::printf("[  FAILED  ] %s: no corpus in %s\n", t.name.c_str(), dir.string().c_str());
            ++failed;
        } else {
            std::printf("[       OK ] %s: %zu inputs (%zu bytes) replayed from %s\n", t.name.c_str(), inputs.size(), bytes,
                        dir.string().c_str());
            ++passed;
        }
    }
    std::printf("tests: %d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}
