# tessera_blender/importer.py — a tessera JSON scene (exemplar, synthesized arrangement or
# animation) as Blender objects: one collection per element class holding the class's
# prototype, and one object per element placed by the element's pose (keyed per frame for
# an animation, animation.py). Usable without the operator:
#
#     from tessera_blender.importer import import_tessera_json
#     result = import_tessera_json("out/scenes/bananas_3d.json")
#
# What becomes what is described in integrations/blender/README.md.
import math
import os
import shutil
import subprocess
import tempfile

import bpy
import mathutils
from mathutils import kdtree

from . import data as tdata
from .data import TesseraFileError

PROTOTYPES_NAME = "tessera prototypes"
INSTANCING_MODES = ("collection", "linked")

# Tableau 10, the class colours of tessera's preview pictures (src/render/palette.hpp), sRGB.
PALETTE = ((0x4e, 0x79, 0xa7), (0xf2, 0x8e, 0x2b), (0xe1, 0x57, 0x59), (0x76, 0xb7, 0xb2),
           (0x59, 0xa1, 0x4f), (0xed, 0xc9, 0x48), (0xb0, 0x7a, 0xa1), (0xff, 0x9d, 0xa7),
           (0x9c, 0x75, 0x5f), (0xba, 0xb0, 0xac))

SMOOTH_ANGLE = math.radians(40.0)  # tessera's pictures split normals at sharper edges
SPHERE_SUBDIVISIONS = 2  # as tessera's default shapes (GeometryOptions)


class ImportResult:
    """What import_tessera_json created.

    collection   the import's top collection (linked to the scene)
    prototypes   class name -> the class's collection (inside the hidden "tessera prototypes")
    objects      one object per element, in the file's element order
    warnings     messages about what could not be built exactly as tessera would
    frames       an animated file's keyed frame numbers, one per time stamp (None when still)
    """

    def __init__(self, collection, prototypes, objects, warnings, frames=None):
        self.collection = collection
        self.prototypes = prototypes
        self.objects = objects
        self.warnings = warnings
        self.frames = frames


def object_name(type_name, element_id):
    """`<type>_<id>`, whitespace replaced by `_`: the name tessera's scene writers give
    the element's node or object."""
    return "".join("_" if c.isspace() else c for c in type_name) + "_" + str(element_id)


def find_tessera(tessera=None):
    """The tessera executable: `tessera` if given, else $TESSERA_CLI, else `tessera` on PATH."""
    for candidate in (tessera, os.environ.get("TESSERA_CLI"), "tessera"):
        if candidate:
            found = shutil.which(candidate)
            if found:
                return found
    return None


