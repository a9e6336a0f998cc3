// The kernel's version, reported by `hello` and the boot line.
#pragma once

#define MODEXLAB_VERSION "0.1.0"
