#!/usr/bin/env python3
# The renderer's folders are layered: no folder includes another that includes it, directly
# or through others (a cycle would mean neither can be built or tested without the other).
# Reads the #include lines of renderer/ (the facade renderer.h/.cpp counts as a folder of its
# own) and fails naming each cycle and the includes that close it; with --print, lists the
# folders from the top layer down.
import collections
import os
import re
import sys

root = os.path.join(sys.argv[1] if len(sys.argv) > 1 and not sys.argv[1].startswith("--") else ".", "renderer")


def folder(path):
    parts = os.path.relpath(path, os.path.dirname(root)).split(os.sep)
    return parts[1] if len(parts) > 2 else "(" + os.path.splitext(parts[1])[0] + ")"


edges = collections.defaultdict(set)
where = collections.defaultdict(list)
for d, _, files in os.walk(root):
    for f in files:
        if not f.endswith((".h", ".cpp")):
            continue
        path = os.path.join(d, f)
        with open(path, encoding="utf-8") as src:
            for line in src:
                m = re.match(r'\s*#include "(renderer/[^"]+)"', line)
                if m:
                    a, b = folder(path), folder(os.path.join(os.path.dirname(root), m.group(1)))
                    if a != b:
                        edges[a].add(b)
                        where[(a, b)].append(os.path.relpath(path, os.path.dirname(root)) + " -> " + m.group(1))
nodes = sorted(set(edges) | {b for v in edges.values() for b in v})

# Tarjan's strongly connected components: a component of more than one folder is a cycle.
index, low, stack, on, cycles, counter = {}, {}, [], set(), [], [0]


def connect(v):
    index[v] = low[v] = counter[0]
    counter[0] += 1
    stack.append(v)
    on.add(v)
    for w in sorted(edges[v]):
        if w not in index:
            connect(w)
            low[v] = min(low[v], low[w])
        elif w in on:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        component = []
        while True:
            w = stack.pop()
            on.discard(w)
            component.append(w)
            if w == v:
                break
        if len(component) > 1:
            cycles.append(sorted(component))


sys.setrecursionlimit(10000)
for v in nodes:
    if v not in index:
        connect(v)
if cycles:
    for c in cycles:
        print("FAIL: these folders include each other:", ", ".join(c))
        for a in c:
            for b in c:
                for w in where.get((a, b), []):
                    print("   ", w)
    sys.exit(1)
if "--print" in sys.argv:
    depth = {}

    def layer(v):
        if v not in depth:
            depth[v] = 1 + max((layer(w) for w in edges[v]), default=-1)
        return depth[v]

    for v in sorted(nodes, key=lambda v: (-layer(v), v)):
        print(layer(v), v, " ".join(sorted(edges[v])))
print("renderer/: %d folders, no cycles" % len(nodes))
