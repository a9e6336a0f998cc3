// The marks (cycle_marks.h): one array for both builds of the kernel.
#include "kernel/platform/cycle_marks.h"

volatile uint8_t modexlab_cycle_marks[cycle_marks::Count] = {};
