// The on-screen bench (onscreen.h).
#include "kernel/show/onscreen.h"

#include "drivers/serial.h"
#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/core/measured.h"
#include "kernel/core/policy.h"
#include "kernel/platform/isa.h"
#include "kernel/present/file_table.h"
#include "kernel/lib/fmt.h"
#include "kernel/lib/json.h"
#include "kernel/lib/qr.h"
#include "kernel/scene/text.h"
#include "kernel/server/commands.h"
#include "kernel/present/current_world.h"

namespace onscreen {

namespace {

constexpr int MAX_SCENES = 16;
constexpr int MAX_ROWS = MAX_SCENES * raster::MAPPER_LIMIT;

struct Row {
    int scene;  // of Setup::scenes
    int mapper;  // registry row
    uint64_t pixels, polygons, ticks_inner, ticks_frame;
    double error;  // make bench's; below 0: none measured
    bool interrupted;
};

// Everything the pages need, static: the rows, the CSV, one QR code at a time (62 KB).
Row g_rows[MAX_ROWS];
int g_row_count = 0;
constexpr int CSV_BYTES = 48 * 1024;
char g_csv[CSV_BYTES];
int g_csv_length = 0;
lib::QrCode g_qr;

// The CSV parts a QR code each: [start, end) of g_csv, whole lines, each with its header.
constexpr int MAX_PARTS = 32, PART_HEADER = 40;
int g_part_start[MAX_PARTS + 1];
int g_part_count = 0;

const char* scene_name(const Setup& s, int i) { return file_table::at(s.scenes[i]).name; }

// per pixel, in tenths
// (in the unit the pages show: TSC cycles, or ns on the PIT clock)
uint64_t tenths_per_pixel(uint64_t ticks, uint64_t pixels) { return pixels ? timer::tenths_shown(ticks) / pixels : 0; }

// a footprint error as the table shows it ("-": none measured)
void put_error(lib::Fmt& f, double e) {
    if (e < 0) f.s("-");
    else f.decimal(e);
}

// Right-aligns the text of `f` in a field of `width` after what `line` holds.
void field(lib::Fmt& line, const lib::Fmt& f, int width) {
    const int n = int(lib::c_length(f.c_str()));
    for (int i = n; i < width; ++i) line.s(" ");
    line.s(f.c_str());
}

class Csv {
public:
    void s(const char* text) {
        for (; *text; ++text) put(*text == ',' ? ' ' : *text);
    }
    void raw(const char* text) {
        for (; *text; ++text) put(*text);
    }
    void u64(uint64_t v) {
        char digits[lib::DECIMAL_MAX_CHARS];
        const size_t n = lib::format_decimal(v, digits);
        for (size_t i = 0; i < n; ++i) put(digits[i]);
    }

private:
    void put(char c) {
        if (g_csv_length < CSV_BYTES - 1) g_csv[g_csv_length++] = c;
    }
};

void build_csv(const Setup& s) {
    g_csv_length = 0;
    Csv c;
    c.raw("modexlab-bench,2,");
    c.s(s.cpu->has_cpuid ? s.cpu->vendor : "no CPUID");
    c.raw(",");
    c.u64(s.cpu->family), c.raw(","), c.u64(s.cpu->model), c.raw(","), c.u64(s.cpu->stepping), c.raw(",");
    c.s(s.cpu->brand);
    c.raw(",");
    c.s(timer::clock_name(timer::clock())), c.raw(","), c.u64(timer::hz()), c.raw(","), c.u64(timer::tsc_hz()), c.raw(",");
    c.u64(timer::cpu_hz()), c.raw(",");
    c.s(isa::name(isa::in_use())), c.raw(","), c.u64(s.frames), c.raw("\n");
    c.raw("scene,mapper,pixels,polygons,inner_ticks,frame_ticks,max_footprint_error\n");
    for (int i = 0; i < g_row_count; ++i) {
        const Row& r = g_rows[i];
        c.s(scene_name(s, r.scene)), c.raw(","), c.s(raster::MAPPERS[r.mapper].name), c.raw(",");
        c.u64(r.pixels), c.raw(","), c.u64(r.polygons), c.raw(","), c.u64(r.ticks_inner), c.raw(","), c.u64(r.ticks_frame), c.raw(",");
        lib::Fmt e;
        put_error(e, r.error);
        c.raw(e.c_str());
        c.raw("\n");
    }
    // parts of whole lines, each within a version 40 code at level L with its header
    const int room = int(lib::qr_capacity(40, lib::QrLevel::L)) - PART_HEADER;
    g_part_count = 0;
    g_part_start[0] = 0;
    for (int at = 0; at < g_csv_length && g_part_count < MAX_PARTS;) {
        int end = at + room < g_csv_length ? at + room : g_csv_length;
        if (end < g_csv_length) {
            int line_end = end;
            while (line_end > at && g_csv[line_end - 1] != '\n') --line_end;
            if (line_end > at) end = line_end;
        }
        g_part_start[++g_part_count] = end;
        at = end;
    }
}

// A page of text lines: the box at the top left over the whole page in paper.
constexpr int PAGE_LINES = 29, PAGE_CHARS = 40, TABLE_ROWS = PAGE_LINES - 2;
struct Page {
    char text[PAGE_LINES][PAGE_CHARS + 1];
    int count = 0;
    void add(const char* line) {
        if (count < PAGE_LINES) lib::copy_c_string(text[count++], PAGE_CHARS + 1, line);
    }
};

void machine_page(const Setup& s, Page* p) {
    p->add("modexlab on-screen bench");
    p->add("");
    lib::Fmt a;
    a.s("CPU    ").s(cpu::class_name(*s.cpu));
    if (s.cpu->has_cpuid) a.s(", ").s(s.cpu->vendor);
    p->add(a.c_str());
    lib::Fmt b;
    b.s("       family ").u(s.cpu->family).s(" model ").u(s.cpu->model).s(" stepping ").u(s.cpu->stepping);
    p->add(b.c_str());
    const char* brand = s.cpu->brand;
    for (int line = 0; *brand && line < 2; ++line) {  // up to 48 characters on two lines
        lib::Fmt c;
        c.s(line ? "       " : "brand  ");
        int n = 0;
        for (; *brand && n < PAGE_CHARS - 7; ++n) {
            const char ch[2] = {*brand++, 0};
            c.s(ch);
        }
        p->add(c.c_str());
    }
    lib::Fmt d;
    d.s("clock  ");
    if (timer::clock() == timer::Clock::Tsc) d.s("TSC ").tenths(timer::tsc_hz() / 100000).s(" MHz (vs PIT)");
    else if (timer::cpu_hz()) d.s("PIT (no TSC), CPU ").tenths(timer::cpu_hz() / 100000).s(" MHz");
    else d.s("PIT 1.193 MHz (no TSC): ns");
    p->add(d.c_str());
    lib::Fmt i;
    i.s("code   built for the ").s(isa::in_use() == isa::Path::P6 ? "P6 (CMOV)" : "486");
    p->add(i.c_str());
    lib::Fmt e;
    e.s("run    ").u(uint32_t(s.scene_count)).s(" scenes x ").u(uint32_t(raster::MAPPER_COUNT)).s(" mappers, ").u(s.frames).s(" frames");
    p->add(e.c_str());
    p->add("");
    p->add(timer::clock() == timer::Clock::Tsc ? "A page a scene: TSC cycles a pixel of"
           : timer::cpu_hz()                   ? "A page a scene: cycles (PIT) a pixel of"
                                               : "A page a scene: nanoseconds a pixel of");
    p->add("the inner loops and of the whole frame,");
    p->add("fastest first, and the footprint error");
    p->add("make bench measured on 8 frames (the");
    p->add("same pictures on every machine). Then");
    p->add("the CSV of the run as QR codes.");
    p->add("");
    p->add("Right, Left: pages   Esc: the show");
}

// The table pages of a scene: its rows sorted by whole-frame cycles a pixel (refusals last).
int table_pages(int rows_of_scene) { return (rows_of_scene + TABLE_ROWS - 1) / TABLE_ROWS; }

void table_page(const Setup& s, int scene, int part, int parts, Page* p) {
    int order[raster::MAPPER_LIMIT], n = 0;
    for (int i = 0; i < g_row_count; ++i)
        if (g_rows[i].scene == scene && n < raster::MAPPER_LIMIT) order[n++] = i;
    auto key = [](const Row& r) { return r.pixels ? r.ticks_frame * 1000 / r.pixels : ~uint64_t(0); };
    for (int i = 1; i < n; ++i)  // insertion: stable, registry order among equals
        for (int j = i; j > 0 && key(g_rows[order[j - 1]]) > key(g_rows[order[j]]); --j) {
            const int t = order[j];
            order[j] = order[j - 1], order[j - 1] = t;
        }
    lib::Fmt title;
    title.s(scene_name(s, scene)).s(", frames: ").u(s.frames).s(" (page ").u(uint32_t(part + 1)).s("/").u(uint32_t(parts)).s(")");
    p->add(title.c_str());
    p->add("mapper               inner   frame  err");
    for (int k = part * TABLE_ROWS; k < n && k < (part + 1) * TABLE_ROWS; ++k) {
        const Row& r = g_rows[order[k]];
        lib::Fmt line;
        line.s(raster::MAPPERS[r.mapper].name);
        for (int c = int(lib::c_length(raster::MAPPERS[r.mapper].name)); c < 19; ++c) line.s(" ");  // (the longest name: 19)
        lib::Fmt inner, frame, err;
        if (r.pixels) {
            inner.tenths(tenths_per_pixel(r.ticks_inner, r.pixels));
            frame.tenths(tenths_per_pixel(r.ticks_frame, r.pixels));
        } else {
            inner.s("-"), frame.s(r.interrupted ? "stopped" : "refused");
        }
        put_error(err, r.error);
        field(line, inner, 7), field(line, frame, 8), field(line, err, 5);
        p->add(line.c_str());
    }
}

int scene_rows(int scene) {
    int n = 0;
    for (int i = 0; i < g_row_count; ++i) n += g_rows[i].scene == scene;
    return n;
}

int page_count(const Setup& s) {
    int n = 1;
    for (int i = 0; i < s.scene_count; ++i) n += table_pages(scene_rows(i));
    return n + g_part_count;
}

void draw_page_text(const Page& p, int page, raster::TextColours c) {
    raster::Target t = vga::page_target(page);
    lib::StrView lines[PAGE_LINES];
    for (int i = 0; i < p.count; ++i) lines[i] = lib::StrView{p.text[i], lib::c_length(p.text[i])};
    raster::fill_target(t, c.paper);
    raster::draw_text_box(t, 0, 0, lines, p.count, c);
}

// Shows page k (0: the machine, then the tables, then the QR codes) and reports it on COM1.
void show_page(const Setup& s, int k, raster::TextColours c) {
    static Page p;
    p.count = 0;
    const int of = page_count(s), page = vga::shown_page() == 0 ? 1 : 0;
    int part = -1;
    if (k == 0) {
        machine_page(s, &p);
    } else {
        int at = 1;
        for (int i = 0; i < s.scene_count && part < 0 && p.count == 0; ++i) {
            const int pages = table_pages(scene_rows(i));
            if (k < at + pages) table_page(s, i, k - at, pages, &p);
            at += pages;
        }
        if (p.count == 0) part = k - at;
    }
    lib::JsonLine e(serial::sink());
    e.str("event", "bench_page").u32("page", uint32_t(k)).u32("of", uint32_t(of));
    if (part < 0) {
        draw_page_text(p, page, c);
        e.begin_array("lines");
        for (int i = 0; i < p.count; ++i) e.item_str(p.text[i]);
        e.end_array();
    } else {
        // the part's header and its lines, as one QR code under a line of text
        static char text[4096];
        lib::Fmt head;
        head.s("modexlab-bench part ").u(uint32_t(part + 1)).s("/").u(uint32_t(g_part_count)).s("\n");
        int n = 0;
        for (const char* h = head.c_str(); *h; ++h) text[n++] = *h;
        for (int i = g_part_start[part]; i < g_part_start[part + 1] && n < int(sizeof text) - 1; ++i) text[n++] = g_csv[i];
        text[n] = 0;
        lib::qr_encode(reinterpret_cast<const uint8_t*>(text), size_t(n), lib::QrLevel::L, &g_qr);
        lib::Fmt caption;
        caption.s("CSV of the run, part ").u(uint32_t(part + 1)).s(" of ").u(uint32_t(g_part_count));
        lib::StrView l{caption.c_str(), lib::c_length(caption.c_str())};
        raster::Target t = vga::page_target(page);
        raster::fill_target(t, c.ink);  // (light all round the code: its quiet zone and more)
        raster::draw_text_box(t, 0, 0, &l, 1, c);
        raster::draw_qr(t, g_qr, c);
        e.str("qr", text).u32("qr_version", uint32_t(g_qr.version));
    }
    vga::flip(page);  // (then the event: what it names is on the screen)
    e.end();
}

}  // namespace

namespace {

// A duration to the nearest second, in the largest units that read well: "42 s", "3 min 5 s", "1 h 12 min".
lib::Fmt& put_duration(lib::Fmt& m, uint64_t seconds) {
    if (seconds >= 3600) return m.u(uint32_t(seconds / 3600)).s(" h ").u(uint32_t(seconds % 3600 / 60)).s(" min");
    if (seconds >= 60) return m.u(uint32_t(seconds / 60)).s(" min ").u(uint32_t(seconds % 60)).s(" s");
    return m.u(uint32_t(seconds)).s(" s");
}

// The progress line over every frame of row `row` (from 1) of `total`: the scene, the mapper, and
// the time left at the pace of the rows done since `started` (none before the first).
void progress_line(lib::Fmt& m, int row, int total, const char* scene, const char* mapper, uint64_t started) {
    m.s("bench ").u(uint32_t(row)).s("/").u(uint32_t(total)).s(": ").s(scene).s(" ").s(mapper);
    if (row == 1) return;
    const uint64_t per_row = timer::since(started) / uint64_t(row - 1), hz = timer::hz();
    put_duration(m.s(", about "), (per_row * uint64_t(total - row + 1) + hz / 2) / hz).s(" left");
}

}  // namespace

bool run(const Setup& s, NextKey next_key, void* ctx) {
    g_row_count = 0;
    const raster::Probe probe = current_world::bench_probe();
    // the bench command's watch: a byte on COM1 stops a long frame (and so the bench), a page fault
    // names the mapper and polygon; and the same instructions as the command's, which it is compared with
    server::Progress progress{"bench", 0, 0};
    const raster::Watch watch = progress.watch();
    raster::TextColours colours{15, 0};
    bool stopped = false;
    const int scenes = s.scene_count < MAX_SCENES ? s.scene_count : MAX_SCENES;
    const int total = scenes * raster::MAPPER_COUNT;
    const uint64_t started = timer::now();
    for (int i = 0; i < scenes && !stopped; ++i) {
        const file_table::File& f = file_table::at(s.scenes[i]);
        raster::ParseError pe;
        if (!current_world::load(f.name, f.data, f.size, &pe)) {  // (too large for the memory left, a bad module)
            current_world::say_skipped(f.name, pe);
            continue;
        }
        colours = raster::text_colours(current_world::world().palette);
        for (int m = 0; m < raster::MAPPER_COUNT && !stopped; ++m) {
            const raster::Mapper& mapper = raster::MAPPERS[m];
            lib::Fmt line;
            progress_line(line, g_row_count + 1, total, f.name, mapper.name, started);
            Row& r = g_rows[g_row_count++];
            r = Row{i, m, 0, 0, 0, 0, -1, false};
            current_world::start_bench_row();
            for (uint32_t k = 0; k < s.frames; ++k) {
                if (server::line_arrived()) return false;
                if (next_key(ctx) == lib::Key::Escape) {
                    stopped = r.interrupted = true;
                    break;
                }
                const current_world::BenchFrame b =
                    current_world::bench_frame(k, s.frames, mapper, raster::home_surface(mapper), raster::Variant::Asm, probe, &watch, line.c_str());
                if (b.cut) return false;  // a line came: the server takes over
                r.pixels += b.stats.pixels, r.polygons += b.stats.polygons;
                r.ticks_inner += b.figures[current_world::B_INNER], r.ticks_frame += b.figures[current_world::B_TICKS];
            }
            double e;
            if (raster::measured_error(f.name, mapper.name, &e)) r.error = e;
            lib::JsonLine j(serial::sink());
            j.str("event", "bench_row").str("scene", f.name).str("mapper", mapper.name).u32("frames", s.frames);
            j.u64("pixels", r.pixels).u64("polygons", r.polygons).u64("ticks_inner", r.ticks_inner).u64("ticks", r.ticks_frame);
            if (r.error >= 0) j.fixed("max_footprint_error", r.error, 3);
            else j.str("max_footprint_error", "none measured");
            j.boolean("interrupted", r.interrupted).u32("row", uint32_t(g_row_count)).u32("of", uint32_t(total)).str("progress", line.c_str()).end();
        }
    }
    build_csv(s);
    {
        lib::JsonLine j(serial::sink());
        j.str("event", "bench_done").u32("rows", uint32_t(g_row_count)).boolean("interrupted", stopped);
        j.begin_object("cpu").str("vendor", s.cpu->has_cpuid ? s.cpu->vendor : "no CPUID").u32("family", s.cpu->family);
        j.u32("model", s.cpu->model).u32("stepping", s.cpu->stepping).str("brand", s.cpu->brand).end_object();
        j.str("cpu_class", cpu::class_name(*s.cpu)).str("isa", isa::name(isa::in_use()));
        j.str("clock", timer::clock_name(timer::clock())).u64("clock_hz", timer::hz()).u64("cpu_hz", timer::cpu_hz());
        j.u64("tsc_hz", timer::tsc_hz()).u32("csv_bytes", uint32_t(g_csv_length)).u32("qr_codes", uint32_t(g_part_count)).u32("pages", uint32_t(page_count(s))).end();
    }
    int k = 0;
    show_page(s, k, colours);
    const int last = page_count(s) - 1;
    for (;;) {
        if (server::line_arrived()) return false;
        const lib::Key key = next_key(ctx);
        if (key == lib::Key::Escape || key == lib::Key::B) return true;
        if ((key == lib::Key::Right || key == lib::Key::N || key == lib::Key::Space || key == lib::Key::PageDown) && k < last) show_page(s, ++k, colours);
        if ((key == lib::Key::Left || key == lib::Key::P || key == lib::Key::PageUp) && k > 0) show_page(s, --k, colours);
    }
}

}  // namespace onscreen