def import_tessera_json(path, collection_name=None, instancing="collection", scene_obj=None, tessera=None,
                        context=None):
    """Imports the tessera JSON file `path` into the current scene; returns an ImportResult.

    collection_name  name of the new top collection (default "tessera <file stem>")
    instancing       "collection": rigid elements of a type with a mesh are Empties instancing
                     the class collection; "linked": mesh objects sharing the class's mesh data
    scene_obj        an OBJ scene written by `tessera scene` for this file, for the
                     per-element meshes of deformable types; when not given and the file has
                     deformable types with meshes, the tessera executable (`tessera`,
                     $TESSERA_CLI or PATH) writes one to a temporary directory
    An animated file (with "frames") is built at frame 0 and keyed at every frame
    (tessera_blender.animation); the scene's frame range becomes the animation's.
    Raises TesseraFileError (a ValueError) naming the file for data that cannot be read."""
    if instancing not in INSTANCING_MODES:
        raise ValueError(f"instancing must be one of {', '.join(INSTANCING_MODES)}, got {instancing!r}")
    context = context or bpy.context
    doc = tdata.load_document(path)
    warnings = []
    stem = os.path.splitext(os.path.basename(doc.path))[0]

    # Everything that can fail on reading comes first, before anything is created.
    meshes = {}
    for t in doc.types:
        if t.mesh:
            try:
                meshes[t.name] = tdata.read_mesh(t.mesh)
            except TesseraFileError as e:
                raise TesseraFileError(f"element type '{t.name}': {e}") from None
    shapes = [_sample_shape(doc, i) for i in range(len(doc.types))]
    for e in doc.elements:
        columns = doc.types[e.type].columns
        if shapes[e.type] == "grid" and (len(e.samples) % columns or len(e.samples) < 2 * columns):
            raise TesseraFileError(f"{doc.path}: type '{doc.types[e.type].name}' is a sheet but its "
                                   f"{len(e.samples)} samples are not a grid of {columns} columns and 2 or more rows")
    deformed = _deformed_meshes(doc, scene_obj, tessera, warnings, shapes)

    top = bpy.data.collections.new(collection_name or f"tessera {stem}")
    context.scene.collection.children.link(top)
    top["tessera_file"] = doc.path
    prototypes_root = bpy.data.collections.new(PROTOTYPES_NAME)
    top.children.link(prototypes_root)
    for layer in context.scene.view_layers:
        found = _layer_collection(layer.layer_collection, prototypes_root)
        if found is not None:
            found.exclude = True  # the prototypes are only seen through their instances

    materials = [_material(t.name, i) for i, t in enumerate(doc.types)]
    prototypes = {}
    class_mesh = {}
    for i, t in enumerate(doc.types):
        c = bpy.data.collections.new(t.name)
        c["tessera_class"] = t.name
        prototypes_root.children.link(c)
        prototypes[t.name] = c
        if t.name in meshes:
            vertices, faces = meshes[t.name]
            mesh = _new_mesh(t.name, vertices, faces, materials[i])
            prototype = bpy.data.objects.new(t.name, mesh)
            prototype["tessera_class"] = t.name
            prototype["tessera_mesh"] = t.mesh
            c.objects.link(prototype)
            class_mesh[i] = mesh

    # Rigid types with a mesh: the pose of the mesh's origin. Without a reference layout
    # the origin is the samples' centroid (derived layouts are centred); a given layout
    # may be off centre, and the mesh then sits at centroid - scale * R * mean(layout).
    reference = {}
    for i, t in enumerate(doc.types):
        first = next((e for e in doc.elements if e.type == i), None)
        if first is not None and i in class_mesh:
            reference[i] = t.reference or tdata.derived_reference(first)
    spacing = None  # for default shapes of elements without a radius, computed on need

    element_collections = {}
    sphere_meshes = {}
    objects = []
    for e in doc.elements:
        t = doc.types[e.type]
        material = materials[e.type]
        if e.type not in element_collections:
            c = bpy.data.collections.new(f"{t.name} elements")
            top.children.link(c)
            element_collections[e.type] = c
        name = object_name(t.name, e.id)
        location = mathutils.Vector(e.position)
        rotation = mathutils.Quaternion(e.orientation)
        fit_error = None
        is_deformed = None
        if e.type in class_mesh and t.reference and t.rigid:
            mean = mathutils.Vector([sum(p[k] for p in t.reference) / len(t.reference) for k in range(3)])
            location = location - e.scale * (rotation @ mean)
        shape = shapes[e.type]
        if shape is None and e.type in class_mesh and not t.rigid and e.index in deformed:
            # A mesh of its own: tessera's deformed mesh, brought into the element's frame.
            is_deformed = True
            inverse = rotation.conjugated()
            world, faces = deformed[e.index]
            local = [(inverse @ (mathutils.Vector(v) - location)) / e.scale for v in world]
            obj = bpy.data.objects.new(name, _new_mesh(name, local, faces, material))
        elif shape is None and e.type in class_mesh:
            if not t.rigid:
                is_deformed = False  # no deformed mesh available: the rest shape, posed
            elif len(e.samples) > 1:
                fit_error = _fit_error(reference[e.type], e, location, rotation)
            if instancing == "collection":
                obj = bpy.data.objects.new(name, None)
                obj.instance_type = "COLLECTION"
                obj.instance_collection = prototypes[t.name]
                obj.empty_display_size = 0.25 * _extent(meshes[t.name][0])
            else:
                obj = bpy.data.objects.new(name, class_mesh[e.type])
        else:
            radius = e.radius
            if not radius > 0.0:
                if spacing is None:
                    spacing = _default_spacing(doc)
                radius = (0.5 if len(e.samples) == 1 else 0.2) * spacing
            if len(e.samples) == 1:
                # tessera's icosphere has the element's radius whatever its scale.
                key = round(radius / e.scale, 12)
                if key not in sphere_meshes:
                    sphere_meshes[key] = _new_mesh(f"{t.name} sphere r={radius / e.scale:.6g}",
                                                   *_icosphere(key, SPHERE_SUBDIVISIONS), material)
                    prototype = bpy.data.objects.new(sphere_meshes[key].name, sphere_meshes[key])
                    prototype["tessera_class"] = t.name
                    prototypes[t.name].objects.link(prototype)
                obj = bpy.data.objects.new(name, sphere_meshes[key])
            elif shape == "grid":
                obj = bpy.data.objects.new(name, _grid_mesh(name, e, location, rotation, t.columns, material))
                obj["tessera_shape"] = "grid"
            else:
                obj = bpy.data.objects.new(name, _tube_curve(name, e, location, rotation, radius, material))
                obj["tessera_shape"] = "curve"
        obj.location = location
        obj.rotation_mode = "QUATERNION"
        obj.rotation_quaternion = rotation
        obj.scale = (e.scale, e.scale, e.scale)
        obj["tessera_id"] = e.id if e.id < 2 ** 31 else str(e.id)
        obj["tessera_class"] = t.name
        obj["tessera_radius"] = e.radius
        if fit_error is not None:
            obj["tessera_fit_error"] = fit_error
        if is_deformed is not None:
            obj["tessera_deformed"] = is_deformed
        if e.locked:
            obj["tessera_locked"] = True
        for attribute, value in e.attributes.items():
            obj["tessera_attr_" + attribute] = value
        element_collections[e.type].objects.link(obj)
        objects.append(obj)

    frames = None
    if doc.times is not None and len(doc.times) > 1:
        from . import animation  # needs numpy, which Blender ships; still files do not

        if any(not t.rigid and i in class_mesh and shapes[i] is None for i, t in enumerate(doc.types)):
            warnings.append("deformable elements keep their frame-0 shape in an animation; only their pose moves")
        frames = animation.add_keyframes(doc, objects, context)
    context.view_layer.update()
    for w in warnings:
        print("tessera import: warning: " + w)
    return ImportResult(top, prototypes, objects, warnings, frames)


