"""Bad arguments raise ValueError subclasses whose message names the argument; file
problems raise OSError subclasses; nothing is written by a failed call."""
import numpy as np
import pytest

import tessera


@pytest.mark.parametrize("kwargs, needle", [
    (dict(radius=-1.0), "radius"),
    (dict(k=0), "k must be an integer >= 1, got 0"),
    (dict(relax_sweeps=-1), "relax_sweeps must be an integer from 0 to 1000, got -1"),
    (dict(search="fast"), "search must be kcoherence or exhaustive"),
    (dict(matching="best"), "matching must be greedy or hungarian"),
    (dict(iterations=-2), "iterations"),
    (dict(threads=-1), "threads"),
    (dict(method="magic"), "method must be 'det', 'pcf' or 'dynamic'"),
    (dict(domain="circle:4"), "domain: expected box:"),
    (dict(domain="box:10,10,10"), "is 3D but the exemplar is 2D"),
    (dict(domain=(1, 2, 3)), "domain must be"),
    (dict(scale=-1), "scale must be a number > 0"),
    (dict(max_fails=10), "max_fails applies to method='pcf' only"),
    (dict(method="pcf", radius=1.0), "radius applies to method='det' or 'dynamic' only"),
    (dict(method="dynamic", k=8), "k applies to method='det' only"),
    (dict(method="dynamic", matches=0), "matches must be an integer from 1 to 8, got 0"),
    (dict(method="pcf", grid_cells=0), "grid_cells must be an integer from 1 to 4096, got 0"),
    (dict(gravity="down"), "gravity: expected an axis"),
    (dict(boundary="-x"), "boundary needs boundary_distance > 0"),
    (dict(field="spiral:1,2"), "field"),
    (dict(progress=42), "progress must be callable"),
])
def test_bad_options_raise_value_errors_naming_them(two_class, kwargs, needle):
    with pytest.raises(ValueError) as error:
        tessera.synthesize(two_class, **{"iterations": 1, **kwargs})
    assert isinstance(error.value, tessera.TesseraError)
    assert needle in str(error.value)


@pytest.mark.parametrize("kwargs, needle", [
    (dict(positions=np.zeros(5)), "positions must be an N x 2 or N x 3 array, got shape (5,)"),
    (dict(positions=np.zeros((4, 2)), classes=[0, 1]), "classes must have 4 rows"),
    (dict(positions=np.zeros((2, 2)), classes=[0, 1], class_names=["a"]), "class_names has 1 names"),
    (dict(positions=np.zeros((2, 2)), radii=[1.0, -1.0], domain=((0, 0), (1, 1))), "radius"),
    (dict(positions=np.zeros((2, 2)), orientations=np.zeros((2, 4)), domain=((0, 0), (1, 1))),
     "orientations must be unit quaternions"),
    (dict(positions=np.zeros((3, 2)), element_of_sample=[0, 2, 2]), "element_of_sample must number"),
    (dict(positions=np.zeros((2, 2)), ids=[4, 4], domain=((0, 0), (1, 1))), "ids must be unique"),
    (dict(positions=np.zeros((2, 2))), "no extent along x"),
    (dict(positions=np.zeros((2, 2)), types=[{"name": "x"}], domain=((0, 0), (1, 1))),
     "'x' is not one of class_names"),
])
def test_bad_arrays_raise_value_errors_naming_them(kwargs, needle):
    with pytest.raises(ValueError) as error:
        tessera.exemplar(**kwargs)
    assert needle in str(error.value)


def test_file_errors_are_os_errors(tmp_path):
    with pytest.raises(OSError) as error:
        tessera.load(tmp_path / "missing.json")
    assert isinstance(error.value, tessera.FileError)
    assert "missing.json" in str(error.value)


def test_malformed_files_are_input_errors(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y\n1,2\n3,oops\n")
    with pytest.raises(tessera.InputError) as error:
        tessera.load(bad)
    assert "bad.csv:3:" in str(error.value) and "'oops'" in str(error.value)


def test_a_failed_save_leaves_no_file(two_class, tmp_path):
    with pytest.raises(tessera.OptionError):
        tessera.save(two_class, tmp_path / "out.unknown")
    assert list(tmp_path.iterdir()) == []
