"""tessera.Grower: growth over a region and by a count, from an exemplar patch or next to
locked elements that never move; keyword defaults are the library's, bad values name the
keyword, the thread count changes nothing, progress can cancel."""
import inspect
import threading

import numpy as np
import pytest

import tessera
from tessera import _tessera
from conftest import ROOT, run_docs_example


@pytest.fixture
def two_class_file():
    return tessera.load(ROOT / "examples" / "two_class_2d.json")


def inside(region, arrangement):
    return all(region.contains(p) for p in arrangement.positions)


def test_growing_a_region_fills_it_and_stays_inside(two_class_file):
    ex = two_class_file
    region = ex.domain.scaled(2.0)
    grower = tessera.Grower(ex, seed=4)
    report = grower.grow(region)
    assert report["covered"] and not report["bound_hit"]
    out = grower.arrangement
    assert isinstance(out, tessera.Arrangement)
    # Four times the area: about four times the elements, none outside the region.
    assert 0.85 * 4 * len(ex) <= len(out) <= 1.15 * 4 * len(ex)
    assert len(grower) == len(out)
    assert inside(region, out)
    assert set(out.classes) == {0, 1} and out.class_names == ex.class_names
    assert grower.radius > 0
    assert grower.locked.dtype == bool and grower.locked.shape == (len(out),) and not grower.locked.any()
    assert grower.horizon.dtype.kind == "i" and np.all(grower.horizon < len(out))


def test_report_has_every_count():
    keys = {"rounds", "added", "candidates", "merged", "high_energy", "outside", "reassigned", "last_made",
            "displaced", "filled", "uncovered", "relaxed", "covered", "bound_hit", "energy", "seconds",
            "rare", "thinned"}
    ex = tessera.load(ROOT / "examples" / "two_class_2d.json")
    report = tessera.Grower(ex).grow(50)
    assert set(report) == keys
    assert report["added"] > 0 and report["rounds"] >= 1 and report["seconds"] >= 0


def test_elements_it_starts_from_never_move(two_class_file):
    ex = two_class_file
    start = ex.copy()
    grower = tessera.Grower(ex, seed=2)
    grower.set_arrangement(start)
    np.testing.assert_array_equal(grower.locked, True)
    grower.grow(ex.domain.scaled(2.0))
    out = grower.arrangement
    assert len(out) > 3 * len(start)
    row = {element_id: k for k, element_id in enumerate(out.ids)}
    kept = [row[element_id] for element_id in start.ids]
    np.testing.assert_array_equal(out.centroids[kept], start.centroids)
    np.testing.assert_array_equal(out.positions[kept], start.positions)  # one sample per element
    np.testing.assert_array_equal(out.classes[kept], start.classes)
    assert grower.locked[kept].all()
    assert grower.locked.sum() == len(start)


def test_grow_by_a_count_and_by_a_step(two_class_file):
    grower = tessera.Grower(two_class_file)
    grower.grow(100)
    before = len(grower)
    assert 80 <= before <= 140
    report = grower.step()
    assert report["rounds"] == 1 and report["added"] > 0
    assert len(grower) == before + report["added"]


def test_tree_search_choice_grows_too(two_class_file):
    region = two_class_file.domain.scaled(1.5)
    grower = tessera.Grower(two_class_file, choice="mcts", playouts=8)
    assert grower.grow(region)["covered"]
    assert 0.8 * 2.25 * len(two_class_file) <= len(grower) <= 1.2 * 2.25 * len(two_class_file)
    assert inside(region, grower.arrangement)


def test_exemplar_may_be_a_path_but_not_anything(two_class_file):
    assert tessera.Grower(ROOT / "examples" / "two_class_2d.json").grow(20)["added"] > 0
    with pytest.raises(tessera.OptionError, match="exemplar must be a tessera.Exemplar"):
        tessera.Grower(42)
    with pytest.raises(tessera.OptionError, match="arrangement must be"):
        tessera.Grower(two_class_file).set_arrangement(42)


def test_regions_in_every_form_agree(two_class_file):
    by_domain = tessera.Grower(two_class_file).grow(tessera.Domain.box((0, 0), (15, 15)))
    by_corners = tessera.Grower(two_class_file).grow(((0, 0), (15, 15)))
    by_text = tessera.Grower(two_class_file).grow("box:15,15")
    assert by_domain["added"] == by_corners["added"] == by_text["added"]


def test_seed_starts_from_an_exemplar_patch_at_the_centre(two_class_file):
    grower = tessera.Grower(two_class_file)
    grower.seed((50.0, 50.0))
    out = grower.arrangement
    assert len(out) > 1
    assert np.linalg.norm(out.centroids.mean(axis=0) - [50.0, 50.0]) < 3 * grower.radius
    assert len(grower.horizon) == len(out)


