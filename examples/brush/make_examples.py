"""Writes the brushing examples' exemplars (docs/brush.md, "Examples"):

strands_3d.json  deformable 6-sample strands in a 6x6x6 box, laid along +x with a gentle bend
                 each, on a jittered lattice: the elements that fill a volume along a field
                 (the paper's Figure 1c).

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


if __name__ == "__main__":
    with open("strands_3d.json", "w") as f:
        json.dump(strands(), f, indent=1)
