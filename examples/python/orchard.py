"""The Python module's demo (docs/python.md): an orchard exemplar of trees with a bush
beside each, built from numpy arrays, scattered over 16x its area with both methods, and
written as pictures, a USD layer and a metrics report.

Usage: PYTHONPATH=build/python /usr/bin/python3 examples/python/orchard.py OUT_DIR
"""
import json
import pathlib
import sys

import numpy as np

import tessera


def main(out):
    out.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(1)
    trees = rng.uniform(0, 10, (30, 2))
    bushes = np.clip(trees + rng.uniform(-0.8, 0.8, (30, 2)), 0, 10)
    ex = tessera.exemplar(np.vstack([trees, bushes]), classes=[0] * 30 + [1] * 30,
                          class_names=["tree", "bush"], radii=[0.4] * 30 + [0.15] * 30,
                          domain=((0, 0), (10, 10)))
    tessera.render(ex, out / "orchard_exemplar.png", width=200)
    sweeps = []
    det = tessera.synthesize(ex, domain="box:40,40", seed=7, progress=sweeps.append)
    tessera.render(det, out / "orchard_det.png")
    tessera.save(det, out / "orchard_det.usda")
    tessera.save(det, out / "orchard_det.json")
    # The same exemplar by the PCF method (bushes depend on trees by default).
    pcf = tessera.synthesize(ex, domain="box:40,40", method="pcf", seed=7)
    tessera.render(pcf, out / "orchard_pcf.png")
    report = {"det": tessera.metrics(ex, det), "pcf": tessera.metrics(ex, pcf)}
    (out / "orchard_metrics.json").write_text(json.dumps(report, indent=2))
    for name, result in (("det", det), ("pcf", pcf)):
        counts = dict(zip(result.class_names, np.bincount(result.classes).tolist()))
        print("orchard %s: %d elements %s, pair correlation error %.3f"
              % (name, len(result), counts, report[name]["pcf_relative_error"]))
    print("orchard det: %d progress events, final energy %.4g" % (len(sweeps), det.stats["final_energy"]))


if __name__ == "__main__":
    main(pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/python"))
