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

}  // namespace timing
