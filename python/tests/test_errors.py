"""Bad input: one facet.Error that names the function and the argument, never a crash."""
import math

import numpy as np
import pytest

import facet
from scenes import front_camera, quad, triangle

VERTICES, FACES = triangle()


def add_mesh(**changes):
    arguments = {"vertices": VERTICES, "faces": FACES, **changes}
    facet.Scene().add_mesh(**arguments)


BAD_CALLS = [
    # add_mesh: shapes, dtypes, values
    (lambda: add_mesh(faces=np.zeros((5, 4), int)),
     r"add_mesh: faces must be an \(M, 3\) integer array, got shape \(5, 4\)"),
    (lambda: add_mesh(faces=np.zeros((1, 3), np.float32)),
     r"add_mesh: faces must be an \(M, 3\) integer array, got dtype float32"),
    (lambda: add_mesh(faces=[[0, 1, 3]]),
     r"add_mesh: faces\[0, 2\] is 3, out of range for 3 vertices"),
    (lambda: add_mesh(faces=[[0, -1, 2]]), r"add_mesh: faces\[0, 1\] is -1, out of range"),
    (lambda: add_mesh(faces=np.zeros((0, 3), int)), r"add_mesh: faces has no triangles"),
    (lambda: add_mesh(vertices=np.zeros((3, 2))),
     r"add_mesh: vertices must be an \(N, 3\) float array, got shape \(3, 2\)"),
    (lambda: add_mesh(vertices=np.zeros(9)),
     r"vertices must be an \(N, 3\) float array, got shape \(9,\)"),
    (lambda: add_mesh(vertices=[["a", "b", "c"]] * 3), r"vertices must be .*got dtype <U1"),
    (lambda: add_mesh(vertices=[[0, 0], [1, 0, 0]]),
     r"add_mesh: vertices: cannot be read as an array"),
    (lambda: add_mesh(vertices=[[0, 0, 0], [1, 0, math.nan], [0, 1, 0]]),
     r"add_mesh: vertices\[1\] is not a finite float32: \(1, 0, nan\)"),
    (lambda: add_mesh(vertices=[[0, 0, 0], [1e39, 0, 0], [0, 1, 0]]),
     r"add_mesh: vertices\[1\] is not a finite float32"),
    (lambda: add_mesh(normals=np.zeros((2, 3))),
     r"add_mesh: normals must be an \(N, 3\) float array with N = 3 \(a row per vertex\), "
     r"got shape \(2, 3\)"),
    (lambda: add_mesh(uvs=np.zeros((3, 3))), r"add_mesh: uvs must be an \(N, 2\) float array"),
    (lambda: add_mesh(uvs=[[0, 0], [1, math.inf], [0, 1]]),
     r"add_mesh: uvs\[1\] is not a finite float32"),
    (lambda: add_mesh(colors=np.zeros((3, 5))),
     r"add_mesh: colors must be an \(N, 3\) or \(N, 4\)"),
    (lambda: add_mesh(colors=np.full((3, 3), 255)), r"add_mesh: colors .*got dtype int64"),
    (lambda: add_mesh(colors=np.full((3, 3), 1.5)), r"add_mesh: colors\[0\] is outside \[0, 1\]"),
    (lambda: add_mesh(texture=np.zeros((4, 4, 3), np.uint8)), r"add_mesh: a texture needs uvs"),
    (lambda: add_mesh(uvs=np.zeros((3, 2)), texture=np.zeros((4, 4), np.uint8)),
     r"add_mesh: texture must be an \(H, W, 3\) or \(H, W, 4\) uint8 image, got shape \(4, 4\)"),
    (lambda: add_mesh(uvs=np.zeros((3, 2)), texture=np.zeros((4, 4, 3))),
     r"add_mesh: texture must be .* uint8 image, got dtype float64"),
    (lambda: add_mesh(pose=np.eye(3)),
     r"add_mesh: pose must be a 4x4 float matrix, got shape \(3, 3\)"),
    (lambda: add_mesh(pose=np.full((4, 4), math.nan)), r"add_mesh: pose must be finite"),
    (lambda: add_mesh(material="pbr"), r"add_mesh: material must be a facet.Material, got str"),
    # materials and lights
    (lambda: facet.Material(shading="toon"),
     r"Material: shading must be one of unlit, .*got 'toon'"),
    (lambda: facet.Material(roughness=2), r"Material: roughness must be in \[0, 1\]"),
    (lambda: facet.Material(metallic="x"), r"Material: metallic must be a number, got str"),
    (lambda: facet.Material(base_color=(1, 0)), r"Material: base_color must be 3 or 4 numbers"),
    (lambda: facet.Material(base_color=(2, 0, 0)), r"Material: base_color must be in \[0, 1\]"),
    (lambda: facet.Material(cull="both"), r"Material: cull must be one of back, front, none"),
    (lambda: facet.Material(alpha_mode="glass"), r"Material: alpha_mode must be one of opaque"),
    (lambda: facet.Light.directional((0, 0, 0)), r"Light.directional: direction must not be"),
    (lambda: facet.Light.point((0, 0)), r"Light.point: position must be 3 numbers"),
    (lambda: facet.Light.point((0, 0, 0), intensity=-1), r"Light.point: intensity must not be"),
    (lambda: facet.Light.spot((0, 0, 0), (0, -1, 0), inner_cone=40, outer_cone=30),
     r"Light.spot: the cones need 0 <= inner_cone <= outer_cone <= 90"),
    (lambda: facet.Scene().add_light("sun"), r"add_light: light must be a facet.Light, got str"),
    # cameras
    (lambda: facet.Camera.look_at((0, 0, 0), (0, 0, 0)),
     r"Camera.look_at: camera: eye and target"),
    (lambda: facet.Camera.look_at((0, 0, 1), (0, 0, 0), fov_y=180),
     r"Camera.look_at: camera: field of view must be between 0 and 180"),
    (lambda: facet.Camera.look_at((0, 0, 1), (0, 0, 0), near=2, far=1), r"far plane"),
    (lambda: facet.Camera.look_at((0, 0, 1), (0, 0, 0), up=(0, 0, 1)), r"up is parallel"),
    (lambda: setattr(front_camera(), "near", -1),
     r"Camera.near: camera: near plane must be positive"),
    # renderers
    (lambda: facet.Renderer(64, 48, msaa=3), r"renderer: msaa must be 1, 2, 4, 8 or 16 .*got 3"),
    (lambda: facet.Renderer(0, 48), r"Renderer: size 0x48 is outside 1x1 .. 8192x8192"),
    (lambda: facet.Renderer(64, 48, threads=1000), r"renderer: threads must be .*256, got 1000"),
    (lambda: facet.Renderer(64, 48, tile_size=20),
     r"renderer: tile size must be 16, 32, 64 or 128"),
    (lambda: facet.Renderer(64, 48, background=(1, 0)), r"Renderer: background must be 3 or 4"),
    (lambda: facet.Renderer(8, 8).render(facet.Scene(), front_camera(), ["color", "normals"]),
     r"render: unknown output 'normals' \(valid: color, depth"),
    (lambda: facet.Renderer(8, 8).render(facet.Scene(), front_camera(), 42),
     r"render: outputs must be a sequence of names"),
    (lambda: facet.Renderer(8, 8).render(facet.Scene(), front_camera(), color_format="half"),
     r"render: color_format must be 'uint8' or 'float', got 'half'"),
    (lambda: facet.Renderer(8, 8).render("scene", front_camera()),
     r"render: scene must be a facet.Scene, got str"),
    (lambda: facet.Renderer(8, 8).render(facet.Scene(), "camera"),
     r"render: camera must be a facet.Camera, got str"),
    # files
    (lambda: facet.load(42), r"load: path must be a str or an os.PathLike, got int"),
    (lambda: facet.write_png("x.png", np.zeros((4, 4, 2), np.uint8)),
     r"write_png: image must be an \(H, W, 3\) or \(H, W, 4\) uint8 image"),
    (lambda: facet.write_png("/nonexistent-dir/x.png", np.zeros((4, 4, 3), np.uint8)),
     r"/nonexistent-dir/x.png"),
    (lambda: facet.write_png("x.jpg", np.zeros((4, 4, 3), np.uint8)), r"x.jpg"),
]


@pytest.mark.parametrize("call, message", BAD_CALLS)
def test_bad_input_raises_one_facet_error(call, message):
    with pytest.raises(facet.Error, match=message):
        call()


def test_facet_error_is_an_exception_class():
    assert issubclass(facet.Error, Exception)


def test_a_bad_call_leaves_the_scene_as_it_was():
    scene = facet.Scene()
    scene.add_mesh(*quad()[:2])
    with pytest.raises(facet.Error):
        scene.add_mesh(VERTICES, [[0, 1, 7]])
    assert len(scene.instances) == 1
    assert scene.add_mesh(VERTICES, FACES) == 2


def test_a_camera_change_that_cannot_project_is_not_made():
    camera = front_camera()
    with pytest.raises(facet.Error):
        camera.eye = camera.target
    assert camera.eye == (0, 0, 3)
