"""Renders a Phellem scene file with Blender Cycles on the CPU, for bench/run_cycles_comparison.sh.

  blender -b --factory-startup -noaudio --python-exit-code 2 \
      -P bench/cycles/cycles_render.py -- SCENE.json SPP OUT.exr THREADS

Supports what the comparison scene uses: a pinhole camera, a sun with a finite disk, a
uniform environment and glTF mesh objects. The glTF is imported with Blender's own importer
(Y-up -> Z-up, as Phellem reads it) and every material becomes a Lambertian Diffuse BSDF fed
by the same base colour and texture, so the two renderers integrate the same light
transport. Prints one line `CYCLES_RESULT {json}` with the render time.
"""
import json
import math
import os
import sys
import time

import bpy
import numpy
from mathutils import Vector

# Debian 12 ships Blender 3.4, whose glTF importer still uses numpy.bool, with NumPy 1.24,
# which removed that alias: restore it (it always meant the builtin bool).
if not hasattr(numpy, "bool"):
    numpy.bool = bool


def to_blender(v):
    # Phellem and glTF are Y-up; Blender is Z-up: (x, y, z) -> (x, -z, y).
    return Vector((v[0], -v[2], v[1]))


def fail(msg):
    print("cycles_render.py: error: " + msg, file=sys.stderr)
    sys.exit(2)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(argv) != 4:
        fail("usage: -- SCENE.json SPP OUT.exr THREADS")
    scene_path, spp, out_path, threads = argv[0], int(argv[1]), os.path.abspath(argv[2]), int(argv[3])
    desc = json.load(open(scene_path))
    base = os.path.dirname(os.path.abspath(scene_path))

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene

    for obj in desc.get("objects", []):
        if obj.get("type") != "mesh" or not obj["file"].endswith((".gltf", ".glb")) or "transform" in obj:
            fail("only untransformed glTF mesh objects are supported")
        bpy.ops.import_scene.gltf(filepath=os.path.join(base, obj["file"]))

    # Lambertian materials: Diffuse BSDF (roughness 0 = Lambert) with the Principled BSDF's
    # base colour input (constant or image texture).
    for mat in bpy.data.materials:
        if not mat.use_nodes:
            continue
        nt = mat.node_tree
        principled = next((n for n in nt.nodes if n.type == "BSDF_PRINCIPLED"), None)
        output = next((n for n in nt.nodes if n.type == "OUTPUT_MATERIAL"), None)
        if principled is None or output is None:
            fail("material %s has no Principled BSDF" % mat.name)
        diffuse = nt.nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Roughness"].default_value = 0.0
        src = principled.inputs["Base Color"]
        if src.is_linked:
            nt.links.new(src.links[0].from_socket, diffuse.inputs["Color"])
        else:
            diffuse.inputs["Color"].default_value = src.default_value
        nt.links.new(diffuse.outputs["BSDF"], output.inputs["Surface"])

    # Cycles keeps 8-bit sRGB images as bytes and converts to linear *after* interpolation
    # (NODE_IMAGE_COMPRESS_AS_SRGB), so magnified texel edges come out darker than when
    # interpolating linear values, as Phellem (and OIIO) do. Give Cycles the same linear data:
    # a float copy of every 8-bit colour image, decoded with the sRGB curve. Set
    # CYCLES_SRGB_BYTES=1 to keep Cycles' own handling instead.
    if os.environ.get("CYCLES_SRGB_BYTES") != "1":
        for node in [n for m in bpy.data.materials if m.use_nodes for n in m.node_tree.nodes if n.type == "TEX_IMAGE"]:
            img = node.image
            if img is None or img.is_float or img.colorspace_settings.name != "sRGB":
                continue
            px = numpy.array(img.pixels[:], dtype=numpy.float32).reshape(-1, img.channels)
            rgb = px[:, :3]
            px[:, :3] = numpy.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
            lin = bpy.data.images.new(img.name + "_linear", img.size[0], img.size[1], alpha=img.channels == 4, float_buffer=True)
            lin.colorspace_settings.name = "Linear"
            if img.channels == 4:
                lin.pixels = px.ravel()
            else:
                lin.pixels = numpy.concatenate([px, numpy.ones((px.shape[0], 1), numpy.float32)], axis=1).ravel()
            node.image = lin

    cam_desc = desc["camera"]
    cam_data = bpy.data.cameras.new("camera")
    cam_data.sensor_fit = "VERTICAL"
    cam_data.angle_y = math.radians(cam_desc.get("fov_deg", 45.0))
    cam_data.clip_start = 1e-3
    cam_data.clip_end = 1e5
    cam = bpy.data.objects.new("camera", cam_data)
    scene.collection.objects.link(cam)
    pos, look = to_blender(cam_desc["position"]), to_blender(cam_desc["look_at"])
    if cam_desc.get("up", [0, 1, 0]) != [0, 1, 0] or cam_desc.get("aperture_radius", 0) != 0:
        fail("only a pinhole camera with up [0, 1, 0] is supported")
    cam.location = pos
    # The camera looks down its -Z with its +Y turned towards the world's up (+Z).
    cam.rotation_euler = (look - pos).to_track_quat("-Z", "Y").to_euler()
    scene.camera = cam

    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    bg.inputs["Color"].default_value = (0, 0, 0, 1)
    bg.inputs["Strength"].default_value = 1.0
    scene.world = world
    for light in desc.get("lights", []):
        if light["type"] == "sun":
            data = bpy.data.lights.new("sun", type="SUN")
            data.energy = light["irradiance"]  # W/m²: irradiance on a surface facing the sun
            data.color = light.get("color", [1, 1, 1])
            data.angle = math.radians(light.get("angle_deg", 0.53))
            sun = bpy.data.objects.new("sun", data)
            sun.rotation_euler = to_blender(light["direction"]).normalized().to_track_quat("Z", "Y").to_euler()
            scene.collection.objects.link(sun)
        elif light["type"] == "environment" and "color" in light:
            bg.inputs["Color"].default_value = list(light["color"]) + [1.0]
        else:
            fail("unsupported light type " + light["type"])

    r = desc.get("render", {})
    res = r.get("resolution", [960, 540])
    scene.render.engine = "CYCLES"
    scene.render.resolution_x, scene.render.resolution_y = res[0], res[1]
    scene.render.resolution_percentage = 100
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads
    scene.render.use_persistent_data = False
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.exr_codec = "ZIP"
    scene.render.filepath = out_path
    scene.view_settings.view_transform = "Standard"
    c = scene.cycles
    c.device = "CPU"
    c.samples = spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.seed = r.get("seed", 0)
    # Unbiased settings: no clamping, no light threshold, no caustic filtering.
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.blur_glossy = 0.0
    # Phellem's max_depth counts surface interactions; Cycles counts bounces after the first.
    bounces = max(0, r.get("max_depth", 8) - 1)
    c.max_bounces = c.diffuse_bounces = bounces
    c.glossy_bounces = c.transmission_bounces = c.volume_bounces = c.transparent_max_bounces = bounces
    filt = r.get("filter", {"type": "blackman-harris", "radius": 1.5})
    if isinstance(filt, str):
        filt = {"type": filt, "radius": 1.5}
    if filt.get("type") != "blackman-harris":
        fail("only the blackman-harris filter maps onto Cycles")
    c.pixel_filter_type = "BLACKMAN_HARRIS"
    # Cycles doubles filter_width for Blackman-Harris before tabulating it over +-width/2, so
    # its support is +-filter_width: the same number as Phellem's radius.
    c.filter_width = filt.get("radius", 1.5)

    t0 = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    seconds = time.perf_counter() - t0
    print("CYCLES_RESULT " + json.dumps({"spp": spp, "time_s": seconds, "threads": threads, "output": out_path}))


main()
