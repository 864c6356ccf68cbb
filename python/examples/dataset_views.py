#!/usr/bin/env python3
"""RGB, depth and instance masks of a model from random views, into one .npz: a synthetic training set for 6D pose
estimation.

    python3 python/examples/dataset_views.py MODEL OUT.npz [--views 100] [--width 640] [--height 480]

The .npz holds rgb (V, H, W, 3) uint8, depth (V, H, W) float32 (distance along the optical axis, 0 where the model
is not), mask (V, H, W) uint8 (1 on the model), K (3, 3) (OpenCV's camera matrix) and world_to_camera (V, 4, 4)
(OpenCV's extrinsics [R | t] of each view). MODEL defaults to Debian's 2CylinderEngine (assimp-testmodels).
"""
import argparse
import os
import sys
import time

import numpy as np

import softgl

DEFAULT_MODEL = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("model", nargs="?", default=DEFAULT_MODEL)
    parser.add_argument("output", nargs="?", default="out/dataset_views.npz")
    parser.add_argument("--views", type=int, default=100)
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=480)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    if not os.path.exists(args.model):
        print(f"dataset_views: {args.model} not found (install assimp-testmodels, or name a model): skipped")
        return 0

    start = time.perf_counter()
    r = softgl.Renderer(args.width, args.height, msaa=4, shader="pbr")
    r.add_model(args.model, object_id=1)
    lo, hi = (np.array(b) for b in r.bounds())
    centre, radius = (lo + hi) / 2, np.linalg.norm(hi - lo) / 2
    # A camera whose vertical field of view is 50 degrees, principal point at the image centre.
    fy = args.height / 2 / np.tan(np.radians(25))
    K = np.array([[fy, 0, (args.width - 1) / 2], [0, fy, (args.height - 1) / 2], [0, 0, 1]])
    rng = np.random.default_rng(args.seed)
    rgb = np.empty((args.views, args.height, args.width, 3), np.uint8)
    depth = np.empty((args.views, args.height, args.width), np.float32)
    mask = np.empty((args.views, args.height, args.width), np.uint8)
    extrinsics = np.empty((args.views, 4, 4))
    for i in range(args.views):
        direction = rng.normal(size=3)
        direction /= np.linalg.norm(direction)
        distance = radius * rng.uniform(2.2, 3.5)
        target = centre + rng.uniform(-0.15, 0.15, size=3) * radius
        up = (0, 1, 0) if abs(direction[1]) < 0.95 else (1, 0, 0)
        extrinsics[i] = softgl.look_at(centre + direction * distance, target, up)
        r.set_intrinsics(K[0, 0], K[1, 1], K[0, 2], K[1, 2], near=distance - 1.5 * radius,
                         far=distance + 1.5 * radius, world_to_camera=extrinsics[i])
        out = r.render(depth=True, ids=True)
        rgb[i], depth[i], mask[i] = out["color"], out["depth"], out["ids"] == 1
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    np.savez_compressed(args.output, rgb=rgb, depth=depth, mask=mask, K=K, world_to_camera=extrinsics)
    print(f"{args.output}: {args.views} views of {args.width} x {args.height} in {time.perf_counter() - start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
