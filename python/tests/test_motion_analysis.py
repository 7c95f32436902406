"""tessera.decompose and tessera.recombine (Dynamic Element Textures, section 5): the split
into coarse motion and details gives the input back, keeps a translating thread whole in the
coarse animation, puts a thread's fine wiggle in the details, does not depend on the thread
count, recombines details of another sample count, and names bad keywords."""
import inspect

import numpy as np
import pytest

import tessera
from conftest import ROOT, run_docs_example


@pytest.fixture(scope="module")
def swirl():
    return tessera.load_animation(ROOT / "examples" / "dynamic" / "swirl_particles_2d.json")


def threads(count, samples, frames, motion):
    """`count` threads of `samples` samples (a multi-sample element is a thread), placed by
    motion(element, sample, frame) -> (x, y)."""
    first = np.array([motion(e, k, 0) for e in range(count) for k in range(samples)], float)
    ex = tessera.exemplar(first, element_of_sample=np.repeat(np.arange(count), samples),
                          domain=((-2, -4), (14, 12)))
    positions = np.array([[motion(e, k, f) for e in range(count) for k in range(samples)] for f in range(frames)],
                         float)
    return tessera.animation(ex, positions)


def test_coarse_plus_detail_is_the_input(swirl):
    coarse, detail = tessera.decompose(swirl)
    assert isinstance(coarse, tessera.Animation) and isinstance(detail, tessera.Animation)
    assert np.array_equal(coarse.times, swirl.times) and detail.positions.shape == swirl.positions.shape
    back = tessera.recombine(coarse, detail)
    assert np.abs(back.positions - swirl.positions).max() < 1e-9
    assert np.linalg.norm(detail.positions, axis=2).max() > 0.01


def test_a_translating_straight_thread_is_all_coarse_to_its_ends():
    clip = threads(2, 12, 6, lambda e, k, f: (0.25 * k + 0.05 * f, 2.0 * e + 0.1 * k - 0.03 * f))
    coarse, detail = tessera.decompose(clip)
    assert np.abs(detail.positions).max() < 1e-9


def test_a_fine_wiggle_goes_to_the_details():
    a = 0.05
    clip = threads(1, 31, 8, lambda e, k, f: (0.25 * k, 0.02 * f + (a if k % 2 == 0 else -a)))
    coarse, detail = tessera.decompose(clip, topology_radius=3)
    signs = np.where(np.arange(31) % 2 == 0, 1.0, -1.0)
    wiggle = (detail.positions[:, 3:-3, 1] * signs[3:-3]).mean()
    assert wiggle == pytest.approx(a, abs=0.002)  # 0.0507 measured (1.3% leaks to the coarse)
    assert np.abs(np.diff(coarse.positions[:, 3:-3, 1], axis=0) - 0.02).max() < 0.002


def test_the_same_bits_for_any_thread_count(swirl):
    one = tessera.decompose(swirl, threads=1)
    three = tessera.decompose(swirl, threads=3)
    assert np.array_equal(one[0].positions, three[0].positions)
    assert np.array_equal(one[1].positions, three[1].positions)


def test_details_of_another_sample_count_are_resampled_along_the_thread():
    line = threads(1, 11, 3, lambda e, k, f: (0.25 * k, 0.1 * f))
    wave = threads(1, 21, 3, lambda e, k, f: (0.01 * np.sin(1.3 * k), 0.02 * np.cos(0.9 * k + f)))
    out = tessera.recombine(line, wave)
    assert np.abs(out.positions - line.positions - wave.positions[:, ::2]).max() < 1e-12


def test_keywords_follow_the_option_table_and_bad_input_is_named(swirl):
    parameters = inspect.signature(tessera.decompose).parameters
    assert [(p.name, p.default) for p in parameters.values() if p.kind is inspect.Parameter.KEYWORD_ONLY] == [
        ("spatial_radius", 0.0), ("topology_radius", 3), ("temporal_radius", 2), ("threads", 0)]
    with pytest.raises(tessera.OptionError, match="^spatial_radius must be a number >= 0, got -1"):
        tessera.decompose(swirl, spatial_radius=-1.0)
    with pytest.raises(tessera.OptionError, match="^temporal_radius must be an integer from 0"):
        tessera.decompose(swirl, temporal_radius=-1)
    with pytest.raises(TypeError, match="unexpected keyword argument 'radius'"):
        tessera.decompose(swirl, radius=2.0)
    hair = threads(1, 5, 2, lambda e, k, f: (k, f))
    with pytest.raises(tessera.InputError, match="the detail animation has no thread elements"):
        tessera.recombine(hair, swirl)
    with pytest.raises(tessera.OptionError, match="coarse must be a tessera.Animation"):
        tessera.recombine(3, swirl)


def test_the_docs_example_runs(tmp_path):
    (tmp_path / "examples").symlink_to(ROOT / "examples")
    scope = run_docs_example("### Coarse and detail motion", tmp_path)
    assert np.abs(scope["back"].positions - scope["swirl"].positions).max() < 1e-9
    alone = tessera.load_animation(tmp_path / "swirl_details.json")
    assert alone.frame_count == 32
    assert np.allclose(alone.positions, scope["coarse"].positions[:1] + scope["detail"].positions)


def test_animate_gives_a_still_of_threads_motion_with_frame_zero_the_still():
    still = tessera.load(ROOT / "examples" / "noodles_2d.json")
    clip = tessera.animate(still, frames=8, threads=2)
    assert clip.frame_count == 8
    first = tessera.animate(ROOT / "examples" / "noodles_2d.json", frames=8, threads=1)
    assert np.array_equal(clip.positions, first.positions)  # any thread count, a path or an exemplar
    assert np.array_equal(clip.positions[0], first.positions[0])
    moved = np.linalg.norm(clip.positions[-1] - clip.positions[0], axis=1).mean()
    assert moved > 0.02
    assert list(inspect.signature(tessera.animate).parameters)[:4] == ["still", "seed", "threads", "frames"]


def test_animate_names_bad_keywords():
    with pytest.raises(tessera.OptionError, match="^frames must be an integer from 2"):
        tessera.animate(ROOT / "examples" / "poisson_disk_2d.json", frames=1)
    with pytest.raises(TypeError, match="unexpected keyword argument 'frame'"):
        tessera.animate(ROOT / "examples" / "poisson_disk_2d.json", frame=3)


def test_animate_continues_a_short_clip(swirl):
    clip = tessera.animate(ROOT / "examples" / "dynamic" / "swirl_particles_2d.json", frames=40, threads=2)
    assert clip.frame_count == 40
    assert np.array_equal(clip.positions[:32], swirl.positions)  # the clip's own frames first
    assert np.linalg.norm(clip.positions[39] - clip.positions[31], axis=1).mean() > 0.01
    same = tessera.animate(swirl, frames=32)
    assert np.array_equal(same.positions, swirl.positions)  # long enough: as it is