def test_same_seed_same_output_for_any_thread_count(two_class_file):
    region = two_class_file.domain.scaled(1.6)
    a = tessera.Grower(two_class_file, seed=11, threads=1)
    b = tessera.Grower(two_class_file, seed=11, threads=2)
    a.grow(region)
    b.grow(region)
    np.testing.assert_array_equal(a.arrangement.positions, b.arrangement.positions)
    np.testing.assert_array_equal(a.arrangement.classes, b.arrangement.classes)


def test_grow_zero_names_the_argument(two_class_file):
    with pytest.raises(tessera.OptionError, match=r"^n: must be > 0, got 0$"):
        tessera.Grower(two_class_file).grow(0)


@pytest.mark.parametrize("kwargs, needle", [
    (dict(energy_factor=0.5), "energy_factor must be a number > 1, got 0.5"),
    (dict(threshold=0.0), "threshold must be a number > 0 and <= 1, got 0"),
    (dict(patch_extent=0.5), "patch_extent"),
    (dict(solves=101), "solves must be an integer from 0 to 100, got 101"),
    (dict(max_rounds=0), "max_rounds"),
    (dict(threads=-1), "threads"),
    (dict(k=2.5), "k must be an integer >= 1, got 2.5"),
    (dict(radius="wide"), "radius must be a number >= 0, got 'wide'"),
    (dict(choice="best"), "choice must be patch or mcts, got 'best'"),
    (dict(field="spiral:1,2"), "field"),
    (dict(seed=-1), "seed must be an unsigned 64-bit integer"),
])
def test_bad_keywords_raise_option_errors_naming_them(two_class_file, kwargs, needle):
    with pytest.raises(tessera.OptionError) as error:
        tessera.Grower(two_class_file, **kwargs)
    assert needle in str(error.value)


@pytest.mark.parametrize("target, error, needle", [
    (None, tessera.OptionError, "grow needs a region or a number of elements"),
    (True, tessera.OptionError, "grow needs a region"),
    ("circle:4", tessera.OptionError, "region: expected box:"),
    (((100, 100), (110, 110)), tessera.InputError, "region: it does not touch the arrangement"),
    (tessera.Domain.box((0, 0, 0), (5, 5, 5)), tessera.DomainError, "region: 3D, the exemplar is 2D"),
])
def test_bad_regions_name_the_region(two_class_file, target, error, needle):
    grower = tessera.Grower(two_class_file)
    grower.grow(30)
    with pytest.raises(error) as raised:
        grower.grow(target)
    assert needle in str(raised.value)


def test_progress_reports_rounds_and_can_cancel(two_class_file):
    events = []
    report = tessera.Grower(two_class_file).grow(two_class_file.domain.scaled(1.5), progress=events.append)
    stages = [e["stage"] for e in events]
    assert stages[0] == "round" and stages[-1] == "done"
    # A round's event is re-sent while the next round runs (the cancel's polls): count distinct ones.
    assert len({e["iteration"] for e in events if e["stage"] == "round"}) == report["rounds"] + 1
    assert events[-1]["fraction"] == 1.0

    grower = tessera.Grower(two_class_file)
    with pytest.raises(tessera.Cancelled):
        grower.grow(500, progress=lambda e: e["iteration"] < 1)
    assert len(grower) > 0  # the rounds before the cancel stay
    assert grower.last_report["rounds"] >= 1 and grower.last_report["added"] == len(grower)

    class Stop(Exception):
        pass

    def boom(event):
        raise Stop("enough")

    with pytest.raises(Stop, match="enough"):
        tessera.Grower(two_class_file).grow(100, progress=boom)


def test_the_callback_may_look_but_not_grow(two_class_file):
    grower = tessera.Grower(two_class_file)
    sizes = []
    grower.grow(200, progress=lambda e: sizes.append(len(grower.arrangement)))
    assert len(sizes) > 2 and sizes[0] > 0 and sizes[-1] == len(grower)
    with pytest.raises(RuntimeError, match="cannot change"):
        grower.grow(100, progress=lambda e: grower.step())


def test_another_thread_is_refused_while_it_grows(two_class_file):
    grower = tessera.Grower(two_class_file, threads=1)
    started, release = threading.Event(), threading.Event()
    errors = []

    def hold(event):
        started.set()
        release.wait(5)  # the GIL is free while this thread waits here

    def run():
        grower.grow(50, progress=hold)

    worker = threading.Thread(target=run)
    worker.start()
    try:
        assert started.wait(5)
        for attempt in (lambda: grower.step(), lambda: grower.arrangement):
            try:
                attempt()
            except RuntimeError as e:
                errors.append(str(e))
    finally:
        release.set()
        worker.join()
    assert len(errors) == 2 and all("another thread" in e for e in errors)


def test_the_docs_example_runs(capsys):
    # The example names its exemplar relative to the repository.
    scope = run_docs_example("## Growth: tessera.Grower", ROOT)
    out = scope["out"]
    assert isinstance(out, tessera.Arrangement) and len(out) > 4 * 112
    assert "grown in" in capsys.readouterr().out
