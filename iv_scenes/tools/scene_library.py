#!/usr/bin/env python3
"""Writes the scene library of iv_scenes/ (see iv_scenes/README.md).

Usage:
  scene_library.py DIR            writes chapel.iv, bottles.iv, foliage.iv, atrium.iv and
                                  all_directions.iv into DIR (the committed copies)
  scene_library.py --stress N OUT writes a stress scene of about N triangles to OUT: a floor
                                  under a field of lat-long spheres, half of them coloured glass
                                  (one sphere mesh, instanced with USE, keeps the file small);
                                  stress_100k.iv and stress_1m.iv were written with N = 100000
                                  and N = 1000000
Every scene is deterministic: the same command writes the same bytes.
"""
import math
import os
import sys

HEADER = "#Inventor V2.1 ascii\n\n"


def look_at(position, target, up=(0.0, 0.0, 1.0)):
    """A PerspectiveCamera's position and orientation (axis angle) looking from `position` at
    `target` with `up` as the upward direction."""
    def norm(v):
        length = math.sqrt(sum(c * c for c in v))
        return tuple(c / length for c in v)

    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    forward = norm(tuple(t - p for t, p in zip(target, position)))
    right = norm(cross(forward, up))
    true_up = cross(right, forward)
    # Columns: where the camera's x, y and z axes go (it looks along -z).
    m = [[right[i], true_up[i], -forward[i]] for i in range(3)]
    trace = m[0][0] + m[1][1] + m[2][2]
    angle = math.acos(max(-1.0, min(1.0, (trace - 1) / 2)))
    if abs(angle) < 1e-9:
        axis = (0.0, 0.0, 1.0)
    elif abs(angle - math.pi) < 1e-6:
        i = max(range(3), key=lambda k: m[k][k])
        v = [0.0, 0.0, 0.0]
        v[i] = math.sqrt((m[i][i] + 1) / 2)
        for k in range(3):
            if k != i:
                v[k] = m[i][k] / (2 * v[i])
        axis = tuple(v)
    else:
        axis = norm((m[2][1] - m[1][2], m[0][2] - m[2][0], m[1][0] - m[0][1]))
    return ("  PerspectiveCamera { position %g %g %g orientation %.5f %.5f %.5f %.5f "
            "heightAngle 0.9 nearDistance 0.2 farDistance 60 }\n"
            % (position + axis + (angle,)))


def quad(corners, indent="    "):
    points = ", ".join("%g %g %g" % c for c in corners)
    return (f"{indent}Coordinate3 {{ point [ {points} ] }}\n"
            f"{indent}FaceSet {{ numVertices 4 }}\n")


def box(center, size, indent="    "):
    (x, y, z), (w, d, h) = center, size
    return (f"{indent}Separator {{ Translation {{ translation {x:g} {y:g} {z:g} }} "
            f"Cube {{ width {w:g} height {d:g} depth {h:g} }} }}\n")


def material(diffuse, transparency=0.0, extra=""):
    r, g, b = diffuse
    return (f"Material {{ diffuseColor {r:g} {g:g} {b:g} transparency {transparency:g}"
            f"{' ' + extra if extra else ''} }}")


def wall_with_windows(y, width, height, windows, indent="    "):
    """An opaque wall in the plane y, spanning x in [-width/2, width/2] and z in [0, height],
    with rectangular holes (x0, x1, z0, z1) for the windows: strips between the holes."""
    out = ""
    xs = sorted({-width / 2, width / 2} | {w[0] for w in windows} | {w[1] for w in windows})
    for x0, x1 in zip(xs, xs[1:]):
        holes = sorted((w[2], w[3]) for w in windows if w[0] <= x0 and x1 <= w[1])
        z = 0.0
        for z0, z1 in holes + [(height, height)]:
            if z0 > z:
                out += quad([(x0, y, z), (x1, y, z), (x1, y, z0), (x0, y, z0)], indent)
            z = z1
    return out


def stained_glass(x0, x1, z0, z1, y, columns, rows, seed, indent="    "):
    colours = [(0.9, 0.15, 0.1), (0.1, 0.35, 0.9), (0.95, 0.8, 0.1), (0.1, 0.7, 0.25),
               (0.6, 0.1, 0.7), (0.95, 0.5, 0.1)]
    out = ""
    for i in range(columns):
        for j in range(rows):
            c = colours[(i * 7 + j * 3 + seed) % len(colours)]
            a0, a1 = x0 + (x1 - x0) * i / columns, x0 + (x1 - x0) * (i + 1) / columns
            b0, b1 = z0 + (z1 - z0) * j / rows, z0 + (z1 - z0) * (j + 1) / rows
            out += f"{indent}Separator {{ {material(c, 0.45)}\n"
            out += quad([(a0, y, b0), (a1, y, b0), (a1, y, b1), (a0, y, b1)], indent + "  ")
            out += f"{indent}}}\n"
    return out


