// CPUID: vendor, family/model/stepping and the feature flags the lab cares about.
#pragma once

#include <stdint.h>

namespace cpu {

struct Info {
    bool has_cpuid = false;
    char vendor[13] = {};
    uint32_t family = 0, model = 0, stepping = 0;
    uint32_t features_edx = 0;  // CPUID.1:EDX
    uint32_t features_ecx = 0;  // CPUID.1:ECX
    char brand[49] = {};        // CPUID 0x80000002-4, leading blanks dropped; empty where the CPU has none
};

struct Feature {
    const char* name;
    bool in_ecx;
    uint8_t bit;
};

extern const Feature FEATURES[];
extern const int FEATURE_COUNT;

Info detect();
bool has(const Info& info, const Feature& f);
// The CPU's class for people: "386/486 (no CPUID)", "486", "Pentium (P5)", "P6 or later".
const char* class_name(const Info& info);
inline bool has_tsc(const Info& info) { return info.has_cpuid && ((info.features_edx >> 4) & 1); }
// CPUID says there is no FPU (a CPU without CPUID says nothing: entry.asm's probe does).
inline bool denies_fpu(const Info& info) { return info.has_cpuid && !(info.features_edx & 1); }
// CMOV and an FPU: FCMOV and FCOMI come with both (the P6's).
inline bool has_p6_instructions(const Info& info) {
    constexpr uint32_t FPU = 1u << 0, CMOV = 1u << 15;
    return info.has_cpuid && (info.features_edx & (FPU | CMOV)) == (FPU | CMOV);
}

}  // namespace cpu
