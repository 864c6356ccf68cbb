#!/usr/bin/env python3
"""What the Python module adds to a frame, and how soon the first frame comes after `import softgl`.

    PYTHONPATH=build/release/python python3 python/bench/overhead.py build/release/python/softgl_python_frame [MODEL]

Times the same frame (MODEL at 640 x 480, framed from azimuth 30 and elevation 20, three-point lighting,
PhongShader, 4x multisampling, the colour read back) through the C++ API (softgl_python_frame) and through
Renderer.render(), in alternating runs, and prints each run's median milliseconds and their ratio. Then starts a
fresh interpreter that imports softgl, loads MODEL and renders it once, and prints the time from before the import
to the first image.
"""
import os
import statistics
import subprocess
import sys
import time

import numpy as np

MODEL = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"
W, H, FRAMES, RUNS = 640, 480, 40, 5


def python_frame_ms(model):
    import softgl
    r = softgl.Renderer(W, H, msaa=4, shader="phong")
    r.add_model(model)
    r.frame(azimuth=30, elevation=20, fov_y=40)
    r.render()  # warm-up
    times = []
    for _ in range(FRAMES):
        start = time.perf_counter()
        image = r.render()["color"]
        times.append((time.perf_counter() - start) * 1000)
    assert image.shape == (H, W, 3)
    return statistics.median(times)


FIRST = """
import time
start = time.perf_counter()
import softgl
r = softgl.Renderer(640, 480, msaa=4)
r.add_model({model!r})
r.frame()
image = r.render()["color"]
print(time.perf_counter() - start)
"""


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    program = sys.argv[1]
    model = sys.argv[2] if len(sys.argv) > 2 else MODEL
    if not os.path.exists(model):
        print(f"overhead: {model} not found: skipped")
        return 0
    rows = []
    for run in range(RUNS):
        cpp = float(subprocess.run([program, model, str(W), str(H), str(FRAMES)], check=True, capture_output=True,
                                   text=True).stdout)
        py = python_frame_ms(model)
        rows.append((cpp, py))
        print(f"run {run + 1}: C++ {cpp:.2f} ms, Python {py:.2f} ms, Python / C++ {py / cpp:.3f}")
    ratios = [py / cpp for cpp, py in rows]
    print(f"median Python / C++: {statistics.median(ratios):.3f}")
    firsts = [float(subprocess.run([sys.executable, "-c", FIRST.format(model=model)], check=True,
                                   capture_output=True, text=True).stdout) for _ in range(3)]
    print("import to first image: " + ", ".join(f"{t:.2f} s" for t in firsts))
    return 0


if __name__ == "__main__":
    sys.exit(main())
