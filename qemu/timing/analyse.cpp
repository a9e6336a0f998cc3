// The static analyser (analyse.h).
#include "qemu/timing/analyse.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "qemu/timing/p5.h"

namespace timing {

namespace {

constexpr int MOST_DATA_BRANCHES = 16;
constexpr int MOST_ENUMERATED = 8;  // up to this many, the 486's share figure weighs every pair of paths
constexpr int WARM_UP = 3;  // iterations before the one measured: the 486 looks back two cycles

struct Body {
    const std::vector<Insn>& insns;
    std::vector<int> target;       // each branch's target index (size: falls off the end)
    std::vector<int> data_branch;  // -1, or the branch's number among the data-dependent ones
    bool loop_branch = false;
    int exits = 0;                 // conditional jumps out of the body
};

Body shape(const std::vector<Insn>& insns) {
    if (insns.empty()) throw std::runtime_error("an empty loop body");
    Body b{insns, std::vector<int>(insns.size(), -1), std::vector<int>(insns.size(), -1)};
    const uint32_t top = insns.front().address, end = insns.back().address + insns.back().size;
    int count = 0;
    for (size_t i = 0; i < insns.size(); ++i) {
        const Insn& in = insns[i];
        if (in.kind != Kind::Jcc && in.kind != Kind::Jmp) continue;
        const bool last = i + 1 == insns.size();
        if (last && in.target == top) {
            b.loop_branch = true;
            b.target[i] = 0;
            continue;
        }
        if (in.target < top || in.target > end) {
            // a conditional jump out of the body is the loop's exit: it falls through while the loop runs
            if (in.kind == Kind::Jmp) throw std::runtime_error("'" + in.text + "' leaves the loop body");
            ++b.exits;
            continue;
        }
        int t = int(insns.size());
        for (size_t k = 0; k < insns.size(); ++k)
            if (insns[k].address == in.target) t = int(k);
        if (t == int(insns.size()) && in.target != end) throw std::runtime_error("'" + in.text + "' jumps into an instruction");
        b.target[i] = t;
        if (in.kind == Kind::Jcc) b.data_branch[i] = count++;
    }
    if (count > MOST_DATA_BRANCHES) throw std::runtime_error("more than 16 data-dependent branches in one loop body");
    return b;
}

// The instructions an iteration runs on a path (bit k: data-dependent branch k taken), and
// whether each goes to its target, appended to a stream: each one's index in the body kept, and
// where each iteration starts.
struct Stream {
    std::vector<Executed> insns;
    std::vector<size_t> body_index;
    std::vector<size_t> starts;
};

void append(const Body& b, unsigned path, Stream* s) {
    s->starts.push_back(s->insns.size());
    for (size_t i = 0; i < b.insns.size();) {
        const Insn& in = b.insns[i];
        const bool loop = b.loop_branch && i + 1 == b.insns.size();
        const bool taken = in.kind == Kind::Jmp || loop || (b.data_branch[i] >= 0 && ((path >> b.data_branch[i]) & 1));
        s->insns.push_back(Executed{&in, taken});
        s->body_index.push_back(i);
        if (loop) break;
        i = taken ? size_t(b.target[i]) : i + 1;
    }
}

// The 486: one iteration on a path; its lines where `lines`.
long iterate(const Body& b, I486& cpu, unsigned path, std::vector<Line>* lines) {
    Stream s;
    append(b, path, &s);
    const long start = cpu.now();
    for (size_t k = 0; k < s.insns.size(); ++k) {
        const Step st = cpu.run(*s.insns[k].insn, s.insns[k].taken);
        if (lines) (*lines)[s.body_index[k]] = Line{s.insns[k].insn->text, st.start, st.clocks, st.stalls};
    }
    return cpu.now() - start;
}

// The cycles of an iteration on path `cur` after iterations on path `prev`.
long measure(const Body& b, Mode mode, unsigned prev, unsigned cur, std::vector<Line>* lines) {
    I486 cpu(mode);
    for (int k = 0; k < WARM_UP; ++k) iterate(b, cpu, prev, nullptr);
    return iterate(b, cpu, cur, lines);
}

// The Pentium: a stream of iterations, each on its path, run at once (an instruction pairs with the
// next, across iterations too); the cycles of iterations [first, last) per iteration, and the
// lines of iteration `first`.
double run_p5(const Body& b, Mode mode, int precision, const std::vector<unsigned>& paths, size_t first, size_t last, std::vector<Line>* lines) {
    Stream s;
    for (unsigned p : paths) append(b, p, &s);
    s.starts.push_back(s.insns.size());
    const std::vector<P5Issue> issues = P5(precision, mode).run(s.insns);
    auto cycle_at = [&](size_t k) { return k < issues.size() ? issues[k].cycle : issues.back().cycle + issues.back().clocks; };
    if (lines)
        for (size_t k = s.starts[first]; k < s.starts[first + 1]; ++k) {
            const P5Issue& is = issues[k];
            Line& l = (*lines)[s.body_index[k]];
            l.cycle = is.cycle, l.clocks = is.clocks, l.stalls = is.stalls, l.pipe = is.pipe;
        }
    return double(cycle_at(s.starts[last]) - cycle_at(s.starts[first])) / double(last - first);
}

// Iterations' paths for a share: `warm` then `count` more, each branch taken with probability
// `share` by a fixed generator (the same figure every run), the measured run's first all taken (its
// diagram's).
std::vector<unsigned> drawn_paths(double share, unsigned all, int data_branches, size_t warm, size_t count) {
    std::vector<unsigned> paths;
    uint32_t x = 12345;
    for (size_t k = 0; k < warm + count + 1; ++k) {
        unsigned p = 0;
        for (int d = 0; d < data_branches; ++d) {
            x = x * 1664525u + 1013904223u;
            if (double(x >> 8) / double(1u << 24) < share) p |= 1u << d;
        }
        paths.push_back(k == warm ? all : p);
    }
    return paths;
}

constexpr size_t WARM = 8, SHARED = 4096;

// The Pentium's figure: its branch target buffer learns, so a steady state is many iterations on.
double pentium(const Body& b, Mode mode, int precision, const BranchPolicy& branch, unsigned all, int data_branches, std::vector<Line>* lines) {
    std::vector<unsigned> paths;
    switch (branch.kind) {
    case BranchPolicy::Taken:
    case BranchPolicy::NotTaken:
    case BranchPolicy::Pattern: paths.assign(WARM + 2, branch.path(data_branches)); return run_p5(b, mode, precision, paths, WARM, WARM + 1, lines);
    case BranchPolicy::Alternate:
        for (size_t k = 0; k < WARM + 3; ++k) paths.push_back(k % 2 ? 0 : all);
        return run_p5(b, mode, precision, paths, WARM, WARM + 2, lines);
    case BranchPolicy::Share:
        return run_p5(b, mode, precision, drawn_paths(branch.share, all, data_branches, WARM, SHARED), WARM, WARM + SHARED, lines);
    }
    return 0;
}

// The 486's share figure where there are too many paths to weigh every pair: the mean over drawn
// iterations run one after another.
double sampled_486(const Body& b, Mode mode, double share, unsigned all, int data_branches) {
    I486 cpu(mode);
    const std::vector<unsigned> paths = drawn_paths(share, all, data_branches, WARM, SHARED);
    long measured = 0;
    for (size_t k = 0; k < paths.size(); ++k) {
        const long c = iterate(b, cpu, paths[k], nullptr);
        if (k >= WARM && k < WARM + SHARED) measured += c;
    }
    return double(measured) / double(SHARED);
}

// Straight-line code run once from an idle machine, every branch as `path` says: the cycles from
// the first issue to the last completion.
double once(const Body& b, Cpu cpu, Mode mode, int precision, unsigned path, std::vector<Line>* lines) {
    Stream s;
    append(b, path, &s);
    long first = 0, last = 0;
    if (cpu == Cpu::I486) {
        I486 m(mode);
        for (size_t k = 0; k < s.insns.size(); ++k) {
            const Step st = m.run(*s.insns[k].insn, s.insns[k].taken);
            (*lines)[s.body_index[k]] = Line{s.insns[k].insn->text, st.start, st.clocks, st.stalls};
            last = std::max(last, st.done);
        }
    } else {
        const std::vector<P5Issue> issues = P5(precision, mode).run(s.insns);
        first = issues.front().cycle;
        for (size_t k = 0; k < issues.size(); ++k) {
            Line& l = (*lines)[s.body_index[k]];
            l.cycle = issues[k].cycle, l.clocks = issues[k].clocks, l.stalls = issues[k].stalls, l.pipe = issues[k].pipe;
            last = std::max(last, issues[k].done);
        }
    }
    return double(last - first + 1);
}

}  // namespace

unsigned BranchPolicy::path(int count) const {
    const unsigned all = (1u << count) - 1;
    if (kind == Taken) return all;
    if (kind != Pattern) return 0;
    if (int(pattern.size()) != count)
        throw std::runtime_error("the branch pattern '" + pattern + "' has " + std::to_string(pattern.size()) + " letters for " + std::to_string(count) +
                                 " data-dependent branches");
    unsigned p = 0;
    for (int k = 0; k < count; ++k) {
        if (pattern[size_t(k)] != 't' && pattern[size_t(k)] != 'n') throw std::runtime_error("a branch pattern is of t and n: '" + pattern + "'");
        if (pattern[size_t(k)] == 't') p |= 1u << k;
    }
    return p;
}

std::string BranchPolicy::name() const {
    switch (kind) {
    case Pattern: return pattern;
    case Taken: return "taken";
    case NotTaken: return "not-taken";
    case Alternate: return "alternate";
    case Share: {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", share);
        return buf;
    }
    }
    return "?";
}

Report analyse(const std::vector<Insn>& insns, Cpu cpu, Mode mode, const BranchPolicy& branch, const Options& options) {
    const Body b = shape(insns);
    Report r;
    r.loop_branch = b.loop_branch;
    r.exits = b.exits;
    for (int d : b.data_branch) r.data_branches += d >= 0;
    const unsigned all = (1u << r.data_branches) - 1;
    r.lines.assign(insns.size(), Line{});
    for (size_t i = 0; i < insns.size(); ++i) r.lines[i].text = insns[i].text;
    if (options.once) {
        if (branch.kind == BranchPolicy::Alternate || branch.kind == BranchPolicy::Share)
            throw std::runtime_error("code run once takes each branch one way: taken, not-taken or a pattern");
        r.cycles_per_iteration = once(b, cpu, mode, options.precision, branch.path(r.data_branches), &r.lines);
        return r;
    }
    if (cpu == Cpu::Pentium) {
        r.cycles_per_iteration = pentium(b, mode, options.precision, branch, all, r.data_branches, &r.lines);
        return r;
    }
    switch (branch.kind) {
    case BranchPolicy::Taken:
    case BranchPolicy::NotTaken:
    case BranchPolicy::Pattern: {
        const unsigned p = branch.path(r.data_branches);
        r.cycles_per_iteration = double(measure(b, mode, p, p, &r.lines));
        break;
    }
    case BranchPolicy::Alternate:
        r.cycles_per_iteration = (double(measure(b, mode, 0, all, &r.lines)) + double(measure(b, mode, all, 0, nullptr))) / 2;
        break;
    case BranchPolicy::Share: {
        if (r.data_branches > MOST_ENUMERATED) {
            r.cycles_per_iteration = sampled_486(b, mode, branch.share, all, r.data_branches);
            measure(b, mode, all, all, &r.lines);
            break;
        }
        // each path's probability, every branch taken with probability `share` on its own
        const double p = branch.share;
        auto chance = [&](unsigned path) {
            double c = 1;
            for (int k = 0; k < r.data_branches; ++k) c *= (path >> k) & 1 ? p : 1 - p;
            return c;
        };
        double expected = 0;
        for (unsigned prev = 0; prev <= all; ++prev)
            for (unsigned cur = 0; cur <= all; ++cur) {
                const double c = chance(prev) * chance(cur);
                if (c > 0) expected += c * double(measure(b, mode, prev, cur, nullptr));
            }
        measure(b, mode, all, all, &r.lines);
        r.cycles_per_iteration = expected;
        break;
    }
    }
    return r;
}

namespace {
std::string number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", std::round(x * 1000) / 1000);
    return buf;
}
}  // namespace

