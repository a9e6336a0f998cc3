// The build of the C++ for this CPU (isa.h).
#include "kernel/platform/isa.h"

#include "drivers/cpu.h"

namespace isa {

namespace {

Path g_path = Path::I486;

}  // namespace

Path in_use() { return g_path; }
void use(Path path) { g_path = path; }

Path for_this_cpu() {
    const cpu::Info info = cpu::detect();
    constexpr uint32_t FPU = 1u << 0, CMOV = 1u << 15;  // (FCMOV and FCOMI come with both)
    return info.has_cpuid && (info.features_edx & (FPU | CMOV)) == (FPU | CMOV) ? Path::P6 : Path::I486;
}

const char* name(Path path) { return path == Path::P6 ? "p6" : "i486"; }

}  // namespace isa
