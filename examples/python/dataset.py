#!/usr/bin/env python3
"""Renders a model from viewpoints spread evenly over a sphere around it, with facet: color,
depth, instance masks and every view's camera, into a folder.

    python3 examples/python/dataset.py model.glb out/ --views 100 --size 640x480

Writes into the output folder:
    color_000.png ...     RGBA, sRGB (the background transparent)
    depth_000.npy ...     float32 (H, W): distance along the camera axis, scene units, 0 = empty
    instance_000.npy ...  uint32 (H, W): the instance ids of facet.Scene, 0 = empty
    cameras.npz           per view (first axis): world_to_camera (OpenGL axes), projection
                          (OpenGL), intrinsics K and world_to_camera_opencv (OpenCV), eye
    cameras.json          the views in words: eye, target, up, field of view, near, far

dataset_pyrender.py is the same job written for pyrender, to compare with.
"""
import argparse
import json
import os
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import facet
import views


def arguments(argv):
    parser = argparse.ArgumentParser(
        description="Render a model from viewpoints on a sphere around it: color PNGs, depth "
        "as .npy (distance along the camera axis, 0 where empty), instance ids, and the "
        "cameras (cameras.npz, cameras.json).",
    )
    parser.add_argument("model", help="model file: glTF/GLB, OBJ, PLY, STL, FBX, ... (facet.load)")
    parser.add_argument("output", help="folder to write into (made if missing)")
    parser.add_argument("--views", type=int, default=100, help="viewpoints (default: 100)")
    parser.add_argument("--size", type=views.parse_size, default=(640, 480),
                        help="image size WIDTHxHEIGHT (default: 640x480)")
    parser.add_argument("--fov", type=float, default=45.0,
                        help="vertical field of view in degrees (default: 45)")
    parser.add_argument("--outputs", default="color,depth,instance",
                        help="comma-separated, of color, depth, instance (default: all three)")
    parser.add_argument("--workers", type=int, default=1,
                        help="Python threads rendering at once, each with its own renderer "
                        "(default: 1; facet releases the GIL while it renders)")
    parser.add_argument("--threads", type=int, default=0,
                        help="render threads per renderer (default: 0, all cores)")
    options = parser.parse_args(argv)
    if options.views < 1:
        parser.error("--views must be at least 1")
    if options.workers < 1:
        parser.error("--workers must be at least 1")
    options.outputs = options.outputs.split(",")
    if not options.outputs or not set(options.outputs) <= {"color", "depth", "instance"}:
        parser.error("--outputs takes color, depth and instance")
    return options


def cameras_around(scene, count, fov_y, aspect):
    lower, upper = (np.array(corner) for corner in scene.bounds)
    center = (lower + upper) / 2.0
    radius = max(float(np.linalg.norm(upper - lower)) / 2.0, 1e-6)
    distance, near, far = views.framing(center, radius, fov_y, aspect)
    return [
        facet.Camera.look_at(center + distance * direction, center, views.up_for(direction),
                             fov_y, near, far)
        for direction in views.sphere_directions(count)
    ]


def main(argv=None):
    options = arguments(argv)
    width, height = options.size
    try:
        scene = facet.load(options.model)
        cameras = cameras_around(scene, options.views, options.fov, width / height)
        outputs = options.outputs
        os.makedirs(options.output, exist_ok=True)
        local = threading.local()

        def render(index):
            if not hasattr(local, "renderer"):
                local.renderer = facet.Renderer(width, height, threads=options.threads,
                                                background=(0, 0, 0, 0))
            frame = local.renderer.render(scene, cameras[index], outputs)
            stem = os.path.join(options.output, f"{{}}_{index:03d}")
            if "color" in frame:
                facet.write_png(stem.format("color") + ".png", frame["color"])
            for name in ("depth", "instance"):
                if name in frame:
                    np.save(stem.format(name) + ".npy", frame[name])

        start = time.perf_counter()
        with ThreadPoolExecutor(options.workers) as pool:
            list(pool.map(render, range(len(cameras))))
        seconds = time.perf_counter() - start
    except facet.Error as error:
        print(f"dataset: {error}", file=sys.stderr)
        return 2

    world_to_camera = np.array([camera.view_matrix() for camera in cameras])
    np.savez(
        os.path.join(options.output, "cameras.npz"),
        world_to_camera=world_to_camera,
        world_to_camera_opencv=views.OPENGL_TO_OPENCV @ world_to_camera,
        projection=np.array([camera.projection_matrix(width / height) for camera in cameras]),
        intrinsics=np.array([views.intrinsics(camera.fov_y, width, height) for camera in cameras]),
        eye=np.array([camera.eye for camera in cameras]),
    )
    described = [
        {"index": index, "eye": camera.eye, "target": camera.target, "up": camera.up,
         "fov_y": camera.fov_y, "near": camera.near, "far": camera.far}
        for index, camera in enumerate(cameras)
    ]
    with open(os.path.join(options.output, "cameras.json"), "w") as file:
        json.dump({"model": options.model, "width": width, "height": height,
                   "outputs": outputs, "views": described}, file, indent=1)
    print(f"dataset: {len(cameras)} views of {options.model} ({width}x{height}, "
          f"{', '.join(outputs)}) in {options.output}, {seconds:.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
