#include "world_files.hpp"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "tessera/error.hpp"
#include "tessera/io.hpp"

namespace tessera_cli {
namespace {

namespace fs = std::filesystem;

nlohmann::json point(const tessera::Vec3& p, int dimension) {
    nlohmann::json a = nlohmann::json::array({p.x, p.y});
    if (dimension == 3) a.push_back(p.z);
    return a;
}

// The index.json already in `dir`, or null; a file that is not a world index is an error.
nlohmann::json existing_index(const std::string& dir) {
    const fs::path path = fs::path(dir) / "index.json";
    if (!fs::exists(path)) return nullptr;
    nlohmann::json index;
    try {
        index = nlohmann::json::parse(tessera::read_file(path.string()));
    } catch (const nlohmann::json::exception&) {
        index = nullptr;
    }
    if (!index.is_object() || index.value("format", "") != "tessera-world" || !index["tiles"].is_array())
        throw tessera::Error(tessera::ErrorKind::option, "-o " + dir + ": index.json there is not a tessera world index");
    return index;
}

}  // namespace

void check_world_dir(const std::string& dir, const tessera::TileMaker& maker) {
    const nlohmann::json index = existing_index(dir);
    if (!index.is_null() && index.value("world", "") != tessera::content_hash(maker.fingerprint()))
        throw tessera::Error(tessera::ErrorKind::option,
                             "-o " + dir + ": it holds the tiles of another world (another exemplar, tile size, seed "
                                           "or growth option); give another directory");
}

std::string tile_file_name(const tessera::TileCoord& t, int dimension) {
    std::string name = "tile_" + std::to_string(t.x) + "_" + std::to_string(t.y);
    if (dimension == 3) name += "_" + std::to_string(t.z);
    return name + ".json";
}

void write_world_dir(const std::string& dir, const tessera::TileMaker& maker, const std::string& input,
                     const std::vector<tessera::TileCoord>& wanted,
                     const std::map<tessera::TileCoord, tessera::Arrangement>& made) {
    std::error_code error;
    fs::create_directories(dir, error);
    if (error) throw tessera::Error(tessera::ErrorKind::io, "-o " + dir + ": cannot create the directory (" + error.message() + ")");
    const int dim = maker.dimension();
    const double size = maker.options().tile_size;
    // Tiles listed by an earlier run into the same directory (check_world_dir: the same world)
    // stay listed, those made again replaced (they are the same tiles).
    std::map<std::string, nlohmann::json> listed;
    if (const nlohmann::json before = existing_index(dir); !before.is_null())
        for (const auto& t : before["tiles"]) listed[t.value("file", "")] = t;
    for (const tessera::TileCoord& t : wanted) {
        const tessera::Arrangement& a = made.at(t);
        const std::string file = tile_file_name(t, dim);
        tessera::write_file_atomic((fs::path(dir) / file).string(), tessera::tile_to_json(a));
        const tessera::Box b = tessera::tile_box(t, size, dim);
        nlohmann::json coord = nlohmann::json::array({t.x, t.y});
        if (dim == 3) coord.push_back(t.z);
        listed[file] = {{"tile", coord}, {"file", file}, {"bounds", {{"lo", point(b.lo, dim)}, {"hi", point(b.hi, dim)}}},
                        {"elements", a.elements.size()}, {"hash", tessera::tile_hash(a)}};
    }
    nlohmann::json tiles = nlohmann::json::array();
    std::size_t elements = 0;
    for (const auto& [file, t] : listed) {
        tiles.push_back(t);
        elements += t.value("elements", std::size_t{0});
    }
    std::sort(tiles.begin(), tiles.end(), [](const nlohmann::json& a, const nlohmann::json& b) { return a["tile"] < b["tile"]; });
    const nlohmann::json index = {{"format", "tessera-world"}, {"version", 1}, {"dimension", dim},
                                  {"tile_size", size}, {"seed", maker.options().grow.seed},
                                  {"exemplar", input}, {"world", tessera::content_hash(maker.fingerprint())},
                                  {"elements", elements}, {"tiles", tiles}};
    tessera::write_file_atomic((fs::path(dir) / "index.json").string(), index.dump(1) + "\n");
}

}  // namespace tessera_cli
