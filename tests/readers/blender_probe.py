# Run by tests/test_foreign_readers.cpp through `blender -b --python` (Blender 3.4, Debian's):
# imports every .glb in $PW_PROBE_DIR with Blender's own glTF importer, as File > Import > glTF
# does, and writes the mesh objects' names, parents and world-space bounds (metres, +Z up) to
# $PW_PROBE_DIR/blender.json.
import json
import os

import numpy as np

if not hasattr(np, "bool"):
    np.bool = bool  # Blender 3.4's glTF importer still uses the alias NumPy 1.24 removed

import bpy
from mathutils import Vector

folder = os.environ["PW_PROBE_DIR"]
out = {}
for name in sorted(os.listdir(folder)):
    if not name.endswith(".glb"):
        continue
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=os.path.join(folder, name))
    lo, hi, objects = [float("inf")] * 3, [float("-inf")] * 3, []
    for obj in bpy.context.scene.objects:
        if obj.type != "MESH":
            continue
        objects.append({"name": obj.name, "parent": obj.parent.name if obj.parent else ""})
        for v in obj.data.vertices:
            w = obj.matrix_world @ Vector(v.co)
            for i in range(3):
                lo[i], hi[i] = min(lo[i], w[i]), max(hi[i], w[i])
    out[name] = {"bounds": lo + hi, "objects": objects}

with open(os.path.join(folder, "blender.json"), "w") as f:
    json.dump(out, f)
