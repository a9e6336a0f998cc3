// CPUID probing (EFLAGS.ID toggle first: a 486 without CPUID must not fault).
#include "drivers/cpu.h"

namespace cpu {

const Feature FEATURES[] = {
    {"fpu", false, 0}, {"tsc", false, 4}, {"cx8", false, 8}, {"cmov", false, 15},
    {"mmx", false, 23}, {"sse", false, 25}, {"sse2", false, 26}, {"sse3", true, 0},
};
const int FEATURE_COUNT = sizeof(FEATURES) / sizeof(FEATURES[0]);

namespace {

bool cpuid_supported() {
    uint32_t before, after;
    asm volatile(
        "pushfl\n\t"
        "popl %0\n\t"
        "movl %0, %1\n\t"
        "xorl $0x200000, %1\n\t"
        "pushl %1\n\t"
        "popfl\n\t"
        "pushfl\n\t"
        "popl %1\n\t"
        "pushl %0\n\t"
        "popfl"
        : "=&r"(before), "=&r"(after));
    return ((before ^ after) & 0x200000) != 0;
}

void cpuid(uint32_t leaf, uint32_t* a, uint32_t* b, uint32_t* c, uint32_t* d) {
    asm volatile("cpuid" : "=a"(*a), "=b"(*b), "=c"(*c), "=d"(*d) : "a"(leaf), "c"(0));
}

void put_word(char* dst, uint32_t w) {
    for (int i = 0; i < 4; ++i) dst[i] = char(w >> (8 * i));
}

}  // namespace

Info detect() {
    Info info;
    if (!cpuid_supported()) return info;
    info.has_cpuid = true;
    uint32_t a, b, c, d;
    cpuid(0, &a, &b, &c, &d);
    put_word(info.vendor, b);
    put_word(info.vendor + 4, d);
    put_word(info.vendor + 8, c);
    info.vendor[12] = 0;
    if (a >= 1) {
        cpuid(1, &a, &b, &c, &d);
        info.stepping = a & 0xF;
        info.model = (a >> 4) & 0xF;
        info.family = (a >> 8) & 0xF;
        if (info.family == 0xF) info.family += (a >> 20) & 0xFF;
        if (info.family == 0x6 || info.family >= 0xF) info.model |= ((a >> 16) & 0xF) << 4;
        info.features_edx = d;
        info.features_ecx = c;
    }
    cpuid(0x80000000, &a, &b, &c, &d);
    if (a >= 0x80000004 && a < 0x8000FFFF) {  // (a CPU without extended leaves may echo anything)
        char text[48];
        for (uint32_t leaf = 0; leaf < 3; ++leaf) {
            cpuid(0x80000002 + leaf, &a, &b, &c, &d);
            put_word(text + 16 * leaf, a), put_word(text + 16 * leaf + 4, b), put_word(text + 16 * leaf + 8, c), put_word(text + 16 * leaf + 12, d);
        }
        int from = 0, n = 0;
        while (from < 48 && text[from] == ' ') ++from;
        for (; from < 48 && text[from]; ++from) info.brand[n++] = text[from] >= 32 && text[from] < 127 ? text[from] : '?';
        while (n > 0 && info.brand[n - 1] == ' ') --n;
        info.brand[n] = 0;
    }
    return info;
}

const char* class_name(const Info& info) {
    if (!info.has_cpuid) return "386/486 (no CPUID)";
    if (info.family <= 4) return "486";
    if (info.family == 5) return "Pentium (P5)";
    return "P6 or later";
}

bool has(const Info& info, const Feature& f) {
    return ((f.in_ecx ? info.features_ecx : info.features_edx) >> f.bit) & 1;
}

}  // namespace cpu
