// Argument helpers the handlers share: pages, the drawing and animation arguments, and the errors
// that name the choices, listed from the same tables the parsers read so that they cannot drift.
#include "drivers/vga.h"
#include "drivers/serial.h"
#include "drivers/timer.h"
#include "kernel/platform/idt.h"
#include "kernel/core/policy.h"
#include "kernel/server/commands.h"
#include "kernel/server/reply.h"
#include "kernel/present/current_world.h"

namespace server {

namespace {

// What each surface does, in Surface's order: the names come from raster::surface_name.
constexpr const char* SURFACE_WORDS[raster::SURFACE_COUNT] = {"rows in RAM then blit", "columns in RAM then blit",
                                                               "columns into the page"};

// The inner-loop variants, the default first.
struct VariantName {
    raster::Variant variant;
    const char* name;
    const char* words;
};
constexpr VariantName VARIANTS[] = {
    {raster::Variant::Asm, "asm", "the NASM loop where there is one"},
    {raster::Variant::Twin, "twin", "the C++ twin"},
};
constexpr int VARIANT_COUNT = sizeof(VARIANTS) / sizeof(VARIANTS[0]);

void unknown_surface(const char* cmd, StrView word) {
    lib::Fmt m;
    m.s("unknown surface '").s(word).s("' (");
    for (int i = 0; i < raster::SURFACE_COUNT; ++i)
        m.s(i ? "; " : "").s(raster::surface_name(raster::Surface(i))).s(": ").s(SURFACE_WORDS[i]);
    reply::error(cmd, m.s(")").c_str());
}

bool parse_variant(const char* cmd, StrView word, raster::Variant* out) {
    for (const VariantName& v : VARIANTS) {
        if (!word.equals(v.name)) continue;
        *out = v.variant;
        return true;
    }
    lib::Fmt m;
    m.s("unknown variant '").s(word).s("' (");
    for (int i = 0; i < VARIANT_COUNT; ++i) m.s(i ? "; " : "").s(VARIANTS[i].name).s(": ").s(VARIANTS[i].words);
    reply::error(cmd, m.s(")").c_str());
    return false;
}

// Why the mapper cannot draw through the surface: its walkers, and the target it needs.
void cannot_draw_through(const char* cmd, const raster::Mapper& mp, raster::Surface s) {
    lib::Fmt m;
    m.s("mapper ").s(mp.name).s(" cannot draw through surface ").s(raster::surface_name(s)).s(" (it walks");
    for (raster::Axis axis : WALKERS)
        if (raster::mapper_walks(mp, axis)) m.s(" ").s(walker_name(axis));
    if (mp.needs & raster::NEED_PLANAR_TARGET) {
        m.s(" and needs ");
        raster::describe_needs(m, raster::NEED_PLANAR_TARGET);
    }
    reply::error(cmd, m.s(")").c_str());
}

}  // namespace

bool interrupted(uint32_t step) { return step > 0 && line_arrived(); }

raster::Watch Progress::watch() { return raster::Watch{keep_going, this, &idt::drawing_now()}; }

bool Progress::keep_going(void* ctx, uint32_t done, uint32_t total) {
    if (line_arrived()) return false;
    auto* p = static_cast<Progress*>(ctx);
    const uint64_t now = timer::now();
    if (p->interval && now >= p->next) {
        lib::JsonLine(serial::sink()).str("event", "progress").str("cmd", p->cmd).u32("polygons", done).u32("of", total).end();
        p->next = now + p->interval;
    }
    return true;
}

Progress progress(const char* cmd, const Context&) { return Progress{cmd, timer::hz(), timer::now() + timer::hz()}; }

void usage_error(const char* cmd) {
    const Command* c = find_command(StrView{cmd, lib::c_length(cmd)});
    lib::Fmt m;
    m.s("usage: ").s(c ? c->usage : cmd);
    reply::error(cmd, m.c_str());
}

void unknown_name_error(const char* cmd, const char* kind, StrView word, NameAt name_at, int count) {
    lib::Fmt m;
    m.s("unknown ").s(kind).s(" '").s(word).s("' (").s(kind).s("s: ");
    for (int i = 0; i < count; ++i) m.s(i ? ", " : "").s(name_at(i));
    reply::error(cmd, m.s(")").c_str());
}

bool parse_page(const char* cmd, StrView word, int* page) {
    if (vga::page_count() == 0) {
        reply::error(cmd, "no graphics mode: send 'mode modex' or 'mode 13h' first");
        return false;
    }
    uint32_t p;
    if (!lib::parse_u32(word, &p) || p >= uint32_t(vga::page_count())) {
        lib::Fmt m;
        m.s("bad page '").s(word).s("': mode ").s(vga::mode_name(vga::mode())).s(" has pages 0..").u(uint32_t(vga::page_count() - 1));
        reply::error(cmd, m.c_str());
        return false;
    }
    *page = int(p);
    return true;
}

bool parse_draw_args(const char* cmd, const StrView* args, size_t nargs, bool with_page, DrawArgs* d) {
    d->mapper = raster::find_mapper(args[0]);
    if (!d->mapper) {
        unknown_name_error(cmd, "mapper", args[0], [](int i) { return raster::MAPPERS[i].name; }, raster::MAPPER_COUNT);
        return false;
    }
    if (vga::mode() != vga::Mode::ModeX) {
        lib::Fmt m;
        m.s(cmd).s(" draws into Mode X pages: send 'mode modex' first");
        reply::error(cmd, m.c_str());
        return false;
    }
    size_t next = 1;
    if (with_page && !parse_page(cmd, args[next++], &d->page)) return false;
    d->surface = raster::home_surface(*d->mapper);  // (unless a surface is named)
    if (nargs > next && !raster::surface_from_name(args[next], &d->surface)) {
        unknown_surface(cmd, args[next]);
        return false;
    }
    ++next;
    if (nargs > next && !parse_variant(cmd, args[next], &d->variant)) return false;
    d->axis = raster::surface_axis(*d->mapper, d->surface);
    if (!raster::draws_through(*d->mapper, d->surface)) {
        cannot_draw_through(cmd, *d->mapper, d->surface);
        return false;
    }
    return true;
}

bool parse_animation_args(const char* cmd, const StrView* args, size_t nargs, uint32_t most, const char* count_note,
                          uint32_t* frames, DrawArgs* d) {
    if (!lib::parse_u32(args[0], frames) || *frames == 0 || *frames > most) {
        lib::Fmt m;
        m.s("bad frame count: 1..").u(most).s(count_note);
        reply::error(cmd, m.c_str());
        return false;
    }
    return parse_draw_args(cmd, args + 1, nargs - 1, false, d) && need_world(cmd);
}

bool need_world(const char* cmd) {
    if (current_world::loaded()) return true;
    reply::error(cmd, "no 3D scene: 'load NAME' one (see 'files') or upload one with 'scene BYTES CRC32'");
    return false;
}


}  // namespace server
