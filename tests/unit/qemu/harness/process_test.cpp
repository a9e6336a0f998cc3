// Under test: qemu/harness/process.h, readback.h.
// The QEMU command line the harness builds, what exit statuses mean, and readback decoding.
#include <gtest/gtest.h>

#include <algorithm>

#include "kernel/lib/encode.h"
#include "qemu/lib/error.h"
#include "qemu/harness/process.h"
#include "qemu/harness/readback.h"

namespace {

using namespace harness;


bool has_pair(const std::vector<std::string>& a, const std::string& k, const std::string& v) {
    for (size_t i = 0; i + 1 < a.size(); ++i)
        if (a[i] == k && a[i + 1] == v) return true;
    return false;
}

TEST(QemuArguments, KernelBootIsHeadlessTcgWithDebugExit) {
    QemuConfig c;
    c.image = "k.elf";
    c.append = "boot=serve";
    c.run_dir = "/r";
    auto a = qemu_arguments(c, "/s/com1", "/s/qmp");
    EXPECT_TRUE(has_pair(a, "-kernel", "k.elf"));
    EXPECT_TRUE(has_pair(a, "-append", "boot=serve"));
    EXPECT_TRUE(has_pair(a, "-display", "none"));
    EXPECT_TRUE(has_pair(a, "-machine", "pc,accel=tcg"));
    EXPECT_TRUE(has_pair(a, "-device", "isa-debug-exit,iobase=0xf4,iosize=0x04"));
    EXPECT_TRUE(has_pair(a, "-chardev", "socket,id=com1,path=/s/com1"));
    EXPECT_TRUE(has_pair(a, "-mon", "chardev=qmp,mode=control"));
    EXPECT_NE(std::find(a.begin(), a.end(), "-no-reboot"), a.end());
    EXPECT_EQ(std::find(a.begin(), a.end(), "-icount"), a.end());
    c.icount = true;
    EXPECT_TRUE(has_pair(qemu_arguments(c, "a", "b"), "-icount", "shift=0,align=off,sleep=off"));
}

TEST(QemuArguments, IsoAsCdromAndAsUsbStick) {
    QemuConfig c;
    c.image = "m.iso";
    c.medium = BootMedium::Cdrom;
    EXPECT_TRUE(has_pair(qemu_arguments(c, "a", "b"), "-cdrom", "m.iso"));
    c.medium = BootMedium::Usb;
    auto a = qemu_arguments(c, "a", "b");
    EXPECT_TRUE(has_pair(a, "-drive", "if=none,id=stick,format=raw,file=m.iso"));
    EXPECT_TRUE(has_pair(a, "-device", "nec-usb-xhci,id=xhci"));
    EXPECT_EQ(std::find(a.begin(), a.end(), "-cdrom"), a.end());
    EXPECT_EQ(std::find(a.begin(), a.end(), "-kernel"), a.end());
}

TEST(ExitInfo, DecodesIsaDebugExitStatuses) {
    auto text = [](int status) { return ExitInfo{true, status, 0}.describe(); };
    EXPECT_NE(text(0).find("never a pass"), std::string::npos);
    EXPECT_NE(text(7).find("kernel exit code 3"), std::string::npos);
    EXPECT_NE(text(2 * (0x40 + 6) + 1).find("CPU exception, vector 6"), std::string::npos);
    EXPECT_NE(text(2 * 0x60 + 1).find("kernel panic"), std::string::npos);
    EXPECT_NE(text(2).find("not from isa-debug-exit"), std::string::npos);
    EXPECT_NE((ExitInfo{false, 0, 9}.describe()).find("signal 9"), std::string::npos);
}

// A readback reply as the kernel builds it, from the same encoders.
json make_readback(const std::vector<uint8_t>& pixels, int w, int h) {
    std::string data;
    lib::Sink sink{[](void* ctx, const char* d, size_t n) { static_cast<std::string*>(ctx)->append(d, n); }, &data};
    lib::Base64Encoder b64(sink);
    size_t packed = lib::packbits_encode(pixels.data(), pixels.size(), [](void* e, uint8_t b) { static_cast<lib::Base64Encoder*>(e)->put(b); }, &b64);
    b64.finish();
    char crc[16];
    std::snprintf(crc, sizeof crc, "0x%08x", lib::crc32(0, pixels.data(), pixels.size()));
    return {{"seq", 1}, {"ok", true}, {"width", w}, {"height", h}, {"encoding", "packbits+base64"},
            {"crc32", crc}, {"data", data}, {"packed_bytes", packed}};
}

TEST(Readback, DecodesAndChecks) {
    std::vector<uint8_t> px(320 * 240);
    for (size_t i = 0; i < px.size(); ++i) px[i] = uint8_t(i % 320 < 100 ? 7 : i * 31 / 7);
    json r = make_readback(px, 320, 240);
    EXPECT_EQ(decode_readback(r).index, px);

    json bad_crc = r;
    bad_crc["crc32"] = "0x00000000";
    EXPECT_THROW(decode_readback(bad_crc), HarnessError);
    json short_data = make_readback(std::vector<uint8_t>(px.begin(), px.end() - 1), 320, 240);
    EXPECT_THROW(decode_readback(short_data), HarnessError);
    json bad_b64 = r;
    bad_b64["data"] = std::string(bad_b64["data"]).substr(1);
    EXPECT_THROW(decode_readback(bad_b64), HarnessError);
    json bad_encoding = r;
    bad_encoding["encoding"] = "raw";
    EXPECT_THROW(decode_readback(bad_encoding), HarnessError);
    json missing = r;
    missing.erase("crc32");
    EXPECT_THROW(decode_readback(missing), HarnessError);
}

}  // namespace
