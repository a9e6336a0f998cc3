// The host tools' one argument parser: options with a value or without, positionals, checked
// getters, and run_cli, which turns a UsageError into "PROGRAM: why", the usage and exit status 2.
#pragma once

#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace harness {

// A command line that does not fit the program's usage. Not a HarnessError: that one means the
// command line was fine and the work failed (exit status 1, not 2).
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A command line sorted by parse_command_line. A word starting with "--" is an option; an option
// given twice counts with its last value (text), or with every value (texts).
class CommandLine {
public:
    // -h or --help was given: the rest was not read.
    bool help() const { return help_; }
    const std::vector<std::string>& positionals() const { return positionals_; }

    bool has(std::string_view option) const;
    std::string text(std::string_view option, std::string fallback = {}) const;
    std::vector<std::string> texts(std::string_view option) const;
    // A comma-separated value's items, empty ones dropped ("--scenes a,b"); none when absent.
    std::vector<std::string> list(std::string_view option) const;
    // A whole number in low..high (UsageError "--frames takes 1..1000" else), or fallback when absent.
    int integer(std::string_view option, int low, int high, int fallback) const;
    // The value that goes with the name given (UsageError "--axis takes rows or columns" else).
    template <typename T>
    T choice(std::string_view option, std::initializer_list<std::pair<std::string_view, T>> allowed, T fallback) const {
        if (!has(option)) return fallback;
        const std::string given = text(option);
        for (const auto& [name, value] : allowed)
            if (given == name) return value;
        std::vector<std::string_view> names;
        for (const auto& entry : allowed) names.push_back(entry.first);
        throw UsageError(std::string(option) + " takes " + one_of(names));
    }

    // "a", "a or b", "a, b or c": the allowed values in a message.
    static std::string one_of(const std::vector<std::string_view>& names);

private:
    friend CommandLine parse_command_line(const std::vector<std::string>&, const std::vector<std::string_view>&,
                                          const std::vector<std::string_view>&);
    const std::string* last_value(std::string_view option) const;

    std::vector<std::string> declared_;  // a getter asking for another option is a bug in the program
    std::vector<std::pair<std::string, std::string>> given_;  // option and value ("" for a flag), in order
    std::vector<std::string> positionals_;
    bool help_ = false;
};

// Sorts words (argv without the program, or after a subcommand) into the options named in
// with_value (the next word is the value, whatever it looks like, or the rest of --option=value)
// and flags, and positionals.
// UsageError: an option it does not know, or one without its value.
CommandLine parse_command_line(const std::vector<std::string>& words, const std::vector<std::string_view>& with_value,
                               const std::vector<std::string_view>& flags);

// The names, the nearest to `word` first (edit distance; ties in the order given), as "a, b, c":
// what a message lists after a name it does not know.
std::string nearest_first(const std::string& word, const std::vector<std::string>& names);

// The name a typo of `word` would be: the nearest within an edit distance of max(1, a third of
// its length), other than the word itself (the first of equals); "" where none is.
std::string near_name(const std::string& word, const std::vector<std::string>& names);

// A program's main: `--version` anywhere prints "PROGRAM VERSION" (status 0); else runs body with
// the words after the program's name and returns its status. A UsageError from it prints
// "PROGRAM: why" and the usage on stderr (status 2), any other exception "PROGRAM: what" (status 1).
int run_cli(std::string_view program, std::string_view usage, int argc, char** argv,
            const std::function<int(const std::vector<std::string>&)>& body);

// -h/--help: the usage on stdout, status 0.
int show_usage(std::string_view usage);

}  // namespace harness
