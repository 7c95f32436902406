// step_physics: the interleaved physics solver of Discrete Element Textures (section 5):
// a few Bullet rigid-body steps after a search/assign iteration. Each call builds its
// own world (bodies in element order, so runs are deterministic), steps it, writes the
// bodies' rigid motions back to the samples and poses, and tears it down.
//
// Bullet works in single precision with absolute tolerances (contact margins, split-
// impulse threshold), so the world is expressed in normalised coordinates: origin at
// the domain's centre, lengths scaled so the mean collision radius is 0.5. Gravity is
// scaled by the same factor, which leaves the motion (in data units) unchanged.
// Displacements are taken as differences of Bullet positions, so a body that does not
// move writes back its samples exactly.
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "physics/hulls.hpp"
#include "physics/shapes.hpp"
#include "tessera/error.hpp"
#include "tessera/mesh.hpp"
#include "tessera/physics.hpp"

namespace tessera {
namespace {

using physics::ElementShape;

constexpr double kPi = 3.14159265358979323846;

void check_options(const PhysicsOptions& o) {
    auto fail = [](const std::string& what) { throw Error(ErrorKind::option, "physics: " + what); };
    if (o.substeps < 0 || o.substeps > 10000) fail("substeps must be in 0..10000, got " + std::to_string(o.substeps));
    if (!(o.time_step > 0) || !std::isfinite(o.time_step)) fail("time_step must be > 0");
    if (!(o.friction >= 0) || !std::isfinite(o.friction)) fail("friction must be >= 0");
    if (!(o.restitution >= 0 && o.restitution <= 1)) fail("restitution must be in [0, 1]");
    if (!(o.damping >= 0 && o.damping <= 1)) fail("damping must be in [0, 1]");
    if (!(o.overlap_correction > 0 && o.overlap_correction <= 1)) fail("overlap_correction must be in (0, 1]");
    if (o.solver_iterations < 1 || o.solver_iterations > 1000) fail("solver_iterations must be in 1..1000");
    if (!(o.tolerance >= 0) || !std::isfinite(o.tolerance)) fail("tolerance must be finite and >= 0");
}

// Data coordinates <-> Bullet coordinates.
struct Frame {
    Vec3 origin;
    double scale = 1.0;
    btVector3 to_bullet(const Vec3& p) const {
        const Vec3 q = (p - origin) * scale;
        return {btScalar(q.x), btScalar(q.y), btScalar(q.z)};
    }
    btVector3 to_bullet_vector(const Vec3& v) const {
        return {btScalar(v.x * scale), btScalar(v.y * scale), btScalar(v.z * scale)};
    }
};

Vec3 to_vec(const btVector3& v) { return {double(v.x()), double(v.y()), double(v.z())}; }

// Owns one Bullet world and everything in it; removes bodies before the world dies.
struct World {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btTriangleMesh>> meshes;
    std::vector<std::unique_ptr<btRigidBody>> statics;
    std::vector<std::unique_ptr<btRigidBody>> bodies;  // one per element, in element order

    World() = default;
    World(const World&) = delete;
    World& operator=(const World&) = delete;
    ~World() {
        for (auto it = bodies.rbegin(); it != bodies.rend(); ++it) world.removeRigidBody(it->get());
        for (auto it = statics.rbegin(); it != statics.rend(); ++it) world.removeRigidBody(it->get());
    }

