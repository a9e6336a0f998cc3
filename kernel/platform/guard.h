// Paging with guard pages: the kernel identity-maps the whole 4 GiB (4 MiB pages) and keeps its
// textures, RAM surfaces and scene buffers in a pool of RAM the memory map reports (kernel_start
// places it, kernel/platform/memory.h), mapped with 4 KiB pages, where every buffer
// ends exactly where an unmapped page begins and has an unmapped page before its first page. A
// mapper that reads past a texture or writes past a surface takes a page fault there, which the
// exception handler reports with the buffer it hit (docs/platform.md, "Guard pages").
#pragma once

#include <stddef.h>
#include <stdint.h>

// placement new (the kernel has no <new>)
inline void* operator new(size_t, void* at) noexcept { return at; }

namespace guard {

constexpr size_t PAGE = 4096;
constexpr size_t MAX_POOL_BYTES = 96u << 20;  // what the page tables cover: a larger stretch is cut

// The pool: the whole pages of [start, end), at most MAX_POOL_BYTES; called once, before any take.
void place(uint32_t start, uint32_t end);
uint32_t pool_start();
size_t pool_bytes();
size_t taken_bytes();  // by the buffers kept for the boot, guards included

// Turns paging on (CR4.PSE, CR3, CR0.PG). False, with paging left off and the pool still usable
// without guards, on a CPU without 4 MiB pages (CPUID.1:EDX.PSE).
bool init(uint32_t cpuid_features_edx);
bool enabled();

// `bytes` from the pool, named for fault reports (`what`, and `name` after it unless null: strings
// that outlive the buffer, e.g. "world texture" and the texture's name): the buffer's last byte is the
// last byte of a page whose next page is unmapped, and the page before its first page is unmapped
// (a buffer that is not a whole number of pages starts inside its first page: a read that far
// before it, but within that page, is not caught). Panics when the pool is full.
uint8_t* take(size_t bytes, const char* what, const char* name = nullptr);

// A buffer kept only until release_transient(), taken from the other end of the pool (the 3D
// scene's textures, made again on every load), guarded the same way.
uint8_t* take_transient(size_t bytes, const char* what, const char* name = nullptr);
void release_transient();

// What a buffer of `bytes` takes of the pool: its whole pages and the guard page beside it.
constexpr size_t footprint(size_t bytes) { return ((bytes + PAGE - 1) / PAGE + 1) * PAGE; }
// The pool not taken, in footprint's terms: buffers whose footprints add up to at most this fit;
// and what it is once the transient buffers are given back.
size_t transient_room();
size_t room_after_release();
size_t transient_taken();  // by the transient buffers, guards included
// Counts release_transient's calls: an owner of transient buffers keeps the count it took them
// at, and knows them given back when the count has moved on.
uint32_t transient_generation();

// An object of type T in a buffer of its own (zeroed, constructed), kept for the boot.
template <typename T>
T* take_object(const char* what) {
    return new (take(sizeof(T), what)) T;
}

// What a faulting address hit: the buffer whose guard page holds it, and how far past its end or
// before its start; false when the address is in no guard page of the pool.
struct Hit {
    const char* what;
    const char* name;  // or null
    bool after;       // past the end (else before the start)
    uint32_t offset;  // 1: the byte just past the last (or just before the first)
};
bool find(uint32_t address, Hit* hit);

}  // namespace guard
