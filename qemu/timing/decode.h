// x86 machine code to timing::Insn, by Capstone (its registers read and written, explicit and
// implicit, and its flags), in 16- or 32-bit mode.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "qemu/timing/insn.h"

namespace timing {

struct DecodeError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Every instruction of `bytes`, the first at `address`; `bits` 16 or 32. Throws DecodeError at a
// byte sequence that is no instruction (its offset named); with `stop_at_bad`, returns the ones
// before it instead (code followed by data).
std::vector<Insn> decode(const uint8_t* bytes, size_t size, int bits, uint32_t address = 0, bool stop_at_bad = false);

}  // namespace timing
