# integrations/blender/tests/check_import.py — checks the add-on's import of tessera JSON
# files, inside Blender:
#
#   blender --background --factory-startup --python-exit-code 1 \
#       --python integrations/blender/tests/check_import.py -- FILE.json [FILE.json ...]
#
# For each file (read here with plain `json`, independently of the add-on's reader) and
# each instancing mode: one object per element, with the element's class, id, pose
# (matrix_world against position/centroid, orientation [w, x, y, z] and scale) for the
# first, middle and last element; prototype collections named by class inside the
# excluded "tessera prototypes"; mesh prototypes with as many vertices as their mesh
# files; rigid mesh instances drawing their prototype; and, when $TESSERA_CLI is set,
# deformable elements matching the meshes of `tessera scene`. The add-on is also
# registered and its operator run once from the File > Import operator id.
# Exits non-zero with one line per failed check.
import json
import math
import os
import subprocess
import sys
import tempfile

import bpy
import mathutils

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))  # integrations/blender

import tessera_blender  # noqa: E402
from tessera_blender import importer  # noqa: E402

TOLERANCE = 1e-5
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
    return condition


def close(a, b, what):
    """Within TOLERANCE relative to the larger magnitude (1 at least)."""
    scale = max(1.0, max(abs(x) for x in list(a) + list(b)))
    worst = max(abs(x - y) for x, y in zip(a, b))
    return check(worst <= TOLERANCE * scale, f"{what}: {tuple(a)} != {tuple(b)} (off by {worst:.3g})")


def mesh_vertex_count(path):
    """Vertices of an OBJ (`v` lines) or ASCII PLY (`element vertex N`) file."""
    with open(path, encoding="utf-8") as f:
        if path.lower().endswith(".ply"):
            for line in f:
                tokens = line.split()
                if tokens[:2] == ["element", "vertex"]:
                    return int(tokens[2])
                if tokens[:1] == ["end_header"]:
                    break
            return None
        return sum(1 for line in f if line.split()[:1] == ["v"])


def expected_elements(doc):
    """Per element: (type name, id, location, quaternion (w, x, y, z), scale)."""
    dim = doc["dimension"]
    types = doc.get("types", [])
    out = []
    for i, e in enumerate(doc["elements"]):
        name = e.get("type", types[0]["name"] if len(types) == 1 else "default")
        points = [e["position"]] if "position" in e else e["samples"]
        points = [list(p) + [0.0] * (3 - dim) for p in points]
        location = [sum(p[k] for p in points) / len(points) for k in range(3)]
        if "orientation" in e:
            q = e["orientation"]
        elif "angle" in e:
            q = [math.cos(e["angle"] / 2), 0.0, 0.0, math.sin(e["angle"] / 2)]
        else:
            q = [1.0, 0.0, 0.0, 0.0]
        length = math.sqrt(sum(c * c for c in q))
        q = [c / length for c in q]
        t = next((t for t in types if t["name"] == name), {})
        if t.get("mesh") and t.get("reference") and t.get("rigid", True):
            # A given layout off centre: the mesh origin is centroid - s R mean(layout).
            ref = [list(r) + [0.0] * (3 - dim) for r in t["reference"]]
            mean = mathutils.Vector([sum(r[k] for r in ref) / len(ref) for k in range(3)])
            offset = mathutils.Quaternion(q) @ mean * e.get("scale", 1.0)
            location = [location[k] - offset[k] for k in range(3)]
        out.append((name, e.get("id", i), location, q, e.get("scale", 1.0)))
    return out


