// core/mesh_io.cpp — small readers for the triangle meshes that bound 3D domains
// (and, with a direction per vertex, carry mesh orientation fields): Wavefront OBJ
// and ASCII PLY. Hand-written because only vertices, faces and per-vertex vectors are
// needed and every error must name the file and line, which the few-line parsing
// here makes easy (binary PLY is refused with a clear message).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tessera/error.hpp"
#include "tessera/mesh.hpp"

namespace tessera {
namespace {

[[noreturn]] void fail(const std::string& source, int line, const std::string& what) {
    throw Error(ErrorKind::input, source + ":" + std::to_string(line) + ": " + what);
}

bool parse_number(const std::string& token, double& value) {
    char* end = nullptr;
    value = std::strtod(token.c_str(), &end);
    return !token.empty() && end == token.c_str() + token.size() && std::isfinite(value);
}

bool parse_integer(const std::string& token, long& value) {
    char* end = nullptr;
    value = std::strtol(token.c_str(), &end, 10);
    return !token.empty() && end == token.c_str() + token.size();
}

std::vector<std::string> split(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> tokens;
    for (std::string t; in >> t;) tokens.push_back(t);
    return tokens;
}

void add_polygon(TriangleMesh& mesh, const std::vector<int>& poly) {
    for (size_t k = 1; k + 1 < poly.size(); ++k) mesh.triangles.push_back({poly[0], poly[k], poly[k + 1]});
}

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// The OBJ reader; with `normals`, vn lines are collected too (in file order).
TriangleMesh read_obj(const std::string& text, const std::string& source, std::vector<Vec3>* normals,
                      int* last_normal_line) {
    TriangleMesh mesh;
    std::istringstream in(text);
    std::string line;
    struct Face { std::vector<long> refs; int line; };
    std::vector<Face> faces;
    for (int number = 1; std::getline(in, line); ++number) {
        const auto tokens = split(line.substr(0, line.find('#')));
        if (tokens.empty()) continue;
        if (tokens[0] == "v") {
            if (tokens.size() < 4) fail(source, number, "a vertex needs 3 coordinates ('v x y z')");
            Vec3 v;
            for (int k = 0; k < 3; ++k)
                if (!parse_number(tokens[k + 1], v[k]))
                    fail(source, number, "'" + tokens[k + 1] + "' is not a finite number");
            mesh.vertices.push_back(v);
        } else if (tokens[0] == "vn" && normals) {
            if (tokens.size() < 4) fail(source, number, "a normal needs 3 components ('vn x y z')");
            Vec3 v;
            for (int k = 0; k < 3; ++k)
                if (!parse_number(tokens[k + 1], v[k]))
                    fail(source, number, "'" + tokens[k + 1] + "' is not a finite number");
            normals->push_back(v);
            *last_normal_line = number;
        } else if (tokens[0] == "f") {
            if (tokens.size() < 4) fail(source, number, "a face needs at least 3 vertices");
            Face face{{}, number};
            for (size_t k = 1; k < tokens.size(); ++k) {
                long index = 0;
                if (!parse_integer(tokens[k].substr(0, tokens[k].find('/')), index) || index == 0)
                    fail(source, number, "'" + tokens[k] + "' is not a vertex index");
                // Negative indices count back from the vertices read so far.
                if (index < 0) index += static_cast<long>(mesh.vertices.size()) + 1;
                face.refs.push_back(index);
            }
            faces.push_back(std::move(face));
        }
    }
    for (const Face& f : faces) {
        std::vector<int> poly;
        for (long index : f.refs) {
            if (index < 1 || index > static_cast<long>(mesh.vertices.size()))
                fail(source, f.line, "vertex index " + std::to_string(index) + " is out of range (the file has " +
                                         std::to_string(mesh.vertices.size()) + " vertices)");
            poly.push_back(static_cast<int>(index - 1));
        }
        add_polygon(mesh, poly);
    }
    return mesh;
}

// The PLY reader; with `extra`, the vertex properties named `extra_names` are read into
// (*extra)[vertex][k] and must all be present.
TriangleMesh read_ply(const std::string& text, const std::string& source, const std::vector<std::string>& extra_names,
                      std::vector<Vec3>* extra) {
    std::istringstream in(text);
    std::string line;
    int number = 0;
    auto next = [&](std::vector<std::string>& tokens) {
        while (std::getline(in, line)) {
            ++number;
            tokens = split(line);
            if (!tokens.empty() && tokens[0] != "comment" && tokens[0] != "obj_info") return true;
        }
        return false;
    };
    std::vector<std::string> tokens;
    if (!next(tokens) || tokens[0] != "ply") fail(source, std::max(number, 1), "not a PLY file (no 'ply' magic)");
    struct Element { std::string name; long count = 0; std::vector<std::string> properties; int list_property = -1; };
    std::vector<Element> elements;
    bool ascii = false;
    while (true) {
        if (!next(tokens)) fail(source, number, "the header has no 'end_header'");
        if (tokens[0] == "end_header") break;
        if (tokens[0] == "format") {
            if (tokens.size() < 2 || tokens[1] != "ascii")
                fail(source, number, "only ASCII PLY meshes are read (got format " +
                                         (tokens.size() > 1 ? tokens[1] : std::string("?")) + "); convert it to ascii");
            ascii = true;
        } else if (tokens[0] == "element") {
            long count = 0;
            if (tokens.size() != 3 || !parse_integer(tokens[2], count) || count < 0)
                fail(source, number, "malformed element line");
            elements.push_back({tokens[1], count, {}, -1});
        } else if (tokens[0] == "property") {
            if (elements.empty()) fail(source, number, "property before any element");
            if (tokens.size() >= 5 && tokens[1] == "list") elements.back().list_property = int(elements.back().properties.size());
            elements.back().properties.push_back(tokens.back());
        }
    }
    if (!ascii) fail(source, number, "the header has no 'format ascii 1.0' line");
    TriangleMesh mesh;
    for (const Element& e : elements) {
        int ix = -1, iy = -1, iz = -1;
        int ie[3] = {-1, -1, -1};
        for (int p = 0; p < int(e.properties.size()); ++p) {
            if (e.properties[p] == "x") ix = p;
            if (e.properties[p] == "y") iy = p;
            if (e.properties[p] == "z") iz = p;
            for (size_t k = 0; k < extra_names.size() && k < 3; ++k)
                if (e.properties[p] == extra_names[k]) ie[k] = p;
        }
        const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
        if (is_vertex && (ix < 0 || iy < 0 || iz < 0)) fail(source, number, "element vertex lacks x, y or z");
        if (is_vertex && extra && (ie[0] < 0 || ie[1] < 0 || ie[2] < 0))
            fail(source, number, "element vertex lacks " + extra_names[0] + ", " + extra_names[1] + " or " +
                                     extra_names[2]);
        if (is_face && e.list_property < 0) fail(source, number, "element face has no vertex index list");
        for (long r = 0; r < e.count; ++r) {
            if (!next(tokens)) fail(source, number, "the file ends inside element " + e.name);
            if (is_vertex) {
                if (int(tokens.size()) < int(e.properties.size()))
                    fail(source, number, "a vertex needs " + std::to_string(e.properties.size()) + " values");
                Vec3 v;
                const int idx[3] = {ix, iy, iz};
                for (int k = 0; k < 3; ++k)
                    if (!parse_number(tokens[idx[k]], v[k]))
                        fail(source, number, "'" + tokens[idx[k]] + "' is not a finite number");
                mesh.vertices.push_back(v);
                if (extra) {
                    Vec3 w;
                    for (int k = 0; k < 3; ++k)
                        if (!parse_number(tokens[ie[k]], w[k]))
                            fail(source, number, "'" + tokens[ie[k]] + "' is not a finite number");
                    extra->push_back(w);
                }
            } else if (is_face) {
                // Properties before the list take one token each (rare); then count, indices.
                const size_t at = static_cast<size_t>(e.list_property);
                long count = 0;
                if (tokens.size() <= at || !parse_integer(tokens[at], count) || count < 3 ||
                    tokens.size() < at + 1 + size_t(count))
                    fail(source, number, "malformed face (expected a count >= 3 and that many indices)");
                std::vector<int> poly;
                for (long k = 0; k < count; ++k) {
                    long index = 0;
                    if (!parse_integer(tokens[at + 1 + k], index) || index < 0 ||
                        index >= static_cast<long>(mesh.vertices.size()))
                        fail(source, number, "'" + tokens[at + 1 + k] + "' is not a valid vertex index (the file has " +
                                                 std::to_string(mesh.vertices.size()) + " vertices)");
                    poly.push_back(static_cast<int>(index));
                }
                add_polygon(mesh, poly);
            }
        }
    }
    return mesh;
}

// The text of a .obj or .ply file; `ext` receives its lower-case extension.
std::string read_mesh_text(const std::string& path, std::string& ext) {
    ext = lower_extension(path);
    if (ext != ".obj" && ext != ".ply")
        throw Error(ErrorKind::input, path + ": unsupported mesh format '" + ext + "' (supported: .obj, .ply)");
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error(ErrorKind::io, path + ": cannot open the mesh file");
    std::ostringstream buffer;
    buffer << file.rdbuf();
    return buffer.str();
}

}  // namespace

TriangleMesh parse_obj(const std::string& text, const std::string& source) {
    return read_obj(text, source, nullptr, nullptr);
}

TriangleMesh parse_ply_mesh(const std::string& text, const std::string& source) {
    return read_ply(text, source, {}, nullptr);
}

VertexDirectionMesh parse_obj_vertex_directions(const std::string& text, const std::string& source) {
    VertexDirectionMesh out;
    int last_line = 0;
    out.mesh = read_obj(text, source, &out.directions, &last_line);
    if (out.directions.size() != out.mesh.vertices.size())
        fail(source, std::max(last_line, 1),
             "the file has " + std::to_string(out.mesh.vertices.size()) + " vertices (v) but " +
                 std::to_string(out.directions.size()) + " directions (vn); a direction field needs one vn per v");
    return out;
}

VertexDirectionMesh parse_ply_vertex_directions(const std::string& text, const std::string& source) {
    VertexDirectionMesh out;
    out.mesh = read_ply(text, source, {"vx", "vy", "vz"}, &out.directions);
    return out;
}

TriangleMesh read_triangle_mesh(const std::string& path) {
    std::string ext;
    const std::string text = read_mesh_text(path, ext);
    return ext == ".obj" ? parse_obj(text, path) : parse_ply_mesh(text, path);
}

VertexDirectionMesh read_vertex_directions(const std::string& path) {
    std::string ext;
    const std::string text = read_mesh_text(path, ext);
    return ext == ".obj" ? parse_obj_vertex_directions(text, path) : parse_ply_vertex_directions(text, path);
}

}  // namespace tessera
