#!/usr/bin/env python3
# Writes a glTF file of N objects (EXT_mesh_gpu_instancing) for the many-objects figures of
# docs/scenes.md: python3 tests/bench/many_objects.py OUT.gltf [N]
import base64, json, math, struct, sys
# A glTF of N instances (EXT_mesh_gpu_instancing) of two shapes in two materials, in a grid.
n = int(sys.argv[2]) if len(sys.argv) > 2 else 10000
# An octahedron subdivided once: 32 triangles.
def octa():
    v = [(1,0,0),(-1,0,0),(0,1,0),(0,-1,0),(0,0,1),(0,0,-1)]
    f = [(0,2,4),(2,1,4),(1,3,4),(3,0,4),(2,0,5),(1,2,5),(3,1,5),(0,3,5)]
    verts = list(v); faces = []
    cache = {}
    def mid(a, b):
        k = (min(a,b), max(a,b))
        if k not in cache:
            p = [(verts[a][i]+verts[b][i])/2 for i in range(3)]
            l = math.sqrt(sum(c*c for c in p)); verts.append(tuple(c/l for c in p)); cache[k] = len(verts)-1
        return cache[k]
    for a,b,c in f:
        ab, bc, ca = mid(a,b), mid(b,c), mid(c,a)
        faces += [(a,ab,ca),(ab,b,bc),(ca,bc,c),(ab,bc,ca)]
    return verts, faces
def box():
    v = [(x,y,z) for z in (-1,1) for y in (-1,1) for x in (-1,1)]
    f = [(0,2,3),(0,3,1),(4,5,7),(4,7,6),(0,1,5),(0,5,4),(2,6,7),(2,7,3),(0,4,6),(0,6,2),(1,3,7),(1,7,5)]
    return v, f
buf = b""; views = []; accs = []; meshes = []
def add(data, target=None):
    global buf
    while len(buf) % 4: buf += b"\0"
    views.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(data)}); buf += data
    return len(views) - 1
for k, (v, f) in enumerate([octa(), box()]):
    pv = add(b"".join(struct.pack("<3f", *p) for p in v))
    accs.append({"bufferView": pv, "componentType": 5126, "count": len(v), "type": "VEC3",
                 "min": [min(p[i] for p in v) for i in range(3)], "max": [max(p[i] for p in v) for i in range(3)]})
    iv = add(b"".join(struct.pack("<3H", *t) for t in f))
    accs.append({"bufferView": iv, "componentType": 5123, "count": 3*len(f), "type": "SCALAR"})
    meshes.append({"primitives": [{"attributes": {"POSITION": 2*k}, "indices": 2*k+1, "material": k}]})
nodes = []
side = int(math.ceil(math.sqrt(n)))
for k in range(2):
    cnt = n // 2 + (n % 2 if k == 0 else 0)
    t = []; r = []; s = []
    for i in range(cnt):
        j = 2*i + k
        x, y = j % side, j // side
        t += [(x - side/2) * 3.0, 0.0, (y - side/2) * 3.0]
        a = (j * 0.618) % (2*math.pi)
        r += [0.0, math.sin(a/2), 0.0, math.cos(a/2)]
        sc = 0.6 + 0.5 * ((j * 7919) % 101) / 100.0
        s += [sc, sc * (0.7 + 0.6 * ((j * 104729) % 97) / 96.0), sc]
    tv = add(struct.pack("<%df" % len(t), *t)); accs.append({"bufferView": tv, "componentType": 5126, "count": cnt, "type": "VEC3"})
    rv = add(struct.pack("<%df" % len(r), *r)); accs.append({"bufferView": rv, "componentType": 5126, "count": cnt, "type": "VEC4"})
    sv = add(struct.pack("<%df" % len(s), *s)); accs.append({"bufferView": sv, "componentType": 5126, "count": cnt, "type": "VEC3"})
    nodes.append({"name": ["spheres", "boxes"][k], "mesh": k, "extensions": {"EXT_mesh_gpu_instancing": {"attributes": {
        "TRANSLATION": len(accs)-3, "ROTATION": len(accs)-2, "SCALE": len(accs)-1}}}})
doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}], "nodes": nodes, "meshes": meshes,
       "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.35, 0.25, 1], "metallicFactor": 0, "roughnessFactor": 0.6}},
                     {"pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.45, 0.8, 1], "metallicFactor": 0, "roughnessFactor": 0.8}}],
       "accessors": accs, "bufferViews": views,
       "buffers": [{"byteLength": len(buf), "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}],
       "extensionsUsed": ["EXT_mesh_gpu_instancing"], "extensionsRequired": ["EXT_mesh_gpu_instancing"]}
json.dump(doc, open(sys.argv[1], "w"))