    btCollisionShape* keep(btCollisionShape* shape) {
        shapes.emplace_back(shape);
        return shape;
    }
    void add_static(btCollisionShape* kept_shape, const PhysicsOptions& o) {
        btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, kept_shape);
        info.m_friction = btScalar(o.friction);
        info.m_restitution = btScalar(o.restitution);
        statics.push_back(std::make_unique<btRigidBody>(info));
        world.addRigidBody(statics.back().get());
    }
};

// The domain's bounding box as inward-facing static planes (4 in 2D, 6 in 3D).
void add_box_walls(World& w, const Box& box, int dimension, const Frame& f, const PhysicsOptions& o) {
    for (int axis = 0; axis < dimension; ++axis) {
        for (int side = 0; side < 2; ++side) {
            Vec3 n;
            n[axis] = side == 0 ? 1.0 : -1.0;
            Vec3 on;
            on[axis] = side == 0 ? box.lo[axis] : box.hi[axis];
            const btVector3 normal(btScalar(n.x), btScalar(n.y), btScalar(n.z));
            const btScalar constant = normal.dot(f.to_bullet(on));
            w.add_static(w.keep(new btStaticPlaneShape(normal, constant)), o);
        }
    }
}

// Mesh and shell domains: their surface as a static triangle mesh, when the mesh file
// is known (DomainSource::file) and still readable. Returns false when no mesh is available.
bool add_mesh_wall(World& w, const Domain& domain, const Frame& f, const PhysicsOptions& o) {
    if (domain.kind() != Domain::Kind::mesh && domain.kind() != Domain::Kind::shell) return false;
    const DomainSource src = domain.source();
    if (src.file.empty()) return false;
    TriangleMesh mesh;
    try {
        mesh = read_triangle_mesh(src.file);
    } catch (const Error&) {
        return false;  // the file moved since the domain was made: the bounding box walls remain
    }
    if (mesh.triangles.empty()) return false;
    auto tm = std::make_unique<btTriangleMesh>(true, false);
    const auto world_point = [&](int i) { return f.to_bullet(src.origin + (mesh.vertices[i] - src.origin) * src.scale); };
    for (const auto& t : mesh.triangles) tm->addTriangle(world_point(t[0]), world_point(t[1]), world_point(t[2]));
    btCollisionShape* shape = w.keep(new btBvhTriangleMeshShape(tm.get(), true));
    w.meshes.push_back(std::move(tm));
    w.add_static(shape, o);
    return true;
}

// Element types with a mesh collide as the convex hull of their mesh (hulls.hpp), the
// paper's choice for general elements; others as spheres or capsule chains.
btCollisionShape* make_hull(World& w, const std::vector<Vec3>& points, const Element& e, const Frame& f) {
    // Bullet rounds a hull by its collision margin, outward: the points are pulled in by
    // the margin (toward the centre) so that the rounded shape is the mesh's size and
    // bodies come to rest touching, as the measure sees them.
    constexpr double margin = 0.02;  // Bullet units (mean collision radius 0.5)
    auto* hull = new btConvexHullShape();
    w.keep(hull);
    for (const Vec3& v : points) {
        Vec3 p = e.orientation.rotate(v) * (e.scale * f.scale);
        const double len = norm(p);
        if (len > 2 * margin) p = p * ((len - margin) / len);
        hull->addPoint(btVector3(btScalar(p.x), btScalar(p.y), btScalar(p.z)), false);
    }
    hull->setMargin(btScalar(margin));
    hull->recalcLocalAabb();
    return hull;
}

// Polygon domains (2D): every edge of the outer ring and of the holes as a wall, two
// triangles spanning the plane's thickness, so elements come to rest against the
// polygon, not its bounding box, and cannot fall into a hole. A periodic domain has no
// outer ring: only its holes are walls.
bool add_polygon_walls(World& w, const Domain& domain, const Frame& f, const PhysicsOptions& o) {
    if (domain.kind() != Domain::Kind::polygon) return false;
    const DomainSource src = domain.source();
    const double reach = 2.0 * std::max(domain.bounds().size().x, domain.bounds().size().y) + 1.0;  // along z
    auto tm = std::make_unique<btTriangleMesh>(true, false);
    const auto point = [&](const Vec3& p, double z) {
        const Vec3 q = src.origin + (Vec3{p.x, p.y, 0} - src.origin) * src.scale;
        return f.to_bullet(Vec3{q.x, q.y, z});
    };
    const auto ring = [&](const std::vector<Vec3>& r) {
        for (std::size_t i = 0; i < r.size(); ++i) {
            const Vec3& a = r[i];
            const Vec3& b = r[(i + 1) % r.size()];
            tm->addTriangle(point(a, -reach), point(b, -reach), point(b, reach));
            tm->addTriangle(point(a, -reach), point(b, reach), point(a, reach));
        }
    };
    if (!o.periodic) ring(src.outer);
    for (const auto& h : src.holes) ring(h);
    if (tm->getNumTriangles() == 0) return false;
    btCollisionShape* shape = w.keep(new btBvhTriangleMeshShape(tm.get(), true));
    w.meshes.push_back(std::move(tm));
    w.add_static(shape, o);
    return true;
}

// The collision shape of one element, centred on its centroid, and its volume.
btCollisionShape* make_shape(World& w, const Exemplar& data, const ElementShape& s, const Frame& f,
                             const physics::TypeHulls& hulls, int element, double& volume) {
    const Element& e = data.elements[element];
    if (!hulls.points[e.type].empty()) {
        volume = hulls.volume[e.type] * std::pow(e.scale * f.scale, 3);
        return make_hull(w, hulls.points[e.type], e, f);
    }
    const double r = s.radius * f.scale;
    if (s.count == 1) {
        volume = 4.0 / 3.0 * kPi * r * r * r;
        return w.keep(new btSphereShape(btScalar(r)));
    }
    auto* compound = new btCompoundShape(false, s.count - 1);
    w.keep(compound);
    volume = 4.0 / 3.0 * kPi * r * r * r;
    for (int k = 0; k + 1 < s.count; ++k) {
        const Vec3 a = (data.samples[s.first + k].p - s.centroid) * f.scale;
        const Vec3 b = (data.samples[s.first + k + 1].p - s.centroid) * f.scale;
        const Vec3 d = b - a;
        const double len = norm(d);
        btTransform local;
        local.setIdentity();
        const Vec3 mid = (a + b) * 0.5;
        local.setOrigin(btVector3(btScalar(mid.x), btScalar(mid.y), btScalar(mid.z)));
        if (len < 1e-6 * r) {
            compound->addChildShape(local, w.keep(new btSphereShape(btScalar(r))));
            continue;
        }
        const btVector3 dir(btScalar(d.x / len), btScalar(d.y / len), btScalar(d.z / len));
        local.setRotation(shortestArcQuat(btVector3(0, 1, 0), dir));  // capsule axis is y
        compound->addChildShape(local, w.keep(new btCapsuleShape(btScalar(r), btScalar(len))));
        volume += kPi * r * r * len;
    }
    return compound;
}

void add_bodies(World& w, const Exemplar& data, const std::vector<ElementShape>& shapes, const Frame& f,
                const PhysicsOptions& o) {
    const bool plane = data.dimension == 2;
    const physics::TypeHulls hulls(data);
    w.bodies.reserve(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const ElementShape& s = shapes[i];
        double volume = 0;
        btCollisionShape* shape = make_shape(w, data, s, f, hulls, static_cast<int>(i), volume);
        const bool fixed = data.elements[i].locked;
        const btScalar mass = fixed ? btScalar(0) : btScalar(std::max(volume, 1e-12));  // density 1
        btVector3 inertia(0, 0, 0);
        if (!fixed) shape->calculateLocalInertia(mass, inertia);
        btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape, inertia);
        info.m_startWorldTransform.setIdentity();
        info.m_startWorldTransform.setOrigin(f.to_bullet(s.centroid));
        info.m_friction = btScalar(o.friction);
        info.m_restitution = btScalar(o.restitution);
        info.m_linearDamping = btScalar(o.damping);
        info.m_angularDamping = btScalar(o.damping);
        auto body = std::make_unique<btRigidBody>(info);
        if (!fixed) {
            body->setActivationState(DISABLE_DEACTIVATION);
            const btScalar r = btScalar(s.radius * f.scale);
            body->setCcdMotionThreshold(r);
            body->setCcdSweptSphereRadius(btScalar(0.9) * r);
            if (plane) {
                body->setLinearFactor(btVector3(1, 1, 0));
                body->setAngularFactor(btVector3(0, 0, 1));
            }
        }
        w.world.addRigidBody(body.get());
        w.bodies.push_back(std::move(body));
    }
}

