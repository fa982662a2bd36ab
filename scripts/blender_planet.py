# Renders a cover exported with `nephele export --preset blender` on a sphere, as a picture for
# docs/export.md: coverage as white over blue, seen from above LAT, LON.
# Usage: blender -b --factory-startup --python scripts/blender_planet.py --
#        DIR/cover_equirect.exr OUT.png [LAT LON]
# The sphere's material uses the preset's chain: object direction -> Mapping (Y scaled by -1)
# -> Environment Texture (equirectangular), so the map is unmirrored on the planet too.
import math
import sys

import bpy
from mathutils import Vector

args = sys.argv[sys.argv.index('--') + 1:]
image, out = args[0], args[1]
lat, lon = (math.radians(float(args[2])), math.radians(float(args[3]))) if len(args) > 3 else (math.radians(30), math.radians(60))

scene = bpy.context.scene
for obj in list(scene.objects):
    bpy.data.objects.remove(obj)
bpy.ops.mesh.primitive_uv_sphere_add(segments=128, ring_count=64, radius=1.0)
sphere = bpy.context.active_object
bpy.ops.object.shade_smooth()
material = bpy.data.materials.new('nephele_clouds')
material.use_nodes = True
nodes, links = material.node_tree.nodes, material.node_tree.links
nodes.clear()
coords = nodes.new('ShaderNodeTexCoord')
mapping = nodes.new('ShaderNodeMapping')
mapping.inputs['Scale'].default_value = (1.0, -1.0, 1.0)
texture = nodes.new('ShaderNodeTexEnvironment')
texture.image = bpy.data.images.load(image)
texture.image.colorspace_settings.name = 'Non-Color'
mix = nodes.new('ShaderNodeMixRGB')
mix.inputs['Color1'].default_value = (0.05, 0.15, 0.45, 1.0)
mix.inputs['Color2'].default_value = (1.0, 1.0, 1.0, 1.0)
emission = nodes.new('ShaderNodeEmission')
output = nodes.new('ShaderNodeOutputMaterial')
links.new(coords.outputs['Object'], mapping.inputs['Vector'])
links.new(mapping.outputs['Vector'], texture.inputs['Vector'])
links.new(texture.outputs['Color'], mix.inputs['Fac'])
links.new(mix.outputs['Color'], emission.inputs['Color'])
links.new(emission.outputs['Emission'], output.inputs['Surface'])
sphere.data.materials.append(material)

direction = Vector((math.cos(lat) * math.cos(lon), math.cos(lat) * math.sin(lon), math.sin(lat)))
camera = bpy.data.objects.new('camera', bpy.data.cameras.new('camera'))
camera.data.angle = math.radians(35)
camera.location = direction * 4.0
camera.rotation_mode = 'QUATERNION'
camera.rotation_quaternion = (-direction).to_track_quat('-Z', 'Z')
scene.collection.objects.link(camera)
scene.camera = camera
scene.render.engine = 'CYCLES'
scene.cycles.samples = 16
scene.cycles.use_denoising = False
scene.render.resolution_x = scene.render.resolution_y = 320
scene.view_settings.view_transform = 'Standard'
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