# -- helpers -------------------------------------------------------------------------

def _layer_collection(layer, collection):
    if layer.collection == collection:
        return layer
    for child in layer.children:
        found = _layer_collection(child, collection)
        if found is not None:
            return found
    return None


def _material(type_name, index):
    material = bpy.data.materials.new(f"tessera {type_name}")
    srgb = PALETTE[index % len(PALETTE)]
    linear = [c / 255.0 / 12.92 if c / 255.0 <= 0.04045 else ((c / 255.0 + 0.055) / 1.055) ** 2.4 for c in srgb]
    material.diffuse_color = (*linear, 1.0)
    material["tessera_class"] = type_name
    return material


def _new_mesh(name, vertices, faces, material):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([tuple(v) for v in vertices], [], [tuple(f) for f in faces])
    mesh.validate(clean_customdata=False)
    mesh.materials.append(material)
    # Smooth shading, split at edges sharper than 40 degrees, like tessera's pictures.
    mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
    if hasattr(mesh, "use_auto_smooth"):  # Blender < 4.1
        mesh.use_auto_smooth = True
        mesh.auto_smooth_angle = SMOOTH_ANGLE
    elif hasattr(mesh, "set_sharp_from_angle"):  # Blender >= 4.1
        mesh.set_sharp_from_angle(angle=SMOOTH_ANGLE)
    mesh.update()
    return mesh


def _extent(vertices):
    if not vertices:
        return 1.0
    return max(max(v[k] for v in vertices) - min(v[k] for v in vertices) for k in range(3)) or 1.0


def _fit_error(reference, element, location, rotation):
    """RMS distance between the reference layout posed by the element's pose and the
    element's samples (tessera's `fit_error` for the element's own pose)."""
    total = 0.0
    for r, p in zip(reference, element.samples):
        posed = location + element.scale * (rotation @ mathutils.Vector(r))
        total += (posed - mathutils.Vector(p)).length_squared
    return math.sqrt(total / len(reference))


def _default_spacing(doc):
    """tessera's default-shape spacing: the mean nearest-neighbour distance between
    element centroids; for a lone element the mean distance between its consecutive
    samples; else 1."""
    n = len(doc.elements)
    if n >= 2:
        tree = kdtree.KDTree(n)
        for i, e in enumerate(doc.elements):
            tree.insert(e.position, i)
        tree.balance()
        total = 0.0
        for i, e in enumerate(doc.elements):
            for _, j, distance in tree.find_n(e.position, 2):
                if j != i:
                    total += distance
                    break
        if total > 0.0:
            return total / n
    gaps = [math.dist(a, b) for e in doc.elements for a, b in zip(e.samples, e.samples[1:])]
    if gaps and sum(gaps) > 0.0:
        return sum(gaps) / len(gaps)
    return 1.0


