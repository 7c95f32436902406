#!/usr/bin/env python3
"""Writes the exemplars of the PCF method (docs/pcf.md) under examples/pcf/: multi-class
distributions of points and disks in the spirit of the figures of Ecormier-Nocca et al.,
"Accurate Synthesis of Multi-Class Disk Distributions" (2019).

Each is built by random sequential placement with per-class acceptance rules (the rules
are the "ecology" of the scene), so the files are deterministic (fixed seeds) and the
script needs only the standard library: python3 examples/pcf_examples.py.
Types carry "depends_on" (the dependency graph of section 3.2) where the scene has one.
"""
import json
import math
import os
import random

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "pcf")


# Colours of the classes in pictures ("color" of a type, docs/format.md) where the name is
# not a colour already (clustered_four's classes are named after theirs).
COLORS = {
    "tree": "#2e7d32", "mushroom": "#b5651d", "grass": "#9acd32",
    "large": "#1f4e79", "medium": "#2e75b6", "small": "#5b9bd5", "tiny": "#9dc3e6",
    "plate": "#c8c2b4", "bowl": "#7fa7c4", "glass": "#a8dcea", "food": "#c76b29", "candy": "#e0529c",
    "oak": "#556b2f", "pine": "#1b4d3e", "birch": "#d8cfa8", "hazel": "#8e6b3e", "holly": "#b22222",
    "fern": "#4f9a3f", "heather": "#9b5f9e", "moss": "#8a9a5b",
}


def r4(v):
    return round(v, 4)


class Scene:
    def __init__(self, size, seed):
        self.size = size
        self.rng = random.Random(seed)
        self.disks = []  # (x, y, r, class)

    def near(self, x, y, reach, cls=None):
        for d in self.disks:
            if (cls is None or d[3] == cls) and math.hypot(d[0] - x, d[1] - y) < reach + d[2]:
                yield d

    def place(self, cls, count, radius, accept, tries=200000, margin=None):
        """Random sequential placement: up to `count` disks of class `cls` whose radius is
        drawn by radius(rng) and whose position passes accept(x, y, r)."""
        placed = 0
        m = 0.0 if margin is None else margin
        for _ in range(tries):
            if placed >= count:
                break
            r = radius(self.rng)
            x = self.rng.uniform(m, self.size[0] - m)
            y = self.rng.uniform(m, self.size[1] - m)
            if accept(x, y, r):
                self.disks.append((x, y, r, cls))
                placed += 1
        return placed

    def write(self, name, classes, description, depends=None):
        types = []
        for c in classes:
            t = {"name": c}
            if c in COLORS:
                t["color"] = COLORS[c]
            if depends is not None and c in depends:
                t["depends_on"] = depends[c]
            types.append(t)
        doc = {"format": "tessera", "version": 1, "description": description, "dimension": 2,
               "domain": {"type": "box", "min": [0.0, 0.0], "max": list(self.size)}, "types": types,
               "elements": [{"type": c, "position": [r4(x), r4(y)], "radius": r4(r)} for x, y, r, c in self.disks]}
        with open(os.path.join(HERE, name + ".json"), "w") as f:
            json.dump(doc, f, indent=0)
            f.write("\n")
        counts = {c: sum(1 for d in self.disks if d[3] == c) for c in classes}
        print(name, len(self.disks), counts)


def clear_of(scene, x, y, r, cls, gap=0.0):
    """No disk of class `cls` within r + its radius + gap."""
    return not any(math.hypot(d[0] - x, d[1] - y) < r + d[2] + gap for d in scene.near(x, y, r + gap + 20, cls))


def toy_forest():
    """Figure 1: trees; mushrooms in the shade near the border of tree canopies; grass only in
    the sun. Mushrooms and grass depend on the trees (5 PCFs)."""
    s = Scene((100.0, 100.0), 41)
    s.place("tree", 26, lambda g: g.uniform(6.0, 9.0),
            lambda x, y, r: all(math.hypot(d[0] - x, d[1] - y) > 0.85 * (r + d[2]) for d in s.near(x, y, r + 10, "tree")))

    def shaded_rim(x, y, r):
        trees = list(s.near(x, y, r, "tree"))
        if not trees or not clear_of(s, x, y, r, "mushroom", 1.0):
            return False
        # Near the border of a canopy, inside it: 0.65 to 0.95 of the tree's radius from its centre.
        return any(0.65 * d[2] < math.hypot(d[0] - x, d[1] - y) < 0.95 * d[2] for d in trees)

    s.place("mushroom", 60, lambda g: g.uniform(0.8, 1.2), shaded_rim)

    def sunny(x, y, r):
        return not any(math.hypot(d[0] - x, d[1] - y) < d[2] + r for d in s.near(x, y, r, "tree")) and \
            clear_of(s, x, y, r, "grass", 1.6)

    s.place("grass", 375, lambda g: g.uniform(0.6, 1.0), sunny)
    s.write("toy_forest", ["tree", "mushroom", "grass"],
            "Toy forest (Figure 1): trees; mushrooms in the shade near the rim of tree canopies; "
            "grass only in the sun. Mushrooms and grass depend on trees.",
            {"mushroom": ["tree"], "grass": ["tree"]})


