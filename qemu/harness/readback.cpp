// readback reply -> index image, with every check the wire format allows.
#include "qemu/harness/readback.h"

#include <cstdio>

#include "kernel/lib/encode.h"
#include "qemu/lib/error.h"

namespace harness {

IndexImage decode_readback(const json& reply) {
    for (const char* key : {"width", "height", "encoding", "crc32", "data"})
        if (!reply.contains(key)) throw HarnessError(std::string("readback reply without \"") + key + "\"");
    if (reply["encoding"] != "packbits+base64") throw HarnessError("readback: unknown encoding " + reply["encoding"].dump());
    int width = reply["width"].get<int>(), height = reply["height"].get<int>();
    if (width <= 0 || height <= 0 || width > 1024 || height > 1024) throw HarnessError("readback: bad size");
    const std::string& data = reply["data"].get_ref<const std::string&>();

    std::vector<uint8_t> packed(data.size() / 4 * 3 + 3);
    size_t packed_size = 0;
    if (!lib::base64_decode(data.data(), data.size(), packed.data(), packed.size(), &packed_size))
        throw HarnessError("readback: bad base64 data");
    if (reply.contains("packed_bytes") && reply["packed_bytes"] != packed_size)
        throw HarnessError("readback: " + std::to_string(packed_size) + " PackBits bytes, reply says " + reply["packed_bytes"].dump());

    IndexImage image{width, height, std::vector<uint8_t>(size_t(width) * size_t(height))};
    size_t produced = 0;
    if (!lib::packbits_decode(packed.data(), packed_size, image.index.data(), image.index.size(), &produced))
        throw HarnessError("readback: bad PackBits data (truncated packet or more than width x height indices)");
    if (produced != image.index.size())
        throw HarnessError("readback: " + std::to_string(produced) + " indices, expected " + std::to_string(image.index.size()));

    char crc_text[16];
    std::snprintf(crc_text, sizeof crc_text, "0x%08x", lib::crc32(0, image.index.data(), image.index.size()));
    if (reply["crc32"] != crc_text) throw HarnessError("readback: CRC-32 " + std::string(crc_text) + " of the data, reply says " + reply["crc32"].dump());
    return image;
}

}  // namespace harness
