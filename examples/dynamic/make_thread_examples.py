"""Writes the dynamic examples of threads and sheets (docs/dynamic.md, "Threads and sheets on
a coarse motion"): an animated exemplar of fine motion and a coarse motion to lay it on.

noodles_2d.json          6 hanging noodles of 16 samples (spacing ~0.25) with kinks along
                         their length and a wave running down them, on a slow swing: the
                         exemplar (its swing is the coarse motion the analysis removes).
noodles_coarse_2d.json   24 straight noodles hanging from a fork that swings them: one
                         coarse motion duplicated for every noodle, as in the paper's Figure 10.
paper_3d.json            4 paper sheets of 6 x 6 samples (spacing 0.2) fluttering with waves
                         across them while they drift down: the exemplar.
paper_coarse_3d.json     12 flat sheets falling on spirals and tumbling slowly, never through
                         each other: the coarse motion (Figure 13).

Run from this folder: python3 make_thread_examples.py (deterministic: a fixed seed).
"""
import json
import math
import random


def number(v):
    return float("%.6f" % v)


def write(path, description, dimension, box, types, elements, frames, dt):
    """elements: [(type, [[sample positions] per frame])]."""
    doc = {"format": "tessera", "version": 1, "dimension": dimension, "description": description,
           "domain": {"type": "box", "min": box[0], "max": box[1]}, "types": types,
           "elements": [{"id": i, "type": t} for i, (t, _) in enumerate(elements)], "frames": []}
    for f in range(frames):
        doc["frames"].append({"time": number(f * dt), "elements": [
            {"id": i, "samples": [[number(c) for c in p[:dimension]] for p in track[f]]}
            for i, (_, track) in enumerate(elements)]})
    with open(path, "w") as out:
        out.write(json.dumps(doc, separators=(",", ":")).replace('{"time"', '\n {"time"') + "\n")


def hanging_noodles(seed=5, count=6, samples=16, spacing=0.25, frames=40, dt=0.1):
    rng = random.Random(seed)
    elements = []
    for n in range(count):
        x0 = 1.0 + 1.2 * n
        kinks = [(0.07 * (0.6 + 0.8 * rng.random()), 2 * math.pi / rng.uniform(3.0, 5.0), rng.uniform(0, 6.3))
                 for _ in range(2)]
        wave_phase = rng.uniform(0, 6.3)
        track = []
        for f in range(frames):
            t = f * dt
            swing = 0.4 * math.sin(2 * math.pi * t / 4.0 + 0.3 * n)
            pts = []
            for i in range(samples):
                u = i / (samples - 1)
                kink = sum(a * math.sin(k * i + p) for a, k, p in kinks)
                wave = 0.06 * u * math.sin(2 * math.pi * (i / 6.0 - t / 1.2) + wave_phase)
                pts.append((x0 + swing * u * u + kink + wave, 4.5 - spacing * i))
            track.append(pts)
        elements.append(("noodle", track))
    write("noodles_2d.json",
          "6 hanging noodles (16 samples, spacing 0.25) with kinks (wavelength 3-5 samples) and a wave running "
          "down them (period 1.2), on a slow swing; examples/dynamic/make_thread_examples.py",
          2, ([0, 0], [8, 5]), [{"name": "noodle", "rigid": False, "topology": "thread"}], elements, frames, dt)


def swinging_fork(count=24, samples=16, spacing=0.24, frames=60, dt=0.1):
    elements = []
    for n in range(count):
        top = (0.5 + 0.5 * n, 5.0)
        track = []
        for f in range(frames):
            t = f * dt
            angle = 0.45 * math.sin(2 * math.pi * t / 3.0)
            pts = []
            for i in range(samples):
                # The swing bends the noodle more towards its free end.
                x, y = top
                for k in range(i):
                    ak = angle * (0.3 + 0.7 * k / (samples - 1))
                    x += spacing * math.sin(ak)
                    y -= spacing * math.cos(ak)
                pts.append((x + 0.6 * math.sin(2 * math.pi * t / 3.0), y))
            track.append(pts)
        elements.append(("noodle", track))
    write("noodles_coarse_2d.json",
          "24 straight noodles (16 samples, spacing 0.24) hanging from a fork that swings them (period 3): one "
          "coarse motion for every noodle; examples/dynamic/make_thread_examples.py",
          2, ([-1, 0], [14, 6]), [{"name": "noodle", "rigid": False, "topology": "thread"}], elements, frames, dt)


