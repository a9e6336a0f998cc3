// modexlab-timing: the cycles a loop body takes on a 486 or a P5 Pentium, by the timing model
// (qemu/timing, docs/cycles.md), from a NASM listing.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "qemu/lib/command_line.h"
#include "qemu/timing/analyse.h"
#include "qemu/timing/listing.h"

namespace {

using namespace harness;

const char* USAGE =
    "usage: modexlab-timing --cpu 486|pentium [--branch taken|not-taken|alternate|P] [--pixels N] [--precision 24|53|64] [--once] [--json] FILE.asm\n"
    "       modexlab-timing --cpu 486|pentium [...] --mapper NAME [--objects DIR]\n"
    "       modexlab-timing --cpu 486|pentium [...] --object FILE.o --function SYMBOL\n"
    "  FILE.asm: a NASM listing (bits 16: real mode; bits 32: protected mode), its code one iteration of a loop\n"
    "  --mapper: a registered mapper's NASM inner loop, from the kernel's objects (DIR: build/kernel/asm), run\n"
    "    from the repository's root; --object/--function: the first loop of SYMBOL in an object (32-bit)\n"
    "  prints each instruction's cycle (and pipe, on the Pentium), clocks and stalls, then 'cycles per iteration: X'\n"
    "  --branch: how its data-dependent branches go (P: each taken with probability P, 0..1; a pattern such as\n"
    "    tnt: each as its letter says, in the body's order; default taken)\n"
    "  --pixels: the pixels an iteration draws (default: the listing's '; pixels:' line, or 1)\n"
    "  --precision: the x87's precision control, which the Pentium's FDIV time follows (default: the listing's\n"
    "    '; precision:' line; else 53 for the kernel's objects, as it boots, and 64 for a listing, as FNINIT leaves it)\n"
    "  --once: straight-line code run once from an idle machine, to its last result (default: the listing's\n"
    "    '; run: once' line); otherwise the code is a loop's body and the figure its steady state\n";

timing::BranchPolicy branch_policy(const std::string& s) {
    timing::BranchPolicy b;
    if (s.empty() || s == "taken") return b;
    if (s == "not-taken") return b.kind = timing::BranchPolicy::NotTaken, b;
    if (s == "alternate") return b.kind = timing::BranchPolicy::Alternate, b;
    if (!s.empty() && s.find_first_not_of("tn") == std::string::npos) return b.kind = timing::BranchPolicy::Pattern, b.pattern = s, b;
    char* end = nullptr;
    const double p = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end || !(p >= 0 && p <= 1)) throw UsageError("--branch takes taken, not-taken, alternate, a share 0..1 or a pattern of t and n");
    b.kind = timing::BranchPolicy::Share, b.share = p;
    return b;
}

int timing_tool(const std::vector<std::string>& words) {
    const CommandLine c = parse_command_line(words, {"--cpu", "--branch", "--pixels", "--precision", "--mapper", "--objects", "--object", "--function"},
                                            {"--json", "--once"});
    if (c.help()) return show_usage(USAGE);
    const int sources = int(c.positionals().size()) + int(c.has("--mapper")) + int(c.has("--object"));
    if (sources != 1) throw UsageError("one listing, --mapper or --object, please");
    if (c.has("--object") != c.has("--function")) throw UsageError("--object and --function go together");
    const timing::Cpu cpu = c.choice<timing::Cpu>("--cpu", {{"486", timing::Cpu::I486}, {"pentium", timing::Cpu::Pentium}}, timing::Cpu::I486);
    if (!c.has("--cpu")) throw UsageError("--cpu is needed: 486 or pentium");
    const timing::BranchPolicy branch = branch_policy(c.text("--branch"));
    const timing::Listing l = c.has("--mapper") ? timing::read_mapper_loop(c.text("--mapper"), c.text("--objects", "build/kernel/asm"))
                              : c.has("--object") ? timing::read_object_loop(c.text("--object"), c.text("--function"))
                                                  : timing::read_listing(c.positionals()[0]);
    int pixels = l.header.count("pixels") ? std::atoi(l.header.at("pixels").c_str()) : 1;
    pixels = c.integer("--pixels", 1, 1 << 20, pixels < 1 ? 1 : pixels);
    const timing::Mode mode = l.bits == 16 ? timing::Mode::Real16 : timing::Mode::Protected32;
    timing::Options o;
    const bool kernel = c.has("--mapper") || c.has("--object");
    o.precision = l.header.count("precision") ? std::atoi(l.header.at("precision").c_str()) : kernel ? 53 : 64;
    o.precision = c.has("--precision") ? c.choice<int>("--precision", {{"24", 24}, {"53", 53}, {"64", 64}}, 64) : o.precision;
    if (o.precision != 24 && o.precision != 53 && o.precision != 64) throw UsageError(l.path + ": '; precision:' takes 24, 53 or 64");
    o.once = c.has("--once") || (l.header.count("run") && l.header.at("run") == "once");
    const timing::Report r = timing::analyse(l.insns, cpu, mode, branch, o);
    if (c.has("--json")) std::printf("%s\n", timing::json(r, pixels, c.text("--cpu"), branch.name()).c_str());
    else std::fputs(timing::diagram(r, pixels).c_str(), stdout);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return run_cli("modexlab-timing", USAGE, argc, argv, timing_tool);
}
