# Loads a density.vdb written by `nephele model` as a Blender Volume object (background mode)
# and prints what Blender sees: the grids with their class and type, and the object's bounding
# box in metres (Blender bounds the active leaf nodes of 8^3 voxels, voxel centre to centre). Usage: blender -b --factory-startup --python scripts/blender_volume_probe.py -- FILE.vdb
import sys

import bpy
from mathutils import Vector

path = sys.argv[sys.argv.index('--') + 1]
bpy.ops.object.volume_import(filepath=path, align='WORLD', location=(0, 0, 0))
obj = bpy.context.active_object
volume = obj.data
volume.grids.load()
for grid in volume.grids:
    print('GRID %s %s %d' % (grid.name, grid.data_type, grid.channels), flush=True)
corners = [obj.matrix_world @ Vector(c) for c in obj.bound_box]
low = [min(c[i] for c in corners) for i in range(3)]
high = [max(c[i] for c in corners) for i in range(3)]
print('BOUNDS %.3f %.3f %.3f %.3f %.3f %.3f' % (*low, *high), flush=True)
