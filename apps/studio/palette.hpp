// apps/studio/palette.hpp — exemplars for a session's palette (docs/studio.md, "Palette"):
// from a file under the project root (tessera::load) or inline in the request
// (tessera::parse_json), and the list of built-in examples, <root>/examples/*.json that
// tessera::load accepts. An inline exemplar may name files too (a mask or mesh domain, a
// type's mesh): they are held to the root like every other path.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>

#include "apps/studio/api_json.hpp"
#include "tessera/exemplar.hpp"

namespace tessera_studio {

// The exemplar of a palette entry's source (a path string or an inline object); `where`
// names it in messages ("palette.sticks"). 400 for bad content, 403/404 for a path refused
// or missing.
tessera::Exemplar load_palette_exemplar(const Json& source, const std::string& where,
                                        const std::filesystem::path& root);

// The built-in examples, re-read only when a file changed (size or time), so that listing
// them stays cheap under many tabs.
class ExampleCatalog {
public:
    explicit ExampleCatalog(std::filesystem::path root);
    // [{"name": "sticks_2d", "path": "examples/sticks_2d.json", "dimension": 2,
    //   "elements": 60, "types": ["stick"]}, ...] sorted by name.
    Json list();

private:
    struct Entry {
        std::uintmax_t size = 0;
        std::filesystem::file_time_type time;
        Json info;  // null when tessera::load refused the file
        bool known = false;
    };
    const std::filesystem::path root_;
    std::mutex mutex_;
    std::map<std::string, Entry> entries_;  // by path relative to the root
};

}  // namespace tessera_studio
