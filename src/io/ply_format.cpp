// io/ply_format.cpp — ASCII PLY writer: one vertex per sample with its element,
// sample index, class and the element's pose, so that point-instancing tools
// (Houdini, Blender geometry nodes, MeshLab) can place geometry per element.
// Layout in docs/format.md. Writer only: PLY has no place for the domain or the
// type flags, so it is an export, not an exchange format.
#include <set>
#include <string>

#include "io/io_util.hpp"
#include "tessera/io.hpp"

namespace tessera {

using namespace io_detail;

namespace {

// PLY property names are single tokens: spaces and other odd characters become '_'.
std::string property_name(const std::string& name) {
    std::string out = name;
    for (char& c : out) {
        const bool ok =
            (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
        if (!ok) c = '_';
    }
    return out.empty() ? std::string("_") : out;
}

// Comment lines end at a line break, so names are written on one line.
std::string one_line(const std::string& text) {
    std::string out = text;
    for (char& c : out)
        if (c == '\n' || c == '\r') c = ' ';
    return out;
}

}  // namespace

std::string to_ply(const Exemplar& data) {
    std::string out = "ply\nformat ascii 1.0\n";
    out += "comment tessera dimension " + std::to_string(data.dimension) + "\n";
    for (size_t t = 0; t < data.types.size(); ++t)
        out += "comment class " + std::to_string(t) + " " + one_line(data.types[t].name) + "\n";
    out += "element vertex " + std::to_string(data.samples.size()) + "\n";
    for (const char* name : {"x", "y", "z"}) out += std::string("property double ") + name + "\n";
    for (const char* name : {"element", "sample", "class"}) out += std::string("property int ") + name + "\n";
    for (const char* name : {"qw", "qx", "qy", "qz", "pscale"})
        out += std::string("property double ") + name + "\n";
    // Free attributes survive export (DESIGN.md, "Frames and interchange"); a name that
    // clashes with a fixed property or another attribute gets a numeric suffix.
    std::set<std::string> used = {"x",  "y",  "z",  "element", "sample", "class",
                                  "qw", "qx", "qy", "qz",      "pscale"};
    for (const auto& name : data.attribute_names) {
        std::string unique = property_name(name);
        for (int n = 2; used.count(unique); ++n) unique = property_name(name) + "_" + std::to_string(n);
        used.insert(unique);
        out += "property double " + unique + "\n";
    }
    out += "end_header\n";

    for (size_t i = 0; i < data.elements.size(); ++i) {
        const Element& e = data.elements[i];
        const Quat& q = e.orientation;
        std::string tail = " " + std::to_string(e.type) + " " + format_number(q.w) + " " +
                           format_number(q.x) + " " + format_number(q.y) + " " + format_number(q.z) + " " +
                           format_number(e.scale);
        for (double a : e.attributes) tail += " " + format_number(a);
        for (int s = 0; s < e.sample_count; ++s) {
            const Vec3& p = data.samples[e.first_sample + s].p;
            out += format_number(p.x) + " " + format_number(p.y) + " " + format_number(p.z) + " " +
                   std::to_string(i) + " " + std::to_string(s) + tail + "\n";
        }
    }
    return out;
}

}  // namespace tessera
