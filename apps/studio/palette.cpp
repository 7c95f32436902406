// apps/studio/palette.cpp — palette exemplars and the built-in examples (palette.hpp).
#include "apps/studio/palette.hpp"

#include <set>
#include <vector>

#include "apps/studio/static_files.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"

namespace tessera_studio {
namespace fs = std::filesystem;

namespace {

fs::path checked_path(const std::string& relative, const std::string& where, const fs::path& root,
                      const std::vector<std::string>& extensions) {
    const ResolvedPath r = resolve_under(root, relative, extensions);
    if (r.status != 200) throw ApiError(r.status, where + ": " + relative + ": " + r.reason);
    return r.path;
}

// Replaces the file named by member `key` of `object` with its checked absolute path.
void hold_to_root(Json& object, const std::string& key, const std::string& where, const fs::path& root) {
    const auto it = object.find(key);
    if (it == object.end()) return;
    if (!it->is_string()) bad_request(where + "." + key + ": expected a path");
    const std::string relative = it->get<std::string>();
    if (relative.empty()) return;  // "no mesh"
    *it = checked_path(relative, where + "." + key, root, root_file_extensions()).string();
}

Json inline_with_checked_files(Json exemplar, const std::string& where, const fs::path& root) {
    if (auto domain = exemplar.find("domain"); domain != exemplar.end() && domain->is_object()) {
        hold_to_root(*domain, "image", where + ".domain", root);
        hold_to_root(*domain, "file", where + ".domain", root);
    }
    if (auto types = exemplar.find("types"); types != exemplar.end() && types->is_array())
        for (size_t k = 0; k < types->size(); ++k)
            if ((*types)[k].is_object())
                hold_to_root((*types)[k], "mesh", where + ".types[" + std::to_string(k) + "]", root);
    return exemplar;
}

Json example_info(const std::string& relative, const tessera::Exemplar& ex) {
    Json types = Json::array();
    for (const tessera::ElementType& t : ex.types) types.push_back(t.name);
    return {{"name", fs::path(relative).stem().string()},
            {"path", relative},
            {"dimension", ex.dimension},
            {"elements", ex.elements.size()},
            {"types", std::move(types)}};
}

}  // namespace

tessera::Exemplar load_palette_exemplar(const Json& source, const std::string& where, const fs::path& root) {
    try {
        if (source.is_string())
            return tessera::load(
                checked_path(source.get<std::string>(), where, root, {".json", ".csv"}).string());
        if (source.is_object())
            return tessera::parse_json(inline_with_checked_files(source, where, root).dump(), where);
    } catch (const tessera::Error& e) {
        if (e.kind() == tessera::ErrorKind::internal) throw;
        bad_request(e.what());
    }
    bad_request(where + ": expected a path under the root or an inline tessera exemplar object");
}

ExampleCatalog::ExampleCatalog(fs::path root) : root_(std::move(root)) {}

Json ExampleCatalog::list() {
    std::lock_guard lock(mutex_);
    std::error_code error;
    std::set<std::string> seen;
    for (fs::directory_iterator it(root_ / "examples", error), end; !error && it != end;
         it.increment(error)) {
        const fs::path& path = it->path();
        if (lower_extension(path) != ".json" || !it->is_regular_file(error)) continue;
        const std::string relative = "examples/" + path.filename().string();
        if (resolve_under(root_, relative, {".json"}).status != 200) continue;  // a symlink leading out
        const auto size = it->file_size(error);
        const auto time = it->last_write_time(error);
        if (error) continue;
        seen.insert(relative);
        Entry& entry = entries_[relative];
        if (entry.known && entry.size == size && entry.time == time) continue;
        entry = {size, time, Json(), true};
        try {
            entry.info = example_info(relative, tessera::load(path.string()));
        } catch (const tessera::Error&) {
            // Not an exemplar (a domain or edit file): not listed.
        }
    }
    Json out = Json::array();
    for (auto it = entries_.begin(); it != entries_.end();) {
        if (!seen.count(it->first)) {
            it = entries_.erase(it);
            continue;
        }
        if (!it->second.info.is_null()) out.push_back(it->second.info);
        ++it;
    }
    return out;
}

}  // namespace tessera_studio
