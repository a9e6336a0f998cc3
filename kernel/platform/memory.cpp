// The pool's RAM (memory.h).
#include "kernel/platform/memory.h"

#include "kernel/lib/mem.h"

namespace memory {

namespace {

// 1 MiB .. the last page below 4 GiB: below it BIOS and VGA, above it what 32 bits cannot address
constexpr uint64_t LOW = 0x100000, HIGH = 0xFFFFF000ull;

uint64_t string_end(uint32_t at) {
    const char* s = reinterpret_cast<const char*>(uintptr_t(at));
    uint64_t n = 0;
    while (s[n]) ++n;
    return uint64_t(at) + n + 1;
}

// The largest part of [lo, hi) clear of every kept range, into *best where it is larger.
void consider(uint64_t lo, uint64_t hi, const Range* kept, int count, Range* best) {
    if (lo < LOW) lo = LOW;
    if (hi > HIGH) hi = HIGH;
    while (lo < hi) {
        bool inside = false;  // in a kept range: past it
        for (int i = 0; i < count && !inside; ++i)
            if (kept[i].start <= lo && lo < kept[i].end) lo = kept[i].end, inside = true;
        if (inside) continue;
        uint64_t end = hi;  // free up to the nearest kept range above
        for (int i = 0; i < count; ++i)
            if (kept[i].start > lo && kept[i].start < end) end = kept[i].start;
        if (end - lo > best->bytes()) *best = Range{lo, end};
        lo = end;
    }
}

}  // namespace

int kept(const multiboot::Info* info, uint64_t image_start, uint64_t image_end, Range* out, bool modules_kept) {
    int n = 0;
    auto add = [&](uint64_t start, uint64_t end) {
        if (n < MAX_KEPT && end > start) out[n++] = Range{start, end};
    };
    add(image_start, image_end);
    const uint64_t at = uintptr_t(info);
    add(at, at + sizeof(multiboot::Info) + sizeof(multiboot::FramebufferInfo));
    if (info->flags & multiboot::INFO_CMDLINE) add(info->cmdline, string_end(info->cmdline));
    if (info->flags & multiboot::INFO_LOADER_NAME) add(info->boot_loader_name, string_end(info->boot_loader_name));
    if (info->flags & multiboot::INFO_MEMORY_MAP) add(info->mmap_addr, uint64_t(info->mmap_addr) + info->mmap_length);
    if (info->flags & multiboot::INFO_MODULES) {
        const auto* mods = reinterpret_cast<const multiboot::Module*>(uintptr_t(info->mods_addr));
        add(info->mods_addr, uint64_t(info->mods_addr) + uint64_t(info->mods_count) * sizeof(multiboot::Module));
        Range modules{~0ull, 0}, names{~0ull, 0};
        auto widen = [](Range& r, uint64_t start, uint64_t end) {
            if (start < r.start) r.start = start;
            if (end > r.end) r.end = end;
        };
        for (uint32_t i = 0; i < info->mods_count; ++i) {
            const uint64_t name_end = mods[i].string ? string_end(mods[i].string) : 0;
            if (!modules_kept) {
                if (mods[i].string) add(mods[i].string, name_end);
                continue;
            }
            if (i < uint32_t(MODULES_APART)) {
                add(mods[i].mod_start, mods[i].mod_end);
                if (mods[i].string) add(mods[i].string, name_end);
                continue;
            }
            widen(modules, mods[i].mod_start, mods[i].mod_end);
            if (mods[i].string) widen(names, mods[i].string, name_end);
        }
        add(modules.start, modules.end);
        add(names.start, names.end);
    }
    return n;
}

Range largest_free(const multiboot::Info* info, const Range* kept, int count) {
    Range best;
    if (info->flags & multiboot::INFO_MEMORY_MAP) {
        for (uint32_t off = 0; off + sizeof(multiboot::MemoryRegion) <= info->mmap_length;) {
            const auto* r = reinterpret_cast<const multiboot::MemoryRegion*>(uintptr_t(info->mmap_addr) + off);
            if (multiboot::usable(r->type)) consider(r->addr, r->addr + r->len, kept, count, &best);
            off += r->size + 4;
        }
    } else if (info->flags & multiboot::INFO_MEMORY) {
        consider(LOW, LOW + uint64_t(info->mem_upper) * 1024, kept, count, &best);
    }
    return best;
}

Range gather_modules(const multiboot::Info* info, Range pool, bool move) {
    if (!(info->flags & multiboot::INFO_MODULES)) return pool;
    auto* mods = reinterpret_cast<multiboot::Module*>(uintptr_t(info->mods_addr));
    constexpr uint64_t PAGE = 4096;
    uint64_t below = pool.end & ~(PAGE - 1);  // the modules moved so far lie in [below, pool.end)
    for (uint32_t i = 0; i < info->mods_count; ++i) {
        const uint64_t start = mods[i].mod_start, end = mods[i].mod_end;
        if (end > pool.start && start < pool.end && (start < pool.start || end > pool.end)) return Range{};
        if (start >= pool.start && end <= pool.end) below -= (end - start + PAGE - 1) & ~(PAGE - 1);
    }
    if (below <= pool.start) return Range{};
    // The highest first, each to just below the last one moved: up, or where it is, never down (so
    // over nothing still to move); checked for every module before any moves.
    auto walk = [&](bool moving) {
        uint64_t top = pool.end & ~(PAGE - 1), done_below = ~0ull;
        for (;;) {
            int next = -1;
            for (uint32_t i = 0; i < info->mods_count; ++i) {
                const uint64_t start = mods[i].mod_start;
                if (start >= pool.start && mods[i].mod_end <= pool.end && start < done_below && (next < 0 || start > mods[next].mod_start))
                    next = int(i);
            }
            if (next < 0) return true;
            multiboot::Module& m = mods[next];
            const uint64_t size = m.mod_end - m.mod_start, to = (top - size) & ~(PAGE - 1);
            if (to < m.mod_start) return false;
            done_below = m.mod_start;
            if (moving) {
                memmove(reinterpret_cast<void*>(uintptr_t(to)), reinterpret_cast<const void*>(uintptr_t(m.mod_start)), size_t(size));
                m.mod_start = uint32_t(to), m.mod_end = uint32_t(to + size);
            }
            top = to;
        }
    };
    if (!walk(false)) return Range{};
    if (move) walk(true);
    return Range{pool.start, below};
}

}  // namespace memory
