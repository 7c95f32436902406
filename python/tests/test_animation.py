"""Animations (tessera.Animation) from numpy arrays and files, and dynamic synthesis:
synthesize(method="dynamic") keeps the exemplar's motion, is the same for every thread count,
names a bad keyword, and its results travel through .json, .csv and an animated PNG."""
import os

import numpy as np
import pytest

import tessera
from conftest import run_docs_example

VELOCITY = np.array([0.2, 0.1])  # units per frame (time stamps 0, 1, 2, ...)


@pytest.fixture(scope="module")
def drifting():
    """A jittered 8 x 8 lattice of particles drifting at a constant velocity, 10 frames."""
    rng = np.random.default_rng(5)
    base = np.array([(x + 0.5, y + 0.5) for x in range(8) for y in range(8)], float)
    base += rng.uniform(-0.15, 0.15, base.shape)
    ex = tessera.exemplar(base, radii=np.full(len(base), 0.2), domain=((0, 0), (8, 8)))
    return tessera.animation(ex, np.stack([base + f * VELOCITY for f in range(10)]))


@pytest.fixture(scope="module")
def synthesized(drifting):
    return tessera.synthesize(drifting, domain=((0, 0), (16, 16)), method="dynamic", frames=6, seed=2, threads=1)


def mean_velocity(animation):
    """The mean per-frame displacement over every sample and frame."""
    return np.diff(animation.positions, axis=0).mean(axis=(0, 1)) / np.diff(animation.times).mean()


def test_an_animation_from_arrays_keeps_them(drifting):
    assert len(drifting) == drifting.frame_count == 10
    assert drifting.positions.shape == (10, 64, 2)
    assert np.array_equal(drifting.times, np.arange(10.0))
    assert isinstance(drifting.exemplar, tessera.Exemplar) and len(drifting.exemplar) == 64
    assert np.allclose(drifting.frame(3).positions, drifting.positions[3])
    assert np.allclose(drifting.frame(-1).positions, drifting.positions[9])
    assert np.allclose(drifting.velocities[1:], VELOCITY)
    with pytest.raises(IndexError):
        drifting.frame(10)


def test_bad_arrays_name_what_is_wrong(drifting):
    ex = drifting.exemplar
    with pytest.raises(tessera.OptionError, match=r"positions must be an F x 64 x 2 array.*got shape \(3, 5, 2\)"):
        tessera.animation(ex, np.zeros((3, 5, 2)))
    with pytest.raises(tessera.OptionError, match="times must be a 1-D array of 2 time stamps"):
        tessera.animation(ex, drifting.positions[:2], times=[0.0])
    with pytest.raises(tessera.InputError, match="time stamps must strictly increase") as error:
        tessera.animation(ex, drifting.positions[:3], times=[0.0, 1.0, 1.0])
    assert len(str(error.value).splitlines()) == 1


def test_dynamic_synthesis_fills_the_box_and_keeps_the_motion(drifting, synthesized):
    assert isinstance(synthesized, tessera.AnimatedArrangement)
    frames, samples, dimension = synthesized.positions.shape
    assert (frames, dimension) == (6, 2)
    # 4x the area: about 4x the 64 particles.
    assert 0.8 * 4 * 64 <= samples <= 1.2 * 4 * 64
    expected = mean_velocity(drifting)
    assert np.linalg.norm(mean_velocity(synthesized) - expected) <= 0.15 * np.linalg.norm(expected)
    assert synthesized.stats["threads"] == 1 and "final_energy" in synthesized.stats


def test_an_animation_means_the_dynamic_method_and_threads_change_nothing(drifting, synthesized):
    # method left at its default: an Animation is synthesized by "dynamic".
    again = tessera.synthesize(drifting, domain=((0, 0), (16, 16)), frames=6, seed=2, threads=2)
    assert np.array_equal(again.positions, synthesized.positions)
    assert np.array_equal(again.times, synthesized.times)


def test_progress_reports_the_frames(drifting):
    events = []
    tessera.synthesize(drifting, frames=3, iterations=1, threads=1, progress=events.append)
    stages = {e["stage"] for e in events}
    assert {"first frame", "frame", "done"} <= stages
    with pytest.raises(tessera.Cancelled):
        tessera.synthesize(drifting, frames=3, progress=lambda event: False)


