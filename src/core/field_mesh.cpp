// core/field_mesh.cpp — orientation fields given at the vertices of a triangle mesh
// (or of a point cloud, a mesh without faces).
//
// With faces, a query finds the closest point of the surface; the direction there is
// the barycentric blend of the triangle's vertex directions projected onto its plane,
// and the frame's z is the blended vertex normal (faces are first oriented
// consistently, so normals do not flip between neighbours). Without faces, the
// direction is the inverse-distance-weighted blend of the 8 nearest vertices.
//
// Both searches run on a uniform grid of cells built once (triangles are binned by
// their bounding boxes, vertices by position): a query visits rings of cells around
// the point's cell and stops as soon as no unvisited cell can hold anything closer,
// so it costs O(1) on average and allocates nothing. Visiting order is fixed, so the
// result is a pure function of the point.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "core/field_data.hpp"
#include "core/triangle_closest.hpp"
#include "tessera/error.hpp"
#include "tessera/field.hpp"

namespace tessera {
namespace {

// A uniform grid of cubic cells over a box, each cell listing the items (triangles or
// vertices) whose bounding box overlaps it (compressed rows: start_[c] .. start_[c + 1]).
class CellIndex {
public:
    // `boxes` gives each item's bounding box (lo, hi).
    void build(const std::vector<std::pair<Vec3, Vec3>>& boxes) {
        Vec3 hi;
        lo_ = hi = boxes.empty() ? Vec3{} : boxes[0].first;
        for (const auto& [a, b] : boxes)
            for (int k = 0; k < 3; ++k) lo_[k] = std::min(lo_[k], a[k]), hi[k] = std::max(hi[k], b[k]);
        // Cubic cells, about 2 per item; axes thinner than a cell get a single cell.
        const double target = std::clamp(2.0 * static_cast<double>(boxes.size()), 1.0, double(1 << 21));
        const double extent[3] = {hi.x - lo_.x, hi.y - lo_.y, hi.z - lo_.z};
        const double largest = std::max({extent[0], extent[1], extent[2]});
        cell_ = 1.0;
        if (largest > 0.0) {
            bool thin[3];
            for (int k = 0; k < 3; ++k) thin[k] = !(extent[k] > 1e-9 * largest);
            for (int round = 0; round < 3; ++round) {
                double volume = 1.0;
                int axes = 0;
                for (int k = 0; k < 3; ++k)
                    if (!thin[k]) volume *= extent[k], ++axes;
                // volume <= largest^axes and target >= 1, so the largest axis never turns thin.
                cell_ = std::pow(volume / target, 1.0 / axes);
                bool changed = false;
                for (int k = 0; k < 3; ++k)
                    if (!thin[k] && extent[k] < cell_) thin[k] = changed = true;
                if (!changed) break;
            }
        }
        for (int k = 0; k < 3; ++k)
            dims_[k] = static_cast<int>(std::clamp(std::ceil(extent[k] / cell_), 1.0, double(1 << 21)));
        inv_cell_ = 1.0 / cell_;
        const std::size_t cells = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
        start_.assign(cells + 1, 0);
        for (int pass = 0; pass < 2; ++pass) {
            std::vector<std::size_t> fill;
            if (pass == 1) {
                for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
                items_.resize(start_[cells]);
                fill.assign(start_.begin(), start_.end() - 1);
            }
            for (std::size_t item = 0; item < boxes.size(); ++item) {
                const auto a = cell_of(boxes[item].first), b = cell_of(boxes[item].second);
                for (int z = a[2]; z <= b[2]; ++z)
                    for (int y = a[1]; y <= b[1]; ++y)
                        for (int x = a[0]; x <= b[0]; ++x) {
                            const std::size_t c = index(x, y, z);
                            if (pass == 0)
                                ++start_[c + 1];
                            else
                                items_[fill[c]++] = static_cast<int>(item);
                        }
            }
        }
        const std::size_t rows = static_cast<std::size_t>(dims_[1]) * dims_[2];
        row_first_.assign(rows, dims_[0]);
        row_last_.assign(rows, -1);
        for (std::size_t row = 0; row < rows; ++row)
            for (int x = 0; x < dims_[0]; ++x) {
                const std::size_t c = static_cast<std::size_t>(x) + static_cast<std::size_t>(dims_[0]) * row;
                if (start_[c + 1] == start_[c]) continue;
                row_first_[row] = std::min(row_first_[row], x);
                row_last_[row] = x;
            }
    }

