"""Scenes from arrays and from files: instance ids, attributes, materials, lights, cameras."""
import math
import pathlib
import warnings

import numpy as np
import pytest

import facet
from scenes import icosphere, quad, triangle, write_obj


def test_add_mesh_returns_instance_ids_in_the_order_added():
    scene = facet.Scene()
    assert len(scene.instances) == 0
    assert scene.bounds is None
    assert [scene.add_mesh(*triangle()) for _ in range(3)] == [1, 2, 3]
    assert len(scene.instances) == 3
    assert scene.triangle_count == 3


def test_add_mesh_takes_lists_and_any_real_dtype():
    scene = facet.Scene()
    scene.add_mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    for dtype in (np.int8, np.uint16, np.int32, np.uint64):
        scene.add_mesh(np.eye(3, dtype=np.float64), np.array([[0, 1, 2]], dtype))
    assert len(scene.instances) == 5


def test_add_mesh_takes_every_attribute():
    vertices, faces, uvs = quad()
    scene = facet.Scene()
    texture = np.zeros((4, 8, 3), np.uint8)
    pose = np.eye(4)
    pose[:3, 3] = (10, 20, 30)
    instance = scene.add_mesh(
        vertices,
        faces,
        normals=np.tile([0, 0, 1], (4, 1)),
        uvs=uvs,
        colors=np.full((4, 4), 0.5, np.float32),
        texture=texture,
        material=facet.Material(shading="phong"),
        pose=pose,
        name="floor",
    )
    assert instance == 1
    lower, upper = scene.bounds
    assert lower == pytest.approx((9, 19, 30))
    assert upper == pytest.approx((11, 21, 30))
    scene.add_mesh(vertices, faces, colors=np.full((4, 3), 200, np.uint8))


def test_add_mesh_copies_its_arrays():
    vertices, faces = triangle()
    scene = facet.Scene()
    scene.add_mesh(vertices, faces)
    vertices[:] = 100  # changes nothing in the scene
    lower, upper = scene.bounds
    assert upper == pytest.approx((1, 1, 0))


def test_material_defaults_and_keywords():
    material = facet.Material()
    assert material.shading == "lambert"
    assert material.base_color == (1.0, 1.0, 1.0, 1.0)
    assert material.roughness == 0.6
    assert material.cull == "back"
    material = facet.Material(
        (0.2, 0.4, 0.6), "pbr", metallic=1.0, roughness=0.25, cull="none", alpha_mode="blend"
    )
    assert material.base_color == (0.2, 0.4, 0.6, 1.0)
    assert (material.shading, material.metallic, material.roughness) == ("pbr", 1.0, 0.25)
    assert (material.cull, material.alpha_mode) == ("none", "blend")
    material.shading = "unlit"
    material.emissive = (2, 0, 0)
    assert material.shading == "unlit" and material.emissive == (2.0, 0.0, 0.0)
    assert "shading='unlit'" in repr(material)
    assert set(facet.SHADING_MODELS) >= {"unlit", "lambert", "phong", "pbr", "flat"}


def test_lights_the_first_add_light_replaces_the_default_sun():
    scene = facet.Scene()
    assert [light.type for light in scene.lights] == ["directional"]  # the library's sun
    scene.add_light(facet.Light.point((0, 2, 0), color=(1, 0.5, 0), intensity=3, range=10))
    scene.add_light(facet.Light.spot((0, 3, 0), (0, -1, 0), inner_cone=10, outer_cone=20))
    scene.add_light(facet.Light.directional((0, -1, 0)))
    assert [light.type for light in scene.lights] == ["point", "spot", "directional"]
    point = scene.lights[0]
    assert (point.position, point.color, point.intensity, point.range) == (
        (0.0, 2.0, 0.0),
        (1.0, 0.5, 0.0),
        3.0,
        10.0,
    )
    assert (scene.lights[1].inner_cone, scene.lights[1].outer_cone) == (10.0, 20.0)
    assert "facet.Light.spot(" in repr(scene.lights[1])
    scene.clear_lights()
    assert scene.lights == []
    scene.ambient = (0.5, 0.25, 0)
    assert scene.ambient == (0.5, 0.25, 0.0)


