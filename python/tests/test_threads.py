"""Renderers in several Python threads at once (the GIL is released while a frame renders):
the same images as one after another, whatever the threads share."""
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import facet
from scenes import icosphere, quad

SIZE = (96, 72)


def busy_scene():
    """Spheres of several materials over a floor, lit by every kind of light."""
    scene = facet.Scene()
    vertices, faces = icosphere(2)
    rng = np.random.default_rng(7)
    for index, shading in enumerate(("lambert", "phong", "pbr", "flat", "gouraud", "unlit")):
        pose = np.eye(4)
        pose[:3, 3] = (index % 3 - 1) * 1.2, 0.5, (index // 3) * 1.2 - 0.6
        colors = rng.integers(0, 256, (len(vertices), 3), dtype=np.uint8)
        scene.add_mesh(vertices * 0.5, faces, colors=colors, pose=pose,
                       material=facet.Material(shading=shading, metallic=0.5, roughness=0.3))
    floor, floor_faces, _ = quad(half=4)
    scene.add_mesh(floor @ np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]], np.float32), floor_faces)
    scene.add_light(facet.Light.directional((-0.3, -1, -0.5)))
    scene.add_light(facet.Light.point((0, 3, 2), color=(1, 0.8, 0.6), intensity=4))
    scene.add_light(facet.Light.spot((2, 3, 0), (-1, -1, 0), color=(0.5, 0.5, 1), intensity=6))
    return scene


def cameras(count):
    result = []
    for i in range(count):
        angle = 2 * np.pi * i / count
        eye = (4 * np.sin(angle), 2.5, 4 * np.cos(angle))
        result.append(facet.Camera.look_at(eye, (0, 0.3, 0), fov_y=50, near=0.5, far=20))
    return result


def test_four_threads_with_a_renderer_each_match_serial_rendering():
    scene = busy_scene()
    views = cameras(12)
    renderer = facet.Renderer(*SIZE, threads=2)
    serial = [renderer.render(scene, camera) for camera in views]

    local = threading.local()

    def render(camera):
        if not hasattr(local, "renderer"):
            local.renderer = facet.Renderer(*SIZE, threads=2)
        return local.renderer.render(scene, camera)

    for _ in range(2):
        with ThreadPoolExecutor(4) as pool:
            parallel = list(pool.map(render, views))
        for expected, got in zip(serial, parallel):
            assert np.array_equal(expected["color"], got["color"])
            assert np.array_equal(expected["depth"], got["depth"])
    assert np.count_nonzero(serial[0]["depth"]) > SIZE[0] * SIZE[1] // 4


def test_threads_sharing_one_renderer_take_turns():
    scene = busy_scene()
    views = cameras(8)
    renderer = facet.Renderer(*SIZE)
    serial = [renderer.render(scene, camera)["color"] for camera in views]
    with ThreadPoolExecutor(4) as pool:
        parallel = list(pool.map(lambda camera: renderer.render(scene, camera)["color"], views * 3))
    for index, got in enumerate(parallel):
        assert np.array_equal(serial[index % len(views)], got)


def test_a_scene_may_change_while_other_threads_render_it():
    scene = busy_scene()
    camera = cameras(1)[0]
    stop = threading.Event()
    frames = []

    def keep_rendering():
        renderer = facet.Renderer(48, 36)
        while not stop.is_set():
            frames.append(renderer.render(scene, camera)["color"])

    threads = [threading.Thread(target=keep_rendering) for _ in range(3)]
    for thread in threads:
        thread.start()
    vertices, faces = icosphere(1)
    try:
        for index in range(200):
            pose = np.eye(4)
            pose[:3, 3] = (index % 10) * 0.3 - 1.5, 2, 0
            scene.add_mesh(vertices * 0.1, faces, pose=pose)
            if index % 50 == 0:
                scene.add_light(facet.Light.point((0, 4, 0), intensity=0.1))
    finally:
        stop.set()
        for thread in threads:
            thread.join()
    assert len(scene.instances) == 207
    assert len(frames) >= 3


def test_other_python_threads_run_while_a_frame_renders():
    # A thread that counts, giving the GIL up after each step (sleep(0)), and a switch interval
    # long enough that the main thread never gives it up unasked: the count can only move while
    # the main thread is inside render() if render() releases the GIL.
    vertices, faces = icosphere(5)
    scene = facet.Scene()
    scene.add_mesh(vertices, faces, material=facet.Material(shading="pbr"))
    renderer = facet.Renderer(640, 480, threads=1)
    camera = cameras(1)[0]
    count = [0]
    started, stop = threading.Event(), threading.Event()

    def counter():
        started.set()
        while not stop.is_set():
            count[0] += 1
            time.sleep(0)

    interval = sys.getswitchinterval()
    sys.setswitchinterval(5.0)
    thread = threading.Thread(target=counter)
    try:
        thread.start()
        started.wait()
        moved = 0
        for _ in range(5):
            before = count[0]
            renderer.render(scene, camera, ["color"])
            moved += count[0] - before
    finally:
        stop.set()
        thread.join()
        sys.setswitchinterval(interval)
    assert moved > 0