def _icosphere(radius, subdivisions):
    """tessera's icosphere (src/geometry/shapes.cpp): the same vertices and faces."""
    g = (1.0 + math.sqrt(5.0)) / 2.0
    unit = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g),
            (0, -1, -g), (0, 1, -g), (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    unit = [mathutils.Vector(v).normalized() for v in unit]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
             (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        midpoint = {}

        def middle(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoint:
                unit.append((unit[a] + unit[b]).normalized())
                midpoint[key] = len(unit) - 1
            return midpoint[key]

        finer = []
        for a, b, c in faces:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = finer
    return [u * radius for u in unit], faces


def _sample_shape(doc, type_index):
    """How a type is drawn through its samples: "grid" for sheets without a mesh (and in
    animated files without a rigid mesh), "curve" for threads without a rigid mesh in
    animated files, as tessera's animated USD and glTF draw them; None otherwise (a mesh,
    a sphere, or a still file's tube)."""
    t = doc.types[type_index]
    animated = doc.times is not None
    if t.mesh and (t.rigid or not animated):
        return None
    topology = doc.topology(type_index)
    if topology == "sheet":
        return "grid"
    return "curve" if topology == "thread" and animated else None


def _grid_mesh(name, element, location, rotation, columns, material):
    """The quads of a sheet's sample grid (sample id = row x columns + column), in the
    element's frame, all wound alike: (r, c), (r, c + 1), (r + 1, c + 1), (r + 1, c)."""
    inverse = rotation.conjugated()
    vertices = [(inverse @ (mathutils.Vector(p) - location)) / element.scale for p in element.samples]
    rows = len(vertices) // columns
    faces = [(a, a + 1, a + columns + 1, a + columns)
             for a in (r * columns + c for r in range(rows - 1) for c in range(columns - 1))]
    return _new_mesh(name, vertices, faces, material)


def _tube_curve(name, element, location, rotation, radius, material):
    """A poly curve through the samples (in the element's frame) with a round bevel of
    the tube's radius: the default shape of multi-sample elements without a mesh."""
    curve = bpy.data.curves.new(name, "CURVE")
    curve.dimensions = "3D"
    curve.bevel_depth = radius / element.scale  # the object's scale brings it back
    curve.bevel_resolution = 3
    curve.use_fill_caps = True
    spline = curve.splines.new("POLY")
    spline.points.add(len(element.samples) - 1)
    inverse = rotation.conjugated()
    for point, p in zip(spline.points, element.samples):
        local = (inverse @ (mathutils.Vector(p) - location)) / element.scale
        point.co = (local.x, local.y, local.z, 1.0)
    curve.materials.append(material)
    return curve


def _deformed_meshes(doc, scene_obj, tessera, warnings, shapes):
    """Element index -> (world vertices, faces) of every element of a deformable type with a
    mesh (not drawn through its samples, `shapes`), from an OBJ scene written by tessera
    (given, or written now by the tessera executable; of frame 0 for an animated file).
    Empty, with a warning, when there is none."""
    wanted = [e for e in doc.elements
              if doc.types[e.type].mesh and not doc.types[e.type].rigid and shapes[e.type] is None]
    if not wanted:
        return {}
    with tempfile.TemporaryDirectory(prefix="tessera-blender-") as tmp:
        if scene_obj is None:
            executable = find_tessera(tessera)
            if executable is None:
                warnings.append("deformable types are shown undeformed (their rest mesh posed by each element's "
                                "pose): no tessera executable to rebuild their meshes (give scene_obj=, "
                                "tessera= or set TESSERA_CLI)")
                return {}
            scene_obj = os.path.join(tmp, "scene.obj")
            run = subprocess.run([executable, "scene", doc.path, "-o", scene_obj, "--quiet"],
                                 capture_output=True, text=True)
            if run.returncode != 0:
                warnings.append(f"deformable types are shown undeformed: '{executable} scene' failed: "
                                f"{run.stderr.strip()}")
                return {}
        objects = tdata.read_obj_objects(scene_obj)
    if len(objects) != len(doc.elements):
        raise TesseraFileError(f"{scene_obj}: {len(objects)} objects for {len(doc.elements)} elements; "
                               "is it the scene of this file?")
    result = {}
    for e in wanted:
        name, vertices, faces = objects[e.index]
        if name != object_name(doc.types[e.type].name, e.id):
            raise TesseraFileError(f"{scene_obj}: object {e.index} is '{name}', expected "
                                   f"'{object_name(doc.types[e.type].name, e.id)}'; is it the scene of this file?")
        result[e.index] = (vertices, faces)
    return result
