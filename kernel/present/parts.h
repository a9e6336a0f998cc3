// Buffers each between guard pages (kernel/platform/guard.h), listed once: taken, transient (a
// scene's, given back at the next load) or kept for the boot (a command's, from its first use on),
// or, in a dry run, only counted (what they would take of the pool), so that the two agree.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/core/policy.h"
#include "kernel/core/texture.h"
#include "kernel/lib/fmt.h"
#include "kernel/platform/guard.h"
#include "kernel/scene/scene_text.h"

namespace present {

enum class Take : uint8_t { Count, Transient, Kept };

struct Parts {
    Take how;
    size_t bytes = 0;  // their footprints so far
    bool taking() const { return how != Take::Count; }
    uint8_t* bytes_for(size_t n, const char* what, const char* name = nullptr) {
        bytes += guard::footprint(n);
        return how == Take::Transient ? guard::take_transient(n, what, name) : how == Take::Kept ? guard::take(n, what, name) : nullptr;
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
    if (!p.taking()) return t;
    if (kind) raster::generate_texture(*kind, t.width, t.height, at);
    else __builtin_memcpy(at, t.texels, texels);
    raster::Texture placed{at, t.width, t.height, t.wrap};
    raster::prepare_texture(&placed, bordered, aligned, twice);
    return placed;
}

// A scene the pool has no room for: `error` says what its `part` needs and what is free (after the
// transient buffers are given back); false.
inline bool no_room(raster::ParseError* error, const char* part, size_t need) {
    lib::Fmt m;
    m.s("not enough memory for this scene: ").s(part).s(" need ").u(uint32_t((need + 1023) >> 10)).s(" KiB, ");
    m.u(uint32_t(guard::room_after_release() >> 10)).s(" KiB free (docs/platform.md, Memory)");
    return raster::scene_text::fail(error, 0, m.c_str());
}

}  // namespace present
