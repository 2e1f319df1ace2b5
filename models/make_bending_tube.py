#!/usr/bin/env python3
"""Writes models/bending_tube.gltf: a capped tube skinned to two joints that bends 90 degrees
and back over two seconds (LINEAR rotation of the upper joint), for looking at patterns and
hatching on a deforming surface and for the end-to-end tests.

Run from the repository root: python3 models/make_bending_tube.py
"""
import json
import math

from gltf_buffer import GltfBuffer

AROUND, ALONG, RADIUS, HALF = 48, 48, 0.35, 1.2

pos, nrm, joints, weights, idx = [], [], [], [], []


def weight_upper(y):
    return min(1.0, max(0.0, (y + 0.25) / 0.5))


def vertex(p, n):
    pos.append(p)
    nrm.append(n)
    w = weight_upper(p[1])
    joints.append((0, 1, 0, 0))
    weights.append((1 - w, w, 0, 0))
    return len(pos) - 1


rows = []
for j in range(ALONG + 1):
    y = -HALF + 2 * HALF * j / ALONG
    row = []
    for i in range(AROUND + 1):
        a = 2 * math.pi * i / AROUND
        row.append(vertex((RADIUS * math.cos(a), y, -RADIUS * math.sin(a)), (math.cos(a), 0, -math.sin(a))))
    rows.append(row)
for j in range(ALONG):
    for i in range(AROUND):
        a, b, c, d = rows[j][i], rows[j][i + 1], rows[j + 1][i + 1], rows[j + 1][i]
        idx += [a, b, c, a, c, d]
for y, sign in ((-HALF, -1), (HALF, 1)):
    centre = vertex((0, y, 0), (0, sign, 0))
    ring = [vertex((RADIUS * math.cos(2 * math.pi * i / AROUND), y, -RADIUS * math.sin(2 * math.pi * i / AROUND)), (0, sign, 0))
            for i in range(AROUND + 1)]
    for i in range(AROUND):
        idx += [centre, ring[i], ring[i + 1]] if sign > 0 else [centre, ring[i + 1], ring[i]]

buffer = GltfBuffer()
add = buffer.add


P = add([c for p in pos for c in p], "f", len(pos), "VEC3", 5126,
        minmax=([min(p[k] for p in pos) for k in range(3)], [max(p[k] for p in pos) for k in range(3)]))
N = add([c for n in nrm for c in n], "f", len(nrm), "VEC3", 5126)
J = add([c for j in joints for c in j], "B", len(joints), "VEC4", 5121)
W = add([c for w in weights for c in w], "f", len(weights), "VEC4", 5126)
I = add(idx, "H", len(idx), "SCALAR", 5123)
# Inverse bind matrices: the lower joint at the origin, the upper one at y = 0 too (its pivot).
identity = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
IBM = add(identity + identity, "f", 2, "MAT4", 5126)
times = [0.0, 1.0, 2.0]
rot = []
for deg in (0, 90, 0):
    h = math.radians(deg) / 2
    rot += [0, 0, math.sin(h), math.cos(h)]
T = add(times, "f", 3, "SCALAR", 5126, minmax=([0.0], [2.0]))
R = add(rot, "f", 3, "VEC4", 5126)

gltf = {
    "asset": {"version": "2.0", "generator": "npr-viewer models/make_bending_tube.py"},
    "scene": 0,
    "scenes": [{"nodes": [0, 1]}],
    "nodes": [
        {"name": "tube", "mesh": 0, "skin": 0},
        {"name": "lower joint", "children": [2]},
        {"name": "upper joint"},
    ],
    "meshes": [{"primitives": [{"attributes": {"POSITION": P, "NORMAL": N, "JOINTS_0": J, "WEIGHTS_0": W}, "indices": I, "material": 0}]}],
    "materials": [{"name": "clay", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.78, 0.74, 1], "metallicFactor": 0, "roughnessFactor": 0.8}}],
    "skins": [{"joints": [1, 2], "inverseBindMatrices": IBM}],
    "animations": [{"name": "bend", "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}}],
                    "samplers": [{"input": T, "output": R, "interpolation": "LINEAR"}]}],
    "accessors": buffer.accessors,
    "bufferViews": buffer.views,
    "buffers": buffer.buffers(),
}
with open("models/bending_tube.gltf", "w") as f:
    json.dump(gltf, f, separators=(",", ":"))
    f.write("\n")
