"""Writes the brushing examples' exemplars (docs/brush.md, "Examples"):

strands_3d.json  deformable 6-sample strands in a 6x6x6 box, laid along +x with a gentle bend
                 each, on a jittered lattice: the elements that fill a volume along a field
                 (the paper's Figure 1c).

twigs_3d.json    rigid 3-sample twigs in one layer (8x8, 0.3 thick), mostly along +x: a layered
                 exemplar, which a surface canvas lays into the tangent plane (docs/det.md,
                 "Layered exemplars").
vines_3d.json    deformable 6-sample vines in one layer, bending gently in the layer's plane.
surface_3d.json  the session of the paper's Figure 1b: a collage of twigs and vines on the surface
                 of ../blob.obj, painted along two strokes, a direction stroke, the rest filled.

Run from this folder: python3 make_examples.py (deterministic: a fixed seed).
"""
import json
import math
import random


def strands(seed=7):
    rng = random.Random(seed)
    elements = []
    size, step, length = 6.0, 1.0, 6
    for j in range(5):
        for k in range(5):
            for i in range(2):
                x0 = 0.3 + i * 3.0 + rng.uniform(-0.2, 0.2)
                y0 = 0.7 + j * 1.15 + rng.uniform(-0.15, 0.15)
                z0 = 0.7 + k * 1.15 + rng.uniform(-0.15, 0.15)
                bend, phase = rng.uniform(0.05, 0.2), rng.uniform(0, 2 * math.pi)
                samples = []
                for s in range(length):
                    t = s / (length - 1)
                    samples.append([round(x0 + s * 0.48, 4),
                                    round(y0 + bend * math.sin(math.pi * t + phase), 4),
                                    round(z0 + bend * math.cos(math.pi * t + phase), 4)])
                elements.append({"type": "strand", "samples": samples})
    return {
        "format": "tessera", "version": 1, "dimension": 3,
        "domain": {"type": "box", "min": [0, 0, 0], "max": [size, size, size]},
        "types": [{"name": "strand", "rigid": False, "color": "#c0504d"}],
        "elements": elements,
    }


def layer(name, rigid, color, elements, size=8.0, thickness=0.3):
    return {
        "format": "tessera", "version": 1, "dimension": 3,
        "domain": {"type": "box", "min": [0, 0, 0], "max": [size, size, thickness]},
        "types": [{"name": name, "rigid": rigid, "color": color}],
        "elements": [{"type": name, "samples": s} for s in elements],
    }


def twigs(seed=11):
    """Rigid twigs 0.8 long on a jittered lattice (1.1 along x, 0.55 across), turned by up to
    10 degrees, in the layer's mid-plane z = 0.15."""
    rng = random.Random(seed)
    out = []
    for j in range(14):
        for i in range(7):
            cx = 0.6 + i * 1.1 + rng.uniform(-0.1, 0.1) + (0.55 if j % 2 else 0.0)
            cy = 0.4 + j * 0.55 + rng.uniform(-0.05, 0.05)
            if cx > 7.6:
                continue
            a = math.radians(rng.uniform(-10, 10))
            out.append([[round(cx + t * math.cos(a), 4), round(cy + t * math.sin(a), 4), 0.15]
                        for t in (-0.4, 0.0, 0.4)])
    return layer("twig", True, "#8c564b", out)


def vines(seed=5):
    """Deformable vines of 6 samples 0.4 apart (2 long), rows 0.6 apart, each bent gently
    in the layer's plane."""
    rng = random.Random(seed)
    out = []
    for j in range(13):
        for i in range(3):
            x0 = 0.3 + i * 2.6 + rng.uniform(-0.15, 0.15) + (1.3 if j % 2 else 0.0)
            y0 = 0.4 + j * 0.6 + rng.uniform(-0.05, 0.05)
            if x0 + 2.0 > 7.9:
                continue
            bend, phase = rng.uniform(0.03, 0.12), rng.uniform(0, 2 * math.pi)
            out.append([[round(x0 + s * 0.4, 4), round(y0 + bend * math.sin(math.pi * s / 5 + phase), 4), 0.15]
                        for s in range(6)])
    return layer("vine", False, "#2ca02c", out)


def sphere_point(centre, radius, latitude, longitude):
    """The point of a sphere at `latitude` and `longitude` (radians), rounded to 3 decimals."""
    return [round(centre[0] + radius * math.cos(latitude) * math.cos(longitude), 3),
            round(centre[1] + radius * math.cos(latitude) * math.sin(longitude), 3),
            round(centre[2] + radius * math.sin(latitude), 3)]


def arc(centre, radius, start, end, steps, tilt=0.0):
    """Points of a circle of latitude `tilt` (radians) on a sphere, from angle start to end
    (degrees): the canvas moves them onto the blob's surface."""
    return [sphere_point(centre, radius, tilt, math.radians(start + (end - start) * k / steps))
            for k in range(steps + 1)]


def meridian(centre, radius, azimuth, start, end, steps):
    """A great circle through the poles at `azimuth` (degrees), latitudes start to end."""
    return [sphere_point(centre, radius, math.radians(start + (end - start) * k / steps), math.radians(azimuth))
            for k in range(steps + 1)]


def surface_session():
    centre, r = (6.0, 5.3, 6.0), 6.5
    return {
        "format": "tessera-brush", "version": 1,
        "canvas": "surface:../blob.obj",
        "palette": {"twigs": "twigs_3d.json", "vines": "vines_3d.json"},
        "options": {"seed": 4, "iterations": 6},
        "ops": [
            {"op": "paint", "palette": "vines", "stroke": arc(centre, r, -60, 150, 14, 0.15), "width": 2.5},
            {"op": "paint", "palette": "twigs", "stroke": meridian(centre, r, 250, -60, 70, 10), "width": 2.5},
            {"op": "direction", "stroke": arc(centre, r, 160, 300, 10, -0.6)},
            {"op": "fill"},
        ],
    }


if __name__ == "__main__":
    for name, data in [("strands_3d.json", strands()), ("twigs_3d.json", twigs()), ("vines_3d.json", vines()),
                       ("surface_3d.json", surface_session())]:
        with open(name, "w") as f:
            json.dump(data, f, indent=1)
