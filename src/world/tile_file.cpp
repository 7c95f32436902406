// A world's tiles as data (tessera/world.hpp): the canonical text, its hash, and tiles merged.
#include <algorithm>
#include <cstdio>

#include "tessera/io.hpp"
#include "tessera/world.hpp"
#include "world/append_element.hpp"

namespace tessera {

std::string tile_to_json(const Arrangement& tile) { return to_json(tile); }

std::string tile_hash(const Arrangement& tile) { return content_hash(tile_to_json(tile)); }

std::string content_hash(const std::string& content) {
    // FNV-1a, 64 bits: a content hash to compare tiles by, not a cryptographic one.
    std::uint64_t h = 14695981039346656037ull;
    for (const unsigned char c : content) h = (h ^ c) * 1099511628211ull;
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

Arrangement merge_tiles(const std::vector<const Arrangement*>& tiles, int dimension) {
    Arrangement out;
    out.dimension = dimension;
    Box box{{1e300, 1e300, dimension == 3 ? 1e300 : 0.0}, {-1e300, -1e300, dimension == 3 ? -1e300 : 0.0}};
    for (const Arrangement* t : tiles) {
        if (out.types.empty()) out.types = t->types, out.attribute_names = t->attribute_names;
        const Box& b = t->domain.bounds();
        for (int k = 0; k < dimension; ++k) box.lo[k] = std::min(box.lo[k], b.lo[k]), box.hi[k] = std::max(box.hi[k], b.hi[k]);
        for (const Element& e : t->elements) world::append_element(*t, e, out);
    }
    if (!tiles.empty()) out.domain = Domain::box(box.lo, box.hi, dimension);
    return out;
}

}  // namespace tessera
