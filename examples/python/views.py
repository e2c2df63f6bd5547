"""Viewpoints and camera matrices for the dataset examples (dataset.py with facet,
dataset_pyrender.py with pyrender): plain NumPy, so both scripts place their cameras alike.

Conventions: world_to_camera is OpenGL's (the camera looks down -Z, y up, as facet's
Camera.view_matrix() and pyrender's camera poses); intrinsics K is OpenCV's (x right, y down,
z forward, pixel centres at whole numbers, so the centre of a W x H image is at
((W - 1) / 2, (H - 1) / 2)); OPENGL_TO_OPENCV turns one camera frame into the other.
"""
import argparse
import math

import numpy as np

OPENGL_TO_OPENCV = np.diag([1.0, -1.0, -1.0, 1.0])


def sphere_directions(count):
    """count unit vectors spread evenly over the sphere (a Fibonacci lattice), from +Y down."""
    golden_angle = math.pi * (3.0 - math.sqrt(5.0))
    directions = []
    for i in range(count):
        y = 1.0 - (i + 0.5) * 2.0 / count
        ring = math.sqrt(max(0.0, 1.0 - y * y))
        directions.append((ring * math.cos(golden_angle * i), y, ring * math.sin(golden_angle * i)))
    return np.array(directions)


def up_for(direction):
    """+Y, unless the view looks (almost) straight up or down, where +Z serves instead."""
    return (0.0, 0.0, 1.0) if abs(direction[1]) > 0.99 else (0.0, 1.0, 0.0)


def framing(center, radius, fov_y_degrees, aspect):
    """Distance at which a sphere of radius around center fills the narrower side of the view,
    with near and far planes that hold it: (distance, near, far)."""
    half = math.radians(fov_y_degrees) / 2.0
    if aspect < 1.0:
        half = math.atan(math.tan(half) * aspect)  # the horizontal half-angle is the narrower
    distance = 1.1 * radius / math.sin(half)
    return distance, max(distance - 1.05 * radius, distance * 1e-3), distance + 1.05 * radius


def look_at(eye, target, up):
    """The 4x4 world-to-camera matrix (OpenGL axes) of a camera at eye looking at target."""
    eye, target, up = (np.asarray(v, np.float64) for v in (eye, target, up))
    forward = target - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    true_up = np.cross(right, forward)
    matrix = np.eye(4)
    matrix[0, :3], matrix[1, :3], matrix[2, :3] = right, true_up, -forward
    matrix[:3, 3] = -matrix[:3, :3] @ eye
    return matrix


def intrinsics(fov_y_degrees, width, height):
    """The 3x3 pinhole matrix K (OpenCV conventions, square pixels) of a perspective camera
    with this vertical field of view rendering a width x height image."""
    focal = (height / 2.0) / math.tan(math.radians(fov_y_degrees) / 2.0)
    return np.array(
        [[focal, 0.0, (width - 1) / 2.0], [0.0, focal, (height - 1) / 2.0], [0.0, 0.0, 1.0]]
    )


def parse_size(text):
    """WIDTHxHEIGHT for argparse: (width, height)."""
    try:
        width, height = (int(part) for part in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT, got {text!r}")
    if width < 1 or height < 1:
        raise argparse.ArgumentTypeError(f"the size must be positive, got {text!r}")
    return width, height