def test_camera_fields_and_matrices():
    camera = facet.Camera.look_at(eye=(0, 0, 5), target=(0, 0, 0), fov_y=45, near=0.5, far=50)
    assert (camera.eye, camera.target, camera.up) == ((0, 0, 5), (0, 0, 0), (0, 1, 0))
    assert (camera.fov_y, camera.near, camera.far) == (45.0, 0.5, 50.0)
    view = camera.view_matrix()
    assert view @ np.array([0, 0, 5, 1]) == pytest.approx([0, 0, 0, 1])  # eye at the origin
    assert view @ np.array([0, 0, 0, 1]) == pytest.approx([0, 0, -5, 1])  # target down -Z
    projection = camera.projection_matrix(2.0)
    assert projection[1, 1] == pytest.approx(1 / math.tan(math.radians(22.5)))
    assert projection[0, 0] == pytest.approx(projection[1, 1] / 2)
    camera.eye = (1, 2, 3)
    camera.fov_y = 30
    assert camera.eye == (1, 2, 3) and camera.fov_y == 30
    assert "facet.Camera.look_at(" in repr(camera)


def test_scene_camera_can_be_set():
    scene = facet.Scene()
    camera = facet.Camera.look_at((1, 2, 3), (0, 0, 0))
    scene.camera = camera
    assert scene.camera.eye == (1, 2, 3)


def test_load_reads_a_model_frames_it_and_numbers_its_nodes(tmp_path):
    vertices, faces = icosphere(1)
    path = write_obj(tmp_path / "sphere.obj", vertices + 5, faces)
    scene = facet.load(path)  # a pathlib.Path
    assert len(scene.instances) == 1
    assert scene.triangle_count == len(faces)
    assert scene.bounds[0] == pytest.approx((4, 4, 4), abs=1e-5)
    # The camera frames the model; a file without lights gets three around that view.
    assert scene.camera.target == pytest.approx((5, 5, 5), abs=1e-5)
    assert len(scene.lights) == 3
    (loaded,) = scene.instances  # the node holding the sphere
    added = scene.add_mesh(*triangle())
    assert added > loaded and sorted(scene.instances) == [loaded, added]
    scene.add_light(facet.Light.directional((0, -1, 0)))
    assert len(scene.lights) == 1
    assert len(facet.load(str(path)).instances) == 1


def test_load_frames_the_model_for_each_renderers_aspect(tmp_path):
    # A long bar: framed for 16:9 and narrowed to a tall image it would cross the border.
    vertices, faces = icosphere(1)
    path = write_obj(tmp_path / "bar.obj", vertices * (4, 1, 1), faces)
    scene = facet.load(path)
    for width, height in ((30, 60), (64, 64), (80, 60), (160, 90)):
        depth = facet.Renderer(width, height).render(scene, outputs=("depth",))["depth"]
        border = np.concatenate((depth[0], depth[-1], depth[:, 0], depth[:, -1]))
        assert np.all(border == 0), (width, height)  # 0: nothing drawn
        assert np.count_nonzero(depth) > width * height / 20
    # A camera set by hand is kept as it is (stretched to the image, as any camera is).
    scene.camera = facet.Camera.look_at((0, 0, 3), (0, 0, 0))
    depth = facet.Renderer(30, 60).render(scene, outputs=("depth",))["depth"]
    assert np.count_nonzero(depth[30]) == 30  # the bar crosses the whole row


def test_load_numbers_instances_of_every_object(tmp_path):
    vertices, faces = icosphere(0)
    text = ""
    for index, offset in enumerate((0, 3, 6)):
        text += f"o ball{index}\n"
        text += "".join(f"v {x + offset} {y} {z}\n" for x, y, z in vertices)
    for index in range(3):
        text += f"g ball{index}\n"
        base = index * len(vertices) + 1
        text += "".join(f"f {a + base} {b + base} {c + base}\n" for a, b, c in faces)
    (tmp_path / "balls.obj").write_text(text)
    scene = facet.load(tmp_path / "balls.obj")
    assert len(scene.instances) == 3
    assert scene.triangle_count == 3 * len(faces)


def test_load_turns_import_problems_into_warnings(tmp_path):
    vertices, faces, uvs = quad()
    (tmp_path / "quad.mtl").write_text("newmtl paint\nmap_Kd missing.png\n")
    lines = ["mtllib quad.mtl", "usemtl paint"]
    lines += [f"v {x} {y} {z}" for x, y, z in vertices]
    lines += [f"vt {u} {v}" for u, v in uvs]
    lines += [f"f {a + 1}/{a + 1} {b + 1}/{b + 1} {c + 1}/{c + 1}" for a, b, c in faces]
    (tmp_path / "quad.obj").write_text("\n".join(lines) + "\n")
    with pytest.warns(UserWarning, match="missing.png"):
        scene = facet.load(tmp_path / "quad.obj")
    assert len(scene.instances) == 1


