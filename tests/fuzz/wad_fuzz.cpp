// Fuzz target `wad`: Doom WADs as modexlab-wad reads them (the header, the lump directory, PLAYPAL,
// flats, PNAMES, TEXTURE1/2 and the patches a texture is composed from). Promises: every failure
// is a HarnessError with a message (anything else thrown escapes and is a crash); every graphic the
// list says can be extracted is, with as many pixels as its size says.
#include <memory>
#include <string>
#include <vector>

#include "qemu/lib/error.h"
#include "qemu/tools/wad.h"
#include "tests/fuzz/fuzz.h"

namespace {

// A composed texture's pixels are allocated whole: sizes above this many are listed, not composed
// (a 32767 x 32767 definition would take 1 GiB and seconds a run, not a new path).
constexpr long long MOST_PIXELS = 1 << 22;

template <typename F>
bool refused(F&& f) {
    try {
        f();
        return false;
    } catch (const harness::HarnessError& e) {
        if (!e.what()[0]) fuzz::fail("a HarnessError without a message");
        return true;
    }
}

}  // namespace

MODEXLAB_FUZZ_TARGET(wad) {
    std::string bytes(reinterpret_cast<const char*>(data), size);
    harness::Wad* wad = nullptr;
    if (refused([&] { wad = new harness::Wad(std::move(bytes), "fuzz.wad"); })) return 0;
    const std::unique_ptr<harness::Wad> owned(wad);
    refused([&] { wad->palette(); });
    std::vector<harness::WadListEntry> entries;
    if (refused([&] { entries = wad->list(); })) return 0;
    for (const harness::WadListEntry& e : entries) {
        if (e.problem.empty() != (e.width > 0 && e.height > 0)) fuzz::fail("list: " + e.name + " has a size and a problem, or neither");
        if (!e.problem.empty() || (long long)e.width * e.height > MOST_PIXELS) continue;
        harness::WadImage image;
        const bool failed = refused([&] { image = e.kind == harness::WadKind::Flat ? wad->flat(e.name) : wad->texture(e.name); });
        if (!failed && image.indices.size() != size_t(image.width) * size_t(image.height))
            fuzz::fail(e.name + ": " + std::to_string(image.indices.size()) + " pixels for " + std::to_string(image.width) + " x " +
                       std::to_string(image.height));
    }
    return 0;
}