    // Calls visit(item) for items of cells near p, nearest rows first, skipping every
    // cell farther from p than best_d2() (re-read as it shrinks), until no unvisited
    // cell can hold anything nearer. Rows of cells along x are visited in rings (by
    // Chebyshev distance in y and z) around p's row; within a row only the non-empty
    // span that lies within the current best distance of p is visited. A query near
    // the items costs O(1); far from them, O(rows) = O(cells^(2/3)).
    template <class Visit, class Best>
    void search(const Vec3& p, Visit&& visit, Best&& best_d2) const {
        const auto s = cell_of(p);
        for (int r = 0;; ++r) {
            const int ylo = std::max(s[1] - r, 0), yhi = std::min(s[1] + r, dims_[1] - 1);
            const int zlo = std::max(s[2] - r, 0), zhi = std::min(s[2] + r, dims_[2] - 1);
            for (int z = zlo; z <= zhi; ++z) {
                if (std::abs(z - s[2]) == r) {
                    for (int y = ylo; y <= yhi; ++y) visit_row(p, y, z, s[0], visit, best_d2);
                } else {
                    if (s[1] - r >= 0) visit_row(p, s[1] - r, z, s[0], visit, best_d2);
                    if (s[1] + r < dims_[1]) visit_row(p, s[1] + r, z, s[0], visit, best_d2);
                }
            }
            // Lower bound on the distance to any row outside the visited y-z box.
            double bound2 = std::numeric_limits<double>::infinity();
            const int box_lo[3] = {0, ylo, zlo}, box_hi[3] = {dims_[0] - 1, yhi, zhi};
            for (int k = 1; k < 3; ++k)
                for (int side = 0; side < 2; ++side) {
                    if (side == 0 ? box_lo[k] == 0 : box_hi[k] == dims_[k] - 1) continue;  // nothing beyond
                    double d2 = 0.0;
                    for (int j = 0; j < 3; ++j) {
                        // The cells beyond that face of the box, over the whole grid on the other axes.
                        double a = lo_[j], b = lo_[j] + dims_[j] * cell_;
                        if (j == k) (side == 0 ? b : a) = lo_[j] + (side == 0 ? box_lo[k] : box_hi[k] + 1) * cell_;
                        const double g = p[j] < a ? a - p[j] : (p[j] > b ? p[j] - b : 0.0);
                        d2 += g * g;
                    }
                    bound2 = std::min(bound2, d2);
                }
            if (bound2 == std::numeric_limits<double>::infinity() || best_d2() <= bound2) return;
        }
    }

private:
    Vec3 lo_;
    double cell_ = 1.0, inv_cell_ = 1.0;
    int dims_[3] = {1, 1, 1};
    std::vector<std::size_t> start_;
    std::vector<int> items_;
    std::vector<int> row_first_, row_last_;  // per row (y, z): the span of non-empty cells along x

    // The cells of row (y, z) within the best distance of p, outward from column sx.
    template <class Visit, class Best>
    void visit_row(const Vec3& p, int y, int z, int sx, Visit& visit, Best& best_d2) const {
        const std::size_t row = static_cast<std::size_t>(y) + static_cast<std::size_t>(dims_[1]) * z;
        const int first = row_first_[row], last = row_last_[row];
        if (first > last) return;  // an empty row
        const double gyz = gap(p, 1, y) + gap(p, 2, z);
        if (gyz >= best_d2()) return;
        auto cell = [&](int x) {
            if (gyz + gap(p, 0, x) >= best_d2()) return false;  // and every cell beyond it
            const std::size_t c = index(x, y, z);
            for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) visit(items_[k]);
            return true;
        };
        const int from = std::clamp(sx, first, last);
        for (int x = from; x <= last && cell(x); ++x) {
        }
        for (int x = from - 1; x >= first && cell(x); --x) {
        }
    }