def chapel():
    windows = [(-2.6, -1.4, 1.2, 3.2), (-0.6, 0.6, 1.2, 3.6), (1.4, 2.6, 1.2, 3.2)]
    s = HEADER + ("# A chapel: three stained-glass windows in the south wall, the sun outside.\n"
                  "# Each window is a grid of coloured panes; their light falls on the floor\n"
                  "# in coloured patches. Written by tools/scene_library.py.\n")
    s += "Separator {\n"
    s += look_at((0.5, 5.5, 3.4), (0, -1.2, 0.6))
    s += "  DEF Chapel TransparentShadowGroup {\n"
    s += "    Environment { ambientIntensity 0.15 }\n"
    s += "    DEF Sun DeepShadowLight { location 0.8 -9 4.5 intensity 1 resolution 1024 maxLayers 3 }\n"
    s += "    DEF Fill DirectionalLight { direction 0 -0.3 -1 intensity 0.15 }\n"
    s += "    ShapeHints { vertexOrdering UNKNOWN_ORDERING shapeType UNKNOWN_SHAPE_TYPE }\n"
    s += "    DEF Stone Material { diffuseColor 0.78 0.74 0.68 }\n"
    s += quad([(-4, -3, 0), (4, -3, 0), (4, 6, 0), (-4, 6, 0)])
    s += wall_with_windows(-3, 8, 5, windows)
    s += quad([(-4, -3, 0), (-4, 6, 0), (-4, 6, 5), (-4, -3, 5)])
    s += quad([(4, -3, 0), (4, 6, 0), (4, 6, 5), (4, -3, 5)])
    s += "    DEF Windows Separator {\n"
    for k, (x0, x1, z0, z1) in enumerate(windows):
        s += stained_glass(x0, x1, z0, z1, -3, 3, 5, k, "      ")
    s += "    }\n    DEF Pews Separator { Material { diffuseColor 0.45 0.3 0.18 }\n"
    for row in range(2):
        for side in (-1, 1):
            s += box((side * 2.3, 2.2 + row * 1.4, 0.35), (2.2, 0.35, 0.7), "      ")
    s += "    }\n  }\n}\n"
    return s


def bottles():
    s = HEADER + ("# Coloured bottles and glasses on a table under a lamp: round, two-surfaced\n"
                  "# transparent casters whose shadows carry their colour. Written by\n"
                  "# tools/scene_library.py.\n")
    s += "Separator {\n"
    s += "  PerspectiveCamera { position 0 -4.2 3.4 orientation 1 0 0 0.9 heightAngle 0.75 }\n"
    s += "  DEF Table TransparentShadowGroup {\n"
    s += "    DEF Lamp DeepShadowLight { location 0.6 0.8 3.2 resolution 512 maxLayers 6 }\n"
    s += "    DirectionalLight { direction 0 1 -1 intensity 0.2 }\n"
    s += "    Separator { Material { diffuseColor 0.55 0.38 0.22 }\n"
    s += box((0, 0, -0.05), (4, 3, 0.1), "      ") + "    }\n"
    specs = [((-1.2, 0.2), (0.1, 0.55, 0.2), 0.35, 1.1), ((-0.4, -0.3), (0.55, 0.2, 0.1), 0.3, 0.9),
             ((0.5, 0.3), (0.15, 0.25, 0.8), 0.32, 1.2), ((1.2, -0.4), (0.9, 0.75, 0.15), 0.28, 0.8)]
    for k, ((x, y), colour, radius, height) in enumerate(specs):
        s += f"    DEF Bottle{k} Separator {{ {material(colour, 0.55, 'specularColor 0.8 0.8 0.8 shininess 0.9')}\n"
        s += f"      Translation {{ translation {x:g} {y:g} {height / 2:g} }}\n"
        s += f"      Rotation {{ rotation 1 0 0 1.5708 }}\n"
        s += f"      Cylinder {{ radius {radius:g} height {height:g} }}\n"
        s += f"      Translation {{ translation 0 {height / 2 + 0.15:g} 0 }}\n"
        s += f"      Cone {{ bottomRadius {radius:g} height 0.3 }}\n    }}\n"
    for k, (x, y) in enumerate([(-0.2, 0.7), (0.9, 0.9), (-1.0, -0.8)]):
        s += f"    DEF Glass{k} Separator {{ {material((0.85, 0.95, 1.0), 0.8, 'specularColor 1 1 1 shininess 1')}\n"
        s += f"      Translation {{ translation {x:g} {y:g} 0.25 }} Rotation {{ rotation 1 0 0 1.5708 }}\n"
        s += "      Cylinder { parts (SIDES | BOTTOM) radius 0.18 height 0.5 }\n    }\n"
    s += "  }\n}\n"
    return s


