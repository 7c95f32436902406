// apps/studio/canvas_spec.cpp — a session's canvas from its text form (canvas_spec.hpp).
#include "apps/studio/canvas_spec.hpp"

#include <cstdlib>
#include <optional>
#include <vector>

#include "apps/studio/api_json.hpp"
#include "apps/studio/static_files.hpp"
#include "tessera/error.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/option_text.hpp"

namespace tessera_studio {
namespace {

constexpr size_t max_canvas_text = 1 << 16;

// How many comma-separated numbers `text` is, or nullopt when a field is not a number.
std::optional<size_t> count_numbers(const std::string& text) {
    size_t count = 0, start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        const std::string field =
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        char* end = nullptr;
        std::strtod(field.c_str(), &end);
        if (field.empty() || end != field.c_str() + field.size()) return std::nullopt;
        ++count;
        if (comma == std::string::npos) return count;
        start = comma + 1;
    }
}

// "box:W,H" -> "box:0,0,W,H"; "box:W,H,D" -> "box:0,0,W,H,0,D" (corners xmin,ymin,xmax,ymax,zmin,zmax).
std::string box_corners(const std::string& text) {
    std::vector<std::string> size;
    for (size_t start = 4;;) {
        const size_t comma = text.find(',', start);
        size.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (size.size() == 2) return "box:0,0," + size[0] + "," + size[1];
    if (size.size() == 3) return "box:0,0," + size[0] + "," + size[1] + ",0," + size[2];
    return text;
}

// The file of a form taken relative to the root and checked to stay inside it.
std::string root_file(const std::string& relative, const std::filesystem::path& root) {
    const ResolvedPath r = resolve_under(root, relative, root_file_extensions());
    if (r.status != 200) throw ApiError(r.status, "canvas: " + relative + ": " + r.reason);
    return r.path.string();
}

// `text` with the file it names replaced by its resolved path, and the canvas's dimension.
std::pair<std::string, int> resolved_form(const std::string& text, const std::filesystem::path& root) {
    const size_t colon = text.find(':');
    const std::string kind = text.substr(0, colon),
                      argument = colon == std::string::npos ? "" : text.substr(colon + 1);
    if (kind == "box") {
        const auto n = count_numbers(argument);
        return {text, n && (*n == 3 || *n == 6) ? 3 : 2};  // other counts: the library's message
    }
    if (kind == "polygon") {
        if (count_numbers(argument)) return {text, 2};
        return {"polygon:" + root_file(argument, root), 2};
    }
    if (kind == "mask") {
        const size_t at = argument.rfind('@');
        if (at == std::string::npos)
            bad_request("canvas: a mask canvas needs its box, mask:FILE.png@xmin,ymin,xmax,ymax");
        return {"mask:" + root_file(argument.substr(0, at), root) + argument.substr(at), 2};
    }
    if (kind == "mesh" || kind == "shell") {
        // FILE, then ",numbers" (resolution; shell: thickness first), as the library splits it.
        size_t split = argument.size();
        for (size_t comma = argument.find(','); comma != std::string::npos;
             comma = argument.find(',', comma + 1))
            if (count_numbers(argument.substr(comma + 1))) {
                split = comma;
                break;
            }
        return {kind + ":" + root_file(argument.substr(0, split), root) + argument.substr(split), 3};
    }
    return {text, 2};  // not a form: the library names the accepted ones
}

}  // namespace

Canvas parse_canvas(const std::string& text, const std::filesystem::path& root) {
    if (text.size() > max_canvas_text) bad_request("canvas: longer than 64 KiB");
    const auto [form, dimension] = resolved_form(text, root);
    tessera::Exemplar frame;  // what parse_output_domain takes its lower corner and dimension from
    frame.dimension = dimension;
    frame.domain = tessera::Domain::box({0, 0, 0}, {1, 1, 1}, dimension);
    try {
        tessera::Domain domain = tessera::parse_output_domain(form, frame, 1.0, "canvas");
        return {std::move(domain), dimension, text.rfind("box:", 0) == 0 ? box_corners(text) : text};
    } catch (const tessera::Error& e) {
        if (e.kind() == tessera::ErrorKind::internal) throw;
        bad_request(e.what());
    }
}

}  // namespace tessera_studio