std::string diagram(const Report& r, int pixels) {
    std::ostringstream o;
    const long first = r.lines.empty() ? 0 : r.lines.front().cycle;
    for (const Line& l : r.lines) {
        char head[64];
        if (l.cycle < 0) std::snprintf(head, sizeof head, "%6s %-3s", "-", "");
        else if (l.pipe) std::snprintf(head, sizeof head, "%6ld %c %-3d", l.cycle - first + 1, l.pipe, l.clocks);
        else std::snprintf(head, sizeof head, "%6ld %-3d", l.cycle - first + 1, l.clocks);
        o << head << ' ' << l.text;
        for (size_t k = 0; k < l.stalls.size(); ++k) o << (k ? ", " : "    ; ") << l.stalls[k];
        o << '\n';
    }
    if (r.exits) o << "jumps out of the loop, not taken while it runs: " << r.exits << '\n';
    o << "cycles per iteration: " << number(r.cycles_per_iteration) << '\n';
    if (pixels > 1) o << "cycles per pixel: " << number(r.cycles_per_iteration / pixels) << '\n';
    return o.str();
}

std::string json(const Report& r, int pixels, const std::string& cpu, const std::string& branch) {
    nlohmann::json j;
    j["cpu"] = cpu, j["branch"] = branch, j["pixels"] = pixels;
    j["cycles_per_iteration"] = r.cycles_per_iteration;
    j["cycles_per_pixel"] = r.cycles_per_iteration / pixels;
    j["data_branches"] = r.data_branches;
    j["loop_branch"] = r.loop_branch;
    j["exits"] = r.exits;
    const long first = r.lines.empty() ? 0 : r.lines.front().cycle;
    for (const Line& l : r.lines) {
        nlohmann::json line = {{"text", l.text}, {"cycle", l.cycle < 0 ? -1 : l.cycle - first + 1}, {"clocks", l.clocks}, {"stalls", l.stalls}};
        if (l.pipe) line["pipe"] = std::string(1, l.pipe);
        j["lines"].push_back(line);
    }
    return j.dump();
}

}  // namespace timing
