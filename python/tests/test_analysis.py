"""The PCF method from Python: analyse, synthesize from the model, compare; the standard
pair correlation against spatstat's values; the metrics report."""
import csv
import math

import numpy as np
import pytest

import tessera
from conftest import ROOT, SHARED_DATA


def test_toy_forest_analysis_and_synthesis_keep_the_statistics(tmp_path):
    forest = tessera.load(ROOT / "examples" / "pcf" / "toy_forest.json")
    model = tessera.analyze(forest)
    assert set(model.classes) == set(forest.class_names)
    assert len(model.pcfs) >= len(model.classes)
    for pcf in model.pcfs:
        assert len(pcf["mean"]) == len(model.x)
        assert np.all(pcf["lower"] <= pcf["upper"])
    # Through a file and back, then synthesized into 4x the area.
    tessera.save_model(model, tmp_path / "model.json")
    model = tessera.load_model(tmp_path / "model.json")
    (x0, y0), (x1, y1) = forest.domain.bounds
    domain = tessera.Domain.box((x0, y0), (x0 + 2 * (x1 - x0), y0 + 2 * (y1 - y0)))
    out = tessera.synthesize(model, domain, method="pcf", seed=3)
    quality = tessera.compare_model(model, forest, out)
    assert min(quality["inside_fraction"]) >= 0.9
    for name, ratio in quality["count_ratio"].items():
        assert abs(ratio - 1.0) <= 0.02, name
    tessera.plot_model(model, tmp_path / "pcfs.png", compare=out)
    assert (tmp_path / "pcfs.png").stat().st_size > 1000


def test_model_synthesis_needs_a_domain():
    forest = tessera.load(ROOT / "examples" / "pcf" / "toy_forest.json")
    with pytest.raises(tessera.OptionError, match="domain is required"):
        tessera.synthesize(tessera.analyze(forest), method="pcf")


def reference_curve(name):
    with open(SHARED_DATA / "reference" / (name + "_pcf.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(SHARED_DATA / "reference" / "params.csv") as f:
        params = {row["dataset"]: row for row in csv.DictReader(f)}[name]
    return rows, float(params["bandwidth_sd"]), float(params["rmax"])


def test_pair_correlation_agrees_with_spatstat_on_amacrine():
    with open(SHARED_DATA / "points" / "windows.csv") as f:
        window = {row["name"]: row for row in csv.DictReader(f)}["amacrine"]
    box = tessera.Domain.box((float(window["xmin"]), float(window["ymin"])),
                             (float(window["xmax"]), float(window["ymax"])))
    cells = tessera.load(SHARED_DATA / "points" / "amacrine.csv", input_domain=box)
    rows, bandwidth, r_max = reference_curve("amacrine")
    r, curves, _ = tessera.pair_correlation(cells, r_max=r_max, bandwidth=bandwidth, bins=len(rows))
    reference_r = np.array([float(row["r"]) for row in rows])
    np.testing.assert_allclose(r, reference_r, rtol=1e-9, atol=1e-12)
    checked = 0
    for (a, b), g in curves.items():
        column = "g_%s_%s" % (a, b) if ("g_%s_%s" % (a, b)) in rows[0] else "g_%s_%s" % (b, a)
        expected = np.array([float(row[column]) for row in rows])
        use = (reference_r >= 3 * bandwidth) & (expected >= 0.2)
        np.testing.assert_allclose(g[use], expected[use], rtol=0.03)
        checked += use.sum()
    assert checked > 100


def test_metrics_report_compares_output_with_exemplar(two_class):
    same = tessera.metrics(two_class, two_class)
    assert same["pcf_relative_error"] == 0.0
    assert same["exemplar"]["count_per_class"] == {"stone": 36, "pebble": 36}
    out = tessera.synthesize(two_class, seed=4, iterations=5)
    report = tessera.metrics(two_class, out)
    assert 0.0 < report["pcf_relative_error"] < 0.6
    assert report["output"]["elements"] == len(out)
