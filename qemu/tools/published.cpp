// The published-figures section of the report (published.h).
#include "qemu/tools/published.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "qemu/timing/analyse.h"
#include "qemu/timing/listing.h"

namespace harness {

namespace {

struct Published {
    const char* mapper;  // ours that is that loop, or "" when we did not build it
    const char* loop;
    const char* figure;
    const char* machine;
    const char* listing;  // instructions a pixel of the published listing, counted
    const char* ours;     // the same count for our NASM loop
    // the listing as tests/timing/listings transcribes it ("": none); our loop's pixels a pass, and
    // the two paths of its data-dependent branches the model runs ours by ("" "": taken, not taken)
    const char* listing_file;
    int our_pixels;
    const char* our_paths[2];
};
const Published PUBLISHED[] = {
    {"xsharp-row-out", "Abrash, Black Book listing 58.1 (57.2's loop, OUT per pixel)", "44", "486", "17 (15-17 run), 1 OUT", "17 (15-17 run), 1 OUT",
     "l58-1.asm", 1, {"", ""}},
    {"", "Abrash, listing 58.2 (columns, 16-bit fractions, unrolled)", "22", "486", "13 (11-13 run) + loop control / unroll", "-", "l58-2.asm", 1,
     {"", ""}},
    {"", "Abrash, packed fractions with ADC (no listing)", "10", "486", "no listing", "-", "", 1, {"", ""}},
    {"", "Abrash, listing 58.3 (16-bit, SS:BP texture pointer)", "9", "486", "8 (6-8 run) + loop control / unroll", "-", "l58-3.asm", 1, {"", ""}},
    {"xsharp-column", "Abrash, listing 58.4 (32-bit)", "8", "486", "8 (6-8 run) + loop control / unroll", "8 + 3/2 = 9.5 (unrolled x2)",
     "l58-4.asm", 2, {"", ""}},
    {"xsharp-column", "Abrash, listing 58.4 (32-bit)", "5.5", "Pentium", "8 (6-8 run) + loop control / unroll", "8 + 3/2 = 9.5 (unrolled x2)",
     "l58-4.asm", 2, {"", ""}},
    {"quake-subdiv16", "id Software, d_draw16.s (the cycles: Abrash's, not in the source)", "7.5", "Pentium",
     "6 (unrolled x16); 6 + 68/16 = 10.25 with the segment", "9; 9 + 98/16 = 15.1 with the segment", "quake-d_draw16.asm", 1, {"", ""}},
    {"quake-d_draw16", "id Software, d_draw16.s as shipped (24-bit, chop; the cycles: Abrash's)", "7.5", "Pentium",
     "6 (unrolled x16); 6 + 68/16 = 10.25 with the segment", "the same instructions", "quake-d_draw16.asm", 16, {"ttt", "ntt"}},
    {"quake-subdiv8", "id Software, d_draw.s", "none given", "", "6 (unrolled x8); 6 + 68/8 = 14.5 with the segment",
     "9; 9 + 98/8 = 21.25 with the segment", "", 1, {"", ""}},
    {"fatmap-256", "Byggmastar, fatmap.txt's combined 8:16 loop", "5 (ticks)", "Pentium", "9", "9", "fatmap-combined.asm", 1, {"", ""}},
    {"fatmap-256-16", "Simmons's 8:16 loop, fatmap2.txt section 13", "4 (ticks)", "Pentium", "8", "8 (the same instructions)", "fatmap2-simmons.asm",
     1, {"", ""}},
    {"fatmap-lut", "Byggmastar, fatmap.txt's table-lookup loop", "4 (ticks)", "Pentium", "7", "7", "fatmap-lut.asm", 1, {"", ""}},
    {"hecker-steptable", "Hecker, Game Developer part V listing 2 (not found here)", "none given", "", "not found", "9", "", 1, {"", ""}},
};

// The timing model's cycles a pixel on `machine` ("486" or "Pentium"), the least and the most of
// the two paths ("4" or "4-6"), of a loop; "-" where it cannot say (no listing, no loop, no
// objects: the report's figures come from a tree with the kernel built).
std::string model_range(const std::vector<timing::Insn>& insns, int bits, const std::string& machine, int precision, int pixels,
                        const std::string (&paths)[2]) {
    try {
        const timing::Cpu cpu = machine == "486" ? timing::Cpu::I486 : timing::Cpu::Pentium;
        double lo = 0, hi = 0;
        for (int k = 0; k < 2; ++k) {
            timing::BranchPolicy b;
            if (paths[k].empty()) b.kind = k ? timing::BranchPolicy::NotTaken : timing::BranchPolicy::Taken;
            else b.kind = timing::BranchPolicy::Pattern, b.pattern = paths[k];
            timing::Options o;
            o.precision = precision;
            const double c = timing::analyse(insns, cpu, bits == 16 ? timing::Mode::Real16 : timing::Mode::Protected32, b, o).cycles_per_iteration / pixels;
            lo = k ? std::min(lo, c) : c, hi = k ? std::max(hi, c) : c;
        }
        auto text = [](double c) {  // (two decimals at most, trailing zeros dropped)
            std::string t = fixed(c, 2);
            while (t.back() == '0') t.pop_back();
            if (t.back() == '.') t.pop_back();
            return t;
        };
        return lo == hi ? text(lo) : text(lo) + "-" + text(hi);
    } catch (const std::exception&) {
        return "-";
    }
}

std::string model_of_listing(const Published& p) {
    if (!*p.listing_file || (std::string(p.machine) != "486" && std::string(p.machine) != "Pentium")) return "-";
    try {
        const timing::Listing l = timing::read_listing(std::string("tests/timing/listings/") + p.listing_file);
        const int pixels = l.header.count("pixels") ? std::max(1, std::atoi(l.header.at("pixels").c_str())) : 1;
        const int precision = l.header.count("precision") ? std::atoi(l.header.at("precision").c_str()) : 64;
        return model_range(l.insns, l.bits, p.machine, precision, pixels, {"", ""});
    } catch (const std::exception&) {
        return "-";
    }
}

std::string model_of_ours(const Published& p) {
    if (!*p.mapper || (std::string(p.machine) != "486" && std::string(p.machine) != "Pentium")) return "-";
    try {
        const timing::Listing l = timing::read_mapper_loop(p.mapper, "build/kernel/asm");
        const int precision = l.header.count("precision") ? std::atoi(l.header.at("precision").c_str()) : 53;
        return model_range(l.insns, 32, p.machine, precision, p.our_pixels, {p.our_paths[0], p.our_paths[1]});
    } catch (const std::exception&) {
        return "-";
    }
}

}  // namespace

void write_published(std::ostream& out, const std::vector<TradeRow>& rows) {
    // the classics' published cycles beside our instruction counts, on the scene each drew most of
    out << "\n## The classics' published figures beside ours\n\n"
        << "Published: cycles per pixel of the inner loop on the machine named, as its author gave it. Listing: the instructions "
           "a pixel of the published listing, counted by hand in the steady state (a carry branch taken or not: the range run); "
           "ours counted: the same count for our NASM loop. Ours measured: guest instructions per pixel of our loop under QEMU "
           "icount (with its per-span and per-segment work), on the scene where the mapper drew the most pixels without "
           "refusing a polygon. A Pentium pairs two simple instructions a cycle: cycles and instructions sit side by side, "
           "they do not divide (docs/classics.md, \"The published loops counted\").\n\n"
        << "The model columns: the timing model's cycles a pixel on the machine named (docs/cycles.md), of the listing as "
           "tests/timing/listings transcribes it and of our loop from the kernel's objects, a steady-state pass on each path of its "
           "data-dependent branches (a range where they differ).\n\n"
        << "| loop | published cycles/px | machine | model: listing | model: ours | listing instr/px | ours | ours counted | ours measured "
           "instr/px | scene |\n"
           "|---|--:|---|--:|--:|---|---|---|--:|---|\n";
    auto best_row = [&](const std::string& mapper) -> const TradeRow* {
        const TradeRow* best = nullptr;
        for (const TradeRow& r : rows)
            if (r.mapper == mapper && r.draws_everything() && (!best || r.pixels > best->pixels)) best = &r;
        return best;
    };
    for (const Published& p : PUBLISHED) {
        const TradeRow* r = *p.mapper ? best_row(p.mapper) : nullptr;
        out << "| " << p.loop << " | " << p.figure << " | " << p.machine << " | " << model_of_listing(p) << " | " << model_of_ours(p) << " | "
            << p.listing << " | " << (*p.mapper ? p.mapper : "not built")
            << " | " << p.ours << " | " << (r ? fixed(r->inner_per_pixel(), 1) : "-") << " | " << (r ? r->scene : "-") << " |\n";
    }
    // ours with no published counterpart, counted the same way (asm/fast.asm)
    const std::pair<const char*, const char*> OURS[] = {{"fast-affine", "6 + 3/16 (each pixel stored alone)"},
                                                        {"fast-columns", "6 + 3/8"}};
    for (const auto& [ours, counted] : OURS) {
        const TradeRow* r = best_row(ours);
        out << "| ours: " << ours << " | - | - | - | - | - | " << ours << " | " << counted << " | " << (r ? fixed(r->inner_per_pixel(), 1) : "-")
            << " | " << (r ? r->scene : "-") << " |\n";
    }
    write_goals(out, rows);
}

void write_goals(std::ostream& out, const std::vector<TradeRow>& rows) {
    out << "\n## Our loops against the goals\n\n"
        << "The timing model's cycles a pixel (zero-wait, into RAM): our exactly stepped affine loop (fast-affine's 8:16 core) "
           "and our offset-table loop (fast-table's) from the kernel's objects, a steady-state pass of each; and, on the corridor "
           "and freedoom, the Pentium's drawing cycles a pixel of our fastest perspective mapper within one footprint (measured "
           "max footprint error at most 1, the whole scene drawn) over our fastest affine one's (affine, fast-affine, fast-table, "
           "fast-columns, fast-table-columns). What each lever gave, and the floors the documented rules set: docs/cycles.md, "
           "\"Our loops against the goals\".\n\n"
        << "| goal | machine | at most | model | met |\n|---|---|--:|--:|---|\n";
    struct Loop {
        const char* what;
        const char* mapper;
        int pixels;
        const char* machine;
        double goal;
    };
    const Loop LOOPS[] = {{"exactly stepped affine (fast-affine)", "fast-affine", 16, "486", 6},
                          {"exactly stepped affine (fast-affine)", "fast-affine", 16, "Pentium", 3.5},
                          {"offset table (fast-table)", "fast-table", 32, "486", 3.5},
                          {"offset table (fast-table)", "fast-table", 32, "Pentium", 2}};
    for (const Loop& l : LOOPS) {
        std::string model = "-";
        try {
            model = model_range(timing::read_mapper_loop(l.mapper, "build/kernel/asm").insns, 32, l.machine, 53, l.pixels, {"", ""});
        } catch (const std::exception&) {
        }
        const bool measured = model != "-";
        out << "| " << l.what << " | " << l.machine << " | " << fixed(l.goal, 1) << " | " << model << " | "
            << (!measured ? "-" : std::atof(model.c_str()) <= l.goal ? "yes" : "no") << " |\n";
    }
    const char* const AFFINE[] = {"affine", "fast-affine", "fast-table", "fast-columns", "fast-table-columns"};
    for (const char* scene : {"corridor", "freedoom"}) {
        const TradeRow *persp = nullptr, *affine = nullptr;
        auto per = [](const TradeRow* r) { return r->per_pixel(r->cycles_pentium.draw); };
        for (const TradeRow& r : rows) {
            if (r.scene != scene || r.family != "ours" || !r.draws_everything() || !r.cycles_pentium.draw || r.mapper == "auto") continue;
            const bool is_affine = std::find(std::begin(AFFINE), std::end(AFFINE), r.mapper) != std::end(AFFINE);
            const TradeRow*& best = is_affine ? affine : persp;
            if (!is_affine && r.accuracy.max_footprint_error > 1) continue;
            if (!best || per(&r) < per(best)) best = &r;
        }
        out << "| " << scene << ": fastest perspective within one footprint over fastest affine | Pentium | 1.3 | ";
        if (!persp || !affine) {
            out << "- | - |\n";
            continue;
        }
        const double ratio = per(persp) / per(affine);
        out << persp->mapper << " " << fixed(per(persp), 1) << " / " << affine->mapper << " " << fixed(per(affine), 1) << " = "
            << fixed(ratio, 2) << " | " << (ratio <= 1.3 ? "yes" : "no") << " |\n";
    }
}

}  // namespace harness
