#!/usr/bin/env python3
"""Writes models/pendulum.gltf: a small glTF 2.0 scene that exercises node animation, every
interpolation and a parented transform, for trying --play and for the end-to-end tests.

  a base (static box), a pendulum arm swinging +-50 degrees about z (LINEAR rotation, slerp)
  with a bob at its end (a child node: it moves with the arm), a sphere bouncing (CUBICSPLINE
  translation) and a box that grows in steps (STEP scale). Two seconds, looping.

Run from the repository root: python3 models/make_animated_scene.py
"""
import json
import math

from gltf_buffer import GltfBuffer


def box(sx, sy, sz):
    pos, nrm, idx = [], [], []
    for axis in range(3):
        for sign in (-1, 1):
            n = [0, 0, 0]
            n[axis] = sign
            u, v = [(1, 2), (2, 0), (0, 1)][axis]
            base = len(pos)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0, 0, 0]
                p[axis] = sign
                p[u] = a
                p[v] = b
                pos.append((p[0] * sx, p[1] * sy, p[2] * sz))
                nrm.append(tuple(n))
            quad = [0, 1, 2, 0, 2, 3] if sign > 0 else [0, 2, 1, 0, 3, 2]
            idx += [base + q for q in quad]
    return pos, nrm, idx


def sphere(r, rings=24, segments=48):
    pos, nrm, idx = [], [], []
    for i in range(rings + 1):
        th = math.pi * i / rings
        for j in range(segments + 1):
            ph = 2 * math.pi * j / segments
            n = (math.sin(th) * math.cos(ph), math.cos(th), math.sin(th) * math.sin(ph))
            pos.append(tuple(r * c for c in n))
            nrm.append(n)
    for i in range(rings):
        for j in range(segments):
            a = i * (segments + 1) + j
            b = a + segments + 1
            idx += [a, a + 1, b, a + 1, b + 1, b]
    return pos, nrm, idx


buffer = GltfBuffer()
add = buffer.add


def mesh(shape, material):
    pos, nrm, idx = shape
    flat = [c for p in pos for c in p]
    lo = [min(p[k] for p in pos) for k in range(3)]
    hi = [max(p[k] for p in pos) for k in range(3)]
    p = add(flat, "f", len(pos), "VEC3", 5126, 34962, (lo, hi))
    n = add([c for v in nrm for c in v], "f", len(nrm), "VEC3", 5126, 34962)
    i = add(idx, "H", len(idx), "SCALAR", 5123, 34963)
    return {"primitives": [{"attributes": {"POSITION": p, "NORMAL": n}, "indices": i, "material": material}]}


materials = [
    {"name": "stone", "pbrMetallicRoughness": {"baseColorFactor": [0.55, 0.52, 0.48, 1], "metallicFactor": 0, "roughnessFactor": 0.9}},
    {"name": "brass", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.62, 0.3, 1], "metallicFactor": 0.6, "roughnessFactor": 0.4}},
    {"name": "paint", "pbrMetallicRoughness": {"baseColorFactor": [0.7, 0.25, 0.2, 1], "metallicFactor": 0, "roughnessFactor": 0.5}},
]
meshes = [
    mesh(box(1.6, 0.15, 0.6), 0),   # 0 base
    mesh(box(0.05, 0.8, 0.05), 1),  # 1 arm (hangs from its pivot)
    mesh(sphere(0.28), 1),          # 2 bob
    mesh(sphere(0.35), 2),          # 3 bouncing ball
    mesh(box(0.3, 0.3, 0.3), 0),    # 4 growing box
]
nodes = [
    {"name": "base", "mesh": 0, "translation": [0, -1.2, 0]},
    {"name": "pivot", "translation": [0, 1.5, -0.2], "children": [2]},
    {"name": "arm", "mesh": 1, "translation": [0, -0.8, 0], "children": [3]},
    {"name": "bob", "mesh": 2, "translation": [0, -0.9, 0]},
    {"name": "ball", "mesh": 3, "translation": [1.0, -0.7, 0.9]},
    {"name": "growing box", "mesh": 4, "translation": [-1.1, -0.75, 0.35]},
]

# Swing: the pivot's rotation about z, -50 .. 50 .. -50 degrees over 2 s (LINEAR: slerp).
times = [0.0, 0.5, 1.0, 1.5, 2.0]
angles = [-50, 0, 50, 0, -50]
rot = []
for a in angles:
    h = math.radians(a) / 2
    rot += [0, 0, math.sin(h), math.cos(h)]
t_swing = add(times, "f", len(times), "SCALAR", 5126, minmax=([0.0], [2.0]))
v_swing = add(rot, "f", len(angles), "VEC4", 5126)
# Bounce: the ball's translation, CUBICSPLINE (in-tangent, value, out-tangent per key).
bt = [0.0, 1.0, 2.0]
ys = [-0.7, 0.5, -0.7]
slopes = [2.6, 0.0, -2.6]
bvals = []
for y, m in zip(ys, slopes):
    bvals += [0, m, 0, 1.0, y, 0.9, 0, m, 0]
t_bounce = add(bt, "f", len(bt), "SCALAR", 5126, minmax=([0.0], [2.0]))
v_bounce = add(bvals, "f", len(bt) * 3, "VEC3", 5126)
# Growth: the box's scale in four STEPs.
gt = [0.0, 0.5, 1.0, 1.5]
gs = [1, 1, 1, 1.4, 1.4, 1.4, 1.8, 1.8, 1.8, 1.4, 1.4, 1.4]
t_grow = add(gt, "f", len(gt), "SCALAR", 5126, minmax=([0.0], [1.5]))
v_grow = add(gs, "f", len(gt), "VEC3", 5126)

gltf = {
    "asset": {"version": "2.0", "generator": "npr-viewer models/make_animated_scene.py"},
    "scene": 0,
    "scenes": [{"nodes": [0, 1, 4, 5]}],
    "nodes": nodes,
    "meshes": meshes,
    "materials": materials,
    "animations": [{
        "name": "swing and bounce",
        "channels": [
            {"sampler": 0, "target": {"node": 1, "path": "rotation"}},
            {"sampler": 1, "target": {"node": 4, "path": "translation"}},
            {"sampler": 2, "target": {"node": 5, "path": "scale"}},
        ],
        "samplers": [
            {"input": t_swing, "output": v_swing, "interpolation": "LINEAR"},
            {"input": t_bounce, "output": v_bounce, "interpolation": "CUBICSPLINE"},
            {"input": t_grow, "output": v_grow, "interpolation": "STEP"},
        ],
    }],
    "accessors": buffer.accessors,
    "bufferViews": buffer.views,
    "buffers": buffer.buffers(),
}
with open("models/pendulum.gltf", "w") as f:
    json.dump(gltf, f, separators=(",", ":"))
    f.write("\n")
