// Coverage-guided fuzz targets for every parser that takes outside input (`make fuzz`; the
// corpora are replayed by `make test`; docs/fuzzing.md). A target is written once:
//
//     MODEXLAB_FUZZ_TARGET(scene) { ... data, size ... ; return 0; }
//
// Built with MODEXLAB_LIBFUZZER (clang -fsanitize=fuzzer) it is libFuzzer's entry point, one
// program a target; built without, it registers itself with the replay program
// (replay_main.cpp), which runs every target over its committed corpus, tests/fuzz/corpus/NAME.
// A target checks what the parser promises (an error names its line, a decoded image fits its
// buffer, ...) and calls fuzz::fail when a promise is broken; a crash or a sanitizer report is a
// failure as well.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace fuzz {

using Target = int (*)(const uint8_t* data, size_t size);

struct Registration {
    Registration(const char* name, Target target);
};

// Prints the broken promise (and, when replaying, the input's file) and aborts: libFuzzer keeps the
// input as a crash, the replay program stops without its summary line.
[[noreturn]] void fail(const std::string& what);

}  // namespace fuzz

#ifdef MODEXLAB_LIBFUZZER
#define MODEXLAB_FUZZ_TARGET(name) extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
#else
#define MODEXLAB_FUZZ_TARGET(name)                                                 \
    static int fuzz_target_##name(const uint8_t* data, size_t size);               \
    static const fuzz::Registration fuzz_registration_##name(#name, fuzz_target_##name); \
    static int fuzz_target_##name(const uint8_t* data, size_t size)
#endif