    // Squared distance from p to the slab of cells with index c along `axis`.
    double gap(const Vec3& p, int axis, int c) const {
        const double a = lo_[axis] + c * cell_, g = p[axis] < a ? a - p[axis] : p[axis] - (a + cell_);
        return g > 0.0 ? g * g : 0.0;
    }

    std::array<int, 3> cell_of(const Vec3& p) const {
        std::array<int, 3> c{};
        for (int k = 0; k < 3; ++k) {
            const double u = std::floor((p[k] - lo_[k]) * inv_cell_);
            c[k] = u > 0.0 ? static_cast<int>(std::min(u, double(dims_[k] - 1))) : 0;  // NaN -> 0
        }
        return c;
    }
    std::size_t index(int x, int y, int z) const {
        return static_cast<std::size_t>(x) + static_cast<std::size_t>(dims_[0]) * (y + static_cast<std::size_t>(dims_[1]) * z);
    }
};


Vec3 unit_or_zero(const Vec3& v) {
    const double n = norm(v);
    return n > field_detail::degenerate_norm ? v / n : Vec3{};
}

// Flips triangles so that neighbours across every shared edge traverse it in opposite
// directions; each connected patch keeps the winding of the larger part (by area) of
// its triangles as given.
void orient_consistently(const std::vector<Vec3>& vertices, std::vector<std::array<int, 3>>& triangles) {
    struct Edge { int a, b, face; bool forward; };
    std::vector<Edge> edges;
    edges.reserve(triangles.size() * 3);
    for (int f = 0; f < static_cast<int>(triangles.size()); ++f)
        for (int e = 0; e < 3; ++e) {
            const int u = triangles[f][e], v = triangles[f][(e + 1) % 3];
            edges.push_back({std::min(u, v), std::max(u, v), f, u < v});
        }
    std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
        return std::tie(x.a, x.b, x.face) < std::tie(y.a, y.b, y.face);
    });
    // Adjacency (compressed rows): neighbour face and whether it must flip relative to this one.
    const std::size_t n = triangles.size();
    std::vector<std::size_t> start(n + 1, 0);
    std::vector<std::pair<int, bool>> links;
    std::vector<std::array<int, 3>> pairs;  // face, neighbour, flip
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) ++j;
        for (std::size_t x = i; x < j; ++x)
            for (std::size_t y = i; y < j; ++y)
                if (x != y && edges[x].face != edges[y].face)
                    pairs.push_back({edges[x].face, edges[y].face, edges[x].forward == edges[y].forward ? 1 : 0});
        i = j;
    }
    for (const auto& p : pairs) ++start[static_cast<std::size_t>(p[0]) + 1];
    for (std::size_t f = 0; f < n; ++f) start[f + 1] += start[f];
    links.resize(pairs.size());
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (const auto& p : pairs) links[fill[static_cast<std::size_t>(p[0])]++] = {p[1], p[2] != 0};

    auto area = [&](std::size_t f) {
        const auto& t = triangles[f];
        return norm(cross(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]]));
    };
    std::vector<int> flip(n, -1);
    std::vector<std::size_t> queue;
    for (std::size_t seed = 0; seed < n; ++seed) {
        if (flip[seed] >= 0) continue;
        queue.assign(1, seed);
        flip[seed] = 0;
        double kept = 0.0, flipped = 0.0;
        for (std::size_t q = 0; q < queue.size(); ++q) {
            const std::size_t f = queue[q];
            (flip[f] ? flipped : kept) += area(f);
            for (std::size_t k = start[f]; k < start[f + 1]; ++k) {
                const auto [g, relative] = links[k];
                if (flip[static_cast<std::size_t>(g)] >= 0) continue;  // first come wins (non-manifold edges)
                flip[static_cast<std::size_t>(g)] = flip[f] ^ (relative ? 1 : 0);
                queue.push_back(static_cast<std::size_t>(g));
            }
        }
        const int invert = flipped > kept ? 1 : 0;
        for (const std::size_t f : queue) flip[f] ^= invert;
    }
    for (std::size_t f = 0; f < n; ++f)
        if (flip[f]) std::swap(triangles[f][1], triangles[f][2]);
}

}  // namespace

