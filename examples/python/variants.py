#!/usr/bin/env python3
"""Variants of a scene built in pivy, rendered headlessly by ivshadow.

    PYTHONPATH=build/python python3 examples/python/variants.py OUT_DIR [--size 320x240]

Builds a transparent pane over a floor, lit by a DeepShadowLight inside a
TransparentShadowGroup, all created from Python with SoType.fromName; then, for each pane
colour and transparency, sets the fields in the scene graph and renders it to OUT_DIR/NAME.png
with ivshadow.render (the renderer of `ivshadow render`), printing each render's frame time and
what drew its shadows from the statistics it returns. The variants change what acts on every
path: on a machine without a GPU the group traces (renderer AUTO), where a map's fields do
nothing. A bad assignment comes back as an IvShadowError
naming the node and field.
"""
import argparse
import os

import ivshadow  # first: makes ivshadow's nodes known to pivy's Coin
from pivy import coin

# (name, pane colour, pane transparency)
VARIANTS = [
    ("red", "0.9 0.1 0.1", 0.5),
    ("green", "0.1 0.8 0.2", 0.5),
    ("blue_clearer", "0.1 0.2 0.9", 0.8),
]


def create(type_name, name=None):
    """A node of a type Coin knows by name only, as a file would name it."""
    node_type = coin.SoType.fromName(coin.SbName(type_name))
    if node_type.isBad():
        raise RuntimeError("Coin does not know %s: is ivshadow imported?" % type_name)
    node = node_type.createInstance()
    if name:
        node.setName(name)
    return node


def box(material, translation, width, height, depth):
    part = coin.SoSeparator()
    move = coin.SoTranslation()
    move.translation = translation
    shape = coin.SoCube()
    shape.width, shape.height, shape.depth = width, height, depth
    for child in (move, material, shape):
        part.addChild(child)
    return part


def build_scene():
    """The scene of tests/python/pane.iv, made node by node."""
    group = create("TransparentShadowGroup", "Scene")
    lamp = create("DeepShadowLight", "Lamp")
    lamp.getField("location").set("0.6 -0.4 3")
    group.addChild(lamp)
    floor = coin.SoMaterial()
    floor.diffuseColor = (0.9, 0.9, 0.9)
    group.addChild(box(floor, (0, 0, -0.05), 4, 4, 0.1))
    pane = coin.SoMaterial()
    pane.setName("PaneMaterial")
    pane.transparency = 0.5
    group.addChild(box(pane, (0, 0, 1), 1.4, 1.4, 0.05))
    return group, lamp, pane


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--size", default="320x240")
    args = parser.parse_args()
    size = tuple(int(v) for v in args.size.split("x"))
    os.makedirs(args.out, exist_ok=True)

    scene, lamp, pane = build_scene()
    scene.ref()
    for name, colour, transparency in VARIANTS:
        pane.diffuseColor.setValue(*(float(v) for v in colour.split()))
        pane.transparency.setValue(transparency)
        stats = ivshadow.render(scene, os.path.join(args.out, name + ".png"), size=size)
        if stats.get("tracer_frames", 0) > 0:
            drawn = "traced on the CPU"
        else:
            drawn = "map %d KiB" % (stats.get("dsm_bytes", 0) // 1024)
        print("%s: %.1f ms a frame, %s" % (name, stats["frame_ms_median"], drawn))
    try:
        ivshadow.render(scene, os.path.join(args.out, "never.png"), size=size,
                        sets=["Lamp.colour=1 0 0"])
    except ivshadow.IvShadowError as error:
        print("refused as expected (exit %d): %s" % (error.status, error.message))
    scene.unref()


if __name__ == "__main__":
    main()
