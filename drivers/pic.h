// The two 8259 PICs: remapped away from the CPU exception vectors and fully masked (the kernel polls).
#pragma once

namespace pic {
void remap_and_mask();
}
