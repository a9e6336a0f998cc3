// The timing model's QEMU plugin as a session loads it (docs/cycles.md, "Whole frames"): its
// -plugin argument, and the rows it writes, one a bench row.
#pragma once

#include <string>
#include <vector>

#include "qemu/lib/ordered_json.h"

namespace harness {

struct TimingPlugin {
    std::string cpu = "pentium";  // 486 or pentium
    std::vector<std::string> buses = {"zero-wait"};  // bus models, each counted in the one run
    int precision = 53;
    std::string out;              // the file it writes its rows to
};

// QEMU's -plugin SPEC: the plugin built beside the tools, the marks' address from the kernel's
// symbols (nm). Throws HarnessError where either is missing.
std::string timing_plugin_spec(const TimingPlugin& p, const std::string& kernel_elf);

// Its rows so far: a bench row's figures on each bus, in the order the rows ended.
std::vector<json> timing_plugin_rows(const std::string& out);

}  // namespace harness
