// The host tools' argument parser (args.h): sorting the words, the checked getters, run_cli.
#include "qemu/lib/command_line.h"

#include <algorithm>
#include <charconv>
#include <cstdio>

#include "kernel/version.h"

namespace harness {

namespace {
const char* const EVERY_TOOL = "-h, --help: this text; --version: the version; an option's value may follow it after '='\n";
}

CommandLine parse_command_line(const std::vector<std::string>& words, const std::vector<std::string_view>& with_value,
                               const std::vector<std::string_view>& flags) {
    CommandLine c;
    c.declared_.assign(with_value.begin(), with_value.end());
    c.declared_.insert(c.declared_.end(), flags.begin(), flags.end());
    auto named = [](const std::vector<std::string_view>& names, const std::string& w) {
        return std::find(names.begin(), names.end(), w) != names.end();
    };
    for (size_t i = 0; i < words.size(); ++i) {
        const std::string& w = words[i];
        if (w == "-h" || w == "--help") {
            c.help_ = true;
            break;
        }
        const size_t eq = w.rfind("--", 0) == 0 ? w.find('=') : std::string::npos;
        if (eq != std::string::npos) {  // --option=value
            const std::string option = w.substr(0, eq);
            if (named(flags, option)) throw UsageError(option + " takes no value");
            if (!named(with_value, option)) throw UsageError("unknown option " + option);
            c.given_.emplace_back(option, w.substr(eq + 1));
        } else if (named(with_value, w)) {
            if (i + 1 >= words.size()) throw UsageError(w + " needs a value");
            c.given_.emplace_back(w, words[++i]);
        } else if (named(flags, w)) {
            c.given_.emplace_back(w, std::string());
        } else if (w.rfind("--", 0) == 0) {
            throw UsageError("unknown option " + w);
        } else {
            c.positionals_.push_back(w);
        }
    }
    return c;
}

const std::string* CommandLine::last_value(std::string_view option) const {
    if (std::find(declared_.begin(), declared_.end(), option) == declared_.end())
        throw std::logic_error("the command line was parsed without " + std::string(option));
    for (auto it = given_.rbegin(); it != given_.rend(); ++it)
        if (it->first == option) return &it->second;
    return nullptr;
}

bool CommandLine::has(std::string_view option) const { return last_value(option) != nullptr; }

std::string CommandLine::text(std::string_view option, std::string fallback) const {
    const std::string* v = last_value(option);
    return v ? *v : fallback;
}

std::vector<std::string> CommandLine::texts(std::string_view option) const {
    last_value(option);  // only for its check that the option was declared
    std::vector<std::string> out;
    for (const auto& [name, value] : given_)
        if (name == option) out.push_back(value);
    return out;
}

std::vector<std::string> CommandLine::list(std::string_view option) const {
    std::vector<std::string> out;
    std::string all = text(option);
    for (size_t start = 0; start <= all.size();) {
        size_t comma = std::min(all.find(',', start), all.size());
        if (comma > start) out.push_back(all.substr(start, comma - start));
        start = comma + 1;
    }
    return out;
}

int CommandLine::integer(std::string_view option, int low, int high, int fallback) const {
    const std::string* v = last_value(option);
    if (!v) return fallback;
    // from_chars, not atoi: "12abc", "" and " 12" are refused rather than read as 12 or 0
    long long n = 0;
    auto [end, error] = std::from_chars(v->data(), v->data() + v->size(), n);
    if (error != std::errc() || end != v->data() + v->size() || n < low || n > high)
        throw UsageError(std::string(option) + " takes " + std::to_string(low) + ".." + std::to_string(high));
    return int(n);
}

std::string CommandLine::one_of(const std::vector<std::string_view>& names) {
    std::string out;
    for (size_t i = 0; i < names.size(); ++i) {
        if (i) out += i + 1 == names.size() ? " or " : ", ";
        out += names[i];
    }
    return out;
}

namespace {

// Levenshtein's distance: the least insertions, deletions and substitutions from a to b.
size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string nearest_first(const std::string& word, const std::vector<std::string>& names) {
    std::vector<std::pair<size_t, std::string>> by_distance;
    for (const std::string& n : names) by_distance.emplace_back(edit_distance(word, n), n);
    std::stable_sort(by_distance.begin(), by_distance.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::string out;
    for (const auto& [d, n] : by_distance) out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::string near_name(const std::string& word, const std::vector<std::string>& names) {
    std::string best;
    size_t least = std::max<size_t>(1, word.size() / 3) + 1;
    for (const std::string& n : names)
        if (const size_t d = edit_distance(word, n); d < least && n != word) least = d, best = n;
    return best;
}

int run_cli(std::string_view program, std::string_view usage, int argc, char** argv, const std::function<int(const std::vector<std::string>&)>& body) {
    const std::string name(program);
    const std::vector<std::string> words(argv + 1, argv + argc);
    if (std::find(words.begin(), words.end(), "--version") != words.end()) {
        std::printf("%s %s\n", name.c_str(), MODEXLAB_VERSION);
        return 0;
    }
    try {
        return body(words);
    } catch (const UsageError& e) {
        std::fprintf(stderr, "%s: %s\n%.*s%s", name.c_str(), e.what(), int(usage.size()), usage.data(), EVERY_TOOL);
        return 2;
    } catch (const std::exception& e) {
        // HarnessError says what and where; anything else (out of memory) is still reported, not a crash
        std::fprintf(stderr, "%s: %s\n", name.c_str(), e.what());
        return 1;
    }
}

int show_usage(std::string_view usage) {
    std::fwrite(usage.data(), 1, usage.size(), stdout);
    std::fputs(EVERY_TOOL, stdout);
    return 0;
}

}  // namespace harness
