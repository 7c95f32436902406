"""Writes the dynamic examples' animated exemplars (docs/dynamic.md, "Examples"):

drifting_lattice_2d.json  a jittered hexagonal lattice (12 x 12, spacing 1) drifting at a
                          constant velocity, each particle also circling on its own phase:
                          a known steady motion (the tests build the same kind in code).
swirl_particles_2d.json   Poisson-disk particles (radius 0.5 exclusion, in 10 x 10) at rest
                          on average, each circling with a phase that varies smoothly in
                          space, so that neighbours swirl together: the detail motion that a
                          global flow carries past an obstacle in the demo.

fish_school_2d.json       a loose school of fish at rest on average, each darting along the
                          school's heading and weaving across it, for the demo's turning flow.

obstacle_channel.json     (written by hand) a polygon domain: a 30 x 15 channel with a round
                          obstacle of radius 2.5 at (10, 7.3), for the demo's particles
                          carried past it by a flow.

Run from this folder: python3 make_examples.py (deterministic: a fixed seed).
"""
import json
import math
import random


def write(path, description, dimension, box, types, tracks, dt):
    """types: names, or type objects; tracks: per element (type name, [position per frame])."""
    frames = len(tracks[0][1])
    lines = ['{"format": "tessera", "version": 1, "dimension": %d,' % dimension,
             ' "description": %s,' % json.dumps(description),
             ' "domain": {"type": "box", "min": %s, "max": %s},' % (json.dumps(box[0]), json.dumps(box[1])),
             ' "types": %s,' % json.dumps([t if isinstance(t, dict) else {"name": t} for t in types]),
             ' "elements": [']
    lines.append(",\n".join('  {"id": %d, "type": "%s"}' % (i, t) for i, (t, _) in enumerate(tracks)) + "],")
    lines.append(' "frames": [')
    out = []
    for f in range(frames):
        elements = ",\n".join('   {"id": %d, "position": [%.6f, %.6f]}' % (i, p[f][0], p[f][1])
                              for i, (_, p) in enumerate(tracks))
        out.append('  {"time": %.6g, "elements": [\n%s]}' % (round(f * dt, 6), elements))
    lines.append(",\n".join(out) + "]}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def drifting_lattice(seed=3, nx=12, ny=12, frames=24, velocity=(0.05, 0.02), wobble=0.06):
    rng = random.Random(seed)
    tracks = []
    for j in range(ny):
        for i in range(nx):
            x = i + 0.5 * (j % 2) + 0.08 * (rng.random() - 0.5)
            y = j * math.sqrt(3) / 2 + 0.08 * (rng.random() - 0.5)
            phase = 2 * math.pi * rng.random()
            path = []
            for f in range(frames):
                w = 2 * math.pi * f / 8 + phase
                path.append((x + velocity[0] * f + wobble * math.cos(w), y + velocity[1] * f + wobble * math.sin(w)))
            tracks.append(("dot", path))
    box = ([-0.5, -0.5], [nx + 0.5, ny * math.sqrt(3) / 2 + 0.5])
    write("drifting_lattice_2d.json",
          "Jittered hexagonal lattice drifting at (0.05, 0.02) per frame, each particle circling "
          "(radius 0.06, period 8 frames, own phase); examples/dynamic/make_examples.py",
          2, box, ["dot"], tracks, 0.1)


def poisson_disk(rng, size, r, tries=30):
    """Bridson-style dart throwing by rejection, bounded tries per point."""
    points = []
    for _ in range(4000):
        p = (rng.uniform(0, size), rng.uniform(0, size))
        if all((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 >= r * r for q in points):
            points.append(p)
    return points


def swirl_particles(seed=5, size=10.0, frames=32):
    rng = random.Random(seed)
    tracks = []
    for (x, y) in poisson_disk(rng, size, 0.8):
        # Phase smooth in space (a wave of wavelength 5 along x + y): neighbours swirl together.
        phase = 2 * math.pi * (x + y) / 5.0
        path = []
        for f in range(frames):
            w = 2 * math.pi * f / 16 + phase
            path.append((x + 0.12 * math.cos(w), y + 0.12 * math.sin(w)))
        tracks.append(("grain", path))
    write("swirl_particles_2d.json",
          "Poisson-disk particles (exclusion 0.8) swirling in place: each circles (radius 0.12, "
          "period 16 frames) with a phase that varies smoothly in space; examples/dynamic/make_examples.py",
          2, ([-0.2, -0.2], [size + 0.2, size + 0.2]), ["grain"], tracks, 1 / 24)


def fish_school(seed=9, size=10.0, frames=32):
    """A loose school: fish about 1 apart, each darting back and forth along the school's
    heading (x) and weaving across it, in loose step with its neighbours; at rest on average,
    so that a (turning) flow carries the school."""
    rng = random.Random(seed)
    tracks = []
    for (x, y) in poisson_disk(rng, size, 0.9):
        phase = 2 * math.pi * y / 4.0 + 0.6 * rng.random()
        dart = rng.uniform(0.10, 0.18)
        path = []
        for f in range(frames):
            w = 2 * math.pi * f / 12 + phase
            path.append((x + dart * math.sin(w), y + 0.08 * math.sin(2 * w + 1.0)))
        tracks.append(("fish", path))
    write("fish_school_2d.json",
          "A loose school of fish (Poisson disk, exclusion 0.9) at rest on average: each darts along x "
          "(amplitude 0.10-0.18, period 12 frames) and weaves across (0.08, period 6), in loose step with its "
          "neighbours; examples/dynamic/make_examples.py",
          2, ([-0.2, -0.2], [size + 0.2, size + 0.2]), [{"name": "fish", "glyph": "fish"}], tracks, 1 / 12)


if __name__ == "__main__":
    drifting_lattice()
    swirl_particles()
    fish_school()
