// The boot show: scenes played frame by frame, or patterns; the keyboard drives it, the serial
// line interrupts it.
#include "kernel/show/show.h"

#include "drivers/keyboard.h"
#include "drivers/serial.h"
#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/core/budget.h"
#include "kernel/present/patterns.h"
#include "kernel/present/file_table.h"
#include "kernel/lib/fmt.h"
#include "kernel/lib/json.h"
#include "kernel/lib/keys.h"
#include "kernel/show/onscreen.h"
#include "kernel/scene/text.h"
#include "kernel/server/commands.h"
#include "kernel/present/current_world.h"

namespace show {

namespace {

bool byte_waiting(void*) { return server::line_arrived(); }

bool is_world(const file_table::File& f) {
    raster::ParseError e;
    return raster::scene_version(reinterpret_cast<const char*>(f.data), f.size, &e) == 2;
}

void patterns(uint32_t interval_ms) {
    for (uint32_t n = 0;; ++n) {
        if (server::line_arrived()) return;
        int page = (vga::shown_page() + 1) % vga::MODEX_PAGES;
        patterns::draw(raster::Pattern(n % raster::PATTERN_COUNT), page);
        vga::flip(page);
        if (timer::wait_ms_or(interval_ms, byte_waiting, nullptr)) return;
    }
}

// The budgets the keys step through (auto), in footprints; ANY_ERROR last.
constexpr double BUDGET_STEPS[] = {0, 0.5, 1, 2, 4, raster::ANY_ERROR};
constexpr int BUDGET_STEP_COUNT = sizeof(BUDGET_STEPS) / sizeof(BUDGET_STEPS[0]);
double budget_order(double e) { return e < 0 ? 1e300 : e; }  // any: above every number

constexpr int MAX_SCENES = 64;
constexpr int HUD_LINES = 10, HUD_CHARS = 40, HUD_SHARES = 6;

struct Show {
    Options options;
    int scenes[MAX_SCENES];  // file indices of the 3D scenes
    int scene_count = 0;
    int scene = 0;            // of scenes[]
    bool pinned = false;      // stay on the scene (picked by a key or the boot options)
    bool loaded = false;
    const raster::Mapper* mapper = nullptr;
    raster::Surface surface = raster::Surface::Linear;
    bool paused = false, hud = true, help = false;
    int32_t next_frame = 0, shown_frame = -1;
    raster::TextColours colours{15, 0};
    lib::ScanDecoder decoder;
    // the figures: the last frame's, and when the one before it began (fps over consecutive frames)
    uint64_t last_start = 0, last_hud_ticks = 0;
    bool running_before = false;
    char hud_text[HUD_LINES][HUD_CHARS + 1] = {};
    int hud_count = 0;
    char skipped[HUD_CHARS + 1] = {};  // the HUD's note of the last scene skipped, until the show moves on
    bool served = false;  // a byte on COM1 ended the on-screen bench: the show gives way
};

const file_table::File& scene_file(const Show& s) { return file_table::at(s.scenes[s.scene]); }

// Loads the current scene; one that cannot be (too large for this machine's memory, a bad
// module) is skipped, said on COM1 (a scene_skipped event with the reason) and in the HUD.
bool load_scene(Show& s) {
    const file_table::File& f = scene_file(s);
    raster::ParseError e;
    s.loaded = current_world::load(f.name, f.data, f.size, &e);
    if (s.loaded) s.colours = raster::text_colours(current_world::world().palette);
    s.next_frame = 0;
    if (!s.loaded) {
        current_world::say_skipped(f.name, e);
        lib::Fmt note;  // (the HUD's line is short: COM1 has the whole reason)
        const bool memory = lib::StrView{e.message, lib::c_length(e.message)}.starts_with("not enough memory");
        note.s("skipped ").s(f.name).s(memory ? ": no memory" : ": error");
        lib::copy_c_string(s.skipped, sizeof s.skipped, note.c_str());
    }
    return s.loaded;
}
// The current scene or, where it is skipped, the next that loads; false when none does.
bool load_some_scene(Show& s) {
    for (int tries = 0; tries < s.scene_count; ++tries, s.scene = (s.scene + 1) % s.scene_count)
        if (load_scene(s)) return true;
    return false;
}

void set_line(Show& s, const lib::Fmt& f) {
    if (s.hud_count < HUD_LINES) lib::copy_c_string(s.hud_text[s.hud_count++], HUD_CHARS + 1, f.c_str());
}

// The HUD's lines for a frame just drawn: the scene and frame, the mapper (auto: its budget and
// shares), frames a second and cycles a pixel (TSC; the HUD's own drawing left out), the surface.
void compose_hud(Show& s, const current_world::FrameResult& r, uint64_t period) {
    s.hud_count = 0;
    lib::Fmt a;
    a.s(current_world::name()).s("  frame ").u(uint32_t(s.shown_frame)).s("/").u(uint32_t(current_world::world().frames));
    set_line(s, a);
    if (s.skipped[0]) set_line(s, lib::Fmt().s(s.skipped));
    lib::Fmt b;
    b.s(s.mapper->name);
    if (s.mapper->is_auto) {
        const raster::Budget budget = current_world::budget();
        b.s(", budget ");
        if (budget.max_error < 0) b.s("any");
        else b.decimal(budget.max_error);
        b.s(budget.exact_coverage ? " exact" : " any");
    }
    set_line(s, b);
    lib::Fmt c;
    if (s.paused) c.s("paused");
    else if (period > 0) c.tenths(timer::hz() * 10 / period).s(" fps");
    else c.s("- fps");
    c.s(s.surface == raster::Surface::Vga ? ", VGA memory" : ", RAM + blit");
    set_line(s, c);
    const uint32_t pixels = r.render.stats.pixels;
    lib::Fmt d;
    if (pixels == 0) d.s("no pixels drawn");
    else {
        const uint64_t all = r.ticks_geometry + r.render.ticks_clear + r.render.ticks_draw + r.render.ticks_blit;
        d.s(timer::unit_shown()).s("/px ");
        d.tenths(timer::tenths_shown(r.render.ticks_draw) / pixels);
        d.s(" drawing, ");
        d.tenths(timer::tenths_shown(all) / pixels);
        d.s(" all");
        if (timer::clock() == timer::Clock::Pit) d.s(" (PIT)");
    }
    set_line(s, d);
    if (!s.mapper->is_auto || pixels == 0) return;
    // auto: the mappers that drew pixels, the most first, with their shares
    bool listed[raster::MAPPER_LIMIT] = {};
    for (int k = 0; k < HUD_SHARES; ++k) {
        int best = -1;
        for (int i = 0; i < raster::MAPPER_COUNT; ++i)
            if (!listed[i] && r.render.stats.mapper_pixels[i] > 0 && (best < 0 || r.render.stats.mapper_pixels[i] > r.render.stats.mapper_pixels[best])) best = i;
        if (best < 0) break;
        listed[best] = true;
        lib::Fmt e;
        e.u(uint32_t(uint64_t(r.render.stats.mapper_pixels[best]) * 100 / pixels)).s("% ").s(raster::MAPPERS[best].name);
        set_line(s, e);
    }
}

void draw_hud(Show& s, int page) {
    raster::Target t = vga::page_target(page);
    lib::StrView lines[HUD_LINES];
    for (int i = 0; i < s.hud_count; ++i) lines[i] = lib::StrView{s.hud_text[i], lib::c_length(s.hud_text[i])};
    raster::draw_text_box(t, raster::HUD_X, raster::HUD_Y, lines, s.hud_count, s.colours);
}

// Draws frame n into the back page, the HUD over it, and flips. `running`: a frame of the
// animation going on (its period counts for the frames a second), not a redraw.
void draw_frame(Show& s, int32_t n, bool running) {
    const int page = vga::shown_page() == 0 ? 1 : 0;
    const uint64_t start = timer::now();
    const current_world::FrameResult r = current_world::render(n, *s.mapper, s.surface, page, raster::Variant::Asm);
    s.shown_frame = n;
    const uint64_t period = running && s.running_before ? start - s.last_start - s.last_hud_ticks : 0;
    const uint64_t hud_start = timer::now();
    s.hud_count = 0;
    if (s.hud) {
        compose_hud(s, r, period);
        draw_hud(s, page);
    }
    s.last_hud_ticks = timer::since(hud_start);
    s.last_start = start;
    s.running_before = running;
    vga::flip(page);
}

void draw_help_page(Show& s) {
    const int page = vga::shown_page() == 0 ? 1 : 0;
    raster::Target t = vga::page_target(page);
    raster::draw_help(t, s.colours);
    vga::flip(page);
}

void step_budget(int direction) {
    raster::Budget b = current_world::budget();
    const double now = budget_order(b.max_error);
    int pick = -1;
    for (int i = 0; i < BUDGET_STEP_COUNT; ++i) {
        const double step = budget_order(BUDGET_STEPS[i]);
        if (direction > 0 && step > now) {
            pick = i;
            break;
        }
        if (direction < 0 && step < now) pick = i;
    }
    if (pick < 0) return;
    b.given = true;
    b.max_error = BUDGET_STEPS[pick];
    current_world::set_budget(&b);
}

int mapper_index(const raster::Mapper* m) { return int(m - raster::MAPPERS); }

// The next key pressed on the keyboard (releases and other bytes skipped), or None.
lib::Key next_key(void* ctx) {
    Show& s = *static_cast<Show*>(ctx);
    uint8_t byte;
    lib::KeyEvent ev;
    while (keyboard::next_byte(&byte))
        if (s.decoder.feed(byte, &ev) && ev.pressed) return ev.key;
    return lib::Key::None;
}

// The on-screen bench over `scenes` (frames a row), then the show's scene again; false when a byte
// on COM1 ended it.
bool bench(Show& s, const int* scenes, int count, uint32_t frames) {
    const onscreen::Setup setup{scenes, count, frames, s.options.cpu};
    const bool on = onscreen::run(setup, next_key, &s);
    load_scene(s);
    s.running_before = false;
    return on;
}

// What a key press does; then its event on COM1, with what is on the screen.
void on_key(Show& s, lib::Key key) {
    const lib::Action action = s.help ? lib::Action::Help : lib::action_for(key);
    bool redraw = s.paused;  // a change while paused shows at once
    bool moved = false;      // to another scene: its first frame
    switch (action) {
    case lib::Action::NextScene:
    case lib::Action::PreviousScene:
        s.scene = (s.scene + (action == lib::Action::NextScene ? 1 : s.scene_count - 1)) % s.scene_count;
        s.pinned = true;
        moved = true;
        break;
    case lib::Action::NextMapper:
    case lib::Action::PreviousMapper:
        s.mapper = &raster::MAPPERS[(mapper_index(s.mapper) + (action == lib::Action::NextMapper ? 1 : raster::MAPPER_COUNT - 1)) % raster::MAPPER_COUNT];
        break;
    case lib::Action::BudgetUp:
    case lib::Action::BudgetDown: step_budget(action == lib::Action::BudgetUp ? 1 : -1); break;
    case lib::Action::Pause:
        s.paused = !s.paused;
        redraw = s.paused;  // the paused frame again, its HUD saying so
        break;
    case lib::Action::Step:
        s.paused = true;
        redraw = false;
        if (s.loaded) {
            draw_frame(s, s.next_frame, false);
            s.next_frame = (s.next_frame + 1) % current_world::world().frames;
        }
        break;
    case lib::Action::Surface: s.surface = s.surface == raster::Surface::Vga ? raster::Surface::Linear : raster::Surface::Vga; break;
    case lib::Action::Hud: s.hud = !s.hud; break;
    case lib::Action::Help:
        s.help = !s.help;  // (while the help is up, any key leaves it)
        redraw = !s.help;
        if (s.help) draw_help_page(s);
        break;
    case lib::Action::Bench:
        s.served = !bench(s, s.scenes, s.scene_count, onscreen::DEFAULT_FRAMES);
        redraw = !s.served;
        break;
    case lib::Action::None: redraw = false; break;
    }
    if (s.served) return;  // (the server answers next: no event before its reply)
    if (moved && load_scene(s)) redraw = true;
    if (moved && s.loaded && !s.paused) redraw = false;  // the animation goes on from the new scene's first frame
    if (redraw && s.loaded && !s.help) {
        const int32_t n = moved ? 0 : s.shown_frame < 0 ? 0 : s.shown_frame;
        draw_frame(s, n, false);
        s.next_frame = (n + 1) % current_world::world().frames;
    }
    lib::JsonLine e(serial::sink());
    e.str("event", "key").str("key", lib::key_name(key)).str("action", lib::action_name(action));
    e.str("scene", s.loaded ? current_world::name() : "").i32("frame", s.shown_frame).str("mapper", s.mapper->name);
    server::write_budget(e, "budget", current_world::budget());
    e.boolean("paused", s.paused).str("surface", s.surface == raster::Surface::Vga ? "vga" : "ram").boolean("help", s.help);
    e.begin_array("hud");
    for (int i = 0; i < s.hud_count; ++i) e.item_str(s.hud_text[i]);
    e.end_array().end();
}

// Key presses waiting, handled in order; false when a byte on COM1 ends the show.
bool keys(Show& s) {
    for (lib::Key k; !s.served && (k = next_key(&s)) != lib::Key::None;) on_key(s, k);
    return !s.served && !server::line_arrived();
}

void play(Show& s) {
    s.loaded = false;
    if (!load_some_scene(s)) return;
    for (;;) {
        if (!keys(s)) return;
        if (s.paused || s.help || !s.loaded) continue;
        draw_frame(s, s.next_frame, true);
        if (++s.next_frame < current_world::world().frames) continue;
        s.next_frame = 0;
        if (s.pinned) continue;
        s.scene = (s.scene + 1) % s.scene_count;  // the animation played: on to the next scene
        s.running_before = false;
        s.skipped[0] = 0;  // (a note made now stays while the scene after the skip plays)
        if (!load_some_scene(s)) return;
    }
}

}  // namespace

void run(const Options& o) {
    if (vga::mode() != vga::Mode::ModeX) vga::set_mode_x();
    if (o.patterns) return patterns(o.interval_ms);
    static Show s;  // (its HUD text: off the kernel's stack)
    s = Show{};
    s.options = o;
    s.mapper = o.mapper.empty() ? nullptr : raster::find_mapper(o.mapper);
    if (!s.mapper) s.mapper = raster::find_mapper("auto");
    for (int i = 0; i < file_table::count() && s.scene_count < MAX_SCENES; ++i) {
        const file_table::File& f = file_table::at(i);
        if (!is_world(f) || file_table::find(lib::StrView{f.name, lib::c_length(f.name)}) != &f) continue;  // (shadowed by a module)
        if (!o.scene.empty() && o.scene.equals(f.name)) s.scene = s.scene_count, s.pinned = true;
        s.scenes[s.scene_count++] = i;
    }
    if (s.scene_count == 0 || (!o.scene.empty() && !s.pinned)) return patterns(o.interval_ms);  // none, or no such scene
    if (o.bench_frames > 0 && !bench(s, s.pinned ? &s.scenes[s.scene] : s.scenes, s.pinned ? 1 : s.scene_count, o.bench_frames)) return;
    play(s);
}

}  // namespace show
