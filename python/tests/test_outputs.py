"""The outputs beyond color, and the cameras datasets use: intrinsics and orthographic."""
import numpy as np
import pytest

import facet
from scenes import front_camera, icosphere, quad, unlit

ALL = ("color", "depth", "distance", "normal", "instance", "triangle", "barycentric", "albedo")


def test_every_output_has_its_shape_dtype_and_background():
    scene = facet.Scene()
    vertices, faces, _ = quad(half=0.5)
    scene.add_mesh(vertices, faces, material=unlit((0.25, 0.5, 1.0)))
    frame = facet.Renderer(64, 48, threads=1).render(scene, front_camera(), outputs=ALL)
    assert set(frame) == set(ALL) == set(facet.OUTPUTS)
    expected = {
        "color": ((48, 64, 4), np.uint8),
        "depth": ((48, 64), np.float32),
        "distance": ((48, 64), np.float32),
        "normal": ((48, 64, 3), np.float32),
        "instance": ((48, 64), np.uint32),
        "triangle": ((48, 64), np.uint32),
        "barycentric": ((48, 64, 3), np.float32),
        "albedo": ((48, 64, 4), np.float32),
    }
    for name, (shape, dtype) in expected.items():
        assert frame[name].shape == shape, name
        assert frame[name].dtype == dtype, name
        assert not frame[name][0, 0].any() or name == "color", name  # a corner: background
    centre = (24, 32)
    assert frame["depth"][centre] == pytest.approx(3.0, rel=1e-5)
    # The ray through pixel (32, 24)'s centre, at view depth 1.
    tan_half = np.tan(np.radians(30.0))
    ray = ((32.5 / 64 * 2 - 1) * tan_half * 64 / 48, (1 - 24.5 / 48 * 2) * tan_half, 1.0)
    assert frame["distance"][centre] == pytest.approx(3.0 * np.linalg.norm(ray), rel=1e-5)
    assert frame["normal"][centre] == pytest.approx((0, 0, 1), abs=1e-6)
    assert frame["instance"][centre] == 1
    assert frame["triangle"][centre] in (1, 2)
    assert frame["barycentric"][centre].sum() == pytest.approx(1.0, abs=1e-5)
    assert frame["albedo"][centre] == pytest.approx((0.25, 0.5, 1.0, 1.0), abs=1e-6)


def test_instance_ids_are_what_add_mesh_returned():
    scene = facet.Scene()
    vertices, faces, _ = quad(half=0.4)
    left = scene.add_mesh(vertices, faces, pose=np.array(
        [[1, 0, 0, -0.6], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]))
    right = scene.add_mesh(vertices, faces, pose=np.array(
        [[1, 0, 0, 0.6], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]))
    ids = facet.Renderer(80, 40, threads=1).render(scene, front_camera(), outputs="instance")
    ids = ids["instance"]
    assert (left, right) == (1, 2)
    # x = -0.6, 0 and 0.6 at 3 units with a 60 degree view 80x40: columns 33, 40 and 47.
    assert ids[20, 33] == left and ids[20, 47] == right and ids[20, 40] == 0
    assert set(np.unique(ids)) == {0, left, right}


def test_normals_in_camera_space_face_the_viewer():
    scene = facet.Scene()
    vertices, faces = icosphere(2)
    scene.add_mesh(vertices, faces, normals=vertices)
    camera = facet.Camera.look_at((2, 1, 3), (0, 0, 0))
    frame = facet.Renderer(64, 64, threads=1).render(
        scene, camera, outputs=("normal", "instance"), normal_space="camera"
    )
    drawn = frame["instance"] > 0
    normals = frame["normal"][drawn]
    assert np.allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-5)
    assert (normals[:, 2] > -1e-3).all()  # z toward the viewer on a sphere's visible half
    assert frame["normal"][32, 32] == pytest.approx((0, 0, 1), abs=0.05)


def project(K, pose, points, convention):
    """Pixel coordinates (u, v) of world points by hand: world -> camera frame -> K."""
    to_camera = np.linalg.inv(pose)
    out = []
    for p in points:
        x, y, z = (to_camera @ np.append(p, 1.0))[:3]
        if convention == "opengl":  # OpenGL camera axes: y up, looking down -z
            y, z = -y, -z
        u = K[0, 0] * x / z + K[0, 2]
        v = K[1, 1] * y / z + K[1, 2]
        out.append((u, v))
    return out


