// apps/studio/api_json.hpp — reading the studio's JSON requests (docs/studio.md, "API"):
// bodies parsed once, every field checked with a one-line message that names it as the
// client wrote it ("options.sigma", "stroke[3]"), and brush options checked against the
// library's option table (tessera/option_table.hpp), so the server accepts exactly what the
// CLI and the Python module accept.
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "tessera/brush.hpp"
#include "tessera/option_table.hpp"

namespace tessera_studio {

// Insertion-ordered, so that responses and session files keep the order written (a
// session file's palette order is its entries' indices).
using Json = nlohmann::ordered_json;

// A request that cannot be served: the HTTP status and a one-line message for {"error": ...}.
class ApiError : public std::runtime_error {
public:
    ApiError(int status, const std::string& message) : std::runtime_error(message), status_(status) {}
    int status() const { return status_; }

private:
    int status_;
};

[[noreturn]] void bad_request(const std::string& message);

// The body as a JSON object; 400 naming the parse error's place otherwise.
Json parse_body(const std::string& body);

// Member `key` of `object` (named `where` in messages), or 400 when it is missing.
const Json& require(const Json& object, const std::string& key, const std::string& where = "");
std::string require_string(const Json& object, const std::string& key, const std::string& where = "");
// Rejects members other than `allowed`, naming the first unknown one.
void check_keys(const Json& object, const std::vector<std::string>& allowed, const std::string& where = "");

// `options` (a JSON object) stored into `target` through brush_option_table() for a canvas
// of `dimension`; an unknown or bad option is a 400 naming it "options.NAME".
void apply_brush_options(const Json& options, int dimension, tessera::BrushOptions& target);
// Every option of the table with its value in `options`, in table order.
Json brush_options_json(const tessera::BrushOptions& options);

// The operations of POST /api/sessions/ID/ops and of session files.
struct OpRequest {
    std::string op;                    // paint, direction, erase, fill, optimize
    std::vector<std::string> palette;  // paint: one name; fill: any
    tessera::Stroke stroke;            // paint, direction, erase
    int iterations = -1;               // optimize; -1 = the canvas's BrushOptions::iterations
};
// Checks an op object for a canvas of `dimension` (2D strokes take [x,y] or [x,y,0]).
OpRequest parse_op(const Json& body, int dimension, const std::string& where = "");
// The op as a session file stores it (docs/brush.md, "Session files"): only the members its
// kind uses, points of `dimension` numbers.
Json op_json(const OpRequest& op, int dimension);

Json report_json(const tessera::BrushReport& report);

}  // namespace tessera_studio
