#include "tile_ranges.hpp"

#include <algorithm>
#include <sstream>

#include "common.hpp"

namespace tessera_cli {
namespace {

// Worlds of more tiles than this are built in several runs (their index alone would be large).
constexpr std::int64_t max_tiles = 1 << 22;

std::int64_t parse_end(const std::string& digits, const std::string& text, const std::string& flag) {
    const std::optional<std::string> plain = integer_digits(digits);
    if (!plain) fail_option(flag + ": '" + text + "': '" + digits + "' is not an integer tile coordinate");
    try {
        const long long v = std::stoll(*plain);
        if (v < -(1LL << 40) || v > (1LL << 40)) throw std::out_of_range("coordinate");
        return v;
    } catch (const std::exception&) {
        fail_option(flag + ": '" + text + "': the tile coordinate " + digits + " is out of range");
    }
}

}  // namespace

TileRange parse_tile_range(const std::string& text, int dimension, const std::string& flag) {
    TileRange r;
    r.text = text;
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ',');) parts.push_back(part);
    if (static_cast<int>(parts.size()) != dimension)
        fail_option(flag + ": '" + text + "': a " + std::to_string(dimension) + "D world's tiles are given as " +
                    (dimension == 2 ? "X0:X1,Y0:Y1" : "X0:X1,Y0:Y1,Z0:Z1") + " (ends exclusive)");
    std::int64_t count = 1;
    for (int k = 0; k < dimension; ++k) {
        const size_t colon = parts[k].find(':');
        if (colon == std::string::npos)
            fail_option(flag + ": '" + text + "': '" + parts[k] + "' is not a range FROM:TO");
        r.lo[k] = parse_end(parts[k].substr(0, colon), text, flag);
        r.hi[k] = parse_end(parts[k].substr(colon + 1), text, flag);
        if (r.hi[k] <= r.lo[k])
            fail_option(flag + ": '" + text + "': the range " + parts[k] + " holds no tile (the end is exclusive)");
        count *= std::min<std::int64_t>(r.hi[k] - r.lo[k], max_tiles + 1);
        if (count > max_tiles) fail_option(flag + ": '" + text + "': more than " + std::to_string(max_tiles) + " tiles");
    }
    return r;
}

std::vector<tessera::TileCoord> tiles_of(const std::vector<TileRange>& ranges, const std::string& flag) {
    for (size_t a = 0; a < ranges.size(); ++a)
        for (size_t b = a + 1; b < ranges.size(); ++b) {
            bool overlap = true;
            for (int k = 0; k < 3; ++k)
                overlap = overlap && ranges[a].lo[k] < ranges[b].hi[k] && ranges[b].lo[k] < ranges[a].hi[k];
            if (overlap) fail_option(flag + ": the ranges '" + ranges[a].text + "' and '" + ranges[b].text + "' overlap");
        }
    std::vector<tessera::TileCoord> tiles;
    for (const TileRange& r : ranges)
        for (std::int64_t x = r.lo[0]; x < r.hi[0]; ++x)
            for (std::int64_t y = r.lo[1]; y < r.hi[1]; ++y)
                for (std::int64_t z = r.lo[2]; z < r.hi[2]; ++z) tiles.push_back({x, y, z});
    std::sort(tiles.begin(), tiles.end());
    return tiles;
}

}  // namespace tessera_cli