def clustered_four():
    """Figure 4: red points cluster around isolated cyan points, green around isolated purple
    points; cyan and purple repel each other. 7 PCFs (4 within, 3 edges)."""
    s = Scene((100.0, 100.0), 42)
    s.place("cyan", 12, lambda g: 0.0, lambda x, y, r: clear_of(s, x, y, 0, "cyan", 18), margin=5)
    s.place("purple", 12, lambda g: 0.0,
            lambda x, y, r: clear_of(s, x, y, 0, "cyan", 14) and clear_of(s, x, y, 0, "purple", 18), margin=5)

    def around(centre):
        def ok(x, y, r):
            return any(math.hypot(d[0] - x, d[1] - y) < 6.0 for d in s.near(x, y, 6.0, centre)) and \
                clear_of(s, x, y, 0, "red", 1.2) and clear_of(s, x, y, 0, "green", 1.2)
        return ok

    s.place("red", 72, lambda g: 0.0, around("cyan"))
    s.place("green", 72, lambda g: 0.0, around("purple"))
    s.write("clustered_four", ["cyan", "purple", "red", "green"],
            "Four classes (Figure 4): red clusters around isolated cyan points, green around isolated "
            "purple points; cyan and purple repel. Points (radius 0).",
            {"cyan": [], "purple": ["cyan"], "red": ["cyan"], "green": ["purple"]})


def droplets():
    """Figure 12 (top): water droplets in 4 size classes that never overlap; a chain of
    dependencies from the largest to the smallest."""
    s = Scene((100.0, 100.0), 43)
    sizes = [("large", 3.6, 4.4, 22), ("medium", 2.0, 2.6, 60), ("small", 1.1, 1.5, 150), ("tiny", 0.5, 0.8, 330)]
    for name, lo, hi, n in sizes:
        s.place(name, n, lambda g, lo=lo, hi=hi: g.uniform(lo, hi),
                lambda x, y, r: clear_of(s, x, y, r, None, 0.4), margin=1)
    names = [t[0] for t in sizes]
    s.write("droplets", names,
            "Water droplets in 4 size classes, never overlapping (at least 0.4 apart); each class "
            "depends on the next larger one.",
            {names[i]: [names[i - 1]] for i in range(1, 4)} | {names[0]: []})


def table_set():
    """Figure 12 (middle): plates on a table, a glass touching each plate, a bowl beside half of
    the plates (chosen at random), food items inside plates, candies anywhere (may overlap
    anything). As in the paper's description, glasses, bowls and plates may touch but do not
    overlap, food overlaps (lies in) plates, candies may overlap anything.

    Bowls used to be nested on the first half of the plates placed. Those are the most spread
    out ones, so the 7 bowls' own PCF said "never on neighbouring plates"; at 4x the area the
    bowls then had to sit on a near-maximal set of pairwise distant plates, which the greedy
    initialisation of Algorithm 1 does not find, and the bowls left over landed beside the
    plates, outside the nested envelope every exemplar bowl is in (docs/pcf_synthesis.md,
    known limitations)."""
    s = Scene((160.0, 100.0), 44)
    s.place("plate", 16, lambda g: g.uniform(9.5, 10.5), lambda x, y, r: clear_of(s, x, y, r, "plate", 8.0), margin=11)
    plates = [d for d in s.disks if d[3] == "plate"]
    for x, y, r, _ in plates:  # a glass touching each plate, up and to the right
        a = s.rng.uniform(0.6, 1.1)
        gr = s.rng.uniform(2.6, 3.2)
        s.disks.append((x + (r + gr + 0.2) * math.cos(a), y + (r + gr + 0.2) * math.sin(a), gr, "glass"))
    order = list(range(len(plates)))
    s.rng.shuffle(order)
    bowls = 0
    for k in order:  # a bowl touching a random half of the plates, on the left, clear of everything
        if bowls == len(plates) // 2:
            break
        x, y, r, _ = plates[k]
        for _ in range(50):
            a = s.rng.uniform(2.4, 3.9)
            br = s.rng.uniform(4.0, 4.8)
            bx, by = x + (r + br + 0.2) * math.cos(a), y + (r + br + 0.2) * math.sin(a)
            inside = br < bx < s.size[0] - br and br < by < s.size[1] - br
            if inside and all(math.hypot(d[0] - bx, d[1] - by) > d[2] + br + 0.1 for d in s.disks):
                s.disks.append((bx, by, br, "bowl"))
                bowls += 1
                break

    def on_plate(x, y, r):
        inside = any(math.hypot(d[0] - x, d[1] - y) < d[2] - r for d in plates)
        return inside and clear_of(s, x, y, r, "food", 0.2)

    s.place("food", 80, lambda g: g.uniform(1.5, 2.2), on_plate)
    s.place("candy", 50, lambda g: g.uniform(0.8, 1.1), lambda x, y, r: clear_of(s, x, y, r, "candy", 2.0))
    s.write("table_set", ["plate", "bowl", "glass", "food", "candy"],
            "A table set: plates; a glass touching each plate; a bowl beside half of them; food "
            "inside plates; candies anywhere.",
            {"plate": [], "bowl": ["plate"], "glass": ["plate", "bowl"], "food": ["plate", "bowl"],
             "candy": ["plate"]})