def rotate(p, yaw, pitch):
    x, y, z = p
    x, z = x * math.cos(pitch) + z * math.sin(pitch), -x * math.sin(pitch) + z * math.cos(pitch)
    x, y = x * math.cos(yaw) - y * math.sin(yaw), x * math.sin(yaw) + y * math.cos(yaw)
    return (x, y, z)


def fluttering_paper(seed=7, count=4, side=6, spacing=0.2, frames=40, dt=0.1):
    rng = random.Random(seed)
    elements = []
    for n in range(count):
        centre = (1.0 + 1.6 * (n % 2), 1.0 + 1.6 * (n // 2), 3.0)
        phase, k = rng.uniform(0, 6.3), rng.uniform(2.5, 4.0)
        track = []
        for f in range(frames):
            t = f * dt
            pts = []
            for r in range(side):
                for c in range(side):
                    u, v = (c - (side - 1) / 2) * spacing, (r - (side - 1) / 2) * spacing
                    z = 0.08 * math.sin(k * u - 2 * math.pi * t / 0.8 + phase) + 0.04 * math.sin(3.0 * v + 2 * math.pi * t / 1.1)
                    pts.append((centre[0] + u, centre[1] + v, centre[2] - 0.05 * f + z))
            track.append(pts)
        elements.append(("paper", track))
    write("paper_3d.json",
          "4 paper sheets of 6 x 6 samples (spacing 0.2) fluttering (waves of period 0.8 and 1.1 across them) while "
          "drifting down; examples/dynamic/make_thread_examples.py",
          3, ([0, 0, 0], [4, 4, 4]), [{"name": "paper", "rigid": False, "topology": "sheet", "columns": side}],
          elements, frames, dt)


def tumbling_sheets(seed=11, count=12, side=6, spacing=0.2, frames=60, dt=0.1, apart=1.5):
    """Sheets whose centres stay `apart` (more than a sheet's diagonal, 1.41) in every frame:
    the coarse motion never passes two sheets through each other (drawn again until so)."""
    rng = random.Random(seed)
    elements, paths = [], []

    def centre_at(start, phase, t):
        return (start[0] + 0.4 * math.cos(1.5 * t + phase), start[1] + 0.4 * math.sin(1.5 * t + phase),
                start[2] - 0.5 * t)

    for n in range(count):
        for _ in range(10000):
            start = (rng.uniform(0.5, 5.5), rng.uniform(0.5, 5.5), rng.uniform(4.0, 6.0))
            spin, tilt, phase = rng.uniform(0.4, 0.9), rng.uniform(0.3, 0.6), rng.uniform(0, 6.3)
            path = [centre_at(start, phase, f * dt) for f in range(frames)]
            if all(math.dist(path[f], other[f]) >= apart for other in paths for f in range(frames)):
                break
        else:
            raise SystemExit("tumbling_sheets: no room for sheet %d" % n)
        paths.append(path)
        track = []
        for f in range(frames):
            t = f * dt
            yaw, pitch = spin * t + phase, tilt * math.sin(1.3 * t + phase)
            pts = []
            for r in range(side):
                for c in range(side):
                    p = rotate(((c - (side - 1) / 2) * spacing, (r - (side - 1) / 2) * spacing, 0.0), yaw, pitch)
                    pts.append(tuple(path[f][i] + p[i] for i in range(3)))
            track.append(pts)
        elements.append(("paper", track))
    write("paper_coarse_3d.json",
          "12 flat paper sheets of 6 x 6 samples falling on spirals and tumbling: the coarse motion; "
          "examples/dynamic/make_thread_examples.py",
          3, ([0, 0, 0], [6, 6, 6]), [{"name": "paper", "rigid": False, "topology": "sheet", "columns": side}],
          elements, frames, dt)


if __name__ == "__main__":
    hanging_noodles()
    swinging_fork()
    fluttering_paper()
    tumbling_sheets()
