// PNG through libpng's simplified API, a strict P6 parser, an 8-bit BMP writer, and screendump-to-index
// decoding.
#include "qemu/lib/host_image.h"

#include <png.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "kernel/lib/encode.h"
#include "qemu/lib/error.h"

namespace harness {

namespace {

constexpr size_t BMP_FILE_HEADER_BYTES = 14;
constexpr size_t BMP_INFO_HEADER_BYTES = 40;
constexpr size_t BMP_COLOUR_TABLE_BYTES = 256 * 4;

void put_u16(std::string& b, size_t at, uint32_t v) {
    b[at] = char(v & 0xFF);
    b[at + 1] = char((v >> 8) & 0xFF);
}
void put_u32(std::string& b, size_t at, uint32_t v) {
    put_u16(b, at, v & 0xFFFF);
    put_u16(b, at + 2, v >> 16);
}

}  // namespace

RgbImage decode_png(std::string_view bytes) {
    png_image img{};
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&img, bytes.data(), bytes.size()))
        throw HarnessError(std::string("PNG: ") + img.message);
    img.format = PNG_FORMAT_RGB;
    RgbImage out;
    out.width = int(img.width);
    out.height = int(img.height);
    out.rgb.resize(PNG_IMAGE_SIZE(img));
    if (!png_image_finish_read(&img, nullptr, out.rgb.data(), 0, nullptr)) {
        std::string message = img.message;
        png_image_free(&img);
        throw HarnessError("PNG: " + message);
    }
    return out;
}

RgbImage decode_ppm(std::string_view bytes) {
    size_t pos = 0;
    auto skip_blanks_and_comments = [&] {
        for (;;) {
            while (pos < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
            if (pos < bytes.size() && bytes[pos] == '#') {
                while (pos < bytes.size() && bytes[pos] != '\n') ++pos;
                continue;
            }
            return;
        }
    };
    auto number = [&](const char* what) {
        skip_blanks_and_comments();
        size_t start = pos;
        long v = 0;
        while (pos < bytes.size() && std::isdigit(static_cast<unsigned char>(bytes[pos])) && v < 1000000)
            v = v * 10 + (bytes[pos++] - '0');
        if (pos == start) throw HarnessError(std::string("PPM: missing ") + what);
        if (v >= 1000000) throw HarnessError(std::string("PPM: ") + what + " too large");
        return int(v);
    };
    if (bytes.substr(0, 2) != "P6") throw HarnessError("PPM: not a binary PPM (P6) file");
    pos = 2;
    RgbImage out;
    out.width = number("width");
    out.height = number("height");
    int maxval = number("maxval");
    if (out.width <= 0 || out.height <= 0) throw HarnessError("PPM: empty image");
    if (maxval != 255) throw HarnessError("PPM: maxval " + std::to_string(maxval) + " (only 255 is supported)");
    if (pos >= bytes.size() || !std::isspace(static_cast<unsigned char>(bytes[pos]))) throw HarnessError("PPM: bad header end");
    ++pos;
    size_t need = size_t(out.width) * size_t(out.height) * 3;
    if (bytes.size() - pos < need)
        throw HarnessError("PPM: truncated pixel data (" + std::to_string(bytes.size() - pos) + " of " + std::to_string(need) + " bytes)");
    out.rgb.assign(bytes.begin() + long(pos), bytes.begin() + long(pos + need));
    return out;
}

RgbImage load_image(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw HarnessError(path + ": cannot open the image (" + std::strerror(errno) + ")");
    std::stringstream ss;
    ss << in.rdbuf();
    std::string bytes = ss.str();
    try {
        if (bytes.rfind("\x89PNG", 0) == 0) return decode_png(bytes);
        if (bytes.rfind("P6", 0) == 0) return decode_ppm(bytes);
    } catch (const HarnessError& e) {
        throw HarnessError(path + ": " + e.what());
    }
    throw HarnessError(path + ": neither PNG nor PPM");
}

void save_png(const std::string& path, const RgbImage& image) {
    std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    png_image img{};
    img.version = PNG_IMAGE_VERSION;
    img.width = png_uint_32(image.width);
    img.height = png_uint_32(image.height);
    img.format = PNG_FORMAT_RGB;
    if (!png_image_write_to_file(&img, path.c_str(), 0, image.rgb.data(), 0, nullptr))
        throw HarnessError("cannot write " + path + ": " + img.message);
}

void write_bmp8(const std::string& path, int width, int height, const uint8_t* indices, const uint8_t* palette_rgb768) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0) throw HarnessError(path + ": cannot write a " + size + " BMP");
    if (!indices || !palette_rgb768) throw HarnessError(path + ": no pixels or no palette to write");
    const uint64_t stride = (uint64_t(width) + 3) & ~uint64_t(3);
    const uint64_t pixel_bytes = stride * uint64_t(height);
    const uint64_t data_offset = BMP_FILE_HEADER_BYTES + BMP_INFO_HEADER_BYTES + BMP_COLOUR_TABLE_BYTES;
    const uint64_t file_bytes = data_offset + pixel_bytes;
    if (file_bytes > 0x7FFFFFFF) throw HarnessError(path + ": a " + size + " BMP would be too large");

    std::string out(size_t(file_bytes), '\0');
    out[0] = 'B';
    out[1] = 'M';
    put_u32(out, 2, uint32_t(file_bytes));
    put_u32(out, 10, uint32_t(data_offset));
    const size_t info = BMP_FILE_HEADER_BYTES;
    put_u32(out, info + 0, BMP_INFO_HEADER_BYTES);
    put_u32(out, info + 4, uint32_t(width));
    put_u32(out, info + 8, uint32_t(height));  // positive: rows stored bottom-up
    put_u16(out, info + 12, 1);                // planes
    put_u16(out, info + 14, 8);                // bits a pixel
    put_u32(out, info + 16, 0);                // BI_RGB, uncompressed
    put_u32(out, info + 20, uint32_t(pixel_bytes));
    put_u32(out, info + 32, 256);              // colours used
    const size_t table = info + BMP_INFO_HEADER_BYTES;
    for (size_t i = 0; i < 256; ++i) {
        out[table + 4 * i + 0] = char(palette_rgb768[3 * i + 2]);
        out[table + 4 * i + 1] = char(palette_rgb768[3 * i + 1]);
        out[table + 4 * i + 2] = char(palette_rgb768[3 * i + 0]);
    }
    for (int y = 0; y < height; ++y) {
        const uint8_t* src = indices + size_t(y) * size_t(width);
        const size_t dst = size_t(data_offset) + size_t(height - 1 - y) * size_t(stride);
        std::memcpy(&out[dst], src, size_t(width));
    }

    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) throw HarnessError(path + ": cannot write (" + std::strerror(errno) + ")");
    file.write(out.data(), std::streamsize(out.size()));
    file.close();
    if (!file) throw HarnessError(path + ": writing failed (" + std::strerror(errno) + ")");
}

