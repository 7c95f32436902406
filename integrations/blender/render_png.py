# integrations/blender/render_png.py — imports a tessera JSON file with the add-on and
# renders it with the Workbench engine to a PNG (studio light, class colours, a camera
# framing every element from above at an angle).
#
#   blender --background --factory-startup --python-exit-code 1 \
#       --python integrations/blender/render_png.py -- SCENE.json OUT.png [--width 960] [--height 640]
import argparse
import math
import os
import sys

import bpy
import mathutils

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tessera_blender.importer import import_tessera_json  # noqa: E402


def world_corners(result):
    """Corners of the world-space bounding boxes of everything the import shows."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    mine = {o.name for o in result.collection.all_objects}
    corners = []
    for inst in depsgraph.object_instances:
        parent = inst.parent if inst.is_instance else inst.object
        if parent is None or parent.original.name not in mine or inst.object.type not in {"MESH", "CURVE"}:
            continue
        matrix = inst.matrix_world
        corners += [matrix @ mathutils.Vector(c) for c in inst.object.bound_box]
    return corners


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="render_png.py", description=__doc__)
    parser.add_argument("json")
    parser.add_argument("png")
    parser.add_argument("--width", type=int, default=960)
    parser.add_argument("--height", type=int, default=640)
    args = parser.parse_args(argv)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    result = import_tessera_json(args.json)
    scene = bpy.context.scene
    corners = world_corners(result)
    lo = mathutils.Vector([min(c[k] for c in corners) for k in range(3)])
    hi = mathutils.Vector([max(c[k] for c in corners) for k in range(3)])
    center = (lo + hi) / 2

    # Looking down at 50 degrees from the -y side, turned by 30 degrees about z.
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    scene.collection.objects.link(camera)
    direction = mathutils.Vector((math.sin(math.radians(30)) * math.cos(math.radians(50)),
                                  -math.cos(math.radians(30)) * math.cos(math.radians(50)),
                                  math.sin(math.radians(50))))
    distance = 4.0 * (hi - lo).length + 1.0
    camera.location = center + direction * distance
    camera.rotation_mode = "QUATERNION"
    camera.rotation_quaternion = (-direction).to_track_quat("-Z", "Y")
    camera.data.type = "ORTHO"
    camera.data.clip_end = 2.0 * distance + (hi - lo).length
    # Fit the orthographic frame to the corners seen from the camera.
    to_camera = camera.rotation_quaternion.to_matrix().transposed()
    seen = [to_camera @ (c - center) for c in corners]
    width = max(p.x for p in seen) - min(p.x for p in seen)
    height = max(p.y for p in seen) - min(p.y for p in seen)
    aspect = args.width / args.height
    camera.data.ortho_scale = 1.05 * max(width, height * aspect)
    camera.data.shift_x = (max(p.x for p in seen) + min(p.x for p in seen)) / 2 / camera.data.ortho_scale
    camera.data.shift_y = (max(p.y for p in seen) + min(p.y for p in seen)) / 2 / camera.data.ortho_scale
    scene.camera = camera

    scene.world = bpy.data.worlds.new("tessera background")
    scene.world.color = (0.8, 0.8, 0.8)  # a light grey, as behind tessera's pictures
    scene.render.engine = "BLENDER_WORKBENCH"
    scene.display.shading.light = "STUDIO"
    scene.display.shading.color_type = "MATERIAL"
    scene.display.shading.show_cavity = True
    scene.display.shading.show_shadows = True
    scene.display.render_aa = "FXAA"  # a fraction of the time of the multisampled default, alike here
    scene.render.resolution_x = args.width
    scene.render.resolution_y = args.height
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.render.image_settings.file_format = "PNG"
    scene.render.filepath = os.path.abspath(args.png)
    bpy.ops.render.render(write_still=True)
    print(f"render_png: {len(result.objects)} elements -> {scene.render.filepath}")


main()