// Applies body i's motion to element i; false (and nothing written) when it diverged
// or left the domain's bounds (with one radius of slack).
bool write_back(Exemplar& data, int i, const ElementShape& s, const btRigidBody& body, const btVector3& start,
                const Frame& f, const Box& bounds) {
    const btTransform& t = body.getWorldTransform();
    Vec3 move = to_vec(t.getOrigin() - start) / f.scale;
    const btQuaternion bq = t.getRotation();
    Quat q{double(bq.w()), double(bq.x()), double(bq.y()), double(bq.z())};
    if (data.dimension == 2) {
        move.z = 0;
        q.x = q.y = 0;
    }
    const double qn = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    if (!is_finite(move) || !(qn > 0.5) || !std::isfinite(qn)) return false;
    q = {q.w / qn, q.x / qn, q.y / qn, q.z / qn};
    const Vec3 centre = s.centroid + move;
    for (int a = 0; a < data.dimension; ++a)
        if (centre[a] < bounds.lo[a] - s.radius || centre[a] > bounds.hi[a] + s.radius) return false;
    for (int k = 0; k < s.count; ++k) {
        Vec3& p = data.samples[s.first + k].p;
        p = centre + q.rotate(p - s.centroid);
        if (data.dimension == 2) p.z = 0;
    }
    Element& e = data.elements[i];
    e.position = centre;
    Quat o = q * e.orientation;
    const double on = std::sqrt(o.w * o.w + o.x * o.x + o.y * o.y + o.z * o.z);
    e.orientation = {o.w / on, o.x / on, o.y / on, o.z / on};
    return true;
}

}  // namespace

