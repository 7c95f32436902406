// The edit file of `tessera edit` (docs/format.md, "Edit files"):
//   {"element": 12, "offset": [0.1, 0.0], "type": "big", "radius": 0.3, "angle": 0.5,
//    "attributes": {"hue": 0.25}}
// Only "element" is required. Unknown keys are errors, so typos are reported.
#include <nlohmann/json.hpp>

#include "tessera/edit.hpp"
#include "tessera/error.hpp"

namespace tessera {

ElementEdit parse_edit_json(const std::string& text, const std::string& source) {
    auto fail = [&](const std::string& what) { throw Error(ErrorKind::input, source + ": " + what); };
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        fail(std::string("malformed JSON (") + e.what() + ")");
    }
    if (!doc.is_object()) fail("an edit must be a JSON object");
    for (const auto& item : doc.items())
        if (item.key() != "element" && item.key() != "offset" && item.key() != "type" && item.key() != "radius" &&
            item.key() != "angle" && item.key() != "attributes")
            fail("unknown key '" + item.key() + "'");
    ElementEdit edit;
    if (!doc.contains("element") || !doc["element"].is_number_unsigned())
        fail("\"element\" (the id of the edited element, an integer >= 0) is required");
    edit.element = doc["element"].get<std::uint64_t>();
    if (doc.contains("offset")) {
        const auto& o = doc["offset"];
        if (!o.is_array() || o.size() < 2 || o.size() > 3) fail("\"offset\" must be [dx, dy] or [dx, dy, dz]");
        for (size_t k = 0; k < o.size(); ++k) {
            if (!o[k].is_number()) fail("\"offset\" must hold numbers");
            edit.offset[static_cast<int>(k)] = o[k].get<double>();
        }
    }
    if (doc.contains("type")) {
        if (!doc["type"].is_string()) fail("\"type\" must be a type name");
        edit.type = doc["type"].get<std::string>();
    }
    if (doc.contains("radius")) {
        if (!doc["radius"].is_number()) fail("\"radius\" must be a number");
        edit.radius = doc["radius"].get<double>();
    }
    if (doc.contains("angle")) {
        if (!doc["angle"].is_number()) fail("\"angle\" must be a number (radians)");
        edit.angle = doc["angle"].get<double>();
    }
    if (doc.contains("attributes")) {
        if (!doc["attributes"].is_object()) fail("\"attributes\" must be an object of name: value");
        for (const auto& item : doc["attributes"].items()) {
            if (!item.value().is_number()) fail("attribute '" + item.key() + "' must be a number");
            edit.attributes[item.key()] = item.value().get<double>();
        }
    }
    return edit;
}

}  // namespace tessera
