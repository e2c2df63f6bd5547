"""No growth over long loops: 20,000 small frames, and scenes made and dropped, leave the
process's resident memory where it was after warming up."""
import os

import numpy as np

import facet
from scenes import front_camera, icosphere, quad

PAGE = os.sysconf("SC_PAGE_SIZE")
# Allowance for the allocator's own bookkeeping; a leak of one frame's arrays (64 x 48 x 8
# bytes) every frame would be 240 MB over the run, and one small Python object a frame
# (~50 bytes) about 1 MB.
ALLOWED_GROWTH = 512 * 1024


def resident_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * PAGE


def test_twenty_thousand_frames_keep_memory_flat():
    vertices, faces = icosphere(2)
    scene = facet.Scene()
    scene.add_mesh(vertices, faces, colors=np.full((len(vertices), 3), 0.5, np.float32))
    floor, floor_faces, uvs = quad(z=-1, half=3)
    scene.add_mesh(floor, floor_faces, uvs=uvs, texture=np.full((8, 8, 3), 200, np.uint8))
    renderer = facet.Renderer(64, 48, threads=2)
    camera = front_camera(4.0)

    def frames(count):
        checksum = 0
        for _ in range(count):
            out = renderer.render(scene, camera)
            checksum += int(out["color"][24, 32, 0]) + int(out["depth"][24, 32] > 0)
        return checksum

    frames(2000)  # warm-up: the allocator's pools, NumPy's caches
    before = resident_bytes()
    assert frames(18000) > 0
    grown = resident_bytes() - before
    assert grown < ALLOWED_GROWTH, f"resident memory grew by {grown} bytes over 18000 frames"


def test_scenes_and_renderers_made_and_dropped_keep_memory_flat():
    vertices, faces = icosphere(1)
    camera = front_camera(4.0)

    def rounds(count):
        for _ in range(count):
            scene = facet.Scene()
            scene.add_mesh(vertices, faces, texture=np.zeros((16, 16, 4), np.uint8),
                           uvs=np.zeros((len(vertices), 2)))
            scene.add_light(facet.Light.point((0, 2, 2)))
            facet.Renderer(32, 24, threads=1).render(scene, camera)

    rounds(300)
    before = resident_bytes()
    rounds(1500)
    grown = resident_bytes() - before
    assert grown < ALLOWED_GROWTH, f"resident memory grew by {grown} bytes over 1500 scenes"