def leaf_texture(size=16):
    """Luminance-alpha: a few round leaves (opaque green-ish grey) with gaps between them."""
    texels = []
    centres = [(4, 4, 3.5), (11, 5, 3.2), (7, 11, 3.8), (13, 13, 2.6)]
    for j in range(size):
        for i in range(size):
            inside = any((i - cx) ** 2 + (j - cy) ** 2 <= r * r for cx, cy, r in centres)
            texels.append("0x%02X%02X" % (200, 255 if inside else 0))
    return f"image {size} {size} 2 " + " ".join(texels)


def foliage():
    s = HEADER + ("# Alpha-textured foliage: leaf cards whose texture alpha lets light through\n"
                  "# the gaps, casting dappled light on the ground. Written by\n"
                  "# tools/scene_library.py.\n")
    s += "Separator {\n"
    s += "  PerspectiveCamera { position 0 -6 4.5 orientation 1 0 0 0.95 heightAngle 0.8 }\n"
    s += "  DEF Garden TransparentShadowGroup {\n"
    s += "    DEF Sun DeepShadowLight { location 1 -1 7 resolution 1024 maxLayers 4 }\n"
    s += "    DirectionalLight { direction 0 0.5 -1 intensity 0.2 }\n"
    s += "    Separator { Material { diffuseColor 0.55 0.5 0.35 }\n"
    s += quad([(-4, -4, 0), (4, -4, 0), (4, 4, 0), (-4, 4, 0)], "      ") + "    }\n"
    s += "    DEF Canopy Separator {\n"
    s += "      ShapeHints { vertexOrdering UNKNOWN_ORDERING shapeType UNKNOWN_SHAPE_TYPE }\n"
    s += "      Complexity { textureQuality 0.1 }\n"
    s += f"      Texture2 {{ {leaf_texture()} }}\n"
    s += "      Material { diffuseColor 0.35 0.6 0.25 }\n"
    s += "      TextureCoordinate2 { point [ 0 0, 1 0, 1 1, 0 1 ] }\n"
    for k in range(9):
        x, y = -1.6 + 1.6 * (k % 3), -1.4 + 1.5 * (k // 3)
        z = 2.6 + 0.25 * ((k * 5) % 3)
        tilt = 0.15 * ((k % 2) * 2 - 1)
        c = [(x - 0.8, y - 0.8, z - tilt), (x + 0.8, y - 0.8, z + tilt),
             (x + 0.8, y + 0.8, z + tilt), (x - 0.8, y + 0.8, z - tilt)]
        s += quad(c, "      ")
    s += "    }\n  }\n}\n"
    return s


def atrium():
    s = HEADER + ("# A cathedral-like atrium: the light outside passes three walls of coloured\n"
                  "# windows in a row before it reaches the floor (as in seeds/000's tests):\n"
                  "# shadows of three layers multiply. Written by tools/scene_library.py.\n")
    s += "Separator {\n"
    s += look_at((0.3, 5.5, 3.6), (0, -1.5, 0.4))
    s += "  DEF Atrium TransparentShadowGroup {\n"
    s += "    DEF Sun DeepShadowLight { location 0 -12 6 resolution 1024 maxLayers 5 }\n"
    s += "    DirectionalLight { direction 0 -0.2 -1 intensity 0.15 }\n"
    s += "    ShapeHints { vertexOrdering UNKNOWN_ORDERING shapeType UNKNOWN_SHAPE_TYPE }\n"
    s += "    Separator { Material { diffuseColor 0.85 0.83 0.78 }\n"
    s += quad([(-4, -6, 0), (4, -6, 0), (4, 6, 0), (-4, 6, 0)], "      ") + "    }\n"
    rows = [(-5.0, (0.9, 0.2, 0.15)), (-3.5, (0.2, 0.4, 0.95)), (-2.0, (0.95, 0.85, 0.2))]
    for k, (y, colour) in enumerate(rows):
        windows = [(-3.0, -1.2, 1.0, 3.0), (-0.9, 0.9, 1.0, 3.4), (1.2, 3.0, 1.0, 3.0)]
        s += f"    DEF Screen{k} Separator {{ Material {{ diffuseColor 0.7 0.68 0.62 }}\n"
        s += wall_with_windows(y, 8, 4, windows, "      ")
        s += f"      {material(colour, 0.7)}\n"
        for (x0, x1, z0, z1) in windows:
            s += quad([(x0, y, z0), (x1, y, z0), (x1, y, z1), (x0, y, z1)], "      ")
        s += "    }\n"
    s += "  }\n}\n"
    return s


def all_directions():
    s = HEADER + ("# A caster in every direction around the light: the light sits in the middle\n"
                  "# of a closed room and a coloured glass panel hangs between it and each of\n"
                  "# the six walls, so every face of its cube map holds a shadow. Seen from a\n"
                  "# corner inside the room. Written by tools/scene_library.py.\n")
    s += "Separator {\n"
    s += look_at((2.5, -2.5, 2.2), (-0.8, 0.8, -0.9))
    s += "  DEF Room TransparentShadowGroup {\n"
    s += "    DEF Lamp DeepShadowLight { location 0 0 0 resolution 512 }\n"
    s += "    ShapeHints { vertexOrdering UNKNOWN_ORDERING shapeType UNKNOWN_SHAPE_TYPE }\n"
    s += "    Separator { Material { diffuseColor 0.9 0.9 0.9 }\n"
    r = 3.0
    for axis in range(3):
        for sign in (-1, 1):
            def p(u, v):
                c = [0, 0, 0]
                c[axis] = sign * r
                c[(axis + 1) % 3] = u
                c[(axis + 2) % 3] = v
                return tuple(c)
            s += quad([p(-r, -r), p(r, -r), p(r, r), p(-r, r)], "      ")
    s += "    }\n"
    colours = [(0.9, 0.15, 0.1), (0.1, 0.8, 0.2), (0.15, 0.3, 0.95), (0.95, 0.85, 0.1),
               (0.8, 0.2, 0.8), (0.1, 0.85, 0.85)]
    k = 0
    for axis in range(3):
        for sign in (-1, 1):
            def p(u, v):
                c = [0, 0, 0]
                c[axis] = sign * 1.2
                c[(axis + 1) % 3] = u
                c[(axis + 2) % 3] = v
                return tuple(c)
            s += f"    DEF Panel{k} Separator {{ {material(colours[k], 0.45)}\n"
            s += quad([p(-0.5, -0.3), p(0.5, -0.3), p(0.5, 0.3), p(-0.5, 0.3)], "      ")
            s += "    }\n"
            k += 1
    s += "  }\n}\n"
    return s


def stress(triangles):
    side = 10 if triangles >= 100000 else 4
    spheres = side * side
    n = max(4, int(round(math.sqrt(triangles / (2.0 * spheres)))))
    lines = [HEADER.rstrip("\n"), "",
             f"# Stress scene: {spheres} lat-long spheres of {2 * n * n} triangles each "
             f"({spheres * 2 * n * n} in all), half of them coloured glass, over a floor.",
             "# Generated by: iv_scenes/tools/scene_library.py --stress "
             f"{triangles} OUT", "Separator {",
             look_at((0.0, -13.0, 12.0), (0.0, -0.5, 0.0)).rstrip("\n"),
             "  DEF Stress TransparentShadowGroup {",
             "    DEF Lamp DeepShadowLight { location 0.5 -0.5 8 }",
             "    Separator { Material { diffuseColor 0.8 0.8 0.8 }",
             "      Coordinate3 { point [ -9 -9 0, 9 -9 0, 9 9 0, -9 9 0 ] } FaceSet { numVertices 4 } }",
             "    # The sphere mesh, defined once under a switch that hides it, used by each sphere.",
             "    Switch { whichChild -1 DEF Sphere Separator {"]
    points = []
    for row in range(n + 1):
        theta = math.pi * row / n
        for column in range(n + 1):
            phi = 2 * math.pi * column / n
            points.append("%.4f %.4f %.4f" % (0.6 * math.sin(theta) * math.cos(phi),
                                              0.6 * math.sin(theta) * math.sin(phi),
                                              0.6 * math.cos(theta)))
    lines.append("      Coordinate3 { point [ " + ", ".join(points) + " ] }")
    lines.append(f"      QuadMesh {{ verticesPerRow {n + 1} verticesPerColumn {n + 1} }} }} }}")
    for i in range(spheres):
        x = (i % side - 0.5 * (side - 1)) * 1.4
        y = (i // side - 0.5 * (side - 1)) * 1.4
        glass = i % 2 == 0
        colour = (0.2 + 0.6 * (i % 3 == 0), 0.8, 0.3) if glass else (0.7, 0.7, 0.7)
        lines.append(f"    Separator {{ Translation {{ translation {x:g} {y:g} 2 }} "
                     f"{material(colour, 0.5 if glass else 0.0)} "
                     "USE Sphere }")
    lines += ["  }", "}", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--stress":
        with open(sys.argv[3], "w") as out:
            out.write(stress(int(sys.argv[2])))
    elif len(sys.argv) == 2:
        for name, make in [("chapel", chapel), ("bottles", bottles), ("foliage", foliage),
                           ("atrium", atrium), ("all_directions", all_directions)]:
            with open(os.path.join(sys.argv[1], name + ".iv"), "w") as out:
                out.write(make())
    else:
        sys.exit(__doc__)
