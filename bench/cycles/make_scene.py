#!/usr/bin/env python3
"""Writes the diffuse glTF scene that Phellem and Blender Cycles both render
(bench/run_cycles_comparison.sh): a bark-textured trunk, a checker-textured ground, a sphere
and a box, every material Lambertian (KHR_materials_specular specularFactor 0). Standard
library only; run it to regenerate bench/scenes/cycles/scene.gltf and checker.png.

bark.png is Poly Haven's CC0 "Bark Brown 01" albedo (Rob Tuytel), reduced with
  oiiotool bark_brown_01_polyhaven.jpg --resize 256x256 -d uint8 -o bark.png
"""
import json
import math
import os
import struct
import zlib

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "cycles")


def write_png(path, w, h, rgb_rows):
    raw = b"".join(b"\x00" + bytes(row) for row in rgb_rows)

    def chunk(tag, data):
        c = struct.pack(">I", len(data)) + tag + data
        return c + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def checker(path, n=64, checks=8):
    a, b = (200, 190, 160), (90, 110, 70)
    rows = []
    for y in range(n):
        row = []
        for x in range(n):
            row += a if ((x * checks // n) + (y * checks // n)) % 2 == 0 else b
        rows.append(row)
    write_png(path, n, n, rows)


class Mesh:
    def __init__(self):
        self.p, self.n, self.uv, self.idx = [], [], [], []

    def vertex(self, p, n, uv):
        self.p.append(p)
        self.n.append(n)
        self.uv.append(uv)
        return len(self.p) - 1


def quad_grid(size, reps):
    m = Mesh()
    h = size / 2
    for (x, z, u, v) in [(-h, -h, 0, 0), (h, -h, reps, 0), (h, h, reps, reps), (-h, h, 0, reps)]:
        m.vertex((x, 0.0, z), (0.0, 1.0, 0.0), (u, v))
    m.idx += [0, 2, 1, 0, 3, 2]
    return m


def cylinder(radius, height, seg, u_reps, v_reps):
    m = Mesh()
    for j in range(2):
        for i in range(seg + 1):
            a = 2 * math.pi * i / seg
            m.vertex((radius * math.cos(a), height * j, radius * math.sin(a)), (math.cos(a), 0.0, math.sin(a)),
                     (u_reps * i / seg, v_reps * (1 - j)))
    for i in range(seg):
        a, b, c, d = i, i + 1, seg + 1 + i, seg + 2 + i
        m.idx += [a, c, b, b, c, d]
    return m


def sphere(center, radius, seg):
    m = Mesh()
    rings = seg // 2
    for j in range(rings + 1):
        t = math.pi * j / rings
        for i in range(seg + 1):
            f = 2 * math.pi * i / seg
            n = (math.sin(t) * math.cos(f), math.cos(t), math.sin(t) * math.sin(f))
            m.vertex(tuple(c + radius * k for c, k in zip(center, n)), n, (i / seg, j / rings))
    for j in range(rings):
        for i in range(seg):
            a, b = j * (seg + 1) + i, (j + 1) * (seg + 1) + i
            m.idx += [a, a + 1, b, a + 1, b + 1, b]
    return m


def box(center, half, angle_deg):
    m = Mesh()
    ca, sa = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    rot = lambda v: (ca * v[0] + sa * v[2], v[1], -sa * v[0] + ca * v[2])
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            u_ax, v_ax = [(1, 2), (2, 0), (0, 1)][axis]
            base = len(m.p)
            for (su, sv) in [(-1, -1), (1, -1), (1, 1), (-1, 1)]:
                p = [0.0, 0.0, 0.0]
                p[axis] = sign * half
                p[u_ax] = su * half
                p[v_ax] = sv * half
                q = rot(p)
                m.vertex((center[0] + q[0], center[1] + q[1], center[2] + q[2]), rot(n), ((su + 1) / 2, (sv + 1) / 2))
            tri = [0, 1, 2, 0, 2, 3] if sign > 0 else [0, 2, 1, 0, 3, 2]
            m.idx += [base + k for k in tri]
    return m


def main():
    os.makedirs(HERE, exist_ok=True)
    checker(os.path.join(HERE, "checker.png"))
    meshes = [("ground", quad_grid(8.0, 4.0), 0), ("trunk", cylinder(0.35, 2.6, 64, 2.0, 3.0), 1),
              ("sphere", sphere((1.3, 0.5, 0.7), 0.5, 64), 2), ("box", box((-1.2, 0.3, 0.9), 0.3, 30), 3)]
    binary = bytearray()
    views, accessors, gl_meshes, nodes = [], [], [], []

    def add(data, fmt, count, kind, comp, target, minmax=None):
        while len(binary) % 4:
            binary.append(0)
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(data), "target": target})
        binary.extend(data)
        acc = {"bufferView": len(views) - 1, "componentType": comp, "count": count, "type": kind}
        if minmax:
            acc["min"], acc["max"] = minmax
        accessors.append(acc)
        return len(accessors) - 1

    for name, m, mat in meshes:
        flat = lambda vs: b"".join(struct.pack("<%df" % len(v), *v) for v in vs)
        lo = [min(p[k] for p in m.p) for k in range(3)]
        hi = [max(p[k] for p in m.p) for k in range(3)]
        ap = add(flat(m.p), "f", len(m.p), "VEC3", 5126, 34962, (lo, hi))
        an = add(flat(m.n), "f", len(m.n), "VEC3", 5126, 34962)
        at = add(flat(m.uv), "f", len(m.uv), "VEC2", 5126, 34962)
        ai = add(struct.pack("<%dI" % len(m.idx), *m.idx), "I", len(m.idx), "SCALAR", 5125, 34963)
        gl_meshes.append({"name": name, "primitives": [{"attributes": {"POSITION": ap, "NORMAL": an, "TEXCOORD_0": at},
                                                        "indices": ai, "material": mat}]})
        nodes.append({"name": name, "mesh": len(gl_meshes) - 1})

    lambert = {"KHR_materials_specular": {"specularFactor": 0.0}}
    def material(name, color=None, texture=None):
        pbr = {"metallicFactor": 0.0, "roughnessFactor": 1.0}
        if color:
            pbr["baseColorFactor"] = color + [1.0]
        if texture is not None:
            pbr["baseColorTexture"] = {"index": texture}
        return {"name": name, "pbrMetallicRoughness": pbr, "extensions": lambert}

    doc = {
        "asset": {"version": "2.0", "generator": "phellem bench/cycles/make_scene.py"},
        "extensionsUsed": ["KHR_materials_specular"],
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": gl_meshes,
        "materials": [material("ground", texture=0), material("bark", texture=1),
                      material("terracotta", color=[0.70, 0.32, 0.20]), material("slate", color=[0.30, 0.45, 0.65])],
        "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "images": [{"uri": "checker.png"}, {"uri": "bark.png"}],
        "buffers": [{"uri": "scene.bin", "byteLength": len(binary)}],
        "bufferViews": views,
        "accessors": accessors,
    }
    with open(os.path.join(HERE, "scene.bin"), "wb") as f:
        f.write(binary)
    with open(os.path.join(HERE, "scene.gltf"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
