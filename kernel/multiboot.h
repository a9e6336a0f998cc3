// The parts of the Multiboot v1 information structure the kernel reads.
#pragma once

#include <stdint.h>

namespace multiboot {

constexpr uint32_t BOOTLOADER_MAGIC = 0x2BADB002;
constexpr uint32_t INFO_MEMORY = 1u << 0;
constexpr uint32_t INFO_CMDLINE = 1u << 2;
constexpr uint32_t INFO_MODULES = 1u << 3;
constexpr uint32_t INFO_LOADER_NAME = 1u << 9;

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

// One entry of the module list at mods_addr.
struct Module {
    uint32_t mod_start, mod_end;  // physical addresses: [start, end)
    uint32_t string;              // physical address of a NUL-terminated string, or 0
    uint32_t reserved;
};

}  // namespace multiboot