@pytest.mark.parametrize("kwargs, error, needle", [
    (dict(matches=0), tessera.OptionError, "matches must be an integer from 1 to 8, got 0"),
    (dict(shape="round"), tessera.OptionError, "shape must be"),
    (dict(flow="east"), tessera.OptionError, "flow must be a vector X,Y or X,Y,Z"),
    (dict(k=2), tessera.OptionError, "k applies to method='det' only"),
    (dict(method="pcf"), tessera.OptionError, "an Animation is synthesized with method='dynamic'"),
    (dict(domain="box:10,10,10"), tessera.DomainError, "is 3D but the exemplar is 2D"),
])
def test_bad_options_name_the_keyword(drifting, kwargs, error, needle):
    with pytest.raises(error) as raised:
        tessera.synthesize(drifting, **{"frames": 2, **kwargs})
    assert needle in str(raised.value)


def test_flow_takes_a_sequence_or_text(drifting):
    a = tessera.synthesize(drifting, frames=3, iterations=0, threads=1, flow=(0.5, 0))
    b = tessera.synthesize(drifting, frames=3, iterations=0, threads=1, flow="0.5,0")
    assert np.array_equal(a.positions, b.positions)


@pytest.mark.parametrize("suffix", [".json", ".csv"])
def test_files_round_trip(synthesized, tmp_path, suffix):
    path = tmp_path / ("clip" + suffix)
    tessera.save_animation(synthesized, path)
    back = tessera.load_animation(path)
    assert back.positions.shape == synthesized.positions.shape
    assert np.allclose(back.positions, synthesized.positions)
    assert np.allclose(back.times, synthesized.times)
    assert np.array_equal(back.exemplar.ids, synthesized.exemplar.ids)
    # load() of an animated file is its frame 0; a path with frames means "dynamic".
    assert np.allclose(tessera.load(path).positions, synthesized.positions[0])
    out = tessera.synthesize(path, frames=2, iterations=0, threads=1)
    assert isinstance(out, tessera.AnimatedArrangement) and len(out) == 2


def test_save_writes_an_animated_png(synthesized, tmp_path):
    path = tmp_path / "clip.png"
    tessera.save_animation(synthesized, path)
    data = path.read_bytes()
    assert data.startswith(b"\x89PNG\r\n\x1a\n")
    assert b"acTL" in data
    # save() hands an Animation to save_animation.
    tessera.save(synthesized, tmp_path / "same.png")
    assert (tmp_path / "same.png").read_bytes() == data


def test_a_static_exemplar_is_a_one_frame_animation(two_class):
    # Still elements moved by a global flow (graph synthesis off: it would give them motion).
    out = tessera.synthesize(two_class, method="dynamic", frames=3, temporal_size=1, iterations=0, threads=1,
                             flow=(0.25, 0), graph_frames=0)
    assert out.positions.shape[0] == 3
    velocity = mean_velocity(out)
    assert 0.15 < velocity[0] <= 0.25 and abs(velocity[1]) < 0.05


def test_the_docs_example_runs(tmp_path, capsys):
    scope = run_docs_example("## Animations and dynamic synthesis", tmp_path)
    out = scope["out"]
    assert isinstance(out, tessera.AnimatedArrangement) and out.positions.shape[0] == 6
    assert tessera.load_animation(tmp_path / "drift.json").frame_count == 6
    assert b"acTL" in (tmp_path / "drift.png").read_bytes()
    assert "moving at" in capsys.readouterr().out


EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "dynamic")


def test_threads_follow_a_coarse_motion():
    exemplar = os.path.join(EXAMPLES, "noodles_2d.json")
    coarse = tessera.load_animation(os.path.join(EXAMPLES, "noodles_coarse_2d.json"))
    out = tessera.synthesize(exemplar, coarse=coarse, method="dynamic", seed=3, threads=1)
    assert out.positions.shape == coarse.positions.shape
    offset = np.linalg.norm(out.positions - coarse.positions, axis=2)
    assert 0.0 < offset.mean() < 0.3   # detail laid on, the coarse path kept
    with pytest.raises(tessera.OptionError, match="domain does not apply"):
        tessera.synthesize(exemplar, domain="box:4,4", coarse=coarse, method="dynamic")
