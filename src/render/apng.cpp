// render/apng.cpp — APNG assembly (APNG specification 1.0: acTL, fcTL, fdAT chunks).
#include "render/apng.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "tessera/error.hpp"

namespace tessera::render {

namespace {

constexpr unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

struct Chunk {
    std::string type;
    std::string data;
};

std::uint32_t read_u32(const std::string& s, size_t at) {
    return (std::uint32_t(std::uint8_t(s[at])) << 24) | (std::uint32_t(std::uint8_t(s[at + 1])) << 16) |
           (std::uint32_t(std::uint8_t(s[at + 2])) << 8) | std::uint32_t(std::uint8_t(s[at + 3]));
}

void put_u32(std::string& out, std::uint32_t v) {
    out += static_cast<char>(v >> 24), out += static_cast<char>(v >> 16);
    out += static_cast<char>(v >> 8), out += static_cast<char>(v);
}

void put_u16(std::string& out, std::uint16_t v) { out += static_cast<char>(v >> 8), out += static_cast<char>(v); }

std::vector<Chunk> read_chunks(const std::string& png) {
    if (png.size() < 8 || std::memcmp(png.data(), signature, 8) != 0)
        throw Error(ErrorKind::internal, "assemble_apng: a frame is not a PNG file");
    std::vector<Chunk> chunks;
    size_t at = 8;
    while (at + 12 <= png.size()) {
        const std::uint32_t length = read_u32(png, at);
        if (at + 12 + length > png.size()) throw Error(ErrorKind::internal, "assemble_apng: a frame's PNG is cut");
        chunks.push_back({png.substr(at + 4, 4), png.substr(at + 8, length)});
        at += 12 + length;
    }
    return chunks;
}

void put_chunk(std::string& out, const std::string& type, const std::string& data) {
    put_u32(out, static_cast<std::uint32_t>(data.size()));
    const std::string body = type + data;
    out += body;
    put_u32(out, crc32(reinterpret_cast<const unsigned char*>(body.data()), body.size()));
}

// fcTL: the frame covers the whole canvas, shows for delay_num / delay_den seconds, and
// replaces what was there (dispose none, blend source: every frame is opaque and whole).
std::string frame_control(std::uint32_t sequence, const std::string& ihdr, std::uint16_t delay_num,
                          std::uint16_t delay_den) {
    std::string d;
    put_u32(d, sequence);
    d += ihdr.substr(0, 8);  // width, height
    put_u32(d, 0), put_u32(d, 0);
    put_u16(d, delay_num), put_u16(d, delay_den);
    d += '\0', d += '\0';
    return d;
}

}  // namespace

unsigned crc32(const unsigned char* data, size_t size, unsigned crc) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t c = crc ^ 0xffffffffu;
    for (size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xff] ^ (c >> 8);
    return c ^ 0xffffffffu;
}

std::string assemble_apng(const std::vector<std::string>& frames, double seconds_per_frame) {
    if (frames.empty() || !(seconds_per_frame > 0.0))
        throw Error(ErrorKind::internal, "assemble_apng: no frame or a delay <= 0");
    const std::uint16_t den = 1000;
    const auto num = static_cast<std::uint16_t>(std::clamp(std::lround(seconds_per_frame * den), 1L, 65535L));
    std::string out(reinterpret_cast<const char*>(signature), 8);
    std::uint32_t sequence = 0;
    std::string ihdr;
    for (size_t f = 0; f < frames.size(); ++f) {
        const std::vector<Chunk> chunks = read_chunks(frames[f]);
        if (chunks.empty() || chunks[0].type != "IHDR") throw Error(ErrorKind::internal, "assemble_apng: no IHDR");
        if (f == 0) {
            ihdr = chunks[0].data;
            put_chunk(out, "IHDR", ihdr);
            std::string actl;
            put_u32(actl, static_cast<std::uint32_t>(frames.size()));
            put_u32(actl, 0);  // loop forever
            put_chunk(out, "acTL", actl);
        } else if (chunks[0].data != ihdr) {
            throw Error(ErrorKind::internal, "assemble_apng: frames differ in size or colour type");
        }
        put_chunk(out, "fcTL", frame_control(sequence++, ihdr, num, den));
        for (const Chunk& c : chunks) {
            if (c.type != "IDAT") continue;
            if (f == 0) {
                put_chunk(out, "IDAT", c.data);
            } else {
                std::string d;
                put_u32(d, sequence++);
                put_chunk(out, "fdAT", d + c.data);
            }
        }
    }
    put_chunk(out, "IEND", "");
    return out;
}

}  // namespace tessera::render
