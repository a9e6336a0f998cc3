// Decoding a `readback` reply: base64, then PackBits, then the CRC-32 check (docs/protocol.md).
#pragma once

#include "qemu/lib/ordered_json.h"

#include "qemu/lib/host_image.h"

namespace harness {

// Throws HarnessError when a field is missing, the encoding is unknown, the data does not decode
// to exactly width x height indices, or the CRC-32 differs.
IndexImage decode_readback(const json& reply);

}  // namespace harness
