# tessera_blender/animation.py — the keyframes of an animated tessera file (docs/format.md,
# "Animations (frames)") on the objects the importer made at frame 0's pose:
# - posed objects (rigid meshes, spheres, deformable meshes of untopological types) get
#   location and rotation_quaternion keys: the best rotation of frame 0's samples onto
#   frame f's (about z in 2D), so a rigid element turns as its samples do;
# - curves (threads) get keys on their points' coordinates, splines[0].points[k].co. In
#   Blender 3.4 a curve's points are animatable properties evaluated every frame, so the
#   keys are the motion itself, one F-curve per coordinate, retimable in the Graph Editor;
#   shape keys would store the whole curve once per frame and need a value curve per frame
#   on top, for the same result;
# - grid meshes (sheets) get one shape key per frame, "frame 0", "frame 1", ..., relative
#   to the basis (frame 0), each keyed 0 -> 1 -> 0 around its frame.
# Every key is LINEAR: between frames the samples move in straight lines, as in tessera's
# USD and glTF outputs (for the shape keys, one-hot values blended linearly give exactly
# that). Keys sit at scene.frame_start + (t - t0) x the scene's frame rate: fractional
# frame numbers when the times do not fall on frames, which Blender interpolates.
import math

import bpy
import mathutils
import numpy


def frame_numbers(times, scene):
    """The scene frame of each time stamp, at the scene's frame rate."""
    fps = scene.render.fps / scene.render.fps_base
    return [round(scene.frame_start + (t - times[0]) * fps, 9) for t in times]  # no float noise in the UI


def add_keyframes(doc, objects, context):
    """Keys every element object of an animated import (objects[i] is element i); returns the
    frame numbers. The scene's frame range becomes the animation's."""
    scene = context.scene
    frames = frame_numbers(doc.times, scene)
    for e, obj in zip(doc.elements, objects):
        if obj.get("tessera_shape") == "curve":
            _curve_keys(e, obj, frames)
        elif obj.get("tessera_shape") == "grid":
            _shape_keys(e, obj, frames)
        else:
            _pose_keys(doc, e, obj, frames)
    scene.frame_end = max(scene.frame_start, math.ceil(frames[-1] - 1e-9))
    return frames


# -- keys ----------------------------------------------------------------------------

def _fcurves(id_data, data_path, frames, values, components):
    """One LINEAR F-curve per component of `data_path` on `id_data`, a key per frame."""
    animation = id_data.animation_data or id_data.animation_data_create()
    if animation.action is None:
        animation.action = bpy.data.actions.new(f"{id_data.name} tessera")
    for c in range(components):
        curve = animation.action.fcurves.new(data_path, index=c)
        curve.keyframe_points.add(len(frames))
        curve.keyframe_points.foreach_set("co", [x for f, v in zip(frames, values) for x in (f, v[c])])
        for key in curve.keyframe_points:
            key.interpolation = "LINEAR"
        curve.update()


def _local(obj, point):
    """A world point in the object's frame-0 frame (its location, rotation and scale)."""
    inverse = obj.rotation_quaternion.conjugated()
    return (inverse @ (mathutils.Vector(point) - obj.location)) / obj.scale[0]


def _curve_keys(element, obj, frames):
    for k in range(len(element.samples)):
        values = [tuple(_local(obj, samples[k])) for samples in element.frames]
        _fcurves(obj.data, f"splines[0].points[{k}].co", frames, values, 3)


def _shape_keys(element, obj, frames):
    obj.shape_key_add(name="Basis", from_mix=False)
    for f, samples in enumerate(element.frames):
        key = obj.shape_key_add(name=f"frame {f}", from_mix=False)
        key.data.foreach_set("co", [c for p in samples for c in _local(obj, p)])
        key.value = 0.0
        near = [g for g in (f - 1, f, f + 1) if 0 <= g < len(frames)]
        _fcurves(obj.data.shape_keys, f'key_blocks["{key.name}"].value', [frames[g] for g in near],
                 [(1.0 if g == f else 0.0,) for g in near], 1)


def _pose_keys(doc, element, obj, frames):
    """Location and rotation per frame: frame 0's pose carried by the best rotation of the
    samples (centred) from frame 0 to frame f, and by their centroid's move."""
    first = [mathutils.Vector(p) for p in element.frames[0]]
    c0 = sum(first, mathutils.Vector()) / len(first)
    offset = obj.location - c0  # the mesh origin's place relative to the centroid
    q0 = obj.rotation_quaternion.copy()
    locations, rotations = [], []
    for samples in element.frames:
        points = [mathutils.Vector(p) for p in samples]
        c = sum(points, mathutils.Vector()) / len(points)
        turn = _best_rotation([p - c0 for p in first], [p - c for p in points], doc.dimension == 2)
        q = turn @ q0
        if rotations and q.dot(mathutils.Quaternion(rotations[-1])) < 0.0:
            q.negate()  # the same rotation, the short way from the previous key
        locations.append(tuple(c + turn @ offset))
        rotations.append(tuple(q))
    _fcurves(obj, "location", frames, locations, 3)
    if any(r != rotations[0] for r in rotations):
        _fcurves(obj, "rotation_quaternion", frames, rotations, 4)


def _best_rotation(a, b, planar):
    """The rotation taking the centred points `a` closest to `b` (Kabsch; no reflection).
    In 2D a rotation about z; for points on a line, the shortest turn of the line."""
    if len(a) < 2:
        return mathutils.Quaternion()
    if planar:
        s = sum(p.x * q.y - p.y * q.x for p, q in zip(a, b))
        c = sum(p.x * q.x + p.y * q.y for p, q in zip(a, b))
        return mathutils.Quaternion((0.0, 0.0, 1.0), math.atan2(s, c))
    h = sum(numpy.outer(tuple(p), tuple(q)) for p, q in zip(a, b))
    u, singular, vt = numpy.linalg.svd(h)
    if singular[1] <= 1e-9 * singular[0]:
        return (a[-1] - a[0]).rotation_difference(b[-1] - b[0])
    d = 1.0 if numpy.linalg.det(vt.T @ u.T) > 0 else -1.0
    r = vt.T @ numpy.diag([1.0, 1.0, d]) @ u.T
    return mathutils.Matrix(r.tolist()).to_quaternion()
