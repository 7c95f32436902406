"""Class colours from Python: a type's "color" is read, kept through save and load, used
by render, and refused when it is not a colour; render's legend can be turned off."""
import json

import numpy as np
import pytest

import tessera


def two_types(colors):
    positions = np.array([[1.0, 1.0], [3.0, 3.0], [1.0, 3.0]])
    types = [{"name": "banana", "color": colors[0]}, {"name": "leaf", "color": colors[1]}]
    return tessera.exemplar(positions, classes=np.array([0, 1, 1]), class_names=["banana", "leaf"],
                            radii=np.full(3, 0.4), domain=tessera.Domain.box((0, 0), (4, 4)), types=types)


def test_color_is_kept_through_save_and_load(tmp_path):
    ex = two_types(["#e0b030", "dark green"])
    assert [t["color"] for t in ex.types] == ["#e0b030", "dark green"]
    tessera.save(ex, tmp_path / "ex.json")
    written = json.loads((tmp_path / "ex.json").read_text())
    assert [t["color"] for t in written["types"]] == ["#e0b030", "dark green"]
    assert [t["color"] for t in tessera.load(tmp_path / "ex.json").types] == ["#e0b030", "dark green"]


def test_unknown_color_is_an_option_error_naming_it():
    with pytest.raises(tessera.OptionError, match="blurple"):
        two_types(["#e0b030", "blurple"])


def test_render_draws_the_colors_and_a_legend(tmp_path):
    ex = two_types(["#e0b030", "darkgreen"])
    tessera.render(ex, tmp_path / "with.svg", width=400)
    tessera.render(ex, tmp_path / "without.svg", width=400, legend=False)
    with_legend = (tmp_path / "with.svg").read_text()
    assert 'fill="#e0b030"' in with_legend and 'fill="#006400"' in with_legend
    assert ">banana</text>" in with_legend and ">leaf</text>" in with_legend
    assert "<text" not in (tmp_path / "without.svg").read_text()
