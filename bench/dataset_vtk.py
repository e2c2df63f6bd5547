#!/usr/bin/env python3
"""examples/python/dataset.py's job with VTK's Python offscreen rendering (Debian python3-vtk9,
OpenGL on Mesa llvmpipe under Xvfb), for bench/dataset_vs_vtk.sh: a model from viewpoints on a
sphere, color PNGs and depth .npy (distance along the camera axis, 0 where empty) into a folder,
the same views as facet's (examples/python/views.py). Prints the seconds the views took.

    xvfb-run -a python3 bench/dataset_vtk.py model.obj out/ --views 100 --size 640x480
"""
import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "examples", "python"))
import views  # noqa: E402

import vtk  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("model", help="an OBJ file")
    parser.add_argument("output")
    parser.add_argument("--views", type=int, default=100)
    parser.add_argument("--size", type=views.parse_size, default=(640, 480))
    parser.add_argument("--fov", type=float, default=45.0)
    options = parser.parse_args()
    width, height = options.size
    os.makedirs(options.output, exist_ok=True)

    reader = vtk.vtkOBJReader()
    reader.SetFileName(options.model)
    normals = vtk.vtkPolyDataNormals()  # smooth normals, as facet makes for a file without
    normals.SetInputConnection(reader.GetOutputPort())
    normals.Update()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    renderer = vtk.vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0, 0, 0)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(width, height)
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGBA()
    grab.ReadFrontBufferOff()
    png = vtk.vtkPNGWriter()
    png.SetInputConnection(grab.GetOutputPort())

    lower = np.array(normals.GetOutput().GetBounds()[0::2])
    upper = np.array(normals.GetOutput().GetBounds()[1::2])
    center = (lower + upper) / 2.0
    radius = max(float(np.linalg.norm(upper - lower)) / 2.0, 1e-6)
    distance, near, far = views.framing(center, radius, options.fov, width / height)
    camera = renderer.GetActiveCamera()
    camera.SetViewAngle(options.fov)
    depth = vtk.vtkFloatArray()

    start = time.perf_counter()
    for index, direction in enumerate(views.sphere_directions(options.views)):
        camera.SetPosition(*(center + distance * direction))
        camera.SetFocalPoint(*center)
        camera.SetViewUp(*views.up_for(direction))
        camera.SetClippingRange(near, far)
        window.Render()
        grab.Modified()
        png.SetFileName(os.path.join(options.output, f"color_{index:03d}.png"))
        png.Write()
        window.GetZbufferData(0, 0, width - 1, height - 1, depth)
        z = np.flipud(vtk_to_numpy(depth).reshape(height, width))
        # Window depth to distance along the axis, 0 where empty (as facet's depth output).
        distance_along = near * far / (far - z * (far - near))
        np.save(os.path.join(options.output, f"depth_{index:03d}.npy"),
                np.where(z < 1.0, distance_along, 0.0).astype(np.float32))
    print(f"{time.perf_counter() - start:.3f}")


if __name__ == "__main__":
    main()