RgbImage colourise(const IndexImage& image, const raster::Palette& palette) {
    RgbImage out{image.width, image.height, std::vector<uint8_t>(image.index.size() * 3)};
    for (size_t i = 0; i < image.index.size(); ++i) {
        const raster::Rgb6& c = palette.entry[image.index[i]];
        out.rgb[3 * i] = qemu_widen(c.r);
        out.rgb[3 * i + 1] = qemu_widen(c.g);
        out.rgb[3 * i + 2] = qemu_widen(c.b);
    }
    return out;
}

RgbImage screendump_of(const IndexImage& image, const raster::Palette& palette) {
    RgbImage small = colourise(image, palette);
    RgbImage out{2 * image.width, 2 * image.height, std::vector<uint8_t>(small.rgb.size() * 4)};
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int k = 0; k < 3; ++k) out.rgb[3 * (size_t(y) * size_t(out.width) + size_t(x)) + size_t(k)] = small.at(x / 2, y / 2)[k];
    return out;
}

DecodeResult decode_screendump(const RgbImage& dump, const raster::Palette& palette, ScreenMode mode) {
    DecodeResult r;
    if (dump.width != 2 * mode.width || dump.height != 2 * mode.height) {
        r.error = "screendump is " + std::to_string(dump.width) + "x" + std::to_string(dump.height) + ", not the " +
                  std::to_string(2 * mode.width) + "x" + std::to_string(2 * mode.height) + " of mode " + mode.name;
        return r;
    }
    // widened colour -> the palette entries that show it
    std::map<std::array<uint8_t, 3>, std::vector<int>> entries;
    for (int i = 0; i < 256; ++i) {
        const raster::Rgb6& c = palette.entry[i];
        entries[{qemu_widen(c.r), qemu_widen(c.g), qemu_widen(c.b)}].push_back(i);
    }
    auto colour_text = [](const uint8_t* p) {
        return "(" + std::to_string(p[0]) + "," + std::to_string(p[1]) + "," + std::to_string(p[2]) + ")";
    };
    r.image = IndexImage{mode.width, mode.height, std::vector<uint8_t>(size_t(mode.width) * size_t(mode.height))};
    for (int y = 0; y < mode.height; ++y) {
        for (int x = 0; x < mode.width; ++x) {
            const uint8_t* p = dump.at(2 * x, 2 * y);
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx)
                    if (!std::equal(p, p + 3, dump.at(2 * x + dx, 2 * y + dy))) {
                        r.error = "2x2 block of pixel (" + std::to_string(x) + "," + std::to_string(y) + ") is not uniform: " +
                                  colour_text(p) + " vs " + colour_text(dump.at(2 * x + dx, 2 * y + dy));
                        return r;
                    }
            auto it = entries.find({p[0], p[1], p[2]});
            if (it == entries.end()) {
                r.error = "colour " + colour_text(p) + " at pixel (" + std::to_string(x) + "," + std::to_string(y) + ") is in no palette entry";
                return r;
            }
            if (it->second.size() > 1) {
                r.error = "colour " + colour_text(p) + " at pixel (" + std::to_string(x) + "," + std::to_string(y) + ") matches " +
                          std::to_string(it->second.size()) + " palette entries (" + std::to_string(it->second[0]) + ", " +
                          std::to_string(it->second[1]) + ", ...): the palette cannot be decoded to indices";
                return r;
            }
            r.image.index[size_t(y) * size_t(mode.width) + size_t(x)] = uint8_t(it->second[0]);
        }
    }
    r.ok = true;
    return r;
}

