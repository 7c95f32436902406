// apps/studio/static_files.cpp — path checks for the files the studio serves (static_files.hpp).
#include "apps/studio/static_files.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

namespace tessera_studio {
namespace fs = std::filesystem;

namespace {

ResolvedPath refused(int status, const std::string& reason) {
    return {status, {}, reason};
}

// The reason `relative` is refused by its form alone, or "" when it may be looked up.
std::string form_problem(const std::string& relative) {
    if (relative.empty()) return "an empty path";
    if (relative.front() == '/') return "an absolute path";
    if (relative.find('\\') != std::string::npos) return "a backslash in the path";
    if (relative.find('\0') != std::string::npos) return "a NUL byte in the path";
    // One decoding is the HTTP layer's; a '%' left over means an encoded encoding.
    if (relative.find('%') != std::string::npos) return "a '%' left after decoding (double encoding)";
    for (const fs::path& part : fs::path(relative)) {
        const std::string name = part.string();
        if (name == "..") return "a '..' component";
        if (!name.empty() && name.front() == '.' && name != ".") return "a hidden component";
    }
    return "";
}

}  // namespace

bool is_within(const fs::path& base, const fs::path& path) {
    auto b = base.begin(), p = path.begin();
    for (; b != base.end(); ++b, ++p) {
        if (b->empty()) continue;  // a trailing separator of base
        if (p == path.end() || *b != *p) return false;
    }
    return true;
}

std::string lower_extension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

ResolvedPath resolve_under(const fs::path& base, const std::string& relative,
                           const std::vector<std::string>& extensions) {
    if (const std::string problem = form_problem(relative); !problem.empty()) return refused(403, problem);
    if (!extensions.empty() &&
        std::find(extensions.begin(), extensions.end(), lower_extension(relative)) == extensions.end())
        return refused(404, "not a file type served here");
    std::error_code error;
    const fs::path resolved = fs::weakly_canonical(base / relative, error);
    if (error) return refused(404, "no such file");
    if (!is_within(base, resolved)) return refused(403, "the path leads outside the served folder");
    if (!fs::is_regular_file(resolved, error)) return refused(404, "no such file");
    return {200, resolved, ""};
}

const std::vector<std::string>& root_file_extensions() {
    static const std::vector<std::string> extensions = {".json", ".csv", ".obj", ".ply", ".png"};
    return extensions;
}

// Types carry a parameter ("; charset=utf-8") on purpose: cpp-httplib 0.11 compresses a body
// (Brotli at its slowest, best quality, when the browser offers it) only when the content type
// is exactly "application/json" or "application/javascript" or starts with "text/". A studio
// served on 127.0.0.1 gains nothing from compression and a paint stroke's answer lost ~200 ms.
std::string content_type_for(const std::string& extension) {
    static const std::map<std::string, std::string> types = {{".html", "text/html; charset=utf-8"},
                                                             {".htm", "text/html; charset=utf-8"},
                                                             {".js", "application/javascript; charset=utf-8"},
                                                             {".mjs", "application/javascript; charset=utf-8"},
                                                             {".css", "text/css"},
                                                             {".json", "application/json; charset=utf-8"},
                                                             {".map", "application/json; charset=utf-8"},
                                                             {".csv", "text/csv"},
                                                             {".txt", "text/plain; charset=utf-8"},
                                                             {".svg", "image/svg+xml"},
                                                             {".png", "image/png"},
                                                             {".jpg", "image/jpeg"},
                                                             {".jpeg", "image/jpeg"},
                                                             {".ico", "image/x-icon"},
                                                             {".wasm", "application/wasm"},
                                                             {".woff2", "font/woff2"},
                                                             {".obj", "model/obj"},
                                                             {".ply", "application/x-ply"},
                                                             {".usda", "model/vnd.usda"},
                                                             {".gltf", "model/gltf+json"},
                                                             {".glb", "model/gltf-binary"}};
    const auto it = types.find(extension);
    return it == types.end() ? "application/octet-stream" : it->second;
}

fs::path default_app_dir(const fs::path& executable, const std::string& source_app_dir) {
    std::error_code error;
    const fs::path installed = executable.parent_path() / ".." / "share" / "tessera" / "studio";
    if (!executable.empty() && fs::is_directory(installed, error))
        return fs::weakly_canonical(installed, error);
    if (!source_app_dir.empty() && fs::is_directory(source_app_dir, error))
        return fs::weakly_canonical(source_app_dir, error);
    return {};
}

const std::string& builtin_page() {
    static const std::string page =
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>tessera "
        "studio</title></head>\n"
        "<body><h1>tessera studio</h1>\n"
        "<p>The server is running, but the web front end was not built: no app folder was found "
        "(<code>share/tessera/studio</code> next to the executable, or <code>web/dist</code> in the source "
        "tree).</p>\n"
        "<p>Build it with <code>npm ci &amp;&amp; npm run build</code> in <code>web/</code>, or give "
        "<code>--app-dir DIR</code>. The API is described in <code>docs/studio.md</code>; try "
        "<a href=\"/api/palette\">/api/palette</a>.</p>\n</body></html>\n";
    return page;
}

std::optional<std::string> read_whole_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream s;
    s << in.rdbuf();
    if (in.bad()) return std::nullopt;
    return s.str();
}

}  // namespace tessera_studio
