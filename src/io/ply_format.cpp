// io/ply_format.cpp — ASCII PLY writer for point instancing: one vertex per element
// (not per sample) carrying its pose under the names Houdini's instancing uses, so that
// Copy to Points / Instance place geometry per element (docs/format.md, "PLY"):
//   x y z                         the element's position, the centroid of its samples;
//   orient_x orient_y orient_z orient_w
//                                 its orientation in Houdini's order for `orient`
//                                 (x, y, z, w); PLY properties are scalars, so the four
//                                 are put together by one wrangle line after import;
//   pscale                        the uniform scale to instance at (below);
//   class, id, radius             type index (named by `comment class` lines), element id,
//                                 radius (0 = none); then one property per free attribute.
// pscale is the element's scale, except for types without a mesh whose elements have a
// radius: there it is the radius, so that a unit sphere copied onto the points makes the
// spheres the previews and build_scene draw. Ids are `uint` when every id fits in 32
// bits, else `double`, exact up to 2^53; a larger id cannot be written exactly and is an
// error. Writer only: PLY has no place for the domain or the type flags.
#include <cstdint>
#include <limits>
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

// "uint" when every id fits in 32 bits, else "double" (PLY has no 64-bit integers);
// an id a double cannot hold exactly is an error.
std::string id_type(const Exemplar& data) {
    constexpr std::uint64_t exact_double = std::uint64_t(1) << 53;
    bool fits_uint = true;
    for (const Element& e : data.elements) {
        if (e.id > exact_double)
            throw Error(ErrorKind::input, "element id " + std::to_string(e.id) +
                                              " is too large for PLY (at most 2^53 can be written exactly); "
                                              "use .json or .csv");
        fits_uint = fits_uint && e.id <= std::numeric_limits<std::uint32_t>::max();
    }
    return fits_uint ? "uint" : "double";
}

// The uniform scale a point instancer should apply (see the file comment).
double pscale(const Exemplar& data, const Element& e) {
    const bool has_mesh = !data.types.at(static_cast<size_t>(e.type)).mesh.empty();
    return !has_mesh && e.radius > 0.0 ? e.radius : e.scale;
}

}  // namespace

std::string to_ply(const Exemplar& data) {
    std::string out = "ply\nformat ascii 1.0\n";
    out += "comment tessera dimension " + std::to_string(data.dimension) + "\n";
    for (size_t t = 0; t < data.types.size(); ++t)
        out += "comment class " + std::to_string(t) + " " + one_line(data.types[t].name) + "\n";
    out += "element vertex " + std::to_string(data.elements.size()) + "\n";
    for (const char* name : {"x", "y", "z", "orient_x", "orient_y", "orient_z", "orient_w", "pscale"})
        out += std::string("property double ") + name + "\n";
    out += "property int class\nproperty " + id_type(data) + " id\nproperty double radius\n";
    // Free attributes survive export (DESIGN.md, "Frames and interchange"); a name that
    // clashes with a fixed property or another attribute gets a numeric suffix.
    std::set<std::string> used = {"x",        "y",      "z",     "orient_x", "orient_y", "orient_z",
                                  "orient_w", "pscale", "class", "id",       "radius"};
    for (const auto& name : data.attribute_names) {
        std::string unique = property_name(name);
        for (int n = 2; used.count(unique); ++n) unique = property_name(name) + "_" + std::to_string(n);
        used.insert(unique);
        out += "property double " + unique + "\n";
    }
    out += "end_header\n";

    for (const Element& e : data.elements) {
        Vec3 p;
        for (int s = 0; s < e.sample_count; ++s) p += data.samples[e.first_sample + s].p / e.sample_count;
        const Quat& q = e.orientation;
        out += format_number(p.x) + " " + format_number(p.y) + " " + format_number(p.z) + " " +
               format_number(q.x) + " " + format_number(q.y) + " " + format_number(q.z) + " " +
               format_number(q.w) + " " + format_number(pscale(data, e)) + " " + std::to_string(e.type) +
               " " + std::to_string(e.id) + " " + format_number(e.radius);
        for (double a : e.attributes) out += " " + format_number(a);
        out += "\n";
    }
    return out;
}

}  // namespace tessera
