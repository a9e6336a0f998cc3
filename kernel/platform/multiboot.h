// The parts of the Multiboot v1 information structure the kernel reads.
#pragma once

#include <stdint.h>

namespace multiboot {

constexpr uint32_t BOOTLOADER_MAGIC = 0x2BADB002;
constexpr uint32_t INFO_MEMORY = 1u << 0;
constexpr uint32_t INFO_CMDLINE = 1u << 2;
constexpr uint32_t INFO_MODULES = 1u << 3;
constexpr uint32_t INFO_MEMORY_MAP = 1u << 6;
constexpr uint32_t INFO_LOADER_NAME = 1u << 9;
constexpr uint32_t INFO_FRAMEBUFFER = 1u << 12;

struct Info {
    uint32_t flags;
    uint32_t mem_lower, mem_upper;  // KiB below 1 MiB and above 1 MiB
    uint32_t boot_device;
    uint32_t cmdline;               // physical address of a NUL-terminated string
    uint32_t mods_count, mods_addr;
    uint32_t syms[4];
    uint32_t mmap_length, mmap_addr;
    uint32_t drives_length, drives_addr;
    uint32_t config_table;
    uint32_t boot_loader_name;
};

static_assert(sizeof(Info) == 68, "multiboot info layout up to boot_loader_name");

// The rest of the structure: VBE, then the framebuffer (flags bit 12).
struct [[gnu::packed]] FramebufferInfo {
    uint32_t apm_table;
    uint32_t vbe_control_info, vbe_mode_info;
    uint16_t vbe_mode, vbe_interface_seg, vbe_interface_off, vbe_interface_len;
    uint64_t addr;
    uint32_t pitch, width, height;  // bytes a line; pixels
    uint8_t bpp;
    uint8_t type;  // 0: indexed, 1: RGB, 2: EGA text
    uint8_t padding[2];  // (GRUB lays the colour info out as a union with a 32-bit palette address: at 112)
    uint8_t red_position, red_size, green_position, green_size, blue_position, blue_size;  // type 1
};
static_assert(sizeof(FramebufferInfo) == 118 - 68, "framebuffer fields at offsets 88..117");
inline const FramebufferInfo* framebuffer(const Info* info) {
    return reinterpret_cast<const FramebufferInfo*>(reinterpret_cast<const uint8_t*>(info) + sizeof(Info));
}

// One entry of the memory map (flags bit 6): `size` counts the bytes after itself.
struct [[gnu::packed]] MemoryRegion {
    uint32_t size;
    uint64_t addr, len;
    uint32_t type;  // 1: available RAM; 3: ACPI tables (reclaimable); 4: ACPI NVS; 2: reserved; 5: bad
};
// RAM the kernel may use: available, or kept for ACPI (its tables and its non-volatile storage).
// UEFI firmware leaves ACPI NVS islands where GRUB EFI loads the kernel all the same (OVMF: at 8 MiB,
// the 32-bit one up to 23 MiB); the kernel never uses ACPI nor returns to the firmware, so that RAM
// is as good as any. Reserved regions (MMIO, SMRAM) and bad memory are not.
constexpr bool usable(uint32_t type) { return type == 1 || type == 3 || type == 4; }
// The first address of [lo, hi) that is not RAM, or hi: by the memory map's usable regions
// where there is a map (regions that touch count as one), else by 1 MiB + mem_upper (KiB) where
// that is given; hi where the loader says nothing.
inline uint64_t first_not_ram(const Info* info, uint64_t lo, uint64_t hi) {
    if (info->flags & INFO_MEMORY_MAP) {
        uint64_t at = lo;
        for (bool moved = true; at < hi && moved;) {
            moved = false;
            for (uint32_t off = 0; off + sizeof(MemoryRegion) <= info->mmap_length;) {
                const MemoryRegion* r = reinterpret_cast<const MemoryRegion*>(uintptr_t(info->mmap_addr) + off);
                if (usable(r->type) && r->addr <= at && at < r->addr + r->len) at = r->addr + r->len, moved = true;
                off += r->size + 4;
            }
        }
        return at < hi ? at : hi;
    }
    if (info->flags & INFO_MEMORY) {
        const uint64_t end = 0x100000 + uint64_t(info->mem_upper) * 1024;
        return end < hi ? (end > lo ? end : lo) : hi;
    }
    return hi;
}

// One entry of the module list at mods_addr.
struct Module {
    uint32_t mod_start, mod_end;  // physical addresses: [start, end)
    uint32_t string;              // physical address of a NUL-terminated string, or 0
    uint32_t reserved;
};

}  // namespace multiboot