Vec3 physics_gravity(const PhysicsOptions& options, int dimension) {
    if (!is_finite(options.gravity)) throw Error(ErrorKind::option, "physics: gravity must be finite");
    if (!(options.units_per_metre > 0) || !std::isfinite(options.units_per_metre))
        throw Error(ErrorKind::option, "physics: units_per_metre must be > 0");
    if (options.no_gravity) return {};
    Vec3 g = options.gravity;
    if (dimension == 2) g.z = 0;
    if (squared_norm(g) > 0) return g;
    const double magnitude = 9.81 * options.units_per_metre;
    return dimension == 2 ? Vec3{0, -magnitude, 0} : Vec3{0, 0, -magnitude};
}

PhysicsReport step_physics(Arrangement& data, const Domain& domain, const PhysicsOptions& options) {
    check_options(options);
    const Vec3 gravity = physics_gravity(options, data.dimension);
    if (data.elements.empty()) return {};
    data.validate("step_physics");
    const std::vector<ElementShape> shapes = physics::element_shapes(data);
    const int n = static_cast<int>(shapes.size());

    double mean_radius = 0;
    for (const ElementShape& s : shapes) mean_radius += s.radius / n;
    Frame f;
    f.origin = domain.bounds().center();
    if (data.dimension == 2) f.origin.z = 0;
    f.scale = 0.5 / std::max(mean_radius, 1e-12);

    int lost = 0;
    if (options.substeps > 0) {
        World w;
        w.world.setGravity(f.to_bullet_vector(gravity));
        btContactSolverInfo& solver = w.world.getSolverInfo();
        solver.m_numIterations = options.solver_iterations;
        solver.m_splitImpulse = 1;  // push overlaps apart without adding velocity
        solver.m_splitImpulsePenetrationThreshold = btScalar(-0.02);
        solver.m_erp2 = btScalar(options.overlap_correction);
        if (!options.periodic) add_box_walls(w, domain.bounds(), data.dimension, f, options);
        add_mesh_wall(w, domain, f, options);
        add_polygon_walls(w, domain, f, options);
        add_bodies(w, data, shapes, f, options);

        std::vector<btVector3> start(n);
        for (int i = 0; i < n; ++i) start[i] = w.bodies[i]->getWorldTransform().getOrigin();
        for (int step = 0; step < options.substeps; ++step)
            w.world.stepSimulation(btScalar(options.time_step), 0);  // one fixed step of time_step

        for (int i = 0; i < n; ++i) {
            if (data.elements[i].locked) continue;
            if (!write_back(data, i, shapes[i], *w.bodies[i], start[i], f, domain.bounds())) ++lost;
        }
    }
    PhysicsReport report = measure_physics(data, domain, gravity, options.tolerance);
    report.lost = lost;
    return report;
}

}  // namespace tessera
