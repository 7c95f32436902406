#!/usr/bin/env python3
"""Writes the built-in exemplars of examples/ (tessera native JSON).

Deterministic (fixed seeds) and standard-library only, so the files can be
regenerated anywhere: python3 examples/generate.py. The JSON files are committed;
this script documents how they were made.
"""
import json
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
# Colours of the classes in pictures ("color" of a type, docs/format.md) where the name is not
# a colour already; CSS's "plum" is a pale lilac, so the plums get the fruit's dark purple.
PLUM = "#6a3d7a"
NOODLE = "#e0b84f"  # cooked-noodle yellow


def write(name, dimension, domain_max, types, elements, description):
    doc = {
        "format": "tessera",
        "version": 1,
        "description": description,
        "dimension": dimension,
        "domain": {"type": "box", "min": [0.0] * dimension, "max": domain_max},
        "types": types,
        "elements": elements,
    }
    with open(os.path.join(HERE, name + ".json"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def r4(v):
    return round(v, 4)


def dart_throw(rng, size, min_dist, count, tries=200000, existing=()):
    """Poisson-disk points by dart throwing (torus-free, plain box)."""
    pts = list(existing)
    for _ in range(tries):
        if len(pts) >= count:
            break
        p = [rng.uniform(0, s) for s in size]
        if all(math.dist(p, q[:len(p)]) >= min_dist for q in pts):
            pts.append(p)
    return pts[len(existing):]


def poisson_disk_2d():
    rng = random.Random(11)
    pts = dart_throw(rng, [10, 10], 0.8, 110)
    write("poisson_disk_2d", 2, [10, 10], [{"name": "dot"}],
          [{"type": "dot", "position": [r4(x), r4(y)], "radius": 0.3} for x, y in pts],
          "Poisson-disk points (dart throwing, minimum distance 0.8) in a 10 x 10 box.")


def hex_jittered_2d():
    rng = random.Random(12)
    a = 1.0
    els = []
    rows = int(10 / (a * math.sqrt(3) / 2))
    for j in range(rows):
        for i in range(11):
            x = (i + 0.5 * (j % 2) + 0.25) * a + rng.gauss(0, 0.05 * a)
            y = (j + 0.5) * a * math.sqrt(3) / 2 + rng.gauss(0, 0.05 * a)
            if 0 <= x <= 10 and 0 <= y <= 10:
                els.append({"type": "plum", "position": [r4(x), r4(y)], "radius": 0.45})
    write("hex_jittered_2d", 2, [10, 10], [{"name": "plum", "color": PLUM}], els,
          "Hexagonal lattice of spacing 1 with Gaussian jitter (sd 0.05) in a 10 x 10 box.")


def two_class_2d():
    rng = random.Random(13)
    big = dart_throw(rng, [10, 10], 2.0, 22)
    els = [{"type": "stone", "position": [r4(x), r4(y)], "radius": 0.7} for x, y in big]
    small = []
    for _ in range(200000):
        if len(small) >= 90:
            break
        p = [rng.uniform(0, 10), rng.uniform(0, 10)]
        if all(math.dist(p, q) >= 1.15 for q in big) and all(math.dist(p, q) >= 0.55 for q in small):
            small.append(p)
    els += [{"type": "pebble", "position": [r4(x), r4(y)], "radius": 0.22} for x, y in small]
    write("two_class_2d", 2, [10, 10], [{"name": "stone", "color": "#8a8580"}, {"name": "pebble", "color": "#c9a66b"}],
          els,
          "Two classes: large stones (inhibition 2.0) and pebbles kept off the stones, in a 10 x 10 box.")


def sticks_2d():
    """5-sample sticks of length 1.2 in loose rows, mostly horizontal with tilt."""
    rng = random.Random(14)
    els = []
    centers = dart_throw(rng, [10, 10], 0.9, 120)
    placed = []
    size = [10.0, 10.0]
    for cx, cy in centers:
        ang = rng.gauss(0.0, 0.25)
        length = 1.2
        pts = [[cx + (t / 4 - 0.5) * length * math.cos(ang), cy + (t / 4 - 0.5) * length * math.sin(ang)]
               for t in range(5)]
        # keep sticks apart (periodic window): sample distance >= 0.3 from earlier sticks
        if any(math.sqrt(sum(x * x for x in periodic_delta(p, q, size, (True, True)))) < 0.3
               for p in pts for s in placed for q in s):
            continue
        placed.append(pts)
        els.append({"type": "stick", "samples": [[r4(x), r4(y)] for x, y in pts]})
    write("sticks_2d", 2, [10, 10], [{"name": "stick", "rigid": True, "color": "#a0703c"}], els,
          "Rigid sticks of 5 samples (length 1.2), mostly horizontal; centroids in a 10 x 10 window "
          "of a periodic pattern, so sticks may reach past the window's sides.")


def periodic_delta(a, b, size, periodic):
    d = [a[k] - b[k] for k in range(len(a))]
    for k in range(len(a)):
        if periodic[k]:
            d[k] -= size[k] * round(d[k] / size[k])
    return d


def relax_spheres(pts, radius, size, steps=300):
    """Soft-sphere repulsion in a periodic box until no pair overlaps by more than 1%."""
    d0 = 2 * radius
    n = len(pts)
    for _ in range(steps):
        worst = 0.0
        forces = [[0.0, 0.0, 0.0] for _ in range(n)]
        for i in range(n):
            for j in range(i + 1, n):
                d = periodic_delta(pts[i], pts[j], size, (True, True, True))
                dist2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
                if dist2 < d0 * d0:
                    dist = math.sqrt(dist2) or 1e-9
                    s = (d0 - dist) / dist * 0.5
                    worst = max(worst, d0 - dist)
                    for k in range(3):
                        forces[i][k] += d[k] * s
                        forces[j][k] -= d[k] * s
        for i in range(n):
            for k in range(3):
                pts[i][k] = (pts[i][k] + forces[i][k]) % size[k]
        if worst < 0.01 * d0:
            break
    return pts


def spheres_3d():
    """A random packing of equal spheres, periodic so that the window cuts a stationary pattern."""
    rng = random.Random(15)
    size = [6.2, 6.2, 6.2]
    radius = 0.5
    n = 240  # packing fraction about 0.53
    pts = [[rng.uniform(0, s) for s in size] for _ in range(n)]
    pts = relax_spheres(pts, radius, size)
    write("spheres_3d", 3, size, [{"name": "sphere"}],
          [{"type": "sphere", "position": [r4(c) for c in p], "radius": radius} for p in pts],
          "Dense random packing of 240 spheres of radius 0.5 (packing fraction 0.53), "
          "observed in a 6.2^3 window of a periodic packing.")


def rods_3d():
    """Rigid rods of 5 samples lying in layers on a floor: random heading, small tilt.
    Periodic in x and y, so the window cuts a stationary pattern; z is a real floor and ceiling."""
    rng = random.Random(16)
    size = [8.0, 8.0, 3.0]
    periodic = (True, True, False)
    els, placed = [], []
    for _ in range(100000):
        if len(els) >= 100:
            break
        c = [rng.uniform(0, size[0]), rng.uniform(0, size[1]), rng.uniform(0.25, size[2] - 0.25)]
        yaw = rng.uniform(0, math.pi)
        pitch = rng.gauss(0, 0.12)
        length = 1.6
        d = [math.cos(yaw) * math.cos(pitch), math.sin(yaw) * math.cos(pitch), math.sin(pitch)]
        pts = [[c[k] + (t / 4 - 0.5) * length * d[k] for k in range(3)] for t in range(5)]
        if any(not (0 <= p[2] <= size[2]) for p in pts):
            continue
        if any(math.sqrt(sum(x * x for x in periodic_delta(p, q, size, periodic))) < 0.45
               for p in pts for s in placed for q in s):
            continue
        placed.append(pts)
        els.append({"type": "rod", "samples": [[r4(x) for x in p] for p in pts]})
    write("rods_3d", 3, size, [{"name": "rod", "rigid": True}], els,
          "Rigid rods of 5 samples (length 1.6) with random heading and small tilt, centroids in an "
          "8 x 8 x 3 window (periodic in x and y, so rods may reach past the window's sides).")


def striped_dots_2d():
    """Figure 16 in spirit: small dots in a jittered square lattice, every third row of another
    kind; with striped_dots_2d_edit.json, `tessera edit` grows and shifts one dot of a special
    row and the change spreads to the dots with the same surroundings."""
    rng = random.Random(17)
    els = []
    for j in range(15):
        for i in range(15):
            kind = "accent" if j % 3 == 1 else "dot"
            x = i + 0.5 + rng.gauss(0, 0.03)
            y = j + 0.5 + rng.gauss(0, 0.03)
            els.append({"type": kind, "position": [r4(x), r4(y)], "radius": 0.15})
    write("striped_dots_2d", 2, [15, 15], [{"name": "dot"}, {"name": "accent"}], els,
          "Dots on a jittered square lattice (spacing 1), every third row of type 'accent'.")
    edit = {"element": 7 * 15 + 7, "offset": [0.0, 0.25], "radius": 0.3}
    with open(os.path.join(HERE, "striped_dots_2d_edit.json"), "w") as f:
        json.dump(edit, f)
        f.write("\n")


def plum_stack_2d():
    """A 2D stack of plums (disks of radius 0.5) in hexagonal rows resting on a floor at y = 0,
    with small jitter: the floor row must stay on the floor (`--floor-distance 0.6`)."""
    rng = random.Random(18)
    els = []
    for row in range(5):
        for i in range(12):
            x = 0.5 + i + 0.5 * (row % 2) + rng.gauss(0, 0.03)
            y = 0.5 + row * 0.866 + (0.0 if row == 0 else rng.gauss(0, 0.03))
            if x <= 11.8:
                els.append({"type": "plum", "position": [r4(x), r4(y)], "radius": 0.5})
    write("plum_stack_2d", 2, [12, 4.5], [{"name": "plum", "color": PLUM}], els,
          "Plums stacked in hexagonal rows on a floor (y = 0); the bottom row rests on it.")


def blob_mesh():
    """A closed triangle mesh (OBJ): a lumpy sphere of radius about 6 centred at (6, 6, 6), used
    as a 3D output domain (`--domain mesh:examples/blob.obj`)."""
    rings, segments = 24, 48
    verts = [(6.0, 6.0, 12.0)]
    for i in range(1, rings):
        th = math.pi * i / rings
        for j in range(segments):
            ph = 2 * math.pi * j / segments
            r = 6.0 * (1 + 0.12 * math.sin(3 * ph) * math.sin(th) ** 2 + 0.08 * math.cos(2 * th))
            verts.append((6 + r * math.sin(th) * math.cos(ph), 6 + r * math.sin(th) * math.sin(ph),
                          6 + r * math.cos(th)))
    verts.append((6.0, 6.0, 6.0 - 6.0 * 1.08))
    faces = []
    ring = lambda i, j: 1 + (i - 1) * segments + (j % segments)  # 0-based index of ring i (1..rings-1)
    for j in range(segments):
        faces.append((0, ring(1, j), ring(1, j + 1)))
    for i in range(1, rings - 1):
        for j in range(segments):
            a, b, c, d = ring(i, j), ring(i, j + 1), ring(i + 1, j), ring(i + 1, j + 1)
            faces.append((a, c, d))
            faces.append((a, d, b))
    last = len(verts) - 1
    for j in range(segments):
        faces.append((ring(rings - 1, j), last, ring(rings - 1, j + 1)))
    with open(os.path.join(HERE, "blob.obj"), "w") as f:
        f.write("# lumpy closed sphere, written by examples/generate.py\n")
        for v in verts:
            f.write("v %.5f %.5f %.5f\n" % v)
        for a, b, c in faces:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


def noodles_2d():
    """Deformable noodles of 8 samples (spacing 0.3) that bend gently, packed side by side
    without touching in a 12 x 12 window of a periodic pattern: a 2D exemplar of deformable
    multi-sample elements, whose outputs must neither tear nor leave holes."""
    rng = random.Random(19)
    size = [12.0, 12.0]
    placed, els = [], []
    for _ in range(60000):
        if len(placed) >= 70:
            break
        heading = rng.gauss(0.0, 0.35)  # mostly along x, like noodles combed one way
        p = [rng.uniform(0, size[0]), rng.uniform(0, size[1])]
        turn = rng.gauss(0.0, 0.12)
        pts = []
        for _t in range(8):
            pts.append(list(p))
            heading += turn + rng.gauss(0.0, 0.05)
            p = [p[0] + 0.3 * math.cos(heading), p[1] + 0.3 * math.sin(heading)]
        cx = sum(q[0] for q in pts) / 8
        cy = sum(q[1] for q in pts) / 8
        shift = [cx % size[0] - cx, cy % size[1] - cy]  # centroid inside the window
        pts = [[q[0] + shift[0], q[1] + shift[1]] for q in pts]
        if any(math.sqrt(sum(x * x for x in periodic_delta(a, b, size, (True, True)))) < 0.42
               for a in pts for s in placed for b in s):
            continue
        placed.append(pts)
        els.append({"type": "noodle", "samples": [[r4(x), r4(y)] for x, y in pts], "radius": 0.1})
    write("noodles_2d", 2, size, [{"name": "noodle", "rigid": False, "color": NOODLE}], els,
          "Deformable noodles of 8 samples (spacing 0.3), gently bent and mostly along x, packed "
          "without touching; centroids in a 12 x 12 window of a periodic pattern.")


def membrane_3d():
    """A lipid bilayer like the membranes of on-demand growth (seed 003, Figures 7-9): two
    leaflets of lipids (a head and a three-sample tail pointing to the mid-plane, slightly
    tilted), channel proteins spanning both leaflets (five samples on a vertical axis), and
    a few small molecules at the head groups: the rare class. Periodic in x and y."""
    rng = random.Random(31)
    size = [9.0, 9.0, 6.0]
    periodic = (True, True, False)
    mid = size[2] / 2

    def far(p, others, d):
        return all(math.sqrt(sum(x * x for x in periodic_delta(p, q, size, periodic))) >= d for q in others)

    els = []
    proteins = []
    for _ in range(10000):
        if len(proteins) >= 3:
            break
        c = [rng.uniform(0, size[0]), rng.uniform(0, size[1]), mid]
        if far(c, proteins, 3.6):
            proteins.append(c)
    for c in proteins:
        pts = [[c[0], c[1], mid + (t - 2) * 0.9] for t in range(5)]
        els.append({"type": "channel", "samples": [[r4(x) for x in p] for p in pts], "radius": 0.6})
    for side in (1, -1):
        heads = []
        for _ in range(200000):
            if len(heads) >= 100:
                break
            h = [rng.uniform(0, size[0]), rng.uniform(0, size[1]), mid + side * 1.9]
            if far([h[0], h[1], mid], proteins, 1.25) and far(h, heads, 0.78):
                heads.append(h)
        for h in heads:
            tilt, yaw = rng.gauss(0, 0.12), rng.uniform(0, 2 * math.pi)
            d = [math.sin(tilt) * math.cos(yaw), math.sin(tilt) * math.sin(yaw), -side * math.cos(tilt)]
            pts = [[h[k] + t * 0.55 * d[k] for k in range(3)] for t in range(4)]
            els.append({"type": "lipid", "samples": [[r4(x) for x in p] for p in pts], "radius": 0.3})
    heads = [e["samples"][0] for e in els if e["type"] == "lipid"]
    molecules = []
    for _ in range(100000):
        if len(molecules) >= 12:
            break
        side = rng.choice((1, -1))
        m = [rng.uniform(0, size[0]), rng.uniform(0, size[1]), mid + side * rng.uniform(2.5, 2.8)]
        if far(m, heads, 0.55) and far(m, molecules, 1.5):
            molecules.append(m)
    for m in molecules:
        els.append({"type": "molecule", "samples": [[r4(x) for x in m]], "radius": 0.2})
    write("membrane_3d", 3, size,
          [{"name": "lipid", "rigid": True, "color": "#e8d8a0"},
           {"name": "channel", "rigid": True, "color": "#3f7fbf"},
           {"name": "molecule", "rigid": True, "color": "#d04040"}], els,
          "A lipid bilayer in a 9 x 9 x 6 window (periodic in x and y): two leaflets of lipids of "
          "4 samples (head and tail toward the mid-plane z = 3), 3 channel proteins of 5 samples "
          "spanning both leaflets, 12 small molecules at the head groups (the rare class).")


if __name__ == "__main__":
    poisson_disk_2d()
    hex_jittered_2d()
    two_class_2d()
    sticks_2d()
    spheres_3d()
    rods_3d()
    striped_dots_2d()
    blob_mesh()
    plum_stack_2d()
    noodles_2d()
    membrane_3d()
