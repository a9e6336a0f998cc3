// Paging with guard pages (guard.h): a page directory of 4 MiB identity pages, and 4 KiB page tables
// for the pool, in which take() maps the pages it hands out and unmaps the one after each buffer.
#include "kernel/platform/guard.h"

#include "kernel/platform/panic.h"

namespace guard {

namespace {

constexpr size_t BIG_PAGE = 4u << 20;
// (a pool that does not start on a 4 MiB boundary spans one block more)
constexpr size_t MAX_TABLES = MAX_POOL_BYTES / BIG_PAGE + 1;
constexpr uint32_t PRESENT = 1, WRITABLE = 2, BIG = 1 << 7;
constexpr int MAX_REGIONS = 160;

alignas(PAGE) uint32_t g_directory[1024];
alignas(PAGE) uint32_t g_tables[MAX_TABLES][1024];
uint32_t g_base = 0;        // the pool: [g_base, g_base + g_bytes), whole pages (place)
size_t g_bytes = 0;
uint32_t g_first_block = 0; // the 4 MiB blocks its tables cover: [g_first_block, + g_table_count)
uint32_t g_table_count = 0;

struct Region {
    const char* what;
    const char* name;
    uint32_t first_page;  // the buffer's pages: [first_page, end), the buffer flush against end
    uint32_t start, end;  // the buffer's bytes
};
// the buffers kept for the boot (from the pool's start up) and the transient ones (from its end down)
Region g_regions[MAX_REGIONS];
int g_region_count = 0;
Region g_transient[MAX_REGIONS];
int g_transient_count = 0;
size_t g_cursor = PAGE;               // the pool's first page is the first buffer's guard
size_t g_top = 0;                     // and its last page the last transient buffer's (place)
uint32_t g_generation = 0;            // release_transient's calls
bool g_enabled = false;
bool g_tables_ready = false;  // buffers may be taken by constructors, before init()

uint32_t pool_base() { return g_base; }

uint32_t& entry(uint32_t address) {
    const uint32_t page = (address - g_first_block * uint32_t(BIG_PAGE)) / PAGE;
    return g_tables[page / 1024][page % 1024];
}

// The page tables: every page of the blocks the pool lies in present (identity), but the pool's
// first (the first buffer's guard) and last (the last transient buffer's).
void prepare_tables() {
    if (g_tables_ready) return;
    g_tables_ready = true;
    for (uint32_t t = 0; t < g_table_count; ++t)
        for (uint32_t p = 0; p < 1024; ++p) g_tables[t][p] = ((g_first_block + t) * uint32_t(BIG_PAGE) + p * PAGE) | PRESENT | WRITABLE;
    entry(g_base) &= ~PRESENT;
    entry(g_base + uint32_t(g_bytes) - PAGE) &= ~PRESENT;
}

[[noreturn]] void full(const char* what, size_t bytes) {
    lib::Fmt m;
    if (!g_bytes) panic("the guarded pool was never placed: a buffer was taken before kernel_start");
    m.s("the guarded pool is full: ").s(what).s(" needs ").u(uint32_t(bytes)).s(" bytes, ").u(uint32_t(g_top - g_cursor)).s(" left");
    panic(m.c_str());
}

void set_present(uint32_t address, bool present) {
    uint32_t& e = entry(address);
    e = present ? (e | PRESENT) : (e & ~PRESENT);
    if (g_enabled) asm volatile("invlpg (%0)" : : "r"(address) : "memory");
}

}  // namespace

void place(uint32_t start, uint32_t end) {
    g_base = (start + PAGE - 1) & ~uint32_t(PAGE - 1);
    end &= ~uint32_t(PAGE - 1);
    g_bytes = end > g_base ? end - g_base : 0;
    if (g_bytes > MAX_POOL_BYTES) g_bytes = MAX_POOL_BYTES;
    g_first_block = g_base / uint32_t(BIG_PAGE);
    g_table_count = (g_base + uint32_t(g_bytes) - 1) / uint32_t(BIG_PAGE) - g_first_block + 1;
    g_cursor = PAGE;
    g_top = g_bytes - PAGE;
}

uint32_t pool_start() { return g_base; }
size_t pool_bytes() { return g_bytes; }
size_t taken_bytes() { return g_cursor; }

bool init(uint32_t cpuid_features_edx) {
    prepare_tables();
    for (uint32_t i = 0; i < 1024; ++i) g_directory[i] = (i * BIG_PAGE) | PRESENT | WRITABLE | BIG;
    for (uint32_t t = 0; t < g_table_count; ++t) g_directory[g_first_block + t] = reinterpret_cast<uint32_t>(g_tables[t]) | PRESENT | WRITABLE;
    if (!((cpuid_features_edx >> 3) & 1)) return false;  // no PSE: no 4 MiB pages, no paging
    uint32_t cr4, cr0;
    asm volatile("mov %%cr4, %0" : "=r"(cr4));
    asm volatile("mov %0, %%cr4" : : "r"(cr4 | (1u << 4)));  // PSE
    asm volatile("mov %0, %%cr3" : : "r"(reinterpret_cast<uint32_t>(g_directory)) : "memory");
    asm volatile("mov %%cr0, %0" : "=r"(cr0));
    asm volatile("mov %0, %%cr0" : : "r"(cr0 | (1u << 31)) : "memory");  // PG
    g_enabled = true;
    return true;
}

bool enabled() { return g_enabled; }

uint8_t* take(size_t bytes, const char* what, const char* name) {
    const size_t pages = (bytes + PAGE - 1) / PAGE;
    if (bytes == 0 || g_region_count == MAX_REGIONS || footprint(bytes) > g_top - g_cursor) full(what, bytes);
    prepare_tables();
    const uint32_t first = pool_base() + uint32_t(g_cursor), end = first + uint32_t(pages * PAGE);
    for (uint32_t a = first; a < end; a += PAGE) set_present(a, true);
    set_present(end, false);  // the guard after it (and before the next)
    g_regions[g_region_count++] = Region{what, name, first, end - uint32_t(bytes), end};
    g_cursor += footprint(bytes);
    return reinterpret_cast<uint8_t*>(end - bytes);
}

uint8_t* take_transient(size_t bytes, const char* what, const char* name) {
    const size_t pages = (bytes + PAGE - 1) / PAGE;
    if (bytes == 0 || g_transient_count == MAX_REGIONS || footprint(bytes) > g_top - g_cursor) full(what, bytes);
    prepare_tables();
    const uint32_t end = pool_base() + uint32_t(g_top), first = end - uint32_t(pages * PAGE);
    for (uint32_t a = first; a < end; a += PAGE) set_present(a, true);
    set_present(first - PAGE, false);  // the guard before it (and after the next)
    g_transient[g_transient_count++] = Region{what, name, first, end - uint32_t(bytes), end};
    g_top -= footprint(bytes);
    return reinterpret_cast<uint8_t*>(end - bytes);
}

size_t transient_room() { return g_top - g_cursor; }

size_t room_after_release() { return g_bytes - PAGE - g_cursor; }
size_t transient_taken() { return g_bytes - PAGE - g_top; }
uint32_t transient_generation() { return g_generation; }

void release_transient() {
    ++g_generation;
    g_transient_count = 0;
    g_top = g_bytes - PAGE;
}

bool find(uint32_t address, Hit* hit) {
    if (address < pool_base() || address >= pool_base() + g_bytes) return false;
    const uint32_t page = address & ~uint32_t(PAGE - 1);
    const Region* const lists[2] = {g_regions, g_transient};
    const int counts[2] = {g_region_count, g_transient_count};
    // past the end of a buffer first (the likelier stray), then before the start of one
    for (int after = 1; after >= 0; --after)
        for (int l = 0; l < 2; ++l)
            for (int i = 0; i < counts[l]; ++i) {
                const Region& r = lists[l][i];
                if (after ? page == r.end : page + PAGE == r.first_page) {
                    *hit = Hit{r.what, r.name, after == 1, after ? address - r.end + 1 : r.start - address};
                    return true;
                }
            }
    return false;
}

}  // namespace guard
