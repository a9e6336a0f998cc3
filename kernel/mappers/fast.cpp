// The fast mappers' run loops: the C++ twins of asm/fast.asm's loops (fast_run_loop,
// fast_table_loop, fast_column_run, fast_table_column_loop), their random checks, and the layouts
// the NASM reads. The drivers: fast_draw.cpp.
#include "kernel/mappers/fast.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/selftest.h"

namespace raster {

namespace {

// The lines of a run, and of the next one where there is one, as the NASM run loops walk them
// (rows: FastRunArgs; columns: FastColumnRunArgs): each line's two bounds stepped in place and its
// span clipped and tallied; line(lo, hi) for every line in order, lo > hi where it is empty.
template <typename Args, typename Line>
void walk_lines(const Args& a, Line&& line) {
    if (a.lines <= 0) return;
    EdgeBound *lower = a.lower, *upper = a.upper;
    for (int32_t lines = a.lines, part = 0; part < 2; ++part, lines = a.next_lines, lower = a.next_lower, upper = a.next_upper)
        for (int32_t n = 0; n < lines; ++n) {
            const int32_t lo = lower->q > a.clip_lo ? lower->q : a.clip_lo, hi = upper->q < a.clip_hi ? upper->q : a.clip_hi;
            lower->step();
            upper->step();
            if (lo <= hi) a.tally[0] += 1, a.tally[1] += uint32_t(hi - lo + 1);
            line(lo, hi);
        }
}

// The rows of a run, and of the next one where there is one, as both run loops walk them:
// span(row, lo, hi, u, v) draws pixels lo..hi of a non-empty row, u and v (16.16) the row's as
// FastRunArgs gives them.
template <typename Span>
void run_rows(const FastRunArgs& a, Span&& span) {
    uint8_t* row = a.row;
    uint32_t u = a.u_16_16, v = a.v_16_16;
    walk_lines(a, [&](int32_t lo, int32_t hi) {
        if (lo <= hi) span(row, lo, hi, u, v);
        row += a.pitch;
        u += a.u_row_16_16;
        v += a.v_row_16_16;
    });
}

}  // namespace

namespace {

// The NASM loops' texel pointer into a doubled copy (an offset here), stepped as they step it: the
// wholes of du and dv, and one more column or row on each fraction's carry; its pixels `stride`
// bytes apart from dst, from 16.16 u and v whose wholes are the column and row in the copy.
void doubled_pixels(const uint8_t* texture, int32_t pitch, int32_t du, int32_t dv, uint32_t u, uint32_t v, uint8_t* dst, int32_t count, int32_t stride) {
    const uint32_t p = uint32_t(pitch), du_fraction = uint32_t(du) << 16, dv_fraction = uint32_t(dv) << 16;
    const uint32_t step = uint32_t(dv >> 16) * p + uint32_t(du >> 16);
    uint32_t at = (v >> 16) * p + (u >> 16), u_fraction = u << 16, v_fraction = v << 16;
    for (int32_t n = 0; n < count; ++n, dst += stride) {
        *dst = texture[at];
        const uint32_t carry_v = v_fraction + dv_fraction < v_fraction, carry_u = u_fraction + du_fraction < u_fraction;
        v_fraction += dv_fraction;
        u_fraction += du_fraction;
        at += step + carry_v * p + carry_u;
    }
}

// The 8:16 core's pixels on the tiled block, (u whole & 255, v whole & 255), as doubled_pixels'.
void tiled_pixels(const uint8_t* block, int32_t du, int32_t dv, uint32_t u, uint32_t v, uint8_t* dst, int32_t count, int32_t stride) {
    for (int32_t n = 0; n < count; ++n, dst += stride) {
        *dst = texel256(block, u, v);
        u += uint32_t(du);
        v += uint32_t(dv);
    }
}

// run_rows' spans as runs of pixels: draw(dst, count, u, v), u and v at the span's first pixel.
template <typename Pixels>
void run_row_pixels(const FastRunArgs& a, Pixels&& draw) {
    run_rows(a, [&](uint8_t* row, int32_t lo, int32_t hi, uint32_t u, uint32_t v) {
        draw(row + lo, hi - lo + 1, u + uint32_t(lo) * uint32_t(a.du_16_16), v + uint32_t(lo) * uint32_t(a.dv_16_16));
    });
}

}  // namespace

void fast_run_loop(const void* raw) {
    const auto& a = *static_cast<const FastRunArgs*>(raw);
    run_row_pixels(a, [&](uint8_t* dst, int32_t count, uint32_t u, uint32_t v) {
        if (a.source == DOUBLED_COPY) doubled_pixels(a.texture, a.block_pitch, a.du_16_16, a.dv_16_16, u, v, dst, count, 1);
        else tiled_pixels(a.texture, a.du_16_16, a.dv_16_16, u, v, dst, count, 1);
    });
}

void wrapping_pixels(const Texture& tex, int32_t du, int32_t dv, uint32_t u, uint32_t v, uint8_t* dst, int32_t count, int32_t stride) {
    const TableBlock texture{tex.texels, uint32_t(tex.width - 1), uint32_t(tex.height - 1), tex.width};  // (the texture itself, by masks)
    for (int32_t n = 0; n < count; ++n, dst += stride) {
        *dst = *texture.at(u, v);
        u += uint32_t(du);
        v += uint32_t(dv);
    }
}

void fast_run_loop_wrapping(const FastRunArgs& a, const Texture& tex) {
    run_row_pixels(a, [&](uint8_t* dst, int32_t count, uint32_t u, uint32_t v) { wrapping_pixels(tex, a.du_16_16, a.dv_16_16, u, v, dst, count, 1); });
}

void fast_table_loop(const void* raw) {
    const auto& a = *static_cast<const FastRunArgs*>(raw);
    const TableBlock block{a.texture, a.u_mask, a.v_mask, a.block_pitch};
    run_rows(a, [&](uint8_t* row, int32_t lo, int32_t hi, uint32_t u, uint32_t v) {
        const uint8_t* origin = block.at(u, v);  // the table's first pixel's texel
        for (int32_t x = lo; x <= hi; ++x) row[x] = origin[a.table[x]];
    });
}

void fast_table_column_loop(const void* raw) {
    const auto& a = *static_cast<const FastTableColumnArgs*>(raw);
    for (int32_t n = 0; n < a.count; ++n) a.dst[n * MODEX_ROW_BYTES] = a.source[a.table[n]];
}

void fast_column_run(const void* raw) {
    const auto& a = *static_cast<const FastColumnRunArgs*>(raw);
    const Target& t = *a.target;
    int32_t x = a.x;
    uint32_t u = a.u_16_16, v = a.v_16_16;
    walk_lines(a, [&](int32_t lo, int32_t hi) {
        if (lo <= hi) {
            if (t.select_plane) t.select_plane(t.ctx, x & 3);
            uint8_t* dst = t.base + (x & 3) * t.plane_bytes + lo * MODEX_ROW_BYTES + (x >> 2);
            const uint32_t su = u + uint32_t(lo) * uint32_t(a.du_16_16), sv = v + uint32_t(lo) * uint32_t(a.dv_16_16);  // at the first pixel
            if (a.block_pitch) doubled_pixels(a.texture, a.block_pitch, a.du_16_16, a.dv_16_16, su, sv, dst, hi - lo + 1, MODEX_ROW_BYTES);
            else tiled_pixels(a.texture, a.du_16_16, a.dv_16_16, su, sv, dst, hi - lo + 1, MODEX_ROW_BYTES);
        }
        ++x;
        u += a.u_column_16_16;
        v += a.v_column_16_16;
    });
}

namespace {

// fast_table_column_loop's block with the table it reads.
struct TableColumnCase {
    FastTableColumnArgs args;
    int32_t table[TABLE_LIMIT];
};

}  // namespace

template <>
void move_to_b(TableColumnCase& b, const TableColumnCase& a, const CheckBuffers& buf) {
    b.args.dst = buf.b + (a.args.dst - buf.a);
    b.args.table = b.table;
}

template <>
const void* check_block(const TableColumnCase& a) {
    return &a.args;
}

namespace {

// A doubled copy over the check's texels as a table block, of random power-of-two sides up to 1024
// (above256: one above 256, as fast-affine reads it) whose copy fits the buffer.
TableBlock random_doubled_block(Random& r, const CheckBuffers& buf, bool above256) {
    int32_t w, h;
    random_doubled_sides(r, &w, &h, above256);
    return TableBlock{buf.texels, uint32_t(w - 1), uint32_t(h - 1), doubled_pitch(w)};
}
// fast-affine's and fast-columns' texel pointer from the buffer's start, every start within it: wholes
// of u from 2300 to 4000 and of v from 150 to 300, u stepping by at most 4 texels a pixel or a row
// and v by a quarter, so over 330 pixels and 240 rows u stays within 20..6280 and v within 7..443:
// below 443 * 2064 + 6280 < 1 MiB (any fraction).
template <typename Args>
void random_doubled_uv(Random& r, Args& a) {
    a.u_16_16 = decltype(a.u_16_16)(uint32_t(r.range(2300, 3999)) << 16 | (r.next() & 0xFFFF));
    a.v_16_16 = decltype(a.v_16_16)(uint32_t(r.range(150, 299)) << 16 | (r.next() & 0xFFFF));
    a.du_16_16 = r.range(-0x40000, 0x40000);
    a.dv_16_16 = r.range(-0x4000, 0x4000);
}

}  // namespace

// Columns of 0 to 240 pixels from a random texel of a table block, the table of random steps.
LoopCheck check_fast_table_column(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<TableColumnCase>(m, other, seed, cases, buf, [&](Random& r, TableColumnCase& c) {
        FastTableColumnArgs& a = c.args;
        a.count = random_count(r, 0, 9, 240);
        const TableBlock block = random_doubled_block(r, buf, false);
        const uint32_t u = r.next(), v = r.next();
        a.source = block.at(u, v);
        const int32_t du = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        const int32_t dv = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        build_offset_table(du, dv, a.count, c.table, block);
        a.table = c.table;
        return place_span(buf, a, MODEX_ROW_BYTES);
    });
}

namespace {

// What a run loop updates, which must come out the same: its bounds and its tally.
struct RunState {
    EdgeBound lower, upper, next_lower, next_upper;
    uint32_t tally[2];
    // A run loop's block (FastRunArgs, FastColumnRunArgs) pointed at them, the tally cleared.
    template <typename Args>
    void attach(Args& a) {
        a.lower = &lower, a.upper = &upper, a.next_lower = &next_lower, a.next_upper = &next_upper;
        a.tally = tally;
        tally[0] = tally[1] = 0;
    }
    // The lines a run loop given `a` walks and the pixels it draws, from copies of the bounds (as
    // walk_lines walks them: the twins' walk).
    template <typename Args>
    uint32_t drawn(Args a, int32_t* lines) const {
        RunState copy = *this;
        copy.attach(a);
        int32_t walked = 0;
        walk_lines(a, [&](int32_t, int32_t) { ++walked; });
        *lines = walked;
        return copy.tally[1];
    }
    bool same(const RunState& o) const {
        auto same = [](const EdgeBound& x, const EdgeBound& y) { return x.q == y.q && x.r == y.r; };
        return same(lower, o.lower) && same(upper, o.upper) && same(next_lower, o.next_lower) && same(next_upper, o.next_upper) &&
               tally[0] == o.tally[0] && tally[1] == o.tally[1];
    }
};

// fast_run_loop's block (and fast_table_loop's) with what it updates and the offset table
// fast_table_loop reads.
struct RunCase : RunState {
    FastRunArgs args;
    int32_t table[TABLE_LIMIT];
};

}  // namespace

template <>
void move_to_b(RunCase& b, const RunCase& a, const CheckBuffers& buf) {
    b.args.row = buf.b + (a.args.row - buf.a);
    b.attach(b.args);
    b.args.table = b.table;
}

template <>
bool same_results(const RunCase& a, const RunCase& b) {
    return a.same(b);
}

template <>
const void* check_block(const RunCase& a) {
    return &a.args;
}

namespace {

// A random bound: q anywhere near the rows (often far outside the clip), steps of either sign,
// any remainder and divisor.
EdgeBound random_bound(Random& r, int32_t pitch) {
    EdgeBound b;
    b.first = b.last = 0;
    b.q = r.below(4) == 0 ? r.range(-100000, 100000) : r.range(-20, pitch + 20);
    b.dq = r.below(4) == 0 ? r.range(-400, 400) : r.range(-3, 3);
    b.d = r.below(4) == 0 ? 1 + r.next() % 0x80000000u : uint32_t(r.range(1, 4096));
    b.r = r.next() % b.d;
    b.dr = r.next() % b.d;
    return b;
}

}  // namespace

// fast_run_loop's and fast_table_loop's random cases: a run and the offset table of its steps.
LoopCheck check_fast_run(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<RunCase>(m, other, seed, cases, buf, [&](Random& r, RunCase& c) {
        FastRunArgs& a = c.args;
        // rows of up to 330 bytes; 240 of them fit the buffer with its guards
        a.pitch = r.below(2) ? 320 : r.range(1, 330);
        a.clip_lo = r.range(0, a.pitch - 1);
        a.clip_hi = r.below(8) == 0 ? a.clip_lo - 1 : r.range(a.clip_lo, a.pitch - 1);  // sometimes nothing
        // a third of the runs inside the clip (RUN_inside: its rows up to the first that leaves it)
        const bool inside = r.below(3) == 0 && a.clip_lo <= a.clip_hi;
        // a run's bounds and its rows, up to `most` (inside: up to the first row that leaves the clip)
        auto run = [&](EdgeBound& lower, EdgeBound& upper, int32_t most) {
            lower = random_bound(r, a.pitch);
            upper = random_bound(r, a.pitch);
            if (r.below(2)) upper.q = lower.q + r.range(0, a.pitch), upper.dq = lower.dq + r.range(-2, 2);  // a real-looking span
            if (!inside) return most;
            lower.q = r.range(a.clip_lo, a.clip_hi), lower.dq = r.range(-2, 2);
            upper.q = r.range(lower.q, a.clip_hi), upper.dq = lower.dq + r.range(-2, 2);
            EdgeBound lo = lower, hi = upper;
            int32_t n = 0;
            for (; n < most && (lo.q > hi.q || (lo.q >= a.clip_lo && hi.q <= a.clip_hi)); ++n) lo.step(), hi.step();
            return n;
        };
        a.lines = run(c.lower, c.upper, r.below(8) == 0 ? r.range(0, 3) : r.range(1, 240));
        // half of them with a next run right after (a polygon's second run in the same call), the
        // rows of both within 240; sometimes none said by 0 or less
        const int32_t room = 240 - (a.lines > 0 ? a.lines : 0);
        const int32_t most = r.below(4) == 0 || room < 1 ? r.range(-1, room < 3 ? room : 3) : r.range(1, room);
        a.next_lines = r.below(2) ? 0 : run(c.next_lower, c.next_upper, most);
        if (a.next_lines == 0) c.next_lower = c.next_upper = EdgeBound::constant(0);
        a.inside = inside ? 1 : 0;
        // the texture: fast-table's doubled copy (its pitch and masks), fast-affine's tiled block or a
        // third of the time a doubled copy
        const bool table = m.twin == fast_table_loop;
        a.source = table || r.below(3) == 0 ? DOUBLED_COPY : TILED_BLOCK;
        const TableBlock block = a.source == DOUBLED_COPY ? random_doubled_block(r, buf, !table) : TableBlock{check_aligned_texture(buf), 255, 255, 256};
        a.texture = block.block;
        a.u_mask = block.u_mask, a.v_mask = block.v_mask, a.block_pitch = block.pitch;
        a.u_16_16 = r.next();
        a.v_16_16 = r.next();
        a.u_row_16_16 = r.next();
        a.v_row_16_16 = r.next();
        a.du_16_16 = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        a.dv_16_16 = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        if (m.twin == fast_run_loop && a.source == DOUBLED_COPY) {
            random_doubled_uv(r, a);  // (its u and v at pixel 0 of the first row)
            a.u_row_16_16 = uint32_t(r.range(-0x40000, 0x40000));
            a.v_row_16_16 = uint32_t(r.range(-0x4000, 0x4000));
        }
        c.attach(a);
        // (fast-table: the offsets from a pixel at or left of clip_lo to the pitch's end)
        const int32_t table_x = r.range(0, a.clip_lo);
        build_offset_table(a.du_16_16, a.dv_16_16, a.pitch - table_x, c.table + table_x, block);
        a.table = c.table;
        a.row = buf.a + CHECK_GUARD_BYTES;
        int32_t lines;
        const uint32_t pixels = c.drawn(a, &lines);  // what the rows will draw
        return CheckWindow{0, CHECK_GUARD_BYTES + size_t(lines) * size_t(a.pitch) + CHECK_GUARD_BYTES, pixels};
    });
}


namespace {

// fast_column_run's block with its target and what it updates.
struct ColumnRunCase : RunState {
    FastColumnRunArgs args;
    Target target;
};

}  // namespace

template <>
void move_to_b(ColumnRunCase& b, const ColumnRunCase& a, const CheckBuffers& buf) {
    b.target.base = buf.b + (a.target.base - buf.a);
    b.args.target = &b.target;
    b.attach(b.args);
}

template <>
bool same_results(const ColumnRunCase& a, const ColumnRunCase& b) {
    return a.same(b);
}

template <>
const void* check_block(const ColumnRunCase& a) {
    return &a.args;
}

// Runs of columns into a planar target in the check's buffer (four planes of PLANE_BYTES between
// the guards; no plane selection: tests/asm/column_run_test.cpp calls a logged select_plane): one
// or two runs from a random column, bounds through and out of a random clip (and constant, as the
// driver's lone columns), steps of several texels; the tiled block, or a third of the time a
// doubled copy's pitch with u and v such that the walk stays in the texels (random_doubled_uv, the
// steps from column to column within a texel and a quarter).
LoopCheck check_fast_column_run(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<ColumnRunCase>(m, other, seed, cases, buf, [&](Random& r, ColumnRunCase& c) {
        FastColumnRunArgs& a = c.args;
        c.target = planar_target(buf.a + CHECK_GUARD_BYTES);
        a.clip_lo = r.range(0, SCREEN_HEIGHT - 1);
        a.clip_hi = r.below(8) == 0 ? a.clip_lo - 1 : r.range(a.clip_lo, SCREEN_HEIGHT - 1);  // sometimes nothing
        a.x = r.range(0, SCREEN_WIDTH - 1);
        const int32_t room = SCREEN_WIDTH - a.x;
        auto bound = [&] { return r.below(10) == 0 ? EdgeBound::constant(r.range(-20, SCREEN_HEIGHT + 20)) : random_bound(r, SCREEN_HEIGHT); };
        c.lower = bound(), c.upper = bound();
        if (r.below(2)) c.upper.q = c.lower.q + r.range(0, SCREEN_HEIGHT), c.upper.dq = c.lower.dq + r.range(-2, 2);  // a real-looking span
        c.next_lower = bound(), c.next_upper = bound();
        a.lines = r.below(8) == 0 ? r.range(0, 2) : r.range(1, room);
        a.next_lines = r.below(2) ? 0 : r.range(-1, room - (a.lines > 0 ? a.lines : 0));
        a.texture = check_aligned_texture(buf);
        a.block_pitch = 0;
        a.u_16_16 = r.next(), a.v_16_16 = r.next();
        a.u_column_16_16 = r.below(4) ? uint32_t(r.range(-0x40000, 0x40000)) : r.next();
        a.v_column_16_16 = r.below(4) ? uint32_t(r.range(-0x40000, 0x40000)) : r.next();
        a.du_16_16 = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        a.dv_16_16 = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        if (r.below(3) == 0) {
            int32_t w, h;
            random_doubled_sides(r, &w, &h);
            a.texture = buf.texels;
            a.block_pitch = doubled_pitch(w);
            random_doubled_uv(r, a);
            a.u_column_16_16 = uint32_t(r.range(-0x10000, 0x10000));
            a.v_column_16_16 = uint32_t(r.range(-0x4000, 0x4000));
        }
        a.target = &c.target;
        c.attach(a);
        int32_t lines;
        const uint32_t pixels = c.drawn(a, &lines);  // what the columns will draw
        return CheckWindow{0, CHECK_GUARD_BYTES + 4 * size_t(PLANE_BYTES) + CHECK_GUARD_BYTES, pixels};
    });
}

#if defined(MODEXLAB_OFFSETS)
// The block layouts of this family asm/fast.asm reads (core/asm_offsets.h); core's types' come
// from kernel/core (setup.cpp, walk.cpp, surface.cpp, envelope.cpp).
void fast_offsets() {
    ASM_FIELDS(TCOL, FastTableColumnArgs, dst, count, source, table)
    ASM_FIELDS(RUN, FastRunArgs, row, pitch, lines, clip_lo, clip_hi, lower, upper, next_lines, next_lower, next_upper, texture, u_16_16, v_16_16,
               u_row_16_16, v_row_16_16, du_16_16, dv_16_16, tally, table, inside, source, u_mask, v_mask, block_pitch)
    ASM_FIELDS(CRUN, FastColumnRunArgs, target, x, lines, clip_lo, clip_hi, lower, upper, next_lines, next_lower, next_upper, texture, block_pitch, u_16_16,
               v_16_16, u_column_16_16, v_column_16_16, du_16_16, dv_16_16, tally)
    ASM_CONSTANT(MODEX_ROW_BYTES, MODEX_ROW_BYTES);
    ASM_CONSTANT(SOURCE_TILED_BLOCK, TILED_BLOCK);
}
#endif

}  // namespace raster
