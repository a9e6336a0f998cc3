// The two 8259 PICs: remapped away from the CPU exception vectors (IRQs 0-15 at vectors 0x20-0x2F)
// and fully masked; drivers unmask the IRQs they serve (the keyboard: IRQ 1).
#pragma once

#include <stdint.h>

namespace pic {

constexpr uint8_t VECTOR_BASE = 0x20;

void remap_and_mask();
void unmask(uint32_t irq);
// Whether the IRQ is in service (OCW3: read the ISR): a spurious IRQ 7 or 15 is not.
bool in_service(uint32_t irq);
// Whether the IRQ waits in the request register (raised, not yet acknowledged), masked or not.
bool requested(uint32_t irq);
void end_of_interrupt(uint32_t irq);

}  // namespace pic
