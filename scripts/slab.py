#!/usr/bin/env python3
"""Cuts a slab out of a 3D tessera arrangement, for a picture of its cross-section.

    python3 scripts/slab.py IN.json OUT.json AXIS LO HI

Keeps the elements whose centroid lies in LO <= coordinate AXIS (x, y or z) < HI and
narrows the domain to the slab, so that `tessera render` shows the cut face (the two
leaflets of a grown membrane, heads outside and tails inside).
"""
import json
import sys


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__.strip().splitlines()[2].strip())
    src, dst, axis, lo, hi = sys.argv[1], sys.argv[2], "xyz".index(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
    with open(src) as f:
        doc = json.load(f)
    if doc.get("dimension") != 3 or doc.get("domain", {}).get("type") != "box":
        sys.exit(f"{src}: a 3D arrangement in a box domain is needed")

    def centroid(e):  # single-sample elements are written with a position only
        s = e.get("samples") or [e["position"]]
        return sum(p[axis] for p in s) / len(s)

    doc["elements"] = [e for e in doc["elements"] if lo <= centroid(e) < hi]
    doc["domain"]["min"][axis] = lo
    doc["domain"]["max"][axis] = hi
    with open(dst, "w") as f:
        json.dump(doc, f)


if __name__ == "__main__":
    main()
