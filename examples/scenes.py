#!/usr/bin/env python3
"""Writes the example scenes in the spirit of the Discrete Element Textures paper's figures
(1, 10, 11, 13): exemplars with element meshes under examples/scenes/, meshes under
examples/scenes/meshes/, fields and domains beside them. `scripts/demo` synthesizes each
one and renders it; docs/examples.md lists what each shows.

Deterministic (fixed seeds), standard-library only: python3 examples/scenes.py.
Every exemplar is a window of a pattern periodic in its horizontal axes (the window cuts a
stationary pattern), resting on a floor at z = 0 where it has one.
"""
import json
import math
import os
import random

import scene_meshes as sm

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes")
# Colours of the classes in pictures ("color" of a type, docs/format.md).
PLUM = "#6a3d7a"
PEBBLES = ["#8c8279", "#b5a690", "#6f6a64"]  # greys and sandstone
MESHES = os.path.join(HERE, "meshes")


def r4(v):
    return round(v, 4)


def write_exemplar(name, dimension, size, types, elements, description):
    doc = {"format": "tessera", "version": 1, "description": description, "dimension": dimension,
           "domain": {"type": "box", "min": [0.0] * dimension, "max": size},
           "types": types, "elements": elements}
    with open(os.path.join(HERE, name + ".json"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def write_mesh(mesh, name, comment):
    mesh.write_obj(os.path.join(MESHES, name + ".obj"), comment)
    return "meshes/" + name + ".obj"


def pdelta(a, b, size, periodic):
    d = [a[k] - b[k] for k in range(len(a))]
    for k in range(len(a)):
        if periodic[k]:
            d[k] -= size[k] * round(d[k] / size[k])
    return math.sqrt(sum(c * c for c in d))


class Placer:
    """Dart throwing of sample chains against every placed sample (periodic axes wrap),
    with a grid so that a few thousand chains stay fast."""

    def __init__(self, size, periodic, cell):
        self.size, self.periodic, self.cell = size, periodic, cell
        self.grid = {}

    def key(self, p):
        return tuple(int(math.floor(p[k] / self.cell)) for k in range(len(p)))

    def near(self, p):
        k = self.key(p)
        dims = len(p)
        ranges = [range(k[d] - 1, k[d] + 2) for d in range(dims)]
        n = [max(1, int(math.ceil(self.size[d] / self.cell))) for d in range(dims)]
        import itertools
        for c in itertools.product(*ranges):
            c = tuple(c[d] % n[d] if self.periodic[d] else c[d] for d in range(dims))
            yield from self.grid.get(c, ())

    def fits(self, pts, radius):
        for p in pts:
            for q, rq in self.near(p):
                if pdelta(p, q, self.size, self.periodic) < radius + rq:
                    return False
        return True

    def add(self, pts, radius):
        n = [max(1, int(math.ceil(self.size[d] / self.cell))) for d in range(len(pts[0]))]
        for p in pts:
            k = self.key(p)
            k = tuple(k[d] % n[d] if self.periodic[d] else k[d] for d in range(len(p)))
            self.grid.setdefault(k, []).append((p, radius))


class Depositor:
    """Random sequential deposition on a floor at z = 0 (periodic in x and y): each new
    element is dropped straight down until one of its samples (a ball of its radius)
    touches the floor or an element already there, so the pile is settled and every
    element rests on something, as food in a dish does."""

    def __init__(self, size, cell):
        self.size, self.cell = size, cell
        self.n = [max(1, int(math.ceil(size[k] / cell))) for k in range(2)]
        self.columns = {}

    def _column(self, p):
        return (int(math.floor(p[0] / self.cell)) % self.n[0], int(math.floor(p[1] / self.cell)) % self.n[1])

    def drop(self, pts, radius):
        """The samples moved down to where they come to rest (a new list)."""
        lift = max(radius - p[2] for p in pts)  # the floor
        for p in pts:
            cx, cy = self._column(p)
            for dx in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    for q, rq in self.columns.get(((cx + dx) % self.n[0], (cy + dy) % self.n[1]), ()):
                        ddx = p[0] - q[0]
                        ddy = p[1] - q[1]
                        ddx -= self.size[0] * round(ddx / self.size[0])
                        ddy -= self.size[1] * round(ddy / self.size[1])
                        reach = radius + rq
                        d2 = ddx * ddx + ddy * ddy
                        if d2 < reach * reach:
                            lift = max(lift, q[2] + math.sqrt(reach * reach - d2) - p[2])
        return [[p[0], p[1], p[2] + lift] for p in pts]

    def add(self, pts, radius):
        for p in pts:
            self.columns.setdefault(self._column(p), []).append((p, radius))


def quat_about(axis, angle):
    s = math.sin(angle / 2)
    return [math.cos(angle / 2), axis[0] * s, axis[1] * s, axis[2] * s]


def quat_mul(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return [w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2]


def rotate(q, v):
    w, x, y, z = q
    u = [x, y, z]
    t = [2 * c for c in sm.cross(u, v)]
    c2 = sm.cross(u, t)
    return [v[k] + w * t[k] + c2[k] for k in range(3)]


def random_quat(rng):
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(c * c for c in q))
    q = [c / n for c in q]
    return q if q[0] >= 0 else [-c for c in q]


def posed(reference, q, centre):
    return [[centre[k] + rotate(q, p)[k] for k in range(3)] for p in reference]


# ---------------------------------------------------------------------------------------
def plum_stack_3d():
    """Figure 1 (plums): plums in hexagonal layers stacked on a floor, a little jitter."""
    rng = random.Random(31)
    r = 0.5
    size = [6.0, 6.0 * math.sqrt(3) / 2 * 8 / 6, 2.6]  # 6 plums by 8 rows per layer, periodic
    size[1] = 8 * math.sqrt(3) / 2
    els = []
    for layer in range(3):
        z = r + layer * math.sqrt(2.0 / 3.0) * 2 * r
        off = [(0.0, 0.0), (0.5, math.sqrt(3) / 6), (1.0, math.sqrt(3) / 3)][layer]
        for j in range(8):
            for i in range(6):
                x = (i + 0.5 * (j % 2) + off[0]) % 6.0 + rng.gauss(0, 0.03)
                y = (j * math.sqrt(3) / 2 + off[1]) % size[1] + rng.gauss(0, 0.03)
                if layer == 2 and rng.random() < 0.35:
                    continue  # an uneven top layer
                els.append({"type": "plum", "position": [r4(x % 6.0), r4(y % size[1]), r4(z)],
                            "radius": r, "orientation": [r4(c) for c in quat_about([0, 0, 1], rng.uniform(0, 6.28))]})
    mesh = write_mesh(sm.sphere(r, 10, 18, squash=0.95, dimple=0.12), "plum", "a plum of radius 0.5")
    write_exemplar("plum_stack_3d", 3, [6.0, r4(size[1]), 2.6], [{"name": "plum", "color": PLUM, "mesh": mesh}], els,
                   "Plums (radius 0.5) in three hexagonal layers on a floor at z = 0, the top layer "
                   "uneven; periodic in x and y.")


def pebbles_3d():
    """Figure 13 (pebble sculpture): flattened pebbles of a few sizes, randomly turned, packed."""
    rng = random.Random(32)
    size = [5.0, 5.0, 5.0]
    place = Placer(size, (True, True, True), 0.8)
    shapes = []
    for k, (a, b, c) in enumerate([(0.36, 0.26, 0.18), (0.3, 0.24, 0.16), (0.26, 0.2, 0.15)]):
        shapes.append(("pebble%d" % k, a, b, c))
    types = [{"name": n, "color": PEBBLES[k], "mesh": write_mesh(sm.ellipsoid(a, b, c, 8, 14), n, "a pebble")}
             for k, (n, a, b, c) in enumerate(shapes)]
    els = []
    for _ in range(40000):
        n, a, b, c = shapes[rng.randrange(len(shapes))]
        p = [rng.uniform(0, s) for s in size]
        rad = (a + b) / 2 * 0.95
        if place.fits([p], rad):
            place.add([p], rad)
            els.append({"type": n, "position": [r4(x) for x in p], "radius": r4(a),
                        "orientation": [r4(x) for x in random_quat(rng)]})
    # The sculpture: a chess-pawn-like solid of revolution, 10 units tall.
    profile = [(0, 0), (2.6, 0), (2.6, 0.6), (2.0, 1.0), (1.3, 1.6), (1.0, 3.5), (0.9, 5.5), (1.9, 6.2),
               (1.9, 6.6), (1.2, 7.0), (1.9, 8.0), (2.1, 9.0), (1.8, 10.0), (1.0, 10.6), (0, 10.8)]
    sm.revolve(profile, 48).transformed(lambda p: (p[0] + 3, p[1] + 3, p[2])).write_obj(
        os.path.join(HERE, "sculpture.obj"), "a pawn-like sculpture, 10.8 units tall")
    write_exemplar("pebbles_3d", 3, size, types, els,
                   "Flattened pebbles of three sizes, randomly turned, packed by dart throwing in a "
                   "periodic 5^3 window (%d pebbles)." % len(els))


def dish_3d():
    """Figure 1/11 (a dish): corn kernels, carrot dice and green beans, mixed on a floor."""
    rng = random.Random(33)
    size = [4.0, 4.0, 2.4]
    per = (True, True, False)
    place = Placer(size, per, 0.6)
    bean_ref = [[-0.28, -0.03, 0.0], [0.0, 0.06, 0.0], [0.28, -0.03, 0.0]]
    types = [
        {"name": "corn", "color": "#f2c230", "mesh": write_mesh(sm.sphere(0.15, 8, 12, squash=0.75), "corn", "a corn kernel")},
        {"name": "carrot", "color": "#e8731c", "mesh": write_mesh(sm.box(0.3, 0.3, 0.3), "carrot_dice", "a carrot dice")},
        {"name": "bean", "color": "#5d9b3a", "rigid": True,
         "mesh": write_mesh(sm.tube(sm.subdivide_polyline(bean_ref, 4), [0.05, 0.09, 0.1, 0.11, 0.12, 0.11, 0.1, 0.09, 0.05], 10),
                            "bean", "a green bean, three samples long")},
    ]
    els = []
    pile = Depositor(size, 0.5)
    for _ in range(20000):
        kind = rng.choices(["corn", "carrot", "bean"], [0.5, 0.3, 0.2])[0]
        c = [rng.uniform(0, size[0]), rng.uniform(0, size[1]), 0.0]
        q = quat_mul(quat_about([0, 0, 1], rng.uniform(0, 6.283)), quat_about([1, 0, 0], rng.gauss(0, 0.2)))
        if kind == "bean":
            pts, rad = posed(bean_ref, q, c), 0.11
        else:
            pts, rad = [c], (0.15 if kind == "corn" else 0.2)
        pts = pile.drop(pts, rad)
        if any(p[2] > size[2] - rad for p in pts):
            continue  # the dish is full here
        pile.add(pts, rad)
        e = {"type": kind, "radius": rad, "orientation": [r4(x) for x in q]}
        if kind == "bean":
            e["samples"] = [[r4(x) for x in p] for p in pts]
        else:
            e["position"] = [r4(x) for x in pts[0]]
        els.append(e)
    # The bowl's inside: a spherical cap of radius 6.2 cut at 3.5 above its bottom.
    R, h = 6.2, 3.5
    profile = [(0, 0)]
    for k in range(1, 17):
        z = h * k / 16
        profile.append((math.sqrt(max(0.0, R * R - (R - z) ** 2)), z))
    profile.append((0, h))
    sm.revolve(profile, 48).transformed(lambda p: (p[0] + R, p[1] + R, p[2])).write_obj(
        os.path.join(HERE, "bowl.obj"), "the inside of a bowl (spherical cap, radius 6.2, depth 3.5)")
    write_exemplar("dish_3d", 3, size, types, els,
                   "A dish: corn kernels, carrot dice and three-sample green beans dropped one by one "
                   "into a settled pile on a floor (%d elements), periodic in x and y." % len(els))


def smooth_curve(rng, start, heading, length, samples, bend):
    """A smooth planar curve of `samples` points spaced length/(samples-1) with a slowly
    varying curvature (a cooked noodle)."""
    step = length / (samples - 1)
    pts = [list(start)]
    ang, curv = heading, rng.gauss(0, bend)
    for _ in range(samples - 1):
        curv = 0.8 * curv + rng.gauss(0, bend)
        ang += curv * step
        p = pts[-1]
        pts.append([p[0] + step * math.cos(ang), p[1] + step * math.sin(ang), p[2]])
    return pts


def spaghetti_3d():
    """Figure 11 (spaghetti): deformable strands of 24 samples in a loose layer."""
    rng = random.Random(34)
    n, length, rad = 24, 5.75, 0.06
    size = [9.0, 9.0, 0.7]
    place = Placer(size, (True, True, False), 0.4)
    els = []
    for _ in range(4000):
        z = rng.uniform(0.08, size[2] - 0.08)
        pts = smooth_curve(rng, [rng.uniform(0, 9), rng.uniform(0, 9), z], rng.uniform(0, 6.283), length, n, 0.35)
        for p in pts:
            p[2] += 0.04 * math.sin(3 * p[0])
        if not place.fits(pts, 0.09):
            continue
        place.add(pts, 0.09)
        els.append({"type": "noodle", "samples": [[r4(c) for c in p] for p in pts]})
        if len(els) >= 60:
            break
    reference = [[r4(-length / 2 + length * k / (n - 1)), 0.0, 0.0] for k in range(n)]
    mesh = sm.tube(sm.subdivide_polyline(reference, 3), [rad] * (3 * (n - 1) + 1), 8)
    types = [{"name": "noodle", "color": "#e6c35c", "rigid": False, "mesh": write_mesh(mesh, "noodle", "a straight noodle"),
              "reference": reference}]
    plate = sm.revolve([(0, 0), (9.5, 0), (10, 0.4), (10, 0.8), (0, 0.8)], 64)
    plate.transformed(lambda p: (p[0] + 10, p[1] + 10, p[2])).write_obj(
        os.path.join(HERE, "plate.obj"), "a plate's volume: radius 10, 0.8 deep")
    write_exemplar("spaghetti_3d", 3, size, types, els,
                   "Spaghetti: %d deformable strands of 24 samples (length 5.75), curved at random, "
                   "lying in a layer 0.7 deep; periodic in x and y." % len(els))


def bananas_3d():
    """Figure 1 (bananas): rigid curved fruit of 5 samples lying in a pile."""
    rng = random.Random(35)
    size = [7.0, 7.0, 1.4]
    place = Placer(size, (True, True, False), 0.5)
    ref = []
    for k in range(5):
        a = (k / 4 - 0.5) * 1.1  # an arc of radius 1.6 spanning 63 degrees
        ref.append([1.6 * math.sin(a), 1.6 * (1 - math.cos(a)) - 0.16, 0.0])
    fine = []
    for k in range(17):
        a = (k / 16 - 0.5) * 1.1
        fine.append([1.6 * math.sin(a), 1.6 * (1 - math.cos(a)) - 0.16, 0.0])
    radii = [0.05 + 0.13 * math.sin(math.pi * (0.05 + 0.9 * k / 16)) for k in range(17)]
    types = [{"name": "banana", "color": "#f2d13a", "mesh": write_mesh(sm.tube(fine, radii, 10), "banana", "a banana")}]
    els = []
    for _ in range(30000):
        c = [rng.uniform(0, size[0]), rng.uniform(0, size[1]), rng.uniform(0.16, size[2] - 0.16)]
        q = quat_mul(quat_about([0, 0, 1], rng.uniform(0, 6.283)), quat_about([1, 0, 0], rng.uniform(-0.6, 0.6)))
        pts = posed(ref, q, c)
        if any(not (0.12 <= p[2] <= size[2] - 0.12) for p in pts) or not place.fits(pts, 0.15):
            continue
        place.add(pts, 0.15)
        els.append({"type": "banana", "samples": [[r4(x) for x in p] for p in pts],
                    "orientation": [r4(x) for x in q]})
    write_exemplar("bananas_3d", 3, size, types, els,
                   "Bananas: rigid curved fruit of 5 samples (an arc 1.76 long) in a loose pile on a "
                   "floor (%d bananas); periodic in x and y." % len(els))


def carrots_2d():
    """Figure 10 (carrots in a tai-chi field): rigid 3-sample carrots, mostly along +x."""
    rng = random.Random(36)
    size = [8.0, 8.0]
    place = Placer(size, (True, True), 0.6)
    ref = [[-0.45, 0.0], [0.0, 0.0], [0.45, 0.0]]
    cone = [[-0.55 + 1.1 * k / 8, 0.0, 0.0] for k in range(9)]
    radii = [0.03 + 0.14 * (k / 8) ** 0.7 for k in range(9)]
    types = [{"name": "carrot", "color": "#e8731c", "mesh": write_mesh(sm.tube(cone, radii, 10), "carrot", "a carrot, tip at -x")}]
    els = []
    for _ in range(30000):
        c = [rng.uniform(0, 8), rng.uniform(0, 8)]
        a = rng.gauss(0, 0.12)
        pts = [[c[0] + p[0] * math.cos(a), c[1] + p[0] * math.sin(a)] for p in ref]
        if not place.fits(pts, 0.2):
            continue
        place.add(pts, 0.2)
        els.append({"type": "carrot", "samples": [[r4(x) for x in p] for p in pts], "angle": r4(a)})
    write_exemplar("carrots_2d", 2, size, types, els,
                   "Carrots: rigid 3-sample elements (length 0.9) heading along +x with small turns "
                   "(%d carrots); periodic." % len(els))
    # The tai-chi field on a 64^2 grid over [0, 24]^2: the flow along the level sets of a stream
    # function with two opposite eddies inside a circulating disk (the yin-yang's S-curve).
    n, h, c = 65, 24.0 / 64, 12.0
    vectors = []
    for j in range(n):
        for i in range(n):
            x, y = i * h - c, j * h - c
            # psi = outer circulation + eddy at (0, +5) - eddy at (0, -5)
            def grad(xx, yy):
                e1 = math.exp(-((xx) ** 2 + (yy - 5) ** 2) / 18.0)
                e2 = math.exp(-((xx) ** 2 + (yy + 5) ** 2) / 18.0)
                gx = 0.02 * xx * 2 - 9 * (xx / 9.0) * e1 + 9 * (xx / 9.0) * e2
                gy = 0.02 * yy * 2 - 9 * ((yy - 5) / 9.0) * e1 + 9 * ((yy + 5) / 9.0) * e2
                return gx, gy
            gx, gy = grad(x, y)
            v = (-gy, gx)  # the flow is perpendicular to the gradient
            l = math.hypot(*v) or 1.0
            vectors.append([r4(v[0] / l), r4(v[1] / l)])
    with open(os.path.join(HERE, "taichi_field.json"), "w") as f:
        json.dump({"format": "tessera-field", "dimension": 2, "origin": [0, 0], "spacing": [h, h],
                   "size": [n, n], "vectors": vectors}, f, separators=(",", ":"))
        f.write("\n")
    disk = [[r4(c + 11.5 * math.cos(2 * math.pi * k / 96)), r4(c + 11.5 * math.sin(2 * math.pi * k / 96))]
            for k in range(96)]
    with open(os.path.join(HERE, "taichi_disk.json"), "w") as f:
        json.dump({"type": "polygon", "outer": disk}, f)
        f.write("\n")


def bricks_3d():
    """Figure 13 (building shell): bricks in running bond, a one-brick-thick wall."""
    rng = random.Random(37)
    bl, bh, bd, gap = 0.5, 0.22, 0.24, 0.04
    size = [6.0, 8 * (bh + gap), bd]
    els = []
    for row in range(8):
        y = (row + 0.5) * (bh + gap)
        for i in range(12):
            x = (i + 0.5 + 0.5 * (row % 2)) * (bl + gap * 0.92) % size[0]
            els.append({"type": "brick", "position": [r4(x + rng.gauss(0, 0.01)), r4(y + rng.gauss(0, 0.01)), r4(bd / 2)],
                        "radius": r4(bh / 2)})
    types = [{"name": "brick", "color": "#a4452c", "mesh": write_mesh(sm.box(bl, bh, bd), "brick", "a brick")}]
    house = sm.convex_prism_house(8.0, 6.0, 4.0, 6.5).transformed(lambda p: (p[0] + 5, p[1] + 4, p[2]))
    house.write_obj(os.path.join(HERE, "house.obj"), "a house with a gable roof")
    # The field on the house: per face (vertices not shared), x = horizontal along the face,
    # z = the face's outward normal. ASCII PLY with vx, vy, vz.
    verts, faces = [], []
    for a, b, c in house.f:
        pa, pb, pc = house.v[a], house.v[b], house.v[c]
        nrm = sm.cross([pb[k] - pa[k] for k in range(3)], [pc[k] - pa[k] for k in range(3)])
        l = math.sqrt(sm.dot(nrm, nrm))
        nrm = [x / l for x in nrm]
        d = sm.cross([0, 0, 1], nrm)
        if math.sqrt(sm.dot(d, d)) < 1e-6:
            d = [1, 0, 0]
        l = math.sqrt(sm.dot(d, d))
        d = [x / l for x in d]
        base = len(verts)
        verts += [(p, d) for p in (pa, pb, pc)]
        faces.append((base, base + 1, base + 2))
    with open(os.path.join(HERE, "house_field.ply"), "w") as f:
        f.write("ply\nformat ascii 1.0\ncomment horizontal directions on the house's faces\n")
        f.write("element vertex %d\nproperty float x\nproperty float y\nproperty float z\n" % len(verts))
        f.write("property float vx\nproperty float vy\nproperty float vz\n")
        f.write("element face %d\nproperty list uchar int vertex_indices\nend_header\n" % len(faces))
        for p, d in verts:
            f.write("%.5f %.5f %.5f %.5f %.5f %.5f\n" % (tuple(p) + tuple(d)))
        for a, b, c in faces:
            f.write("3 %d %d %d\n" % (a, b, c))
    write_exemplar("bricks_3d", 3, [r4(x) for x in size], types, els,
                   "Bricks in running bond: a wall one brick (0.24) thick, 8 courses; periodic in x "
                   "and y.")


if __name__ == "__main__":
    os.makedirs(MESHES, exist_ok=True)
    plum_stack_3d()
    pebbles_3d()
    dish_3d()
    spaghetti_3d()
    bananas_3d()
    carrots_2d()
    bricks_3d()
