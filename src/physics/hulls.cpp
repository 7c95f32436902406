// Convex-hull element shapes and their signed distances (GJK with EPA for penetration
// depth: Bullet's btGjkEpaSolver2), for types with meshes. See hulls.hpp.
#include "physics/hulls.hpp"

#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "tessera/error.hpp"
#include "tessera/mesh.hpp"

namespace tessera::physics {

TypeHulls::TypeHulls(const Exemplar& data) : points(data.types.size()), volume(data.types.size(), 0.0) {
    for (std::size_t t = 0; t < data.types.size(); ++t) {
        if (data.types[t].mesh.empty()) continue;
        const TriangleMesh mesh = read_triangle_mesh(data.types[t].mesh);
        if (mesh.triangles.empty())
            throw Error(ErrorKind::input,
                        "type '" + data.types[t].name + "': mesh " + data.types[t].mesh + " has no triangles");
        double v = 0;  // divergence theorem: signed tetrahedra from the origin
        for (const auto& tri : mesh.triangles)
            v += dot(mesh.vertices[tri[0]], cross(mesh.vertices[tri[1]], mesh.vertices[tri[2]])) / 6.0;
        points[t] = mesh.vertices;
        volume[t] = std::abs(v);
        any = true;
    }
}

std::vector<Vec3> world_hull(const TypeHulls& hulls, const Element& e, const Vec3& centroid) {
    std::vector<Vec3> out;
    out.reserve(hulls.points[e.type].size());
    for (const Vec3& v : hulls.points[e.type]) out.push_back(centroid + e.orientation.rotate(v) * e.scale);
    return out;
}

void cover_hull(ElementShape& shape, const std::vector<Vec3>& world_points) {
    for (const Vec3& p : world_points)
        for (int a = 0; a < 3; ++a) {
            shape.lo[a] = std::min(shape.lo[a], p[a]);
            shape.hi[a] = std::max(shape.hi[a], p[a]);
        }
}

namespace {

btVector3 bt(const Vec3& v) { return {btScalar(v.x), btScalar(v.y), btScalar(v.z)}; }
Vec3 vec(const btVector3& v) { return {double(v.x()), double(v.y()), double(v.z())}; }

// One convex piece placed in world space: a hull (identity transform), a sphere or a
// capsule between two samples.
struct Piece {
    std::unique_ptr<btConvexShape> shape;
    btTransform transform;
    double inflation = 0;  // margin added around a hull (see below), taken off the distances
};

std::vector<Piece> pieces(const std::vector<Vec3>& hull, const Sample* samples, int count, double radius) {
    std::vector<Piece> out;
    if (!hull.empty()) {
        // EPA needs a small margin (with none it returns wrong faces for flush polyhedra,
        // e.g. 0.17 instead of 0.3 for two overlapping cubes); the hull is inflated by it,
        // which shifts every signed distance by exactly the margin, so it is added back.
        Vec3 lo = hull[0], hi = hull[0];
        for (const Vec3& p : hull)
            for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
        const double margin = 0.01 * std::max(norm(hi - lo), 1e-12);
        auto h = std::make_unique<btConvexHullShape>();
        for (const Vec3& p : hull) h->addPoint(bt(p), false);
        h->setMargin(btScalar(margin));
        h->recalcLocalAabb();
        out.push_back({std::move(h), btTransform::getIdentity(), margin});
        return out;
    }
    if (count == 1) {
        btTransform t = btTransform::getIdentity();
        t.setOrigin(bt(samples[0].p));
        out.push_back({std::make_unique<btSphereShape>(btScalar(radius)), t});
        return out;
    }
    for (int k = 0; k + 1 < count; ++k) {
        const Vec3 d = samples[k + 1].p - samples[k].p;
        const double len = norm(d);
        btTransform t = btTransform::getIdentity();
        t.setOrigin(bt((samples[k].p + samples[k + 1].p) * 0.5));
        if (len < 1e-9) {
            out.push_back({std::make_unique<btSphereShape>(btScalar(radius)), t});
            continue;
        }
        t.setRotation(shortestArcQuat(btVector3(0, 1, 0), bt(d / len)));  // capsule axis is y
        out.push_back({std::make_unique<btCapsuleShape>(btScalar(radius), btScalar(len)), t});
    }
    return out;
}

}  // namespace

HullContact hull_contact(const std::vector<Vec3>& hull_a, const Sample* samples_a, int count_a, double radius_a,
                         const std::vector<Vec3>& hull_b, const Sample* samples_b, int count_b, double radius_b) {
    const std::vector<Piece> a = pieces(hull_a, samples_a, count_a, radius_a);
    const std::vector<Piece> b = pieces(hull_b, samples_b, count_b, radius_b);
    HullContact best;
    bool found = false;
    for (const Piece& pa : a) {
        for (const Piece& pb : b) {
            // GJK for separated pieces, EPA for the depth of penetrating ones.
            btGjkEpaSolver2::sResults r;
            double gap;
            if (btGjkEpaSolver2::Distance(pa.shape.get(), pa.transform, pb.shape.get(), pb.transform,
                                          btVector3(1, 0, 0), r)) {
                gap = double(r.distance);
            } else if (btGjkEpaSolver2::Penetration(pa.shape.get(), pa.transform, pb.shape.get(), pb.transform,
                                                    btVector3(1, 0, 0), r)) {
                gap = double(r.distance);  // negative: the penetration depth
            } else {
                continue;  // both phases failed (degenerate shapes): no contact information
            }
            gap += pa.inflation + pb.inflation;
            if (found && gap >= best.gap) continue;
            found = true;
            best.gap = gap;
            best.on_a = vec(r.witnesses[0]);
            best.on_b = vec(r.witnesses[1]);
        }
    }
    if (!found) best.gap = 1e300;  // GJK found nothing: treat as far apart
    return best;
}

}  // namespace tessera::physics
