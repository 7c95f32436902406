// Animated PNG (APNG, the PNG extension every browser plays): the frames' own PNG files,
// re-chunked. Frame 0's IDAT chunks stay as they are (a viewer without APNG support shows
// it); each later frame's image data goes into fdAT chunks after an fcTL chunk that says
// where and how long it shows. No pixel is decoded or re-encoded. Written here because no
// Debian library writes APNG (stb_image_write and libpng write single images).
#pragma once

#include <string>
#include <vector>

namespace tessera::render {

// `frames`: PNG files of equal size and colour type; `seconds_per_frame` > 0.
// Throws Error(internal) for frames that are not such PNG files.
std::string assemble_apng(const std::vector<std::string>& frames, double seconds_per_frame);

// CRC-32 of PNG chunks (ISO 3309), over the chunk type and data.
unsigned crc32(const unsigned char* data, size_t size, unsigned crc = 0);

}  // namespace tessera::render
