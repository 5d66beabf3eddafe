#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes worlds/accuracy/scanned_tray.off, the object of the accuracy scenes scanned_tray_mc*
# (numerics section 6 scene 12, "scanned or non-watertight object on a table"): an open tray,
# 0.3 x 0.3 m with 3 cm walls and no lid (not watertight: single-sided surfaces, open top),
# whose bottom is a 24 x 24 grid of cells with every inner vertex moved up or down by up to
# 0.3 mm, as a scanned surface is. Deterministic: the same file on every run.
import random

N = 24           # cells per side of the bottom
SIZE = 0.3       # m
WALL = 0.03      # m
BUMP = 0.0003    # m, largest vertical offset of a bottom vertex

def main():
    rng = random.Random(12)
    vertices, faces = [], []
    index = {}
    for i in range(N + 1):
        for j in range(N + 1):
            inner = 0 < i < N and 0 < j < N
            z = rng.uniform(-BUMP, BUMP) if inner else 0.0
            index[i, j] = len(vertices)
            vertices.append((-SIZE / 2 + SIZE * i / N, -SIZE / 2 + SIZE * j / N, z))
    for i in range(N):
        for j in range(N):
            a, b, c, d = index[i, j], index[i + 1, j], index[i + 1, j + 1], index[i, j + 1]
            faces += [(a, c, b), (a, d, c)]  # outward normal -z: the bottom faces down
    # walls: one quad per side of the rim, bottom edge shared with the grid's border vertices
    rim = [index[i, 0] for i in range(N + 1)] + [index[N, j] for j in range(1, N + 1)] + \
          [index[i, N] for i in range(N - 1, -1, -1)] + [index[0, j] for j in range(N - 1, 0, -1)]
    top = []
    for v in rim:
        x, y, _ = vertices[v]
        top.append(len(vertices))
        vertices.append((x, y, WALL))
    for k in range(len(rim)):
        a, b = rim[k], rim[(k + 1) % len(rim)]
        ta, tb = top[k], top[(k + 1) % len(rim)]
        faces += [(a, b, tb), (a, tb, ta)]  # outward normal away from the tray's centre
    with open("scanned_tray.off", "w") as out:
        out.write("OFF\n# Open tray with a scanned (bumpy) bottom: written by make_scanned_tray.py\n")
        out.write(f"{len(vertices)} {len(faces)} 0\n")
        for x, y, z in vertices:
            out.write(f"{x:.9g} {y:.9g} {z:.9g}\n")
        for f in faces:
            out.write(f"3 {f[0]} {f[1]} {f[2]}\n")

main()
