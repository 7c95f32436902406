"""Exemplars from numpy arrays, and the round trip arrays -> synthesize -> save -> load."""
import json

import numpy as np
import pytest

import tessera

ELEMENT_ARRAYS = ("classes", "radii", "orientations", "scales", "ids", "locked", "centroids")
SAMPLE_ARRAYS = ("positions", "element_of_sample", "sample_ids", "times")


def assert_same_arrays(a, b):
    assert a.dimension == b.dimension
    assert a.class_names == b.class_names
    for name in ELEMENT_ARRAYS + SAMPLE_ARRAYS:
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)


def test_arrays_come_back_as_given(two_class):
    ex = two_class
    assert ex.dimension == 2 and len(ex) == 72 and ex.class_names == ["stone", "pebble"]
    assert ex.positions.shape == (72, 2)
    np.testing.assert_array_equal(ex.classes[:36], 0)
    np.testing.assert_array_equal(ex.radii[36:], 0.2)
    np.testing.assert_array_equal(ex.orientations, np.tile([1.0, 0, 0, 0], (72, 1)))
    np.testing.assert_array_equal(ex.ids, np.arange(72))
    assert ex.domain.bounds == ((0.0, 0.0), (12.0, 12.0))


def test_round_trip_synthesize_save_load(two_class, tmp_path):
    out = tessera.synthesize(two_class, scale=2.0, seed=5, iterations=4)
    assert isinstance(out, tessera.Arrangement)
    assert out.domain.bounds == ((0.0, 0.0), (24.0, 24.0))
    # About 4x the elements, every one inside the domain.
    assert 0.85 * 4 * 72 <= len(out) <= 1.15 * 4 * 72
    assert all(out.domain.contains(p) for p in out.positions)
    path = tmp_path / "out.json"
    tessera.save(out, path)
    back = tessera.load(path)
    assert_same_arrays(out, back)
    # The run statistics are the saved file's "stats" plus the timings a file leaves out.
    assert out.stats["method"] == "det" and len(out.stats["energy"]) == 4
    saved = json.loads(path.read_text())["stats"]
    timings = {"iteration_seconds", "init_seconds", "total_seconds", "threads"}
    assert {k: v for k, v in out.stats.items() if k not in timings} == saved
    assert timings <= out.stats.keys() and len(out.stats["iteration_seconds"]) == 4


def test_multi_sample_elements_with_attributes_and_times(tmp_path):
    # Three sticks of 3 samples each in 3D, with a free attribute and time stamps.
    positions = np.array([[x + 0.3 * s, y, 1.0] for x, y in ((1, 1), (4, 2), (2, 5)) for s in range(3)])
    ex = tessera.exemplar(positions, element_of_sample=np.repeat(np.arange(3), 3),
                          sample_ids=np.tile(np.arange(3), 3), times=np.linspace(0, 1, 9),
                          attributes=np.array([[0.5], [1.5], [2.5]]), attribute_names=["age"],
                          ids=[10, 20, 30], locked=[True, False, False],
                          domain=tessera.Domain.box((0, 0, 0), (6, 6, 2)))
    assert ex.dimension == 3 and len(ex) == 3 and ex.sample_count == 9
    np.testing.assert_allclose(ex.centroids[0], [1.3, 1.0, 1.0])
    path = tmp_path / "sticks.json"
    tessera.save(ex, path)
    back = tessera.load(path)
    assert_same_arrays(ex, back)
    np.testing.assert_array_equal(back.attributes, [[0.5], [1.5], [2.5]])
    assert back.attribute_names == ["age"]


def test_files_load_like_the_cli_reads_them(root):
    ex = tessera.load(root / "examples" / "two_class_2d.json")
    assert ex.class_names == ["stone", "pebble"] and len(ex) == 112


def test_same_seed_same_output_for_any_thread_count(two_class):
    a = tessera.synthesize(two_class, seed=11, iterations=3, threads=1)
    b = tessera.synthesize(two_class, seed=11, iterations=3, threads=2)
    np.testing.assert_array_equal(a.positions, b.positions)
    np.testing.assert_array_equal(a.classes, b.classes)


def test_domain_forms_agree(two_class):
    by_text = tessera.synthesize(two_class, domain="box:20,16", seed=2, iterations=0)
    by_corners = tessera.synthesize(two_class, domain=((0, 0), (20, 16)), seed=2, iterations=0)
    by_object = tessera.synthesize(two_class, domain=tessera.Domain.box((0, 0), (20, 16)), seed=2,
                                   iterations=0)
    np.testing.assert_array_equal(by_text.positions, by_corners.positions)
    np.testing.assert_array_equal(by_text.positions, by_object.positions)
    tri = tessera.synthesize(two_class, domain=tessera.Domain.polygon([(0, 0), (24, 0), (0, 24)]),
                             seed=2, iterations=2)
    inside = [p[0] + p[1] <= 24 + 1e-9 for p in tri.centroids]
    assert np.mean(inside) > 0.99
