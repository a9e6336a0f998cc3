// Reading a NASM listing (listing.h): NASM assembles it (`-f bin`) into a file of our own; the bytes
// are decoded at address 0.
#include "qemu/timing/listing.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "qemu/timing/decode.h"

namespace timing {

namespace {

std::string trim(const std::string& s) {
    const size_t b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// What a shell command prints; throws where it fails.
std::string run(const std::string& command) {
    FILE* p = popen((command + " 2>&1").c_str(), "r");
    if (!p) throw std::runtime_error("cannot run: " + command);
    std::string out;
    char buf[512];
    while (fgets(buf, sizeof buf, p)) out += buf;
    if (pclose(p) != 0) throw std::runtime_error(command + ":\n" + out);
    return out;
}

std::string read_file(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error(path + ": cannot open");
    return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace

Listing read_listing(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error(path + ": cannot open");
    Listing l;
    l.path = path;
    bool in_header = true;
    for (std::string line; std::getline(f, line);) {
        const std::string t = trim(line);
        if (in_header && t.rfind(";", 0) == 0) {
            const std::string body = trim(t.substr(1));
            const size_t colon = body.find(':');
            if (colon != std::string::npos && colon > 0 && body.find(' ') > colon) l.header[body.substr(0, colon)] = trim(body.substr(colon + 1));
            continue;
        }
        if (!t.empty()) in_header = false;
        const std::string code = trim(t.substr(0, t.find(';')));
        if (code == "bits 16" || code == "BITS 16" || code == "[bits 16]") l.bits = 16;
        if (code == "bits 32" || code == "BITS 32" || code == "[bits 32]") l.bits = 32;
    }
    char out[] = "/tmp/modexlab-timing-XXXXXX";
    const int fd = mkstemp(out);
    if (fd < 0) throw std::runtime_error("cannot make a temporary file");
    close(fd);
    const std::string command = "nasm -f bin -o " + quoted(out) + " " + quoted(path) + " 2>&1";
    std::string said;
    FILE* p = popen(command.c_str(), "r");
    if (!p) {
        std::remove(out);
        throw std::runtime_error("cannot run nasm");
    }
    char buf[512];
    while (fgets(buf, sizeof buf, p)) said += buf;
    if (pclose(p) != 0) {
        std::remove(out);
        throw std::runtime_error(path + ": NASM refused it:\n" + said);
    }
    std::ifstream bin(out, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(bin)), std::istreambuf_iterator<char>());
    std::remove(out);
    try {
        l.insns = decode(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), l.bits);
    } catch (const DecodeError& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
    return l;
}

Listing read_object_loop(const std::string& object, const std::string& function) {
    long start = -1;
    std::istringstream symbols(run("nm -P --defined-only " + quoted(object)));
    for (std::string name, type, value; symbols >> name >> type >> value;) {
        std::string rest;
        std::getline(symbols, rest);
        if (name == function) start = std::stol(value, nullptr, 16);
    }
    if (start < 0) throw std::runtime_error(object + ": no symbol '" + function + "'");
    char out[] = "/tmp/modexlab-timing-XXXXXX";
    const int fd = mkstemp(out);
    if (fd < 0) throw std::runtime_error("cannot make a temporary file");
    close(fd);
    std::string text;
    try {
        run("objcopy -O binary --only-section=.text " + quoted(object) + " " + quoted(out));
        text = read_file(out);
    } catch (...) {
        std::remove(out);
        throw;
    }
    std::remove(out);
    if (size_t(start) >= text.size()) throw std::runtime_error(object + ": '" + function + "' lies outside .text");
    const std::vector<Insn> code =
        decode(reinterpret_cast<const uint8_t*>(text.data()) + start, text.size() - size_t(start), 32, uint32_t(start), true);
    for (size_t i = 0; i < code.size(); ++i) {
        const Insn& in = code[i];
        if (in.kind == Kind::Ret) break;  // (the function's end)
        if ((in.kind != Kind::Jcc && in.kind != Kind::Jmp) || in.target > in.address || in.target < uint32_t(start)) continue;
        Listing l;
        l.path = object + ":" + function, l.bits = 32;
        for (size_t k = 0; k <= i; ++k)
            if (code[k].address >= in.target) l.insns.push_back(code[k]);
        return l;
    }
    throw std::runtime_error(object + ": '" + function + "' has no loop (no jump back before its RET)");
}

Listing read_mapper_loop(const std::string& mapper, const std::string& object_dir) {
    // the registry's row: `.name = "NAME"` and, in the same row, TWIN_AND_ASM(LOOP)
    const std::string registry = read_file("kernel/mappers/registry.cpp");
    const size_t at = registry.find(".name = \"" + mapper + "\"");
    if (at == std::string::npos) throw std::runtime_error("no mapper '" + mapper + "' in kernel/mappers/registry.cpp");
    const size_t next = registry.find(".name = \"", at + 1), loop_at = registry.find("TWIN_AND_ASM(", at);
    if (loop_at == std::string::npos || (next != std::string::npos && loop_at > next))
        throw std::runtime_error("mapper '" + mapper + "' has no NASM loop");
    const size_t open = loop_at + 13, close = registry.find(')', open);
    const std::string function = registry.substr(open, close - open) + "_asm";
    for (const auto& entry : std::filesystem::directory_iterator("asm")) {
        if (entry.path().extension() != ".asm") continue;
        const std::string source = read_file(entry.path().string());
        if (source.find("global " + function + "\n") == std::string::npos) continue;
        Listing l = read_object_loop(object_dir + "/" + entry.path().filename().string() + ".o", function);
        l.header["mapper"] = mapper;
        // the x87 precision its loop runs under, where its source states one (`; precision: 24`)
        if (const size_t p = source.find("\n; precision: "); p != std::string::npos)
            l.header["precision"] = source.substr(p + 14, source.find('\n', p + 1) - p - 14);
        return l;
    }
    throw std::runtime_error("no asm/*.asm declares '" + function + "' global");
}

}  // namespace timing
