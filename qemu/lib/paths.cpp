// The tools' build directory and shown paths (paths.h).
#include "qemu/lib/paths.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace harness {

std::string shown_path(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code e;
    const fs::path absolute = fs::absolute(path, e), cwd = fs::current_path(e);
    if (e) return path;
    const fs::path relative = absolute.lexically_normal().lexically_relative(cwd);
    if (relative.empty() || *relative.begin() == "..") return path;
    return relative.string();
}

std::string build_dir() {
    static const std::string dir = [] {
        const char* env = std::getenv("MODEXLAB_BUILD_DIR");
        if (env && *env) return std::string(env);
        std::error_code e;
        const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", e);
        return e ? std::string("build") : shown_path(program.parent_path().parent_path().string());
    }();
    return dir;
}

}  // namespace harness