IndexImage render_pattern(raster::Pattern pattern, ScreenMode mode) {
    IndexImage out{mode.width, mode.height, std::vector<uint8_t>(size_t(mode.width) * size_t(mode.height))};
    for (int y = 0; y < mode.height; ++y)
        for (int x = 0; x < mode.width; ++x)
            out.index[size_t(y) * size_t(mode.width) + size_t(x)] = raster::pattern_pixel(pattern, x, y, mode.width, mode.height);
    return out;
}

std::string Comparison::summary() const {
    if (size_mismatch) return "images differ in size";
    if (differing == 0) return "all " + std::to_string(total) + " pixels equal";
    std::string s = std::to_string(differing) + " of " + std::to_string(total) + " pixels differ; first at";
    for (const PixelDiff& d : first)
        s += " (" + std::to_string(d.x) + "," + std::to_string(d.y) + ") got " + std::to_string(d.actual) + " want " + std::to_string(d.expected) + ";";
    return s;
}

Comparison compare(const IndexImage& actual, const IndexImage& expected) {
    Comparison c;
    c.total = expected.index.size();
    if (actual.width != expected.width || actual.height != expected.height) {
        c.size_mismatch = true;
        c.differing = c.total;
        return c;
    }
    for (int y = 0; y < expected.height; ++y)
        for (int x = 0; x < expected.width; ++x) {
            int a = actual.at(x, y), e = expected.at(x, y);
            if (a == e) continue;
            if (c.first.size() < 10) c.first.push_back({x, y, a, e});
            ++c.differing;
        }
    return c;
}

std::string write_mismatch(const std::string& dir, const std::string& stem, const IndexImage& actual,
                           const IndexImage& expected, const raster::Palette& palette) {
    std::string base = dir + "/" + stem;
    save_png(base + "-actual.png", colourise(actual, palette));
    RgbImage expected_rgb = colourise(expected, palette);
    save_png(base + "-expected.png", expected_rgb);
    if (actual.width == expected.width && actual.height == expected.height) {
        RgbImage diff = expected_rgb;
        for (size_t i = 0; i < expected.index.size(); ++i) {
            bool same = actual.index[i] == expected.index[i];
            for (int k = 0; k < 3; ++k) diff.rgb[3 * i + size_t(k)] = same ? uint8_t(diff.rgb[3 * i + size_t(k)] / 4) : (k == 0 ? 255 : 0);
        }
        save_png(base + "-diff.png", diff);
        return "wrote " + base + "-{actual,expected,diff}.png";
    }
    return "wrote " + base + "-{actual,expected}.png";
}

uint32_t crc32_of(const IndexImage& image) { return lib::crc32(0, image.index.data(), image.index.size()); }

}  // namespace harness
