"""Triangle meshes for the example scenes (examples/scenes.py): element shapes in their
local frame (origin at the centroid of the element's samples, see docs/format.md,
"Element geometry") and closed domain meshes (a bowl's inside, a sculpture, a house).

Standard-library only and deterministic. Every mesh is closed and counter-clockwise
seen from outside, so it serves both as element geometry and as a domain.
"""
import math


class Mesh:
    def __init__(self):
        self.v = []
        self.f = []

    def add(self, other):
        base = len(self.v)
        self.v += other.v
        self.f += [(a + base, b + base, c + base) for a, b, c in other.f]
        return self

    def transformed(self, fn):
        m = Mesh()
        m.v = [fn(p) for p in self.v]
        m.f = list(self.f)
        return m

    def write_obj(self, path, comment):
        with open(path, "w") as out:
            out.write("# %s (examples/scene_meshes.py)\n" % comment)
            for p in self.v:
                out.write("v %.5f %.5f %.5f\n" % tuple(0.0 if abs(c) < 5e-6 else c for c in p))
            for a, b, c in self.f:
                out.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


def revolve(profile, sides):
    """Solid of revolution about +z. `profile` is [(r, z), ...] from the bottom pole to the
    top pole; the first and last r must be 0 (poles). Closed, outward facing."""
    m = Mesh()
    assert profile[0][0] == 0 and profile[-1][0] == 0
    bottom = 0
    m.v.append((0.0, 0.0, profile[0][1]))
    rings = []
    for r, z in profile[1:-1]:
        ring = []
        for s in range(sides):
            a = 2 * math.pi * s / sides
            ring.append(len(m.v))
            m.v.append((r * math.cos(a), r * math.sin(a), z))
        rings.append(ring)
    top = len(m.v)
    m.v.append((0.0, 0.0, profile[-1][1]))
    for s in range(sides):
        t = (s + 1) % sides
        m.f.append((bottom, rings[0][t], rings[0][s]))
        for k in range(len(rings) - 1):
            a, b = rings[k], rings[k + 1]
            m.f.append((a[s], a[t], b[t]))
            m.f.append((a[s], b[t], b[s]))
        m.f.append((rings[-1][s], rings[-1][t], top))
    return m


def sphere(radius, rings=10, sides=16, squash=1.0, dimple=0.0):
    """A sphere (or a spheroid squashed along z) with an optional dimple at the top, a plum."""
    profile = []
    for k in range(rings + 1):
        t = math.pi * k / rings  # 0 at the bottom pole
        r = radius * math.sin(t)
        z = -radius * squash * math.cos(t)
        if dimple and k >= rings - 2:
            z -= dimple * radius * (1.0 if k == rings else 0.4)
        profile.append((0.0 if k in (0, rings) else r, z))
    return revolve(profile, sides)


def ellipsoid(a, b, c, rings=10, sides=16):
    return sphere(1.0, rings, sides).transformed(lambda p: (p[0] * a, p[1] * b, p[2] * c))


def cylinder(radius, height, sides=16):
    h = height / 2
    return revolve([(0, -h), (radius, -h), (radius, h), (0, h)], sides)


def box(sx, sy, sz):
    """Axis-aligned box centred at the origin."""
    m = Mesh()
    for z in (-sz / 2, sz / 2):
        for y in (-sy / 2, sy / 2):
            for x in (-sx / 2, sx / 2):
                m.v.append((x, y, z))
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    for a, b, c, d in quads:
        m.f += [(a, b, c), (a, c, d)]
    return m


def frames_along(points):
    """Rotation-minimising frames (tangent, normal, binormal) along a polyline."""
    n = len(points)
    tangents = []
    for i in range(n):
        a, b = points[max(i - 1, 0)], points[min(i + 1, n - 1)]
        d = [b[k] - a[k] for k in range(3)]
        l = math.sqrt(sum(c * c for c in d))
        tangents.append([c / l for c in d])
    t0 = tangents[0]
    up = [0, 0, 1] if abs(t0[2]) < 0.9 else [1, 0, 0]
    nrm = cross(up, t0)
    frames = []
    for t in tangents:
        nrm = [nrm[k] - t[k] * dot(nrm, t) for k in range(3)]  # project: parallel transport
        l = math.sqrt(dot(nrm, nrm))
        nrm = [c / l for c in nrm]
        frames.append((t, nrm, cross(t, nrm)))
    return frames


def tube(points, radii, sides=10):
    """A closed tube through `points` with per-point radius (caps at both ends)."""
    m = Mesh()
    frames = frames_along(points)
    rings = []
    for p, r, (t, n, b) in zip(points, radii, frames):
        ring = []
        for s in range(sides):
            a = 2 * math.pi * s / sides
            ring.append(len(m.v))
            m.v.append(tuple(p[k] + r * (math.cos(a) * n[k] + math.sin(a) * b[k]) for k in range(3)))
        rings.append(ring)
    start, end = len(m.v), len(m.v) + 1
    m.v.append(tuple(points[0][k] - radii[0] * 0.3 * frames[0][0][k] for k in range(3)))
    m.v.append(tuple(points[-1][k] + radii[-1] * 0.3 * frames[-1][0][k] for k in range(3)))
    for s in range(sides):
        t = (s + 1) % sides
        m.f.append((start, rings[0][t], rings[0][s]))
        for k in range(len(rings) - 1):
            a, c = rings[k], rings[k + 1]
            m.f.append((a[s], a[t], c[t]))
            m.f.append((a[s], c[t], c[s]))
        m.f.append((rings[-1][s], rings[-1][t], end))
    return m


def subdivide_polyline(points, per_segment):
    out = []
    for i in range(len(points) - 1):
        for s in range(per_segment):
            u = s / per_segment
            out.append([points[i][k] * (1 - u) + points[i + 1][k] * u for k in range(3)])
    out.append(list(points[-1]))
    return out


def convex_prism_house(width, depth, wall, ridge):
    """A house: a box of width x depth x wall with a gable roof up to `ridge` (convex solid),
    standing on z = 0, centred in x and y."""
    w, d = width / 2, depth / 2
    v = [(-w, -d, 0), (w, -d, 0), (w, d, 0), (-w, d, 0),
         (-w, -d, wall), (w, -d, wall), (w, d, wall), (-w, d, wall),
         (-w, 0, ridge), (w, 0, ridge)]
    faces = [
        (0, 3, 2, 1),        # floor
        (0, 1, 5, 4),        # wall y = -d
        (2, 3, 7, 6),        # wall y = +d
        (1, 2, 6, 9, 5),     # gable x = +w
        (3, 0, 4, 8, 7),     # gable x = -w
        (4, 5, 9, 8),        # roof, -y side
        (6, 7, 8, 9),        # roof, +y side
    ]
    m = Mesh()
    m.v = [tuple(map(float, p)) for p in v]
    for poly in faces:
        for k in range(1, len(poly) - 1):
            m.f.append((poly[0], poly[k], poly[k + 1]))
    return m


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))
