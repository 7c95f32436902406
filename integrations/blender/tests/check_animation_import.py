# integrations/blender/tests/check_animation_import.py — checks the add-on's import of
# animated tessera JSON files (with "frames"), inside Blender:
#
#   blender --background --factory-startup --python-exit-code 1 \
#       --python integrations/blender/tests/check_animation_import.py -- WORK_DIR [ANIMATED.json ...]
#
# It writes a fixture to WORK_DIR, built here so that every sample's place at every frame is
# known: 3 particles circling, 3 threads of 10 samples swaying, a 4 x 5 sheet waving and a
# rigid tetrahedron turning about z, 6 frames 1/12 s apart (frames 1, 3, ..., 11 at 24 fps).
# For it and each further file, in both instancing modes, the scene is evaluated at every
# keyed frame (and half-way between, where the motion is linear) and the particles' and
# rigid elements' poses, the threads' curve points and the sheets' shape-keyed vertices are
# compared with the file's samples. Exits non-zero with one line per failed check.
import json
import math
import os
import sys

import bpy
import mathutils

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))  # integrations/blender

from tessera_blender import importer  # noqa: E402

TOLERANCE = 1e-5
TURN = 0.3  # the tetrahedron's turn about z per frame, radians
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
    return condition


def close(a, b, what):
    worst = max(abs(x - y) for x, y in zip(a, b))
    return check(worst <= TOLERANCE * max(1.0, max(abs(x) for x in list(a) + list(b))),
                 f"{what}: {tuple(a)} != {tuple(b)} (off by {worst:.3g})")


# -- the fixture ---------------------------------------------------------------------

def fixture_samples(kind, index, f):
    if kind == "dot":
        w = 0.7 * f + index
        return [[2.0 * index + 0.3 * math.cos(w), 0.3 * math.sin(w), 0.1 * index]]
    if kind == "noodle":
        return [[0.3 * k + 0.05 * k * math.sin(0.6 * f + index), 3.0 + index, 0.2 * math.sin(0.5 * f + 0.4 * k + index)]
                for k in range(10)]
    if kind == "cloth":
        return [[6.0 + 0.5 * c, 0.5 * r, 0.3 * math.sin(0.8 * f + 0.9 * c + 0.3 * r)] for r in range(4) for c in range(5)]
    a = TURN * f
    layout = [(-0.5, -0.2, -0.1), (0.9, -0.1, 0.0), (0.0, 0.6, 0.05), (0.1, 0.1, 0.7)]
    return [[math.cos(a) * x - math.sin(a) * y + 0.1 * f, math.sin(a) * x + math.cos(a) * y - 3.0, z + 0.5]
            for x, y, z in layout]


def write_fixture(path, frames=6):
    order = [("dot", 0), ("noodle", 0), ("cloth", 0), ("dot", 1), ("noodle", 1), ("shard", 0), ("dot", 2),
             ("noodle", 2)]
    doc = {
        "format": "tessera", "version": 1, "dimension": 3,
        "domain": {"type": "box", "min": [-1, -4, -1], "max": [9, 6, 2]},
        "types": [{"name": "dot", "topology": "none"}, {"name": "noodle", "topology": "thread", "rigid": False},
                  {"name": "cloth", "topology": "sheet", "columns": 5},
                  {"name": "shard", "mesh": os.path.join(HERE, "data", "tetra.obj")}],
        "elements": [dict({"id": 10 + i, "type": kind}, **({"radius": 0.05} if kind == "noodle" else {}))
                     for i, (kind, _) in enumerate(order)],
        "frames": [{"time": f / 12.0, "elements": [
            {"id": 10 + i, "samples": fixture_samples(kind, index, f)} for i, (kind, index) in enumerate(order)]}
            for f in range(frames)],
    }
    with open(path, "w", encoding="utf-8") as out:
        json.dump(doc, out)
    return path


# -- checks --------------------------------------------------------------------------

def frames_of(doc):
    """Per element: its samples at every frame (3D points), from the file."""
    dim = doc["dimension"]
    trails = {e["id"]: [] for e in doc["elements"]}
    for frame in doc["frames"]:
        for e in frame["elements"]:
            points = e["samples"] if "samples" in e else [e["position"]]
            trails[e["id"]].append([list(p) + [0.0] * (3 - dim) for p in points])
    return [trails[e["id"]] for e in doc["elements"]]


def world_points(obj, depsgraph):
    """The evaluated object's points in world space: curve points or mesh vertices."""
    evaluated = obj.evaluated_get(depsgraph)
    if obj.type == "CURVE":
        local = [p.co.xyz for p in evaluated.data.splines[0].points]
    else:
        mesh = evaluated.to_mesh()
        local = [v.co.copy() for v in mesh.vertices]
        evaluated.to_mesh_clear()
    return [evaluated.matrix_world @ p for p in local]


