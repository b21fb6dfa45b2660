#!/usr/bin/env python3
"""Prints an Open Inventor QuadMesh: a square in the z=0 plane, normal +z, finely divided.

Rows run from +y to -y so that the mesh's quads are counter-clockwise seen from +z, which is
what ShapeHints { vertexOrdering COUNTERCLOCKWISE } promises Coin.

Coin lights per vertex (Gouraud), so a receiver that must show a point light's falloff
accurately needs many vertices. Usage: grid_plane.py HALF_SIZE DIVISIONS [INDENT]
"""
import sys


def grid(half, divisions, indent=""):
    n = divisions + 1
    step = 2.0 * half / divisions
    points = []
    for j in range(n):
        y = half - j * step
        row = ", ".join(f"{-half + i * step:g} {y:g} 0" for i in range(n))
        points.append(f"{indent}    {row}")
    return (f"{indent}Coordinate3 {{\n{indent}  point [\n" + ",\n".join(points) +
            f"\n{indent}  ]\n{indent}}}\n"
            f"{indent}Normal {{ vector 0 0 1 }}\n"
            f"{indent}NormalBinding {{ value OVERALL }}\n"
            f"{indent}QuadMesh {{ verticesPerRow {n} verticesPerColumn {n} }}\n")


if __name__ == "__main__":
    half = float(sys.argv[1])
    divisions = int(sys.argv[2])
    indent = sys.argv[3] if len(sys.argv) > 3 else ""
    sys.stdout.write(grid(half, divisions, indent))
