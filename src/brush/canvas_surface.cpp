// Surface canvases (brush/canvas_surface.hpp) and the canvas state's frames (brush_state.hpp).
#include "brush/canvas_surface.hpp"

#include <algorithm>
#include <cmath>

#include "brush/surface.hpp"
#include "tessera/error.hpp"

namespace tessera {

const Domain& BrushCanvas::Impl::space() const { return surface ? surface->band() : domain; }

Quat BrushCanvas::Impl::frame_of_sample(int s) const {
    if (!surface) return frame_from_direction(direction[s], dimension);
    return frame_from_direction(direction[s], surface->closest(arrangement.samples[s].p).normal);
}

Quat BrushCanvas::Impl::frame_of_element(int e, const Vec3& c) const {
    return brush::frame_at(*this, direction[arrangement.elements[e].first_sample], c);
}

}  // namespace tessera

namespace tessera::brush {

std::shared_ptr<const Surface> surface_of_shell(const Domain& shell) {
    const DomainSource src = shell.source();
    if (src.file.empty())
        throw Error(ErrorKind::domain, "canvas: a shell made from a mesh in memory; give the mesh to "
                                       "BrushCanvas(mesh, thickness) instead");
    TriangleMesh mesh = read_triangle_mesh(src.file);
    for (Vec3& v : mesh.vertices) v = src.origin + (v - src.origin) * src.scale;  // as Domain::scaled
    return std::make_shared<const Surface>(mesh, src.thickness * src.scale, src.file);
}

void snap_elements(BrushCanvas::Impl& st, int first, int last, bool include_locked) {
    if (!st.surface) return;
    Arrangement& arr = st.arrangement;
    for (int i = first; i < last; ++i) {
        const Element& e = arr.elements[i];
        if (e.locked && !include_locked) continue;
        Vec3 c;
        for (int k = 0; k < e.sample_count; ++k) {
            Sample& s = arr.samples[e.first_sample + k];
            const SurfacePoint sp = st.surface->closest(s.p);
            s.p = sp.p;
            c += sp.p;
            st.direction[e.first_sample + k] = tangent_direction(st.direction[e.first_sample + k], sp.normal);
        }
        const OutType& ot = st.out_types[e.type];
        if (!st.palette[ot.kappa].exemplar.types[ot.type].rigid) continue;
        // One orientation for a rigid element: tangent at its centre.
        const Vec3 u = tangent_direction(st.direction[e.first_sample],
                                         st.surface->closest(c / static_cast<double>(e.sample_count)).normal);
        for (int k = 0; k < e.sample_count; ++k) st.direction[e.first_sample + k] = u;
    }
}

Stroke snap_stroke(const BrushCanvas::Impl& st, const Stroke& stroke, double step, int min_points,
                   const std::string& where) {
    if (!st.surface) return stroke;
    Stroke out;
    out.width = stroke.width;
    auto push = [&](const Vec3& p) {
        const Vec3 q = st.surface->closest(p).p;
        if (out.points.empty() || squared_norm(q - out.points.back()) > 1e-18) out.points.push_back(q);
    };
    for (size_t i = 0; i < stroke.points.size(); ++i) {
        if (i == 0) {
            push(stroke.points[0]);
            continue;
        }
        const Vec3 a = stroke.points[i - 1], d = stroke.points[i] - a;
        const int n = std::max(1, static_cast<int>(std::ceil(norm(d) / step)));
        for (int k = 1; k <= n; ++k) push(a + d * (static_cast<double>(k) / n));
    }
    if (static_cast<int>(out.points.size()) < min_points)
        throw Error(ErrorKind::input, where + ": the stroke, moved onto the surface, has fewer than " +
                                          std::to_string(min_points) + " distinct points");
    return out;
}

OrientationField canvas_field(const BrushCanvas::Impl& st, const OrientationField& field) {
    return st.surface ? surface_field(*st.surface, field) : field;
}

Quat frame_at(const BrushCanvas::Impl& st, const Vec3& d, const Vec3& p) {
    if (!st.surface) return frame_from_direction(d, st.dimension);
    return frame_from_direction(d, st.surface->closest(p).normal);
}

Vec3 tangent_at(const BrushCanvas::Impl& st, const Vec3& d, const Vec3& p) {
    return st.surface ? tangent_direction(d, st.surface->closest(p).normal) : d;
}

}  // namespace tessera::brush
