#!/usr/bin/env python3
"""A turntable of any model file as one PNG strip: the model seen from N azimuths, side by side.

    python3 python/examples/turntable.py MODEL OUT.png [--frames 8] [--size 256] [--shader pbr]

MODEL defaults to the Damaged Helmet of ../shared/assets (or Debian's 2CylinderEngine).
"""
import argparse
import os
import sys

import numpy as np

import softgl

HERE = os.path.dirname(os.path.abspath(__file__))
CANDIDATES = [
    os.path.join(HERE, "../../../shared/assets/damaged_helmet/DamagedHelmet.gltf"),
    "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("model", nargs="?")
    parser.add_argument("output", nargs="?", default="out/turntable.png")
    parser.add_argument("--frames", type=int, default=8)
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--shader", default="pbr", choices=["unlit", "phong", "pbr"])
    parser.add_argument("--elevation", type=float, default=15.0)
    args = parser.parse_args()
    model = args.model or next((p for p in CANDIDATES if os.path.exists(p)), None)
    if model is None or not os.path.exists(model):
        print("turntable: no model found (name one): skipped")
        return 0
    r = softgl.Renderer(args.size, args.size, msaa=4, shader=args.shader)
    r.add_model(model)
    r.set_background((0.16, 0.17, 0.2, 1.0))
    frames = []
    for i in range(args.frames):
        r.frame(azimuth=360.0 * i / args.frames, elevation=args.elevation)
        frames.append(r.render()["color"])
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    softgl.write_png(args.output, np.ascontiguousarray(np.concatenate(frames, axis=1)))
    print(args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
