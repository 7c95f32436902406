#!/usr/bin/env python3
"""Gives every element of a tessera animation (or arrangement) a small radius, for a picture.

    python3 scripts/small_disks.py IN.json OUT.json RADIUS [--first-frame]

Elements without a radius are drawn as disks of 0.4 spacings, which hide a motion of a tenth
of a spacing; with a small radius their paths (`tessera render --trail`) show beside them.
With --first-frame only the first frame is kept: a still of the animation, onto which
`tessera recombine` can add the details of another (the demo's analysis pictures).
"""
import json
import sys


def main():
    args = [a for a in sys.argv[1:] if a != "--first-frame"]
    if len(args) != 3:
        sys.exit(__doc__.strip().splitlines()[2].strip())
    src, dst, radius = args[0], args[1], float(args[2])
    with open(src) as f:
        doc = json.load(f)
    for e in doc["elements"]:
        e["radius"] = radius
    if "--first-frame" in sys.argv[1:] and "frames" in doc:
        doc["frames"] = doc["frames"][:1]
    doc.pop("stats", None)
    with open(dst, "w") as f:
        json.dump(doc, f)


if __name__ == "__main__":
    main()
