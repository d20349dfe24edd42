#!/usr/bin/env python3
"""Writes this folder's binary files (the text ones are written by hand): python3 make_binary_files.py

ply_tristrips_big_endian.ply: the square prism of ply_tristrips.ply in the layout of the old Stanford scans, a
binary_big_endian body with a confidence per vertex and the triangles in one tristrips item, strips separated by -1.
"""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

PRISM = [(1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0), (1, 0, 1), (0, 1, 1), (-1, 0, 1), (0, -1, 1)]
STRIPS = [4, 0, 5, 1, 6, 2, 7, 3, 4, 0, -1, 4, 5, 7, 6, 6, 0, 0, 3, 1, 2]


def tristrips_big_endian():
    header = (
        "ply\n"
        "format binary_big_endian 1.0\n"
        "comment a square prism as triangle strips, strips separated by -1\n"
        f"element vertex {len(PRISM)}\n"
        "property float x\nproperty float y\nproperty float z\nproperty float confidence\n"
        "element tristrips 1\n"
        "property list int int vertex_indices\n"
        "end_header\n"
    )
    body = b"".join(struct.pack(">4f", x, y, z, 0.5) for x, y, z in PRISM)
    body += struct.pack(">i", len(STRIPS)) + struct.pack(f">{len(STRIPS)}i", *STRIPS)
    return header.encode("ascii") + body


with open(os.path.join(HERE, "ply_tristrips_big_endian.ply"), "wb") as out:
    out.write(tristrips_big_endian())
