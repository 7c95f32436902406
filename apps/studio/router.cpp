// apps/studio/router.cpp — route matching and error answers (router.hpp).
#include "apps/studio/router.hpp"

#include <httplib.h>

#include <algorithm>

#include "tessera/error.hpp"

namespace tessera_studio {

void send_json(httplib::Response& res, int status, const Json& body) {
    res.status = status;
    // "; charset=utf-8" also keeps cpp-httplib from Brotli-compressing answers (static_files.cpp).
    res.set_content(body.dump() + "\n", "application/json; charset=utf-8");
}

void send_error(httplib::Response& res, int status, const std::string& message) {
    send_json(res, status, {{"error", message}});
}

namespace {

// "/a/b/" -> {"a", "b", ""}: the segments after the leading '/'.
std::vector<std::string> split_path(const std::string& path) {
    std::vector<std::string> segments;
    for (size_t start = 1; start <= path.size();) {
        const size_t slash = std::min(path.find('/', start), path.size());
        segments.push_back(path.substr(start, slash - start));
        start = slash + 1;
    }
    return segments;
}

bool outside_api(const std::string& path) {
    return path != "/api" && path.rfind("/api/", 0) != 0;
}

// Whether `path` (split) fits `route`; its "{}" segments go to `params`.
bool matches(const std::vector<std::string>& pattern, const std::vector<std::string>& path,
             RouteParams& params) {
    if (pattern.size() != path.size()) return false;
    params.clear();
    for (size_t k = 0; k < pattern.size(); ++k) {
        if (pattern[k] == "{}" && !path[k].empty())
            params.push_back(path[k]);
        else if (pattern[k] != path[k])
            return false;
    }
    return true;
}

int status_of(const tessera::Error& e) {
    switch (e.kind()) {
        case tessera::ErrorKind::internal:
            return 500;
        case tessera::ErrorKind::cancelled:
            return 409;
        default:
            return 400;
    }
}

// Calls the handler; whatever it throws becomes one JSON error line.
void call(const RouteHandler& handler, const RouteRequest& request, httplib::Response& res) {
    try {
        handler(request, res);
    } catch (const ApiError& e) {
        send_error(res, e.status(), e.what());
    } catch (const tessera::Error& e) {
        send_error(res, status_of(e), e.what());
    } catch (const std::bad_alloc&) {
        send_error(res, 500, "out of memory");
    } catch (const std::exception& e) {
        send_error(res, 500, std::string("internal error: ") + e.what());
    }
}

}  // namespace

void Router::add(const std::string& method, const std::string& pattern, RouteHandler handler) {
    routes_.push_back({method, split_path(pattern), std::move(handler)});
}

void Router::add_outside_api(const std::string& method, RouteHandler handler) {
    routes_.push_back({method, {}, std::move(handler)});
}

void Router::dispatch(const httplib::Request& req, const std::string& body, httplib::Response& res) const {
    if (req.path.size() > 2048) {
        send_error(res, 414, "path longer than 2048 bytes");
        return;
    }
    const std::string method = req.method == "HEAD" ? "GET" : req.method;
    if (req.path.empty() || req.path.front() != '/') {
        send_error(res, 400, "the path must start with '/'");
        return;
    }
    const std::vector<std::string> path = split_path(req.path);
    std::string allowed;
    RouteParams params;
    for (const Route& route : routes_) {
        const bool fits =
            route.segments.empty() ? outside_api(req.path) : matches(route.segments, path, params);
        if (!fits) continue;
        if (route.method != method) {
            if (allowed.find(route.method) == std::string::npos)
                allowed += (allowed.empty() ? "" : ", ") + route.method;
            continue;
        }
        call(route.handler, {req, body, std::move(params)}, res);
        return;
    }
    if (!allowed.empty()) {
        res.set_header("Allow", allowed);
        send_error(res, 405, req.method + " is not allowed on " + req.path + " (allowed: " + allowed + ")");
        return;
    }
    send_error(res, 404, "no route " + req.method + " " + req.path);
}

}  // namespace tessera_studio
