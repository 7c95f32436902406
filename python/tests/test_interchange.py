"""tessera.save writes files that instancing tools open: a strict check of the .usda
PointInstancer, a structural check of the glTF (both instancing modes), Houdini-style PLY
points, and CSV / JSON round trips."""
import json
import re

import numpy as np
import pytest

import tessera


@pytest.fixture
def arrangement(two_class):
    return tessera.synthesize(two_class, seed=9, iterations=2)


def usda_array(text, declaration):
    """The values of `<type>[] <name> = [...]` in a .usda text, as a list of strings."""
    match = re.search(re.escape(declaration) + r" = \[(.*?)\]", text)
    assert match, declaration
    body = match.group(1)
    return re.findall(r"\([^)]*\)", body) if "(" in body else [v.strip() for v in body.split(",")]


def test_usda_is_a_point_instancer_of_every_element(arrangement, tmp_path):
    tessera.save(arrangement, tmp_path / "out.usda")
    text = (tmp_path / "out.usda").read_text()
    assert text.startswith("#usda 1.0\n")
    assert 'upAxis = "Z"' in text and 'defaultPrim = "World"' in text
    assert 'def PointInstancer "Elements"' in text
    n = len(arrangement)
    positions = usda_array(text, "point3f[] positions")
    orientations = usda_array(text, "quath[] orientations")
    scales = usda_array(text, "float3[] scales")
    proto = [int(v) for v in usda_array(text, "int[] protoIndices")]
    ids = [int(v) for v in usda_array(text, "int64[] ids")]
    assert len(positions) == len(orientations) == len(scales) == len(proto) == len(ids) == n
    np.testing.assert_array_equal(ids, arrangement.ids)
    np.testing.assert_array_equal(proto, arrangement.classes)
    xyz = np.array([[float(c) for c in p.strip("()").split(",")] for p in positions])
    np.testing.assert_allclose(xyz[:, :2], arrangement.centroids, rtol=1e-6, atol=1e-5)
    for q in orientations:
        w, x, y, z = (float(c) for c in q.strip("()").split(","))
        assert abs(w * w + x * x + y * y + z * z - 1.0) < 2e-3  # half precision
    # Every prototype the relationship names is defined under the instancer.
    targets = re.search(r"rel prototypes = \[(.*?)\]", text).group(1)
    for target in re.findall(r"<([^>]+)>", targets):
        assert 'def Mesh "%s"' % target.rsplit("/", 1)[1] in text, target
    assert len(re.findall(r"<([^>]+)>", targets)) == len(arrangement.class_names)


@pytest.mark.parametrize("mode", ["gpu", "nodes"])
def test_gltf_instances_every_element(arrangement, tmp_path, mode):
    tessera.save(arrangement, tmp_path / "out.gltf", gltf_instancing=mode)
    doc = json.loads((tmp_path / "out.gltf").read_text())
    assert doc["asset"]["version"] == "2.0"
    nodes = doc["nodes"]
    root = nodes[doc["scenes"][0]["nodes"][0]]
    assert root["name"] == "tessera z-up" and len(root["children"]) == len(nodes) - 1
    instances = 0
    for node in nodes[:-1]:
        ext = node.get("extensions", {}).get("EXT_mesh_gpu_instancing")
        if ext is None:
            instances += 1
            continue
        counts = {doc["accessors"][i]["count"] for i in ext["attributes"].values()}
        assert len(counts) == 1  # every attribute has one value per instance
        instances += counts.pop()
    assert instances == len(arrangement)
    assert ("EXT_mesh_gpu_instancing" in doc.get("extensionsUsed", [])) == (mode == "gpu")
    for accessor in doc["accessors"]:
        view = doc["bufferViews"][accessor["bufferView"]]
        width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[accessor["type"]] * 4
        assert view["byteLength"] == accessor["count"] * width


def test_ply_points_carry_houdini_attributes(arrangement, tmp_path):
    tessera.save(arrangement, tmp_path / "out.ply")
    header, body = (tmp_path / "out.ply").read_text().split("end_header\n")
    names = re.findall(r"property \w+ (\w+)", header)
    assert names[:11] == ["x", "y", "z", "orient_x", "orient_y", "orient_z", "orient_w", "pscale", "class",
                          "id", "radius"]
    assert "element vertex %d" % len(arrangement) in header
    rows = np.array([[float(v) for v in line.split()] for line in body.splitlines()])
    np.testing.assert_allclose(rows[:, :2], arrangement.centroids)
    np.testing.assert_array_equal(rows[:, 8], arrangement.classes)
    np.testing.assert_array_equal(rows[:, 9], arrangement.ids)
    # orient is (x, y, z, w): the arrays' (w, x, y, z) reordered.
    np.testing.assert_allclose(rows[:, 3:7], arrangement.orientations[:, [1, 2, 3, 0]])


def test_csv_round_trip_keeps_the_arrays(arrangement, tmp_path):
    tessera.save(arrangement, tmp_path / "out.csv")
    back = tessera.load(tmp_path / "out.csv", input_domain=arrangement.domain)
    assert back.class_names == arrangement.class_names
    np.testing.assert_allclose(back.positions, arrangement.positions, rtol=1e-12)
    np.testing.assert_array_equal(back.classes, arrangement.classes)
    np.testing.assert_array_equal(back.ids, arrangement.ids)
    np.testing.assert_allclose(back.radii, arrangement.radii)