def mix(a, b, t):
    return [[(1 - t) * x + t * y for x, y in zip(p, q)] for p, q in zip(a, b)]


def check_at(label, result, trails, frame, expected_index, t=0.0):
    """The scene at `frame` against the samples blended between frames f and f + 1 by t."""
    scene = bpy.context.scene
    scene.frame_set(int(frame), subframe=frame - int(frame))
    depsgraph = bpy.context.evaluated_depsgraph_get()
    f = expected_index
    for i, (obj, trail) in enumerate(zip(result.objects, trails)):
        samples = trail[f] if t == 0.0 else mix(trail[f], trail[f + 1], t)
        what = f"{label}: element {i} ({obj.name}) at frame {frame}"
        shape = obj.get("tessera_shape")
        if shape in ("curve", "grid"):
            points = world_points(obj, depsgraph)
            if check(len(points) == len(samples), f"{what}: {len(points)} points for {len(samples)} samples"):
                for k in sorted({0, len(points) // 2, len(points) - 1}):
                    close(points[k], samples[k], f"{what}: point {k}")
            continue
        centroid = [sum(p[c] for p in samples) / len(samples) for c in range(3)]
        translation, rotation, _ = obj.evaluated_get(depsgraph).matrix_world.decompose()
        close(translation, centroid, f"{what}: location")
        if obj.get("tessera_class") == "shard" and t == 0.0:
            q = mathutils.Quaternion((0.0, 0.0, 1.0), TURN * f)
            sign = 1.0 if rotation.dot(q) >= 0 else -1.0
            close([sign * c for c in rotation], q, f"{what}: rotation")


def check_file(path, instancing, is_fixture):
    label = f"{os.path.basename(path)} ({instancing})"
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.context.scene.render.fps = 24
    result = importer.import_tessera_json(path, instancing=instancing)
    times = [frame["time"] for frame in doc["frames"]]
    expected_frames = [1 + (t - times[0]) * 24 for t in times]
    if not check(result.frames is not None and len(result.frames) == len(times), f"{label}: frames {result.frames}"):
        return
    for got, want in zip(result.frames, expected_frames):
        check(abs(got - want) < 1e-9, f"{label}: keyed frame {got}, expected {want}")
    check(bpy.context.scene.frame_end == math.ceil(expected_frames[-1] - 1e-9),
          f"{label}: scene frame_end {bpy.context.scene.frame_end}")
    check(len(result.objects) == len(doc["elements"]), f"{label}: {len(result.objects)} objects")
    trails = frames_of(doc)
    for f, frame in enumerate(result.frames):
        check_at(label, result, trails, frame, f)
        if f + 1 < len(result.frames):
            check_at(label, result, trails, 0.5 * (frame + result.frames[f + 1]), f, 0.5)
    if is_fixture:
        kinds = {o.get("tessera_class"): o for o in result.objects}
        check(kinds["noodle"].type == "CURVE", f"{label}: a thread is a {kinds['noodle'].type}")
        cloth = kinds["cloth"]
        check(cloth.type == "MESH" and len(cloth.data.polygons) == 12, f"{label}: the sheet is not 12 quads")
        keys = cloth.data.shape_keys.key_blocks if cloth.data.shape_keys else []
        check([k.name for k in keys] == ["Basis"] + [f"frame {f}" for f in range(len(times))],
              f"{label}: the sheet's shape keys are {[k.name for k in keys]}")
    print(f"check_animation_import: {label}: {len(doc['elements'])} elements x {len(times)} frames")


def main():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if not args:
        print("usage: blender --background --python check_animation_import.py -- WORK_DIR [ANIMATED.json ...]")
        sys.exit(2)
    fixture = write_fixture(os.path.join(args[0], "animated_fixture_3d.json"))
    paths = [fixture] + args[1:]
    # The operator takes animated files too.
    bpy.ops.wm.read_factory_settings(use_empty=True)
    import tessera_blender
    tessera_blender.register()
    try:
        status = bpy.ops.import_scene.tessera_json(filepath=fixture)
        check(status == {"FINISHED"}, f"import_scene.tessera_json returned {status} for the animated fixture")
    finally:
        tessera_blender.unregister()
    for path in paths:
        for instancing in importer.INSTANCING_MODES:
            try:
                check_file(path, instancing, path == fixture)
            except Exception as e:  # an error in the import is a failure of this file
                import traceback
                traceback.print_exc()
                failures.append(f"{os.path.basename(path)} ({instancing}): {type(e).__name__}: {e}")
    if failures:
        for f in failures:
            print("FAIL: " + f)
        print(f"check_animation_import: {len(failures)} failed checks")
        sys.exit(1)
    print(f"check_animation_import: all checks passed for {len(paths)} files")


main()
