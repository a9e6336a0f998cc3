// Reading a NASM listing (listing.h): NASM assembles it (`-f bin`) into a file of our own; the bytes
// are decoded at address 0.
#include "qemu/timing/listing.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
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

}  // namespace timing
