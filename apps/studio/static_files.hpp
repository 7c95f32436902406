// apps/studio/static_files.hpp — which files the studio may serve (docs/studio.md,
// "Security"): a path from a request is taken relative to one folder (the app folder or the
// project root) and served only when it stays inside it. Checks are on decoded path
// components, then on the resolved path (std::filesystem::weakly_canonical, so symlinks are
// followed) compared component by component with the folder — never as strings, so neither
// "..", "%2e%2e" nor a symlink leads out, and /rootx is not inside /root.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tessera_studio {

// Where a request path led: a regular file to serve (status 200), or the status to answer
// (403 for a path that would leave the folder or is refused by its form, 404 for one that
// is not there or has an extension the caller does not serve) with a one-line reason.
struct ResolvedPath {
    int status = 404;
    std::filesystem::path path;
    std::string reason;
};

// `relative` (already percent-decoded once, as the HTTP layer hands it over) under the
// canonical folder `base`. Refused: empty, absolute, "\\", NUL, '%' left after decoding
// (double encoding), a ".." or hidden (".name") component; an extension outside
// `extensions` (lower case with the dot; empty = any).
ResolvedPath resolve_under(const std::filesystem::path& base, const std::string& relative,
                           const std::vector<std::string>& extensions = {});

// True when the components of `base` are a prefix of those of `path` (both canonical).
bool is_within(const std::filesystem::path& base, const std::filesystem::path& path);

// Extensions served from the project root by GET /api/files.
const std::vector<std::string>& root_file_extensions();

// Content type by extension (lower case with the dot); application/octet-stream if unknown.
std::string content_type_for(const std::string& extension);

// Lower-cased extension with the dot, "" if none.
std::string lower_extension(const std::filesystem::path& path);

// The default app folder: <dir of executable>/../share/tessera/studio if it exists, else
// `source_app_dir` (the source tree's web/dist) if it exists, else "" (the built-in page).
std::filesystem::path default_app_dir(const std::filesystem::path& executable,
                                      const std::string& source_app_dir);

// The page served at / when there is no app folder: says the web bundle was not built.
const std::string& builtin_page();

// The whole file, or nullopt when it cannot be read.
std::optional<std::string> read_whole_file(const std::filesystem::path& path);

}  // namespace tessera_studio