def test_load_names_the_missing_file(tmp_path):
    with pytest.raises(facet.Error, match="nothing.obj: no such file"):
        facet.load(tmp_path / "nothing.obj")
    with pytest.raises(facet.Error, match="is a directory"):
        facet.load(tmp_path)


def test_version():
    assert facet.__version__.count(".") == 2
    source = pathlib.Path(__file__).resolve().parents[2] / "CMakeLists.txt"
    if source.exists():
        assert f"VERSION {facet.__version__}" in source.read_text()


def write_moving_quad(folder, buffer_uri=None):
    """A glTF quad whose node moves from x = 0 at t = 0 to x = 10 at t = 1 (LINEAR)."""
    import base64
    import json
    import struct

    positions = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0)
    indices = struct.pack("<6H", 0, 1, 2, 0, 2, 3) + b"\0\0"
    times = struct.pack("<2f", 0, 1)
    moves = struct.pack("<6f", 0, 0, 0, 10, 0, 0)
    data = positions + indices + times + moves
    views, offset = [], 0
    for part in (positions, indices, times, moves):
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(part)})
        offset += len(part)
    uri = buffer_uri or "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    if buffer_uri:
        (folder / buffer_uri).write_bytes(data)
    document = {
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR",
             "min": [0], "max": [1]},
            {"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC3"},
        ],
        "bufferViews": views,
        "buffers": [{"byteLength": len(data), "uri": uri}],
        "animations": [{
            "samplers": [{"input": 2, "output": 3, "interpolation": "LINEAR"}],
            "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}],
        }],
    }
    path = folder / "moving.gltf"
    path.write_text(json.dumps(document))
    return path


def test_load_poses_a_gltf_animation_at_a_time(tmp_path):
    path = write_moving_quad(tmp_path)
    assert facet.load(path).bounds[0][0] == pytest.approx(0.0)  # at rest
    assert facet.load(path, time=0.5).bounds[0][0] == pytest.approx(5.0)
    assert facet.load(path, time=7).bounds[0][0] == pytest.approx(10.0)  # clamped to the end
    with pytest.raises(facet.Error, match="animation 2 does not exist"):
        facet.load(path, time=0.5, animation=2)


def test_an_animated_model_is_posed_without_reading_the_file_again(tmp_path):
    path = write_moving_quad(tmp_path)
    model = facet.AnimatedModel(path)
    assert model.duration == pytest.approx(1.0) and model.animation_count == 1
    path.unlink()  # the poses need the file no more
    assert model.scene(0.5).bounds[0][0] == pytest.approx(5.0)
    assert model.scene(0.25).bounds[0][0] == pytest.approx(2.5)
    assert model.scene(7).bounds[0][0] == pytest.approx(10.0)  # clamped to the end
    frame = facet.Renderer(32, 24).render(model.scene(1.0), outputs=["depth"])
    assert (frame["depth"] > 0).any()
    with pytest.raises(facet.Error, match="animation 2 does not exist"):
        facet.AnimatedModel(write_moving_quad(tmp_path), animation=2)


def test_load_reads_outside_files_only_when_allowed(tmp_path):
    model = tmp_path / "model"
    model.mkdir()
    path = write_moving_quad(model, buffer_uri="../shared.bin")
    assert (tmp_path / "shared.bin").exists()  # beside the model's folder, not in it
    with pytest.raises(facet.Error, match="outside"):
        facet.load(path)
    assert facet.load(path, allow_outside_paths=True).triangle_count == 2


def write_obj_triangle(folder):
    # An OBJ with an object line: read by assimp, so fenced (plain geometry alone is facet's).
    path = folder / "triangle.obj"
    path.write_text("o triangle\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    return path


def test_load_fences_assimp_in_time_and_memory(tmp_path, monkeypatch):
    path = write_obj_triangle(tmp_path)
    # The fence's test hook makes the fenced child hang, or allocate without end.
    monkeypatch.setenv("FACET_FENCE_TEST_FAULT", "hang")
    with pytest.raises(facet.Error, match=r"triangle\.obj: .*took longer than 0\.5 s"):
        facet.load(path, import_timeout=0.5)
    # Unfenced, no child is started: the hook never runs and the file loads.
    assert facet.load(path, fence_assimp=False).triangle_count == 1
    monkeypatch.setenv("FACET_FENCE_TEST_FAULT", "memory")
    with pytest.raises(facet.Error, match="more than 256 MiB of memory"):
        facet.load(path, import_memory_limit=256 * 2**20)
    with pytest.raises(facet.Error, match="import_memory_limit must be a positive"):
        facet.load(path, import_memory_limit=0)
