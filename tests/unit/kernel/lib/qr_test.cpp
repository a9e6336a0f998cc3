// The QR encoder (kernel/lib/qr.h) against a decoder of Debian's: every version at levels L and M,
// filled to its capacity, written as a PNG and read back by zbarimg (zbar-tools), byte for byte.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "kernel/core/random.h"
#include "kernel/lib/qr.h"
#include "qemu/harness/session.h"
#include "qemu/lib/host_image.h"

namespace {

using harness::RgbImage;

// The symbol as a camera would see it: `scale` pixels a module, four light modules of quiet zone.
RgbImage picture(const lib::QrCode& q, int scale) {
    RgbImage img;
    img.width = img.height = (q.size + 8) * scale;
    img.rgb.assign(size_t(img.width) * img.height * 3, 255);
    for (int y = 0; y < q.size; ++y)
        for (int x = 0; x < q.size; ++x)
            if (q.at(x, y))
                for (int dy = 0; dy < scale; ++dy)
                    for (int dx = 0; dx < scale; ++dx) {
                        uint8_t* p = &img.rgb[3 * (size_t((y + 4) * scale + dy) * img.width + size_t((x + 4) * scale + dx))];
                        p[0] = p[1] = p[2] = 0;
                    }
    return img;
}

// zbarimg's reading of the PNG: its exit status and the bytes it decoded (binary: no charset guess;
// what it says on stderr, D-Bus noise on a machine without D-Bus among it, left out).
std::pair<int, std::string> zbar(const std::string& png) {
    FILE* p = popen(("zbarimg --quiet --raw -Sbinary " + png + " 2>/dev/null").c_str(), "r");
    std::string out;
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    const int st = pclose(p);
    return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out};
}

std::string tmp_png(const std::string& name) {
    const std::string dir = harness::build_dir() + "/test-tmp/qr";
    std::filesystem::create_directories(dir);
    return dir + "/" + name + ".png";
}

TEST(Qr, TheCapacitiesAreTheStandards) {
    // byte mode, from the standard's table 7
    EXPECT_EQ(lib::qr_capacity(1, lib::QrLevel::L), 17u);
    EXPECT_EQ(lib::qr_capacity(1, lib::QrLevel::M), 14u);
    EXPECT_EQ(lib::qr_capacity(10, lib::QrLevel::M), 213u);
    EXPECT_EQ(lib::qr_capacity(40, lib::QrLevel::L), 2953u);
    EXPECT_EQ(lib::qr_capacity(40, lib::QrLevel::M), 2331u);
    for (int v = 2; v <= 40; ++v) EXPECT_GT(lib::qr_capacity(v, lib::QrLevel::M), lib::qr_capacity(v - 1, lib::QrLevel::M)) << v;
    EXPECT_EQ(lib::qr_capacity(0, lib::QrLevel::L), 0u);
    EXPECT_EQ(lib::qr_capacity(41, lib::QrLevel::L), 0u);
}

TEST(Qr, EveryVersionAtLAndMDecodesToItsBytes) {
    auto q = std::make_unique<lib::QrCode>();
    raster::Random r(11);
    for (lib::QrLevel level : {lib::QrLevel::L, lib::QrLevel::M})
        for (int v = 1; v <= 40; ++v) {
            const std::string name = std::string(level == lib::QrLevel::L ? "L" : "M") + std::to_string(v);
            SCOPED_TRACE(name);
            // as full as the version holds (so this version it is), CSV-like bytes and every byte value
            std::string data;
            const size_t n = lib::qr_capacity(v, level);
            for (size_t i = 0; i < n; ++i) data += v % 2 ? char(r.range(1, 255)) : "0123456789,.;abcdefxyz-\n"[r.below(24)];
            ASSERT_TRUE(lib::qr_encode(reinterpret_cast<const uint8_t*>(data.data()), data.size(), level, q.get()));
            EXPECT_EQ(q->version, v);
            EXPECT_EQ(q->size, 17 + 4 * v);
            EXPECT_GE(q->mask, 0);
            EXPECT_LE(q->mask, 7);
            const std::string png = tmp_png(name);
            harness::save_png(png, picture(*q, v < 20 ? 4 : 3));
            auto [status, out] = zbar(png);
            ASSERT_EQ(status, 0) << "zbarimg read nothing from " << png << ": " << out;
            EXPECT_EQ(out, data) << png;
        }
}

TEST(Qr, TooMuchDataIsRefused) {
    auto q = std::make_unique<lib::QrCode>();
    const std::string data(2332, 'x');
    EXPECT_FALSE(lib::qr_encode(reinterpret_cast<const uint8_t*>(data.data()), data.size(), lib::QrLevel::M, q.get()));
    EXPECT_EQ(q->version, 0);
    EXPECT_TRUE(lib::qr_encode(reinterpret_cast<const uint8_t*>(data.data()), data.size(), lib::QrLevel::L, q.get()));
    EXPECT_GE(lib::qr_capacity(q->version, lib::QrLevel::L), data.size()) << "the smallest version that holds it";
    EXPECT_LT(lib::qr_capacity(q->version - 1, lib::QrLevel::L), data.size());
    EXPECT_TRUE(lib::qr_encode(nullptr, 0, lib::QrLevel::M, q.get()));
    EXPECT_EQ(q->version, 1);
}

}  // namespace