@pytest.mark.parametrize("convention", ["opencv", "opengl"])
def test_intrinsics_put_points_at_the_pixels_K_gives(convention):
    width, height = 160, 120
    K = np.array([[150.0, 0, 70.3], [0, 170.0, 66.8], [0, 0, 1]])
    # A camera 4 units from the origin, turned about y and tilted, looking at the origin.
    angle = np.radians(25.0)
    rotation = np.array(
        [[np.cos(angle), 0, np.sin(angle)], [0, 1, 0], [-np.sin(angle), 0, np.cos(angle)]]
    )
    tilt = np.radians(-10.0)
    rotation = rotation @ np.array(
        [[1, 0, 0], [0, np.cos(tilt), -np.sin(tilt)], [0, np.sin(tilt), np.cos(tilt)]]
    )
    if convention == "opencv":  # looking down +z, y down
        rotation = rotation @ np.diag([1.0, -1.0, -1.0])
    pose = np.eye(4)
    pose[:3, :3] = rotation
    backward = np.diag([1.0, -1.0, -1.0]) if convention == "opencv" else np.eye(3)
    pose[:3, 3] = rotation @ backward @ (0, 0, 4.0)  # 4 units back from the origin
    camera = facet.Camera.from_intrinsics(K, width, height, 0.1, 100.0, pose, convention)
    points = [(0, 0, 0), (0.8, 0.5, -0.3), (-0.9, -0.4, 0.2), (0.3, -0.7, 0.6)]
    scene = facet.Scene()
    half = 0.02
    for p in points:  # a small card around each point, facing the camera
        vertices, faces, _ = quad(half=half)
        marker = np.eye(4)
        marker[:3, :3] = pose[:3, :3] @ backward
        marker[:3, 3] = p
        scene.add_mesh(vertices, faces, pose=marker, material=unlit())
    ids = facet.Renderer(width, height, threads=1).render(scene, camera, outputs="instance")
    ids = ids["instance"]
    for instance, (u, v) in enumerate(project(K, pose, points, convention), start=1):
        rows, columns = np.nonzero(ids == instance)
        assert len(rows) > 0, instance
        assert columns.mean() == pytest.approx(u, abs=0.5), instance
        assert rows.mean() == pytest.approx(v, abs=0.5), instance


def test_a_calibrated_camera_is_for_its_image_size():
    K = [[100.0, 0, 31.5], [0, 100.0, 23.5], [0, 0, 1]]
    camera = facet.Camera.from_intrinsics(K, 64, 48)
    scene = facet.Scene()
    scene.add_mesh(*quad()[:2])
    facet.Renderer(64, 48, threads=1).render(scene, camera, outputs="color")
    with pytest.raises(facet.Error, match="calibrated for 64x48"):
        facet.Renderer(32, 24, threads=1).render(scene, camera, outputs="color")


@pytest.mark.parametrize(
    "K, message",
    [
        ([[0.0, 0, 10], [0, 100, 10], [0, 0, 1]], "fx"),
        ([[100.0, 1, 10], [0, 100, 10], [0, 0, 1]], "no skew"),
        ([[100.0, 0], [0, 100]], "3x3"),
    ],
)
def test_bad_intrinsics_name_the_problem(K, message):
    with pytest.raises(facet.Error, match=message):
        facet.Camera.from_intrinsics(K, 64, 48)


def test_bad_conventions_and_spaces_are_errors():
    K = [[100.0, 0, 31.5], [0, 100.0, 23.5], [0, 0, 1]]
    with pytest.raises(facet.Error, match="convention"):
        facet.Camera.from_intrinsics(K, 64, 48, convention="vulkan")
    with pytest.raises(facet.Error, match="normal_space"):
        facet.Renderer(8, 8).render(facet.Scene(), front_camera(), outputs="normal",
                                    normal_space="tangent")
    with pytest.raises(facet.Error, match="height"):
        facet.Camera.orthographic((0, 0, 3), (0, 0, 0), height=0.0)


def test_orthographic_rays_are_parallel():
    scene = facet.Scene()
    vertices, faces, _ = quad(half=5.0)
    scene.add_mesh(vertices, faces)
    camera = facet.Camera.orthographic((0, 0, 3), (0, 0, 0), height=2.0, near=0.5, far=10.0)
    frame = facet.Renderer(40, 20, threads=1).render(scene, camera, outputs=("depth", "distance"))
    assert np.allclose(frame["depth"], 3.0, rtol=1e-5)
    assert (frame["distance"] == frame["depth"]).all()
