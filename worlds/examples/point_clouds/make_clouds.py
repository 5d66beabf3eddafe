#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the example point clouds of worlds/examples/point_clouds.xml (run from this folder):

cube_rgb_ascii.pcd  1016 points on the surface of a 0.2 m cube centred at the origin (a 14 x 14
                    grid on each face, edges shared), DATA ascii, rgb as PCL >= 1.8 writes it (TYPE
                    F, the packed 0x00RRGGBB written as an integer), coloured by position.
ball_binary.pcd     800 points on a 0.1 m sphere (a Fibonacci spiral), DATA binary: x y z as F4,
                    an 'intensity' U1 and rgb as PCL's packed float, six colour bands by height.
"""
import math
import struct


def cube_points(side=0.2, n=14):
    h = side / 2
    ticks = [-h + side * i / (n - 1) for i in range(n)]
    points = set()
    for axis in range(3):
        for sign in (-h, h):
            for u in ticks:
                for v in ticks:
                    p = [0.0, 0.0, 0.0]
                    p[axis] = sign
                    p[(axis + 1) % 3] = u
                    p[(axis + 2) % 3] = v
                    points.add(tuple(round(c, 12) for c in p))
    return sorted(points)


def ball_points(radius=0.1, n=800):
    golden = math.pi * (3 - math.sqrt(5))
    points = []
    for i in range(n):
        z = 1 - 2 * (i + 0.5) / n
        r = math.sqrt(1 - z * z)
        points.append((radius * r * math.cos(golden * i), radius * r * math.sin(golden * i),
                       radius * z))
    return points


def channel(value):
    return max(0, min(255, int(round(value * 255))))


def write_cube(path):
    points = cube_points()
    lines = ["# .PCD v0.7 - Point Cloud Data file format", "VERSION 0.7", "FIELDS x y z rgb",
             "SIZE 4 4 4 4", "TYPE F F F F", "COUNT 1 1 1 1", f"WIDTH {len(points)}", "HEIGHT 1",
             "VIEWPOINT 0 0 0 1 0 0 0", f"POINTS {len(points)}", "DATA ascii"]
    for x, y, z in points:
        rgb = (channel(x / 0.2 + 0.5) << 16) | (channel(y / 0.2 + 0.5) << 8) | channel(z / 0.2 + 0.5)
        lines.append(f"{x:.6g} {y:.6g} {z:.6g} {rgb}")
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


BANDS = [0xd62728, 0xff7f0e, 0xffdd33, 0x2ca02c, 0x1f77b4, 0x9467bd]


def write_ball(path):
    points = ball_points()
    header = ("# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z intensity rgb\n"
              "SIZE 4 4 4 1 4\nTYPE F F F U F\nCOUNT 1 1 1 1 1\n"
              f"WIDTH {len(points)}\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS {len(points)}\n"
              "DATA binary\n")
    data = bytearray()
    for x, y, z in points:
        band = min(len(BANDS) - 1, int((z / 0.1 + 1) / 2 * len(BANDS)))
        packed = struct.unpack("<f", struct.pack("<I", BANDS[band]))[0]
        data += struct.pack("<fffBf", x, y, z, 200, packed)
    with open(path, "wb") as out:
        out.write(header.encode("ascii") + bytes(data))


if __name__ == "__main__":
    write_cube("cube_rgb_ascii.pcd")
    write_ball("ball_binary.pcd")
