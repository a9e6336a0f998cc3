// A scene's buffers, each between guard pages (kernel/platform/guard.h): taken (transient), or, in
// a dry run, only counted (what they would take of the pool), by one list, so that the two agree.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/core/policy.h"
#include "kernel/core/texture.h"
#include "kernel/platform/guard.h"

namespace present {

struct Parts {
    bool take;
    size_t bytes = 0;  // their footprints so far
    uint8_t* bytes_for(size_t n, const char* what, const char* name = nullptr) {
        bytes += guard::footprint(n);
        return take ? guard::take_transient(n, what, name) : nullptr;
    }
    template <typename T>
    T* of(int32_t count, const char* what) {  // count items of T (none: null)
        return count > 0 ? reinterpret_cast<T*>(bytes_for(size_t(count) * sizeof(T), what)) : nullptr;
    }
};

// The names a texture's buffers go by in fault reports.
struct TextureNames {
    const char *texels, *bordered, *aligned, *doubled;
};

// A texture (its size, and its texels: copied from `t`'s, or generated as `kind` where that is not
// null) in a buffer of its own, with its bordered, aligned and doubled copies made from them in
// theirs (without `doubled`, none doubled). Taking: the texture as the mappers read it (its wrap
// `t`'s); counting: `t` unchanged.
inline raster::Texture texture_parts(Parts& p, const raster::Texture& t, bool doubled, const TextureNames& names, const char* name,
                                     const raster::TextureKind* kind = nullptr) {
    const size_t texels = size_t(t.width) * size_t(t.height);
    uint8_t* at = p.bytes_for(texels, names.texels, name);
    uint8_t* bordered = p.bytes_for(size_t(raster::bordered_bytes(t.width, t.height)), names.bordered, name);
    uint8_t* aligned = raster::wants_aligned256(t) ? p.bytes_for(raster::ALIGNED256_BYTES, names.aligned, name) : nullptr;
    uint8_t* twice = doubled && raster::wants_doubled(t) ? p.bytes_for(size_t(raster::doubled_bytes(t.width, t.height)), names.doubled, name) : nullptr;
    if (!p.take) return t;
    if (kind) raster::generate_texture(*kind, t.width, t.height, at);
    else __builtin_memcpy(at, t.texels, texels);
    raster::Texture placed{at, t.width, t.height, t.wrap};
    raster::prepare_texture(&placed, bordered, aligned, twice);
    return placed;
}

}  // namespace present
