// apps/studio/routes_files.cpp — static files of the app folder, read-only files under the
// project root (GET /api/files) and the built-in examples (GET /api/palette).
#include <httplib.h>

#include "apps/studio/server_context.hpp"
#include "apps/studio/static_files.hpp"
#include "tessera/version.hpp"

namespace tessera_studio {
namespace {

// Larger files are not served: the whole file is held in memory while it is sent.
constexpr std::uintmax_t max_served_file = 64u << 20;

void send_file(httplib::Response& res, const ResolvedPath& resolved, const std::string& what) {
    if (resolved.status != 200) {
        send_error(res, resolved.status, what + ": " + resolved.reason);
        return;
    }
    std::error_code error;
    if (std::filesystem::file_size(resolved.path, error) > max_served_file || error) {
        send_error(res, 403, what + ": larger than 64 MiB, not served");
        return;
    }
    const auto content = read_whole_file(resolved.path);
    if (!content) {
        send_error(res, 404, what + ": cannot be read");
        return;
    }
    res.status = 200;
    res.set_header("Cache-Control", "no-cache");
    res.set_content(*content, content_type_for(lower_extension(resolved.path)).c_str());
}

void serve_static(const ServerContext& ctx, const RouteRequest& r, httplib::Response& res) {
    std::string relative = r.http.path.substr(1);  // the pattern starts with '/'
    if (relative.empty() || relative.back() == '/') relative += "index.html";
    if (ctx.config.app_dir.empty()) {
        if (relative != "index.html") {
            send_error(res, 404, "no app folder: the web front end was not built");
            return;
        }
        res.status = 200;
        res.set_content(builtin_page(), "text/html; charset=utf-8");
        return;
    }
    send_file(res, resolve_under(ctx.config.app_dir, relative), r.http.path);
}

void serve_root_file(const ServerContext& ctx, const RouteRequest& r, httplib::Response& res) {
    if (!r.http.has_param("path")) {
        send_error(res, 400, "path: missing query parameter (GET /api/files?path=relative/path)");
        return;
    }
    const std::string path = r.http.get_param_value("path");
    send_file(res, resolve_under(ctx.config.root, path, root_file_extensions()), "path " + path);
}

}  // namespace

void add_file_routes(Router& router, ServerContext& ctx) {
    router.add("GET", "/api/status", [&ctx](const RouteRequest&, httplib::Response& res) {
        send_json(res, 200,
                  {{"version", tessera::version},
                   {"root", ctx.config.root.string()},
                   {"app", !ctx.config.app_dir.empty()},
                   {"sessions", ctx.sessions.ids().size()}});
    });
    router.add("GET", "/api/files",
               [&ctx](const RouteRequest& r, httplib::Response& res) { serve_root_file(ctx, r, res); });
    router.add("GET", "/api/palette", [&ctx](const RouteRequest&, httplib::Response& res) {
        send_json(res, 200, {{"examples", ctx.examples.list()}});
    });
    // Everything outside /api/ is the front end's.
    router.add_outside_api(
        "GET", [&ctx](const RouteRequest& r, httplib::Response& res) { serve_static(ctx, r, res); });
}

}  // namespace tessera_studio
