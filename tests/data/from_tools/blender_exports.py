# Writes this folder's Blender files with Blender's own exporters (run by make_files.sh; Blender 3.4):
#   suzanne.obj (moved to assets/), suzanne.ply (binary), suzanne.stl (binary): Blender's test character, quads
#     and triangles, with the exporters' default settings;
#   suzanne_subsurf.glb: the same with one level of Subdivision Surface applied on export, as glTF;
#   scan_sphere.ply (ASCII): a sphere with a hole at its north cap and a bow-tie on its equator (of the four faces
#     around a vertex, two opposite ones kept), the defects of a scan.
import os
import sys

import bmesh
import bpy

out = sys.argv[sys.argv.index("--") + 1]


def fresh():
    bpy.ops.wm.read_factory_settings(use_empty=True)


fresh()
bpy.ops.mesh.primitive_monkey_add()
bpy.ops.wm.obj_export(filepath=os.path.join(out, "suzanne.obj"), export_materials=False)
bpy.ops.export_mesh.ply(filepath=os.path.join(out, "suzanne.ply"))
bpy.ops.export_mesh.stl(filepath=os.path.join(out, "suzanne.stl"), use_selection=True)
bpy.context.active_object.modifiers.new("subsurf", "SUBSURF").levels = 1
bpy.ops.export_scene.gltf(filepath=os.path.join(out, "suzanne_subsurf.glb"), export_format="GLB",
                          export_apply=True)

fresh()
bpy.ops.mesh.primitive_uv_sphere_add(segments=16, ring_count=10)
sphere = bpy.context.active_object
bm = bmesh.new()
bm.from_mesh(sphere.data)
cap = [f for f in bm.faces if f.calc_center_median().z > 0.85]
corner = min(bm.verts, key=lambda v: (v.co - v.co.__class__((1.0, 0.0, 0.0))).length)
ring = sorted(corner.link_faces, key=lambda f: (f.calc_center_median() - corner.co).to_2d().angle_signed((0.0, 1.0)))
bmesh.ops.delete(bm, geom=cap + ring[1::2], context="FACES_ONLY")
bm.to_mesh(sphere.data)
bm.free()
bpy.ops.export_mesh.ply(filepath=os.path.join(out, "scan_sphere.ply"), use_ascii=True, use_normals=False,
                        use_uv_coords=False, use_colors=False)
