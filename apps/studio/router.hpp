// apps/studio/router.hpp — the studio's routes over httplib (docs/studio.md, "API"): a
// table of (method, path pattern, handler) matched in order against the decoded path
// segment by segment ("{}" stands for one segment; no std::regex, whose matcher recurses
// per character and trips GCC 12's -Wmaybe-uninitialized in sanitizer builds),
// so that a path known under other methods answers 405 with an Allow header, an unknown
// one a JSON 404, and every failure of a handler one JSON error line: ApiError with its
// status, the library's refusals 400, anything else 500 (and the server goes on).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "apps/studio/api_json.hpp"

namespace httplib {
struct Request;
struct Response;
}  // namespace httplib

namespace tessera_studio {

// The path segments that the pattern's "{}" matched, in order.
using RouteParams = std::vector<std::string>;

// A request as a handler sees it: the body is read by the server under its size cap.
struct RouteRequest {
    const httplib::Request& http;
    const std::string& body;
    RouteParams params;
};
using RouteHandler = std::function<void(const RouteRequest&, httplib::Response&)>;

class Router {
public:
    // `pattern`: "/api/sessions/{}/ops" matches "/api/sessions/s1-ab/ops" with params
    // {"s1-ab"}; a "{}" segment is never empty. HEAD is served by GET routes.
    void add(const std::string& method, const std::string& pattern, RouteHandler handler);
    // The route of every path outside /api/ (the front end's static files).
    void add_outside_api(const std::string& method, RouteHandler handler);
    void dispatch(const httplib::Request& req, const std::string& body, httplib::Response& res) const;

private:
    struct Route {
        std::string method;
        std::vector<std::string> segments;  // empty: every path outside /api/
        RouteHandler handler;
    };
    std::vector<Route> routes_;
};

void send_json(httplib::Response& res, int status, const Json& body);
// {"error": message} with `status`.
void send_error(httplib::Response& res, int status, const std::string& message);

}  // namespace tessera_studio