namespace field_detail {

struct MeshData {
    std::string source;
    std::vector<Vec3> vertices;
    std::vector<Vec3> directions;                // unit, per vertex
    std::vector<std::array<int, 3>> triangles;   // non-degenerate, consistently oriented
    std::vector<Vec3> face_normals;              // unit
    std::vector<Vec3> vertex_normals;            // unit (or zero), area-weighted
    CellIndex index;                             // over triangles, or over vertices without faces

    bool has_faces() const { return !triangles.empty(); }

    // The closest surface point: triangle and barycentric coordinates.
    void closest(const Vec3& p, int& triangle, std::array<double, 3>& bary) const {
        double best = std::numeric_limits<double>::infinity();
        triangle = 0;
        bary = {1, 0, 0};
        index.search(
            p,
            [&](int t) {
                const auto& tri = triangles[static_cast<std::size_t>(t)];
                const Vec3 &a = vertices[tri[0]], &b = vertices[tri[1]], &c = vertices[tri[2]];
                const auto w = core::closest_barycentric(p, a, b, c);
                const double d2 = squared_norm(a * w[0] + b * w[1] + c * w[2] - p);
                if (d2 < best || (d2 == best && t < triangle)) best = d2, triangle = t, bary = w;
            },
            [&] { return best; });
    }

    // Direction and normal at the closest surface point.
    void surface(const Vec3& p, Vec3& direction, Vec3& normal) const {
        int t = 0;
        std::array<double, 3> w{};
        closest(p, t, w);
        const auto& tri = triangles[static_cast<std::size_t>(t)];
        const Vec3& n_face = face_normals[static_cast<std::size_t>(t)];
        Vec3 d = directions[tri[0]] * w[0] + directions[tri[1]] * w[1] + directions[tri[2]] * w[2];
        direction = unit_or_zero(d - n_face * dot(d, n_face));
        normal = unit_or_zero(vertex_normals[tri[0]] * w[0] + vertex_normals[tri[1]] * w[1] +
                              vertex_normals[tri[2]] * w[2]);
        if (normal == Vec3{}) normal = n_face;
    }

    // Inverse-distance-weighted direction of the k = 8 nearest vertices.
    Vec3 point_cloud(const Vec3& p) const {
        constexpr int k_max = 8;
        const int k = static_cast<int>(std::min<std::size_t>(k_max, vertices.size()));
        std::array<int, k_max> nearest{};
        std::array<double, k_max> d2s{};
        int found = 0;
        index.search(
            p,
            [&](int v) {
                const double d2 = squared_norm(vertices[static_cast<std::size_t>(v)] - p);
                if (found == k && !(d2 < d2s[k - 1] || (d2 == d2s[k - 1] && v < nearest[k - 1]))) return;
                int at = found < k ? found++ : k - 1;
                while (at > 0 && (d2 < d2s[at - 1] || (d2 == d2s[at - 1] && v < nearest[at - 1]))) {
                    nearest[at] = nearest[at - 1], d2s[at] = d2s[at - 1];
                    --at;
                }
                nearest[at] = v, d2s[at] = d2;
            },
            [&] { return found < k ? std::numeric_limits<double>::infinity() : d2s[k - 1]; });
        if (d2s[0] <= 1e-24) return directions[static_cast<std::size_t>(nearest[0])];  // on a vertex
        Vec3 sum;
        for (int j = 0; j < found; ++j) sum += directions[static_cast<std::size_t>(nearest[j])] / d2s[j];
        return unit_or_zero(sum);
    }
};

Vec3 mesh_direction(const MeshData& mesh, const Vec3& p) {
    if (!mesh.has_faces()) return mesh.point_cloud(p);
    Vec3 d, n;
    mesh.surface(p, d, n);
    return d;
}

Quat mesh_frame(const MeshData& mesh, const Vec3& p, int dimension) {
    if (!mesh.has_faces()) return frame_from_direction(mesh.point_cloud(p), dimension);
    Vec3 d, n;
    mesh.surface(p, d, n);
    return dimension == 3 ? frame_from_direction(d, n) : frame_from_direction(d, dimension);
}

std::string mesh_describe(const MeshData& mesh) {
    if (!mesh.has_faces()) return "point cloud " + mesh.source + " (" + std::to_string(mesh.vertices.size()) + " vertices)";
    return "mesh " + mesh.source + " (" + std::to_string(mesh.vertices.size()) + " vertices, " +
           std::to_string(mesh.triangles.size()) + " triangles)";
}

}  // namespace field_detail

