// A NASM listing as the analyser reads it: its `bits` (16: real mode, as the Black Book's listings
// ran; 32: protected mode), its header (`; key: value` lines at its top, e.g. `; published: 8`),
// and its code, assembled by NASM into a flat binary and decoded.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "qemu/timing/insn.h"

namespace timing {

struct Listing {
    std::string path;
    int bits = 32;
    std::map<std::string, std::string> header;
    std::vector<Insn> insns;
};

// Throws std::runtime_error naming the file: unreadable, NASM's errors, undecodable bytes.
Listing read_listing(const std::string& path);

// The inner loop of `function` in an assembled object (32-bit ELF, as the kernel's NASM loops are
// built): from the target of the first jump back inside the function to that jump. Throws where
// there is no such symbol or loop.
Listing read_object_loop(const std::string& object, const std::string& function);

// The registered mapper's NASM loop: its `TWIN_AND_ASM(NAME)` row in kernel/mappers/registry.cpp,
// NAME_asm in the asm/*.asm that declares it global, its object in `object_dir` (paths from the
// repository's root), with the header `precision` where the source has a `; precision: N` line.
// Throws for a mapper without a NASM loop.
Listing read_mapper_loop(const std::string& mapper, const std::string& object_dir);

}  // namespace timing
