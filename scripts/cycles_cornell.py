"""Blender (Cycles) side of scripts/cycles-compare.sh: builds raylab's Cornell box from the OBJ that
`raylab convert cornell` writes, with raylab's camera, albedos and lamp radiance, and renders it
with Cycles on the CPU, denoiser off, at the samples and bounces asked for. Prints
"cycles-seconds N" (the render call, scene sync and BVH build included; Blender's start-up not).

Run by the driver: blender -b --factory-startup -P scripts/cycles_cornell.py -- OBJ OUT.exr SPP
MAX_DEPTH THREADS SEED SIZE
"""

import math
import sys
import time

import bpy
from mathutils import Vector

obj_path, out_path, spp, max_depth, threads, seed, size = sys.argv[sys.argv.index("--") + 1 :]
spp, max_depth, threads, seed, size = int(spp), int(max_depth), int(threads), int(seed), int(size)

# raylab's Cornell box (src/scene/cornell_scene.cpp): the lamp's radiance is emission x strength.
LAMP_STRENGTH = 15.0
VFOV = 2.0 * math.atan(12.5 / 35.0)

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene

# raylab is y-up; the importer turns the OBJ's y-up into Blender's z-up: (x, y, z) -> (x, -z, y).
bpy.ops.wm.obj_import(filepath=obj_path, forward_axis="NEGATIVE_Z", up_axis="Y")


def to_blender(v):
    return Vector((v[0], -v[2], v[1]))


# Materials: raylab's Phong "kd x color" diffuse albedo, and the lamp's emission (on its
# front side only, as raylab's) over its diffuse base, from the MTL the importer read.
for mat in bpy.data.materials:
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    bsdf = next((n for n in nodes if n.type == "BSDF_PRINCIPLED"), None)
    base = tuple(bsdf.inputs["Base Color"].default_value) if bsdf else (0.8, 0.8, 0.8, 1.0)
    emission = tuple(bsdf.inputs["Emission"].default_value) if bsdf else (0, 0, 0, 1)
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = base
    if max(emission[:3]) > 0.0:
        # raylab's emitters emit on their front side only: Cycles' backfacing flag picks the
        # plain diffuse base behind.
        emit = nodes.new("ShaderNodeEmission")
        emit.inputs["Color"].default_value = emission
        emit.inputs["Strength"].default_value = LAMP_STRENGTH
        add = nodes.new("ShaderNodeAddShader")
        links.new(diffuse.outputs[0], add.inputs[0])
        links.new(emit.outputs[0], add.inputs[1])
        geometry = nodes.new("ShaderNodeNewGeometry")
        mix = nodes.new("ShaderNodeMixShader")
        links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
        links.new(add.outputs[0], mix.inputs[1])
        links.new(diffuse.outputs[0], mix.inputs[2])
        links.new(mix.outputs[0], out.inputs["Surface"])
    else:
        links.new(diffuse.outputs[0], out.inputs["Surface"])

# Camera at (278, 273, -800) looking along +z, 39.3 degrees vertical field of view.
cam_data = bpy.data.cameras.new("camera")
cam_data.sensor_fit = "VERTICAL"
cam_data.angle = VFOV
cam_data.clip_start = 1.0
cam_data.clip_end = 1e5
cam = bpy.data.objects.new("camera", cam_data)
scene.collection.objects.link(cam)
eye, at = to_blender((278.0, 273.0, -800.0)), to_blender((278.0, 273.0, 0.0))
cam.location = eye
cam.rotation_euler = (at - eye).to_track_quat("-Z", "Y").to_euler()
scene.camera = cam

world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world

scene.render.engine = "CYCLES"
scene.render.resolution_x = size
scene.render.resolution_y = size
scene.render.resolution_percentage = 100
scene.render.threads_mode = "FIXED"
scene.render.threads = threads
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.filepath = out_path
scene.view_settings.view_transform = "Standard"
cycles = scene.cycles
cycles.device = "CPU"
cycles.samples = spp
cycles.use_adaptive_sampling = False
cycles.use_denoising = False
cycles.seed = seed
# raylab's --max-depth counts vertices (1 = direct light only); Cycles counts bounces.
bounces = max_depth - 1
cycles.max_bounces = bounces
cycles.diffuse_bounces = bounces
cycles.glossy_bounces = bounces
cycles.transmission_bounces = bounces
cycles.volume_bounces = 0
cycles.transparent_max_bounces = bounces
cycles.sample_clamp_direct = 0.0
cycles.sample_clamp_indirect = 0.0
cycles.caustics_reflective = True
cycles.caustics_refractive = True
# A pixel-wide box, as raylab's default filter (Cycles' smallest filter width).
cycles.filter_width = 0.01
cycles.film_exposure = 1.0

start = time.perf_counter()
bpy.ops.render.render(write_still=True)
print(f"cycles-seconds {time.perf_counter() - start:.4f}")
