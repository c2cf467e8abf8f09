#!/usr/bin/env python3
"""Writes a copy of an OBJ mesh with every vertex moved by a uniform random
offset of at most SCALE times the mesh's extent (per coordinate), UVs and
normals dropped, faces kept: a "draw" of the same input, to tell a change
that moves a mesh's seams systematically from one that only redraws a
chaotic outcome (notes/issue20/README.md).

Usage: perturb_mesh.py IN.obj OUT.obj [--seed S] [--scale 1e-7]
"""
import argparse
import random


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--scale", type=float, default=1e-7)
    a = ap.parse_args()
    lines = open(a.input).read().splitlines()
    pts = [[float(t) for t in l.split()[1:4]] for l in lines if l.startswith("v ")]
    if not pts:
        raise SystemExit("no vertices in " + a.input)
    extent = max(max(p[i] for p in pts) - min(p[i] for p in pts) for i in range(3))
    rng = random.Random(a.seed)
    out = []
    for l in lines:
        if l.startswith("v "):
            p = [float(t) + extent * a.scale * rng.uniform(-1, 1) for t in l.split()[1:4]]
            out.append("v %.17g %.17g %.17g" % tuple(p))
        elif l.startswith("vt") or l.startswith("vn"):
            continue
        elif l.startswith("f "):
            out.append("f " + " ".join(t.split("/")[0] for t in l.split()[1:]))
        else:
            out.append(l)
    with open(a.output, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
