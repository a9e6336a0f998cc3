// Where the host tools find their build, and how they show a path.
#pragma once

#include <string>

namespace harness {

// The build directory the tools take the kernel, the built scenes and tools from and write runs
// into: MODEXLAB_BUILD_DIR if set, else the one the running program belongs to (the directory
// above its own: build/host/modexlab gives build), so that a copied or moved tree uses its own.
// Relative to the working directory where it lies under it (what the tools then print), else
// absolute.
std::string build_dir();

// The path relative to the working directory where it lies under it, else as it is.
std::string shown_path(const std::string& path);

}  // namespace harness
