#!/usr/bin/env python3
"""Renders a model from viewpoints spread over a sphere around it, as dataset.py does, on a Dask
cluster (facet.dask): each worker renders shards of the views and writes their files.

    python3 examples/python/dask_dataset.py model.glb out/ --views 100 --workers 2
    python3 examples/python/dask_dataset.py /data/model.glb /data/out --scheduler tcp://host:8786

With --scheduler, the workers are those of a running cluster (`dask scheduler` on one machine,
`dask worker tcp://host:8786` on each of the others); the model and the output folder must be
at the same path on every machine. Without it, a cluster of --workers processes on this machine;
with --local, no cluster: facet.dask.render_local in this process (the same files), to compare.

Writes into the output folder, for view N (000, 001, ...):
    view_N_color.png      RGBA, sRGB (the background transparent)
    view_N_depth.npy      float32 (H, W): distance along the camera axis, scene units, 0 = empty
    view_N_OUTPUT.npy     every other output named with --outputs, as facet renders it
    index.json            per view: its files, whether rendered now or found complete, the
                          camera (eye, target, up, fov_y, near, far), world_to_camera (OpenGL)
                          and the intrinsics K (OpenCV)
Run again, it renders only the views whose files are missing.
"""
import argparse
import contextlib
import json
import logging
import os
import sys
import time

import facet
import facet.dask
import views
from dataset import cameras_around


def arguments(argv):
    parser = argparse.ArgumentParser(
        description="Render a model from viewpoints on a sphere around it on a Dask cluster: "
        "color PNGs and the other outputs as .npy, with index.json describing every view.",
    )
    parser.add_argument("model", help="model file: glTF/GLB, OBJ, PLY, STL, FBX, ... (facet.load)")
    parser.add_argument("output", help="folder to write into (made if missing)")
    parser.add_argument("--views", type=int, default=100, help="viewpoints (default: 100)")
    parser.add_argument("--size", type=views.parse_size, default=(640, 480),
                        help="image size WIDTHxHEIGHT (default: 640x480)")
    parser.add_argument("--fov", type=float, default=45.0,
                        help="vertical field of view in degrees (default: 45)")
    parser.add_argument("--outputs", default="color,depth",
                        help="outputs, comma-separated (default: color,depth; facet.OUTPUTS "
                        "lists them)")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--scheduler", metavar="ADDRESS",
                       help="a running Dask scheduler, e.g. tcp://host:8786")
    where.add_argument("--workers", type=int, default=os.cpu_count() or 1,
                       help="without --scheduler: worker processes on this machine (default: "
                       "one a core)")
    where.add_argument("--local", action="store_true",
                       help="no cluster: render in this process, every core on each view")
    parser.add_argument("--threads-per-worker", type=int, default=1,
                        help="without --scheduler: threads of each worker process (default: 1)")
    parser.add_argument("--shard-size", type=int, default=None,
                        help="views per task (default: facet.dask's choice)")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    options = parser.parse_args(argv)
    if options.views < 1:
        parser.error("--views must be at least 1")
    if options.workers < 1 or options.threads_per_worker < 1:
        parser.error("--workers and --threads-per-worker must be at least 1")
    return options


def connect(options, stack):
    """A client of the cluster at --scheduler, or of a new one of --workers processes here;
    stack closes them."""
    import distributed

    if options.scheduler:
        return stack.enter_context(distributed.Client(options.scheduler))
    cluster = stack.enter_context(distributed.LocalCluster(
        n_workers=options.workers, threads_per_worker=options.threads_per_worker,
        processes=True, dashboard_address=":0", silence_logs=logging.ERROR))
    return stack.enter_context(distributed.Client(cluster))


def write_index(options, index, cameras, width, height):
    described = []
    for (stem, entry), camera in zip(index.items(), cameras):
        view = camera.view_matrix()
        described.append({
            "stem": stem, "files": entry["files"], "status": entry["status"],
            **({"error": entry["error"]} if "error" in entry else {}),
            "eye": camera.eye, "target": camera.target, "up": camera.up,
            "fov_y": camera.fov_y, "near": camera.near, "far": camera.far,
            "world_to_camera": view.tolist(),
            "intrinsics": views.intrinsics(camera.fov_y, width, height).tolist(),
        })
    with open(os.path.join(options.output, "index.json"), "w") as file:
        json.dump({"model": os.path.abspath(options.model), "width": width, "height": height,
                   "views": described}, file, indent=1)


def main(argv=None):
    options = arguments(argv)
    width, height = options.size
    outputs = tuple(name.strip() for name in options.outputs.split(",") if name.strip())
    try:
        scene = facet.load(options.model)  # here only to frame the views
        cameras = cameras_around(scene, options.views, options.fov, width / height)
        items = [facet.dask.Item(f"view_{index:03d}", options.model, camera, outputs,
                                 (width, height), {"background": (0, 0, 0, 0)})
                 for index, camera in enumerate(cameras)]
        with contextlib.ExitStack() as stack:
            if options.local:
                where = "in this process"
                start = time.perf_counter()
                index = facet.dask.render_local(items, options.output, progress=not options.quiet,
                                                raise_errors=False)
            else:
                client = connect(options, stack)
                where = f"on {len(client.scheduler_info()['workers'])} workers"
                start = time.perf_counter()
                index = facet.dask.render(client, items, options.output,
                                          shard_size=options.shard_size,
                                          progress=not options.quiet, raise_errors=False)
            seconds = time.perf_counter() - start
    except facet.Error as error:
        print(f"dask_dataset: {error}", file=sys.stderr)
        return 2
    write_index(options, index, cameras, width, height)
    print(f"dask_dataset: {len(items)} views of {options.model} ({width}x{height}, "
          f"{', '.join(outputs)}) in {options.output} {where}: "
          f"{index.summary()} in {seconds:.2f} s, {len(items) / seconds:.1f} views/s")
    for stem in index.failed:
        print(f"dask_dataset: {stem}: {index[stem]['error']}", file=sys.stderr)
    return 1 if index.failed else 0


if __name__ == "__main__":
    sys.exit(main())
