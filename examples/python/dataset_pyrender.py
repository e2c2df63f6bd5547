#!/usr/bin/env python3
"""The job of dataset.py written for pyrender, to compare the two (docs/python.md): a model
from viewpoints on a sphere, color + depth + instance masks + cameras into a folder.

Not run by facet's tests: pyrender, trimesh and Pillow are not in Debian (pip install pyrender
pillow), and pyrender needs OpenGL: a GPU, or on a server PYOPENGL_PLATFORM=egl (a GPU
driver) or PYOPENGL_PLATFORM=osmesa (Mesa's software rasterizer). The outputs follow
dataset.py's conventions, so the two folders can be compared file by file: pyrender's depth is
also the distance along the camera axis with 0 where nothing was drawn.

    python3 examples/python/dataset_pyrender.py model.glb out-pyrender/ --views 100
"""
import argparse
import json
import os
import sys
import time

import numpy as np
import pyrender
import trimesh
from PIL import Image

import views


def arguments(argv):
    parser = argparse.ArgumentParser(
        description="dataset.py's job with pyrender: color PNGs, depth .npy, instance masks "
        "and cameras of a model seen from viewpoints on a sphere.")
    parser.add_argument("model", help="model file trimesh reads (glTF/GLB, OBJ, PLY, STL, ...)")
    parser.add_argument("output", help="folder to write into (made if missing)")
    parser.add_argument("--views", type=int, default=100, help="viewpoints (default: 100)")
    parser.add_argument("--size", type=views.parse_size, default=(640, 480),
                        help="image size WIDTHxHEIGHT (default: 640x480)")
    parser.add_argument("--fov", type=float, default=45.0,
                        help="vertical field of view in degrees (default: 45)")
    return parser.parse_args(argv)


def main(argv=None):
    options = arguments(argv)
    width, height = options.size
    loaded = trimesh.load(options.model, force="scene")
    scene = pyrender.Scene(bg_color=(0, 0, 0, 0), ambient_light=(0.12, 0.12, 0.12))
    # One node per mesh instance, numbered 1, 2, ... as facet numbers its instances.
    instance_ids = {}
    for node_name in loaded.graph.nodes_geometry:
        transform, geometry_name = loaded.graph[node_name]
        mesh = pyrender.Mesh.from_trimesh(loaded.geometry[geometry_name])
        node = scene.add(mesh, pose=transform)
        instance_ids[node] = len(instance_ids) + 1

    lower, upper = loaded.bounds
    center = (lower + upper) / 2.0
    radius = max(float(np.linalg.norm(upper - lower)) / 2.0, 1e-6)
    distance, near, far = views.framing(center, radius, options.fov, width / height)
    camera = pyrender.PerspectiveCamera(yfov=np.radians(options.fov), znear=near, zfar=far,
                                        aspectRatio=width / height)
    camera_node = scene.add(camera)
    # A light that travels with the camera (pyrender has no three-point default).
    light_node = scene.add(pyrender.DirectionalLight(color=np.ones(3), intensity=3.0))

    renderer = pyrender.OffscreenRenderer(width, height)
    # Segmentation renders flat colors per node: instance id i as the color (i, i, i).
    segment_colors = {node: np.full(3, index, np.uint8) for node, index in instance_ids.items()}
    os.makedirs(options.output, exist_ok=True)
    world_to_camera, described = [], []
    start = time.perf_counter()
    for index, direction in enumerate(views.sphere_directions(options.views)):
        eye = center + distance * direction
        up = views.up_for(direction)
        view = views.look_at(eye, center, up)
        pose = np.linalg.inv(view)  # pyrender poses are camera-to-world, OpenGL axes
        scene.set_pose(camera_node, pose)
        scene.set_pose(light_node, pose)
        color, depth = renderer.render(scene, flags=pyrender.RenderFlags.RGBA)
        segments, _ = renderer.render(scene, flags=pyrender.RenderFlags.SEG,
                                      seg_node_map=segment_colors)
        stem = os.path.join(options.output, f"{{}}_{index:03d}")
        Image.fromarray(color).save(stem.format("color") + ".png")
        np.save(stem.format("depth") + ".npy", depth.astype(np.float32))
        np.save(stem.format("instance") + ".npy", segments[..., 0].astype(np.uint32))
        world_to_camera.append(view)
        described.append({"index": index, "eye": eye.tolist(), "target": center.tolist(),
                          "up": list(up), "fov_y": options.fov, "near": near, "far": far})
    seconds = time.perf_counter() - start
    renderer.delete()

    world_to_camera = np.array(world_to_camera)
    np.savez(
        os.path.join(options.output, "cameras.npz"),
        world_to_camera=world_to_camera,
        world_to_camera_opencv=views.OPENGL_TO_OPENCV @ world_to_camera,
        projection=np.array([camera.get_projection_matrix(width, height)] * len(described)),
        intrinsics=np.array([views.intrinsics(options.fov, width, height)] * len(described)),
        eye=np.array([view["eye"] for view in described]),
    )
    with open(os.path.join(options.output, "cameras.json"), "w") as file:
        json.dump({"model": options.model, "width": width, "height": height,
                   "outputs": ["color", "depth", "instance"], "views": described}, file, indent=1)
    print(f"dataset_pyrender: {len(described)} views in {options.output}, {seconds:.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