def dense_ecosystem():
    """Figure 10: 9 species, about 2,300 plants with overlapping canopies. Canopy trees may
    overlap a little; understorey species prefer shade or sun; shrubs and herbs fill in.
    The full hierarchy (every species depends on all larger ones: 45 PCFs)."""
    s = Scene((200.0, 200.0), 45)
    species = [
        # name, radius range, count, rule
        ("oak", (7.0, 10.0), 70, "canopy"),
        ("pine", (5.0, 7.0), 90, "canopy"),
        ("birch", (3.5, 5.0), 140, "gap"),
        ("hazel", (2.5, 3.5), 220, "shade"),
        ("holly", (2.0, 2.8), 200, "shade"),
        ("fern", (1.2, 1.8), 400, "shade"),
        ("heather", (1.0, 1.5), 450, "sun"),
        ("grass", (0.6, 1.0), 500, "sun"),
        ("moss", (0.4, 0.7), 300, "any"),
    ]
    canopy = ("oak", "pine")

    def shade(x, y):
        return any(math.hypot(d[0] - x, d[1] - y) < d[2] for d in s.near(x, y, 0, None) if d[3] in canopy)

    for name, (lo, hi), n, rule in species:
        def ok(x, y, r, name=name, rule=rule):
            if rule == "canopy":
                return all(math.hypot(d[0] - x, d[1] - y) > 0.8 * (r + d[2]) for d in s.near(x, y, r + 10, None)
                           if d[3] in canopy)
            if not clear_of(s, x, y, r, name, 0.3):
                return False
            if rule == "gap":
                return not shade(x, y)
            if rule == "shade":
                return shade(x, y)
            if rule == "sun":
                return not shade(x, y) and all(math.hypot(d[0] - x, d[1] - y) > d[2] + r
                                               for d in s.near(x, y, r + 6, "birch"))
            return True
        s.place(name, n, lambda g, lo=lo, hi=hi: g.uniform(lo, hi), ok, tries=120000)
    names = [t[0] for t in species]
    s.write("dense_ecosystem", names,
            "A dense ecosystem (Figure 10): 9 species with overlapping canopies; understorey species "
            "in shade or sun. Full hierarchy: every species depends on all earlier (larger) ones.")


def wide_radii():
    """Disks whose radii span two orders of magnitude: a few large disks (radius 6 to 10),
    medium ones (1.5 to 2.5) between them and many small ones (0.06 to 0.12) filling the
    space left, none overlapping. A hole several large disks wide or clumped small disks
    show at once; each class depends on the larger ones (the default chain)."""
    s = Scene((100.0, 100.0), 47)
    s.place("large", 14, lambda g: g.uniform(6.0, 10.0), lambda x, y, r: clear_of(s, x, y, r, "large", 4.0))
    s.place("medium", 60, lambda g: g.uniform(1.5, 2.5),
            lambda x, y, r: clear_of(s, x, y, r, "large", 0.5) and clear_of(s, x, y, r, "medium", 2.0))
    s.place("small", 420, lambda g: g.uniform(0.06, 0.12),
            lambda x, y, r: clear_of(s, x, y, r, "large", 0.3) and clear_of(s, x, y, r, "medium", 0.3) and
            clear_of(s, x, y, r, "small", 2.2))
    s.write("wide_radii", ["large", "medium", "small"],
            "Disks with radii over two orders of magnitude (0.06 to 10): large, medium and small, "
            "never overlapping; small disks fill the space between the larger ones.")


if __name__ == "__main__":
    os.makedirs(HERE, exist_ok=True)
    toy_forest()
    clustered_four()
    droplets()
    table_set()
    dense_ecosystem()
    wide_radii()
