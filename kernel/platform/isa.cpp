// The build of the C++ for this CPU (isa.h).
#include "kernel/platform/isa.h"

#include "drivers/cpu.h"

namespace isa {

namespace {

Path g_path = Path::I486;

}  // namespace

Path in_use() { return g_path; }
void use(Path path) { g_path = path; }

Path for_cpu(const cpu::Info& info) { return cpu::has_p6_instructions(info) ? Path::P6 : Path::I486; }

const char* name(Path path) { return path == Path::P6 ? "p6" : "i486"; }

}  // namespace isa
