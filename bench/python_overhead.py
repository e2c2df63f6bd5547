#!/usr/bin/env python3
"""What rendering from Python costs over rendering from C++: the same frame (a model at 640x480,
color, or color and depth) drawn FRAMES times through facet.Renderer.render, against the
renderer's own time for it (Renderer::stats().ms_total, what a C++ caller's finish() takes).
The difference is the module's: argument checks, the GIL, the framebuffer a frame gets and
hands over as arrays. Prints the medians and their ratio.

    PYTHONPATH=build/python/package /usr/bin/python3 bench/python_overhead.py [MODEL] [FRAMES]
"""
import statistics
import sys
import time

import facet


def main():
    model = sys.argv[1] if len(sys.argv) > 1 else "/usr/share/glmark2/models/bunny.obj"
    frames = int(sys.argv[2]) if len(sys.argv) > 2 else 300
    scene = facet.load(model)
    renderer = facet.Renderer(640, 480)
    for outputs in (("color",), ("color", "depth")):
        for _ in range(20):  # warm up: threads started, buffers sized
            renderer.render(scene, outputs=outputs)
        wall, inside = [], []
        for _ in range(frames):
            start = time.perf_counter()
            renderer.render(scene, outputs=outputs)
            wall.append((time.perf_counter() - start) * 1e3)
            inside.append(renderer.stats["ms_total"])
        w, c = statistics.median(wall), statistics.median(inside)
        print(f"{'+'.join(outputs)}: python {w:.3f} ms/frame, renderer {c:.3f} ms/frame, "
              f"python / renderer = {w / c:.3f}")


if __name__ == "__main__":
    main()
