// Paging with guard pages (guard.h): a page directory of 4 MiB identity pages, and 4 KiB page tables
// for the pool, in which take() maps the pages it hands out and unmaps the one after each buffer.
#include "kernel/platform/guard.h"

#include "kernel/platform/panic.h"

namespace guard {

namespace {

constexpr size_t POOL_BYTES = 40u << 20;
constexpr size_t BIG_PAGE = 4u << 20;
constexpr size_t POOL_TABLES = POOL_BYTES / BIG_PAGE;
constexpr uint32_t PRESENT = 1, WRITABLE = 2, BIG = 1 << 7;
constexpr int MAX_REGIONS = 160;

alignas(BIG_PAGE) uint8_t g_pool[POOL_BYTES];
alignas(PAGE) uint32_t g_directory[1024];
alignas(PAGE) uint32_t g_tables[POOL_TABLES][1024];

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
size_t g_top = POOL_BYTES - PAGE;     // and its last page the last transient buffer's
bool g_enabled = false;
bool g_tables_ready = false;  // buffers may be taken by constructors, before init()

uint32_t pool_base() { return reinterpret_cast<uint32_t>(g_pool); }

uint32_t& entry(uint32_t address) {
    const uint32_t page = (address - pool_base()) / PAGE;
    return g_tables[page / 1024][page % 1024];
}

// The page tables: every page of the pool present, but the first (the first buffer's guard).
void prepare_tables() {
    if (g_tables_ready) return;
    g_tables_ready = true;
    const uint32_t base = pool_base();
    for (uint32_t t = 0; t < POOL_TABLES; ++t)
        for (uint32_t p = 0; p < 1024; ++p) g_tables[t][p] = (base + (t * 1024 + p) * PAGE) | PRESENT | WRITABLE;
    g_tables[0][0] &= ~PRESENT;
    g_tables[POOL_TABLES - 1][1023] &= ~PRESENT;
}

[[noreturn]] void full(const char* what, size_t bytes) {
    lib::Fmt m;
    m.s("the guarded pool is full: ").s(what).s(" needs ").u(uint32_t(bytes)).s(" bytes, ").u(uint32_t(g_top - g_cursor)).s(" left");
    panic(m.c_str());
}

void set_present(uint32_t address, bool present) {
    uint32_t& e = entry(address);
    e = present ? (e | PRESENT) : (e & ~PRESENT);
    if (g_enabled) asm volatile("invlpg (%0)" : : "r"(address) : "memory");
}

}  // namespace

bool init(uint32_t cpuid_features_edx) {
    prepare_tables();
    for (uint32_t i = 0; i < 1024; ++i) g_directory[i] = (i * BIG_PAGE) | PRESENT | WRITABLE | BIG;
    for (uint32_t t = 0; t < POOL_TABLES; ++t) g_directory[(pool_base() >> 22) + t] = reinterpret_cast<uint32_t>(g_tables[t]) | PRESENT | WRITABLE;
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
    if (bytes == 0 || g_region_count == MAX_REGIONS || (pages + 1) * PAGE > g_top - g_cursor) full(what, bytes);
    prepare_tables();
    const uint32_t first = pool_base() + uint32_t(g_cursor), end = first + uint32_t(pages * PAGE);
    for (uint32_t a = first; a < end; a += PAGE) set_present(a, true);
    set_present(end, false);  // the guard after it (and before the next)
    g_regions[g_region_count++] = Region{what, name, first, end - uint32_t(bytes), end};
    g_cursor += (pages + 1) * PAGE;
    return reinterpret_cast<uint8_t*>(end - bytes);
}

uint8_t* take_transient(size_t bytes, const char* what, const char* name) {
    const size_t pages = (bytes + PAGE - 1) / PAGE;
    if (bytes == 0 || g_transient_count == MAX_REGIONS || (pages + 1) * PAGE > g_top - g_cursor) full(what, bytes);
    prepare_tables();
    const uint32_t end = pool_base() + uint32_t(g_top), first = end - uint32_t(pages * PAGE);
    for (uint32_t a = first; a < end; a += PAGE) set_present(a, true);
    set_present(first - PAGE, false);  // the guard before it (and after the next)
    g_transient[g_transient_count++] = Region{what, name, first, end - uint32_t(bytes), end};
    g_top -= (pages + 1) * PAGE;
    return reinterpret_cast<uint8_t*>(end - bytes);
}

void release_transient() {
    g_transient_count = 0;
    g_top = POOL_BYTES - PAGE;
}

bool find(uint32_t address, Hit* hit) {
    if (address < pool_base() || address >= pool_base() + POOL_BYTES) return false;
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