OrientationField OrientationField::mesh_vertices(const TriangleMesh& mesh, const std::vector<Vec3>& directions,
                                                 const std::string& source) {
    auto fail = [&](const std::string& what) { throw Error(ErrorKind::input, source + ": " + what); };
    if (mesh.vertices.empty()) fail("a mesh field needs at least one vertex");
    if (directions.size() != mesh.vertices.size())
        fail("the mesh has " + std::to_string(mesh.vertices.size()) + " vertices but " +
             std::to_string(directions.size()) + " directions (one per vertex is needed)");
    auto data = std::make_shared<field_detail::MeshData>();
    data->source = source;
    data->vertices = mesh.vertices;
    data->directions.resize(directions.size());
    for (std::size_t v = 0; v < directions.size(); ++v) {
        if (!is_finite(mesh.vertices[v])) fail("vertex " + std::to_string(v) + " is not finite");
        if (!is_finite(directions[v])) fail("vertex " + std::to_string(v) + " has a non-finite direction");
        if (!(norm(directions[v]) > field_detail::degenerate_norm))
            fail("vertex " + std::to_string(v) + " has a zero direction (every vertex needs a direction)");
        data->directions[v] = directions[v] / norm(directions[v]);
    }
    const int nv = static_cast<int>(mesh.vertices.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        for (int v : tri)
            if (v < 0 || v >= nv)
                fail("triangle " + std::to_string(t) + " has vertex index " + std::to_string(v) + " out of range");
        const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
        const double scale = std::max({squared_norm(b - a), squared_norm(c - a), squared_norm(c - b)});
        if (norm(cross(b - a, c - a)) > 1e-12 * scale) data->triangles.push_back(tri);  // drop degenerate ones
    }
    if (!mesh.triangles.empty() && data->triangles.empty()) fail("every triangle of the mesh is degenerate");

    std::vector<std::pair<Vec3, Vec3>> boxes;
    if (data->has_faces()) {
        orient_consistently(data->vertices, data->triangles);
        data->vertex_normals.assign(data->vertices.size(), Vec3{});
        for (const auto& tri : data->triangles) {
            const Vec3 &a = data->vertices[tri[0]], &b = data->vertices[tri[1]], &c = data->vertices[tri[2]];
            const Vec3 n = cross(b - a, c - a);  // length = twice the area: area weighting
            data->face_normals.push_back(n / norm(n));
            for (int v : tri) data->vertex_normals[v] += n;
            Vec3 lo = a, hi = a;
            for (int k = 0; k < 3; ++k)
                lo[k] = std::min({a[k], b[k], c[k]}), hi[k] = std::max({a[k], b[k], c[k]});
            boxes.push_back({lo, hi});
        }
        for (Vec3& n : data->vertex_normals) n = unit_or_zero(n);
    } else {
        for (const Vec3& v : data->vertices) boxes.push_back({v, v});
    }
    data->index.build(boxes);
    OrientationField f;
    f.kind_ = Kind::mesh;
    f.mesh_ = std::move(data);
    return f;
}

OrientationField OrientationField::mesh_file(const std::string& path) {
    const VertexDirectionMesh m = read_vertex_directions(path);
    return mesh_vertices(m.mesh, m.directions, path);
}

}  // namespace tessera
