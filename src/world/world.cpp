// tessera::World (tessera/world.hpp): tiles answered on demand, with their dependencies,
// kept in memory and optionally in a cache directory.
#include <cmath>
#include <filesystem>
#include <map>

#include "tessera/error.hpp"
#include "tessera/io.hpp"
#include "tessera/world.hpp"

namespace tessera {

namespace fs = std::filesystem;

struct World::Impl {
    TileMaker maker;
    std::string cache_dir;
    std::map<TileCoord, Arrangement> tiles;
    int made = 0;
    Progress progress;

    std::string tile_path(const TileCoord& t) const {
        std::string name = "tile_" + std::to_string(t.x) + "_" + std::to_string(t.y);
        if (maker.dimension() == 3) name += "_" + std::to_string(t.z);
        return (fs::path(cache_dir) / (name + ".json")).string();
    }

    // The cache directory holds tiles of this world only: its fingerprint file says which.
    void open_cache() {
        if (cache_dir.empty()) return;
        std::error_code error;
        fs::create_directories(cache_dir, error);
        if (error) throw Error(ErrorKind::io, "cache directory " + cache_dir + ": cannot create it (" + error.message() + ")");
        const std::string marker = (fs::path(cache_dir) / "world.fingerprint").string();
        if (fs::exists(marker)) {
            if (read_file(marker) != maker.fingerprint())
                throw Error(ErrorKind::option, "cache directory " + cache_dir +
                                                   ": it holds the tiles of another world (another exemplar, "
                                                   "tile size, seed or growth option); give an empty directory");
        } else {
            write_file_atomic(marker, maker.fingerprint());
        }
    }

    const Arrangement& get(const TileCoord& t) {
        if (const auto it = tiles.find(t); it != tiles.end()) return it->second;
        if (!cache_dir.empty() && fs::exists(tile_path(t))) {
            Arrangement a;
            static_cast<Exemplar&>(a) = parse_json(read_file(tile_path(t)), tile_path(t));
            return tiles.emplace(t, std::move(a)).first->second;
        }
        // Dependencies first: at most one per earlier phase deep, so the recursion is short.
        std::vector<NeighbourTile> neighbours;
        for (const TileCoord& d : tile_dependencies(t, maker.dimension())) neighbours.push_back({d, &get(d)});
        Arrangement a = maker.make(t, neighbours, progress);
        ++made;
        if (!cache_dir.empty()) write_file_atomic(tile_path(t), tile_to_json(a));
        return tiles.emplace(t, std::move(a)).first->second;
    }
};

World::World(const Exemplar& exemplar, const WorldOptions& options, std::string cache_dir)
    : impl_(std::make_unique<Impl>(Impl{TileMaker(exemplar, options), std::move(cache_dir), {}, 0, {}})) {
    impl_->open_cache();
}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

const Arrangement& World::tile(const TileCoord& t) {
    if (impl_->maker.dimension() == 2 && t.z != 0)
        throw Error(ErrorKind::input, "tile " + t.describe() + ": a 2D world's tiles have z = 0");
    return impl_->get(t);
}

std::vector<TileCoord> World::tiles_around(const Vec3& p, double radius) const {
    if (!(radius >= 0.0) || !std::isfinite(radius))
        throw Error(ErrorKind::option, "radius must be a number >= 0, got " + std::to_string(radius));
    const int dim = impl_->maker.dimension();
    const double s = impl_->maker.options().tile_size;
    const Vec3 r{radius, radius, dim == 3 ? radius : 0.0};
    const TileCoord lo = tile_at(p - r, s, dim), hi = tile_at(p + r, s, dim);
    std::vector<TileCoord> out;
    for (std::int64_t x = lo.x; x <= hi.x; ++x)
        for (std::int64_t y = lo.y; y <= hi.y; ++y)
            for (std::int64_t z = lo.z; z <= hi.z; ++z) {
                const TileCoord t{x, y, z};
                const Box b = tile_box(t, s, dim);
                double d2 = 0.0;
                for (int k = 0; k < dim; ++k) {
                    const double d = std::max({b.lo[k] - p[k], 0.0, p[k] - b.hi[k]});
                    d2 += d * d;
                }
                if (d2 <= radius * radius) out.push_back(t);
            }
    return out;
}

Arrangement World::around(const Vec3& p, double radius) {
    std::vector<const Arrangement*> parts;
    for (const TileCoord& t : tiles_around(p, radius)) parts.push_back(&tile(t));
    return merge_tiles(parts, impl_->maker.dimension());
}

int World::made() const { return impl_->made; }
int World::known() const { return static_cast<int>(impl_->tiles.size()); }
const TileMaker& World::maker() const { return impl_->maker; }
void World::set_progress(Progress progress) { impl_->progress = std::move(progress); }

}  // namespace tessera
