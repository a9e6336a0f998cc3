// Paging with guard pages (guard.h): a page directory of 4 MiB identity pages, and 4 KiB page tables
// for the pool, in which take() maps the pages it hands out and unmaps the one after each buffer.
#include "kernel/guard.h"

#include "kernel/panic.h"

namespace guard {

namespace {

constexpr size_t POOL_BYTES = 40u << 20;
constexpr size_t BIG_PAGE = 4u << 20;
constexpr size_t POOL_TABLES = POOL_BYTES / BIG_PAGE;
constexpr uint32_t PRESENT = 1, WRITABLE = 2, BIG = 1 << 7;
constexpr int MAX_REGIONS = 96;

alignas(BIG_PAGE) uint8_t g_pool[POOL_BYTES];
alignas(PAGE) uint32_t g_directory[1024];
alignas(PAGE) uint32_t g_tables[POOL_TABLES][1024];

struct Region {
    const char* what;
    const char* name;
    uint32_t first_page;  // the buffer's pages: [first_page, end), the buffer flush against end
    uint32_t start, end;  // the buffer's bytes
};
Region g_regions[MAX_REGIONS];
int g_region_count = 0;
size_t g_cursor = PAGE;  // the pool's first page is the first buffer's guard
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
    if (bytes == 0 || g_region_count == MAX_REGIONS || pages + 1 > (POOL_BYTES - g_cursor) / PAGE) {
        lib::Fmt m;
        m.s("the guarded pool is full: ").s(what).s(" needs ").u(uint32_t(bytes)).s(" bytes, ").u(uint32_t(POOL_BYTES - g_cursor)).s(" left");
        panic(m.c_str());
    }
    prepare_tables();
    const uint32_t first = pool_base() + uint32_t(g_cursor), end = first + uint32_t(pages * PAGE);
    for (uint32_t a = first; a < end; a += PAGE) set_present(a, true);
    set_present(end, false);  // the guard after it (and before the next)
    g_regions[g_region_count++] = Region{what, name, first, end - uint32_t(bytes), end};
    g_cursor += (pages + 1) * PAGE;
    return reinterpret_cast<uint8_t*>(end - bytes);
}

size_t mark() { return size_t(g_region_count); }

void release(size_t m) {
    if (m >= size_t(g_region_count)) return;
    g_region_count = int(m);
    g_cursor = m == 0 ? PAGE : g_regions[m - 1].end + PAGE - pool_base();
}

bool find(uint32_t address, Hit* hit) {
    if (address < pool_base() || address >= pool_base() + POOL_BYTES) return false;
    const uint32_t page = address & ~uint32_t(PAGE - 1);
    for (int i = 0; i < g_region_count; ++i) {
        const Region& r = g_regions[i];
        if (page == r.end) {
            *hit = Hit{r.what, r.name, true, address - r.end + 1};
            return true;
        }
        if (page + PAGE == r.first_page) {
            *hit = Hit{r.what, r.name, false, r.start - address};
            return true;
        }
    }
    return false;
}

size_t pool_bytes() { return POOL_BYTES; }
size_t pool_used() { return g_cursor; }

}  // namespace guard
