# Renders probe directions of a World set up by the blender preset's nephele_world.py, in
# Blender (background mode), and prints one line per probe:
#   PROBE <mapping_y> <latitude> <longitude> <value>
# Usage: blender -b --factory-startup --python-exit-code 1 --python scripts/blender_probe.py --
#        DIR/nephele_world.py DIR/cover_equirect.exr LAT LON [LAT LON ...]
# A camera at the origin looks at each direction (latitude, longitude on nephele's axes: +X
# 0 N 0 E, +Y 0 N 90 E, +Z north) through a 1-degree field; Cycles renders 4 x 4 pixels of the
# background with the Standard view transform, so a pixel is the texture's value. Each probe is
# rendered with the script's Mapping (Y scaled by -1) and again with the Mapping's scale set to
# 1, to show what the reflection changes.
import math
import os
import shutil
import sys
import tempfile

import bpy
from mathutils import Vector

args = sys.argv[sys.argv.index('--') + 1:]
world_script, image = args[0], args[1]
probes = [(float(args[i]), float(args[i + 1])) for i in range(2, len(args), 2)]

sys.argv = [sys.argv[0], '--', image]  # nephele_world.py reads the image path after --
exec(compile(open(world_script).read(), world_script, 'exec'))

scene = bpy.context.scene
scene.render.engine = 'CYCLES'
scene.cycles.samples = 1
scene.cycles.device = 'CPU'
scene.cycles.use_denoising = False  # Debian's Blender has no OpenImageDenoise
scene.world.cycles.sampling_method = 'NONE'  # no importance map: the background is only looked at
scene.render.resolution_x = scene.render.resolution_y = 4
scene.render.resolution_percentage = 100
scene.render.film_transparent = False
scene.view_settings.view_transform = 'Standard'
scene.view_settings.look = 'None'
scene.view_settings.exposure = 0
scene.view_settings.gamma = 1
scene.render.image_settings.file_format = 'OPEN_EXR'
scene.render.image_settings.color_depth = '32'
for obj in list(scene.objects):
    bpy.data.objects.remove(obj)
camera_data = bpy.data.cameras.new('probe')
camera_data.angle = math.radians(1.0)
camera = bpy.data.objects.new('probe', camera_data)
scene.collection.objects.link(camera)
scene.camera = camera
mapping = next(n for n in scene.world.node_tree.nodes if n.type == 'MAPPING')

scratch = tempfile.mkdtemp()
out = os.path.join(scratch, 'probe.exr')
for scale_y in (-1.0, 1.0):
    mapping.inputs['Scale'].default_value = (1.0, scale_y, 1.0)
    for lat, lon in probes:
        la, lo = math.radians(lat), math.radians(lon)
        d = Vector((math.cos(la) * math.cos(lo), math.cos(la) * math.sin(lo), math.sin(la)))
        camera.rotation_mode = 'QUATERNION'
        camera.rotation_quaternion = d.to_track_quat('-Z', 'Y')
        scene.render.filepath = out
        bpy.ops.render.render(write_still=True)
        result = bpy.data.images.load(out)
        pixels = list(result.pixels)
        value = sum(pixels[0::4]) / (len(pixels) // 4)  # mean red
        bpy.data.images.remove(result)
        print('PROBE %g %g %g %.4f' % (scale_y, lat, lon, value), flush=True)
shutil.rmtree(scratch)