def check_file(path, instancing):
    label = f"{os.path.basename(path)} ({instancing})"
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    result = importer.import_tessera_json(path, instancing=instancing)
    expected = expected_elements(doc)
    type_names = [t["name"] for t in doc.get("types", [])] or list(dict.fromkeys(x[0] for x in expected))
    types = {t["name"]: t for t in doc.get("types", [])}

    # One object per element: everything in the import's collection but the prototypes.
    prototypes_root = next((c for c in result.collection.children if c.name.startswith(importer.PROTOTYPES_NAME)),
                           None)
    if not check(prototypes_root is not None, f"{label}: no '{importer.PROTOTYPES_NAME}' collection"):
        return
    hidden = {o.name for o in prototypes_root.all_objects}
    instances = [o for o in result.collection.all_objects if o.name not in hidden]
    check(len(instances) == len(expected),
          f"{label}: {len(instances)} instance objects for {len(expected)} elements in the JSON")
    check(len(result.objects) == len(expected),
          f"{label}: the import returned {len(result.objects)} objects for {len(expected)} elements")
    check(sorted(o.get("tessera_class", "") for o in instances) == sorted(x[0] for x in expected),
          f"{label}: the instances' classes differ from the JSON's element types")

    # Prototype collections, named by class, excluded from the view layer.
    layer = bpy.context.view_layer.layer_collection
    stack, excluded = [layer], None
    while stack:
        lc = stack.pop()
        if lc.collection == prototypes_root:
            excluded = lc.exclude
        stack.extend(lc.children)
    check(excluded is True, f"{label}: '{prototypes_root.name}' is not excluded from the view layer")
    names = sorted(c.name for c in prototypes_root.children)
    check(names == sorted(type_names), f"{label}: prototype collections {names}, classes {sorted(type_names)}")
    for name in type_names:
        c = result.prototypes.get(name)
        if not check(c is not None and c.name == name and c.get("tessera_class") == name,
                     f"{label}: no prototype collection named '{name}'"):
            continue
        mesh_file = types.get(name, {}).get("mesh")
        if mesh_file:
            mesh_file = os.path.join(os.path.dirname(os.path.abspath(path)), mesh_file)
            meshes = [o for o in c.objects if o.type == "MESH"]
            if check(len(meshes) == 1, f"{label}: class '{name}' has {len(meshes)} prototype meshes, expected 1"):
                count = mesh_vertex_count(mesh_file)
                check(len(meshes[0].data.vertices) == count,
                      f"{label}: prototype of '{name}' has {len(meshes[0].data.vertices)} vertices, "
                      f"{os.path.basename(mesh_file)} has {count}")

    # Class and id of every element (in file order); the pose of the first, middle and
    # last element, and of every element whose id needs more than 31 bits or whose scale
    # is not 1.
    for index, (name, element_id, location, q, s) in enumerate(expected):
        obj = result.objects[index]
        what = f"{label}: element {index} ({obj.name})"
        ok = check(obj.get("tessera_class") == name, f"{what}: class {obj.get('tessera_class')!r}, expected {name!r}")
        ok &= check(str(obj.get("tessera_id")) == str(element_id),
                    f"{what}: id {obj.get('tessera_id')!r}, expected {element_id}")
        if not ok:
            break
        if index not in (0, len(expected) // 2, len(expected) - 1) and element_id < 2 ** 31 and s == 1.0:
            continue
        translation, rotation, scale = obj.matrix_world.decompose()
        close(translation, location, f"{what} translation")
        sign = 1.0 if rotation.dot(mathutils.Quaternion(q)) >= 0 else -1.0
        close([sign * c for c in rotation], q, f"{what} rotation")
        close(scale, (s, s, s), f"{what} scale")
        check(obj.rotation_mode == "QUATERNION", f"{what}: rotation mode {obj.rotation_mode}")
        close(obj.rotation_quaternion, q, f"{what} rotation_quaternion")

    # Rigid elements of mesh types show their prototype.
    for index, obj in enumerate(result.objects):
        name = expected[index][0]
        t = types.get(name, {})
        if not t.get("mesh") or not t.get("rigid", True):
            continue
        if instancing == "collection":
            ok = obj.instance_type == "COLLECTION" and obj.instance_collection == result.prototypes[name]
        else:
            ok = obj.type == "MESH" and obj.data == result.prototypes[name].objects[0].data
        if not check(ok, f"{label}: {obj.name} does not instance the prototype of '{name}'"):
            break
    if instancing == "collection":
        # The evaluated scene draws every instance although the prototypes are excluded.
        # (Rigid elements with a mesh, checked above, and undeformed deformable ones.)
        instancers = sum(1 for o in result.objects if o.instance_type == "COLLECTION")
        depsgraph = bpy.context.evaluated_depsgraph_get()
        drawn = sum(1 for i in depsgraph.object_instances
                    if i.is_instance and i.parent is not None and i.parent.original.instance_type == "COLLECTION"
                    and i.object.type == "MESH")
        check(drawn == instancers, f"{label}: {drawn} instanced meshes drawn for {instancers} collection instances")

    # Against tessera's own scene (when $TESSERA_CLI is set): the glTF pose of rigid mesh
    # instances, and the deformed meshes of deformable elements in the OBJ scene.
    cli = os.environ.get("TESSERA_CLI")
    if not cli:
        return
    with tempfile.TemporaryDirectory() as tmp:
        # glTF with one node per element, so that nodes and elements correspond.
        subprocess.run([cli, "scene", path, "-o", os.path.join(tmp, "scene.gltf"), "--gltf-instancing", "nodes",
                        "-q"], check=True)
        subprocess.run([cli, "scene", path, "-o", os.path.join(tmp, "scene.obj"), "-q"], check=True)
        with open(os.path.join(tmp, "scene.gltf"), encoding="utf-8") as f:
            # The last node is the root that turns z-up to glTF's y-up; the others are the elements.
            nodes = json.load(f)["nodes"][:-1]
        from tessera_blender.data import read_obj_objects
        objects = read_obj_objects(os.path.join(tmp, "scene.obj"))
    check(len(nodes) == len(expected) and len(objects) == len(expected),
          f"{label}: tessera scene has {len(nodes)} glTF nodes and {len(objects)} OBJ objects for {len(expected)}")
    compared = 0
    for index, (obj, node) in enumerate(zip(result.objects, nodes)):
        # tessera refits a rigid pose (Kabsch) when the element's own orientation fits its
        # samples worse than rounding (hand-made exemplars); compare where it cannot have.
        # Default spheres are one unit sphere scaled by the radius in tessera's scene and a
        # sphere of that radius here: they are compared by their world-space vertices below.
        if "translation" not in node or obj.get("tessera_fit_error", 0.0) > 1e-7:
            continue
        if not types.get(expected[index][0], {}).get("mesh"):
            continue
        compared += 1
        what = f"{label}: element {index} ({obj.name}) against tessera's glTF node {node.get('name')!r}"
        translation, rotation, scale = obj.matrix_world.decompose()
        close(translation, node["translation"], f"{what}: translation")
        x, y, z, w = node["rotation"]
        sign = 1.0 if rotation.dot(mathutils.Quaternion((w, x, y, z))) >= 0 else -1.0
        close([sign * c for c in rotation], (w, x, y, z), f"{what}: rotation")
        close(scale, node["scale"], f"{what}: scale")
    instanced = sum(1 for i, n in enumerate(nodes) if "translation" in n and types.get(expected[i][0], {}).get("mesh"))
    deformable = [i for i, x in enumerate(expected)
                  if types.get(x[0], {}).get("mesh") and not types[x[0]].get("rigid", True)]
    for index in sorted({deformable[0], deformable[-1]} if deformable else set()):
        obj = result.objects[index]
        what = f"{label}: deformable element {index} ({obj.name})"
        _, world, _ = objects[index]
        if not check(obj.type == "MESH" and len(obj.data.vertices) == len(world) and obj.get("tessera_deformed"),
                     f"{what}: not tessera's deformed mesh"):
            continue
        for k in sorted({0, len(world) // 2, len(world) - 1}):
            close(obj.matrix_world @ obj.data.vertices[k].co, world[k], f"{what}: vertex {k}")
    # Default shapes: spheres as tessera's (same vertices, in world space).
    spheres = 0
    for index, (obj, (_, world, _)) in enumerate(zip(result.objects, objects)):
        if obj.type == "MESH" and not types.get(expected[index][0], {}).get("mesh"):
            spheres += 1
            if not check(len(obj.data.vertices) == len(world),
                         f"{label}: sphere {index} ({obj.name}) has {len(obj.data.vertices)} vertices, "
                         f"tessera's {len(world)}"):
                break
            if not close(obj.matrix_world @ obj.data.vertices[-1].co, world[-1],
                         f"{label}: sphere {index} ({obj.name}) last vertex against tessera's"):
                break
    print(f"check_import: {label}: {len(expected)} elements; against tessera scene: {compared} of {instanced} "
          f"rigid poses (those whose orientation fits the samples to 1e-7), {len(deformable)} deformed meshes, {spheres} spheres")


def main():
    paths = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if not paths:
        print("usage: blender --background --python check_import.py -- FILE.json [FILE.json ...]")
        sys.exit(2)
    # The add-on registers, its menu entry is in File > Import, and its operator imports.
    bpy.ops.wm.read_factory_settings(use_empty=True)
    tessera_blender.register()
    try:
        menu = bpy.types.TOPBAR_MT_file_import
        check(tessera_blender.menu_func_import in getattr(menu, "_dyn_ui_initialize", lambda: [])(),
              "no tessera entry in File > Import")
        status = bpy.ops.import_scene.tessera_json(filepath=os.path.abspath(paths[0]))
        check(status == {"FINISHED"}, f"import_scene.tessera_json returned {status}")
        check(any(o.get("tessera_class") for o in bpy.data.objects), "the operator imported no element")
    finally:
        tessera_blender.unregister()
    check(not hasattr(bpy.types, "IMPORT_SCENE_OT_tessera_json"), "unregister() left the operator registered")
    for path in paths:
        for instancing in importer.INSTANCING_MODES:
            try:
                check_file(path, instancing)
            except Exception as e:  # an error in the import is a failure of this file
                import traceback
                traceback.print_exc()
                failures.append(f"{os.path.basename(path)} ({instancing}): {type(e).__name__}: {e}")
    if failures:
        for f in failures:
            print("FAIL: " + f)
        print(f"check_import: {len(failures)} failed checks")
        sys.exit(1)
    print(f"check_import: all checks passed for {len(paths)} files")


main()
