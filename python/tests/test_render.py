"""Frames as NumPy arrays: color, depth in scene units, outputs asked for, PNG files."""
import numpy as np
import pytest

import facet
from scenes import front_camera, icosphere, quad, unlit


def srgb8(linear):
    """The 8-bit sRGB code of a linear value (IEC 61966-2-1)."""
    linear = np.asarray(linear, np.float64)
    encoded = np.where(linear <= 0.0031308, linear * 12.92, 1.055 * linear ** (1 / 2.4) - 0.055)
    return np.round(encoded * 255).astype(int)


def test_color_is_srgb_uint8_with_alpha_and_the_background_elsewhere():
    vertices, faces, _ = quad(half=0.5)
    scene = facet.Scene()
    scene.add_mesh(vertices, faces, material=unlit((1.0, 0.0, 0.0)))
    renderer = facet.Renderer(64, 48, background=(0, 0, 1, 0.5))
    color = renderer.render(scene, front_camera())["color"]
    assert color.shape == (48, 64, 4) and color.dtype == np.uint8
    assert tuple(color[24, 32]) == (255, 0, 0, 255)
    assert tuple(color[0, 0]) == (0, 0, 255, 128)


def test_float_color_is_linear():
    vertices, faces, _ = quad(half=0.5)
    scene = facet.Scene()
    scene.add_mesh(vertices, faces, material=unlit((0.5, 0.25, 0.125)))
    renderer = facet.Renderer(64, 48)
    frames = {
        format: renderer.render(scene, front_camera(), ["color"], color_format=format)["color"]
        for format in ("uint8", "float")
    }
    assert frames["float"].dtype == np.float32
    assert frames["float"][24, 32] == pytest.approx((0.5, 0.25, 0.125, 1.0), abs=1e-6)
    assert np.abs(frames["uint8"][24, 32, :3] - srgb8([0.5, 0.25, 0.125])).max() <= 1


def test_tone_mapping_keeps_highlights_and_the_background():
    vertices, faces, _ = quad(half=0.5)
    scene = facet.Scene()
    scene.add_mesh(vertices, faces, material=unlit((0.75, 0.1875, 0.0375)))  # x 8: (6, 1.5, 0.3)
    colors = {
        curve: facet.Renderer(64, 48, background=(0.1, 0.2, 0.3), exposure=3, tone_mapping=curve)
        .render(scene, front_camera(), ["color"])["color"]
        for curve in ("none", "pbr-neutral", "aces")
    }
    assert tuple(colors["none"][24, 32, :3]) == (255, 255, 149)  # clipped
    for curve in ("pbr-neutral", "aces"):
        red, green, blue = colors[curve][24, 32, :3]
        assert red > 200 and green < 250, curve  # bright, its hue kept: not clipped to yellow
        assert red > green > blue, curve
        assert np.array_equal(colors[curve][0, 0], colors["none"][0, 0])  # not mapped
    with pytest.raises(facet.Error, match="tone_mapping must be"):
        facet.Renderer(8, 8, tone_mapping="filmic")


@pytest.mark.parametrize("distance", [0.75, 4.0, 37.0])
def test_depth_is_the_distance_along_the_camera_axis(distance):
    # A wall across the upper half of the view at `distance`, nothing below.
    vertices = np.array(
        [[-100, 0, -distance], [100, 0, -distance], [100, 100, -distance], [-100, 100, -distance]],
        np.float32,
    )
    scene = facet.Scene()
    scene.add_mesh(vertices, [[0, 1, 2], [0, 2, 3]], material=unlit())
    camera = facet.Camera.look_at((0, 0, 0), (0, 0, -1), (0, 1, 0), 60, 0.5, 50)
    depth = facet.Renderer(64, 48).render(scene, camera)["depth"]
    assert depth.shape == (48, 64) and depth.dtype == np.float32
    # Along the axis, not along the ray: the same at the centre and at the wall's corners.
    assert depth[12, 32] == pytest.approx(distance, rel=1e-4)
    assert depth[0, 0] == pytest.approx(distance, rel=1e-4)
    assert np.all(depth[30:, :] == 0)  # nothing drawn


def test_depth_of_a_sphere_matches_its_geometry():
    vertices, faces = icosphere(3)
    scene = facet.Scene()
    scene.add_mesh(vertices, faces, material=unlit())
    depth = facet.Renderer(96, 96).render(scene, front_camera(4.0, 40.0), ["depth"])["depth"]
    assert depth[48, 48] == pytest.approx(3.0, abs=0.01)  # the sphere's front point
    drawn = depth > 0
    assert drawn[48, 48] and not drawn[0, 0]
    assert depth[drawn].max() < 4.0


def test_outputs_are_the_ones_asked_for():
    scene = facet.Scene()
    scene.add_mesh(*quad()[:2])
    renderer = facet.Renderer(32, 32)
    assert set(renderer.render(scene, front_camera())) == {"color", "depth"}
    assert list(renderer.render(scene, front_camera(), ("depth",))) == ["depth"]
    assert list(renderer.render(scene, front_camera(), "color")) == ["color"]
    assert list(renderer.render(scene, front_camera(), ["depth", "color", "depth"])) == [
        "depth",
        "color",
    ]
    assert facet.OUTPUTS[:2] == ("color", "depth")


def test_arrays_own_their_memory_and_are_fresh_each_frame():
    scene = facet.Scene()
    scene.add_mesh(*quad()[:2])
    renderer = facet.Renderer(32, 32)
    first = renderer.render(scene, front_camera())
    for array in first.values():
        assert array.flags["C_CONTIGUOUS"] and array.flags["WRITEABLE"]
        assert array.base is not None  # the buffer the renderer filled, not a copy
    first["color"][:] = 7
    second = renderer.render(scene, front_camera())
    assert not np.array_equal(first["color"], second["color"])


def test_the_aspect_comes_from_the_renderer():
    # A square seen straight on is square in any image shape.
    vertices, faces, _ = quad(half=0.5)
    scene = facet.Scene()
    scene.add_mesh(vertices, faces, material=unlit())
    camera = front_camera()
    for width, height in ((96, 48), (48, 96), (64, 64)):
        drawn = facet.Renderer(width, height).render(scene, camera, ["color"])["color"][..., 0] > 0
        rows, columns = np.nonzero(drawn)
        assert rows.ptp() == pytest.approx(columns.ptp(), abs=1)


def test_the_scene_camera_is_the_default():
    scene = facet.Scene()
    scene.add_mesh(*quad(half=2)[:2], material=unlit())
    scene.camera = front_camera(1.0)  # close: the quad fills the view
    color = facet.Renderer(32, 32).render(scene)["color"]
    assert np.all(color[..., 0] == 255)


def test_vertex_colors_uint8_are_srgb_and_float_linear():
    vertices, faces, _ = quad(half=2)
    renderer = facet.Renderer(16, 16)
    for colors, expected in (
        (np.full((4, 3), (200, 100, 50), np.uint8), (200, 100, 50)),
        (np.full((4, 3), 0.5, np.float32), tuple(srgb8([0.5] * 3))),
    ):
        scene = facet.Scene()
        scene.add_mesh(vertices, faces, colors=colors, material=unlit())
        pixel = renderer.render(scene, front_camera(), ["color"])["color"][8, 8, :3]
        assert np.abs(pixel - expected).max() <= 1


def test_texture_row_zero_is_the_top_and_v_points_up():
    vertices, faces, uvs = quad(half=1)
    texture = np.array(
        [[[255, 0, 0], [0, 255, 0]], [[0, 0, 255], [255, 255, 255]]], np.uint8
    ).repeat(2, axis=0).repeat(2, axis=1)  # red green / blue white, 2x2 texels each
    scene = facet.Scene()
    scene.add_mesh(vertices, faces, uvs=uvs, texture=texture, material=unlit())
    # The quad just fills the view (tan 30 degrees = 1 / sqrt(3)): each quarter of the image
    # shows one quarter of the texture, and the filter reads only its color at the middle.
    camera = front_camera(3**0.5, 60.0)
    color = facet.Renderer(64, 64).render(scene, camera, ["color"])["color"].astype(int)
    for (row, column), expected in (
        ((16, 16), (255, 0, 0)),  # top left
        ((16, 48), (0, 255, 0)),
        ((48, 16), (0, 0, 255)),
        ((48, 48), (255, 255, 255)),
    ):
        assert np.abs(color[row, column, :3] - expected).max() <= 1, (row, column)


def test_lights_light_lambert_surfaces():
    vertices, faces, _ = quad(half=2)
    renderer = facet.Renderer(16, 16)

    def brightness(light):
        scene = facet.Scene()
        scene.add_mesh(vertices, faces, material=facet.Material((0.8, 0.8, 0.8)))
        scene.ambient = (0, 0, 0)
        if light is None:
            scene.clear_lights()
        else:
            scene.add_light(light)
        return int(renderer.render(scene, front_camera(), ["color"])["color"][8, 8, 0])

    assert brightness(None) == 0
    facing = brightness(facet.Light.directional((0, 0, -1)))
    slanted = brightness(facet.Light.directional((0, -1, -1)))
    point = brightness(facet.Light.point((0, 0, 1), intensity=1))
    spot = brightness(facet.Light.spot((0, 0, 1), (0, 0, -1)))
    assert facing > slanted > 0
    assert point > 0 and spot > 0


def test_shadows_darken_what_a_light_cannot_reach():
    # A small square half a unit in front of a large one, lit straight along -Z: with shadows
    # the large square is dark behind the small one and lit around it.
    scene = facet.Scene()
    big, faces, _ = quad(half=2)
    scene.add_mesh(big, faces, material=facet.Material((0.8, 0.8, 0.8)))
    small, _, _ = quad(z=0.5, half=0.5)
    scene.add_mesh(small, faces, material=unlit((0, 0, 0)))  # black: only the big one is lit
    scene.ambient = (0, 0, 0)
    scene.add_light(facet.Light.directional((0, 0, -1)))
    camera = facet.Camera.look_at((0.0, -3.0, 3.0), (0, 0, 0), (0, 1, 0), 60.0, 0.1, 100.0)

    def image(**settings):
        return facet.Renderer(64, 64, **settings).render(scene, camera, ["color"])["color"]

    plain, shadowed = image(), image(shadows=True, shadow_map_size=256)
    lit = plain[..., 0] > 0
    darkened = lit & (shadowed[..., 0] < plain[..., 0] // 4)
    kept = lit & (shadowed[..., 0] == plain[..., 0])
    assert darkened.sum() > 20 and kept.sum() > 5 * darkened.sum()
    renderer = facet.Renderer(8, 8, shadows=True)
    assert renderer.shadows and renderer.shadow_cascades == 0  # chosen from the view
    with pytest.raises(facet.Error, match="shadow"):
        facet.Renderer(8, 8, shadows=True, shadow_map_size=0)


def test_a_material_that_casts_no_shadow():
    # The small square of the test above, its material casting no shadow: the large one is lit
    # behind it, as without shadows.
    scene = facet.Scene()
    big, faces, _ = quad(half=2)
    scene.add_mesh(big, faces, material=facet.Material((0.8, 0.8, 0.8)))
    small, _, _ = quad(z=0.5, half=0.5)
    scene.add_mesh(small, faces, material=facet.Material((0, 0, 0), "unlit", casts_shadows=False))
    scene.ambient = (0, 0, 0)
    scene.add_light(facet.Light.directional((0, 0, -1)))
    camera = facet.Camera.look_at((0.0, -3.0, 3.0), (0, 0, 0), (0, 1, 0), 60.0, 0.1, 100.0)

    def image(**settings):
        return facet.Renderer(64, 64, **settings).render(scene, camera, ["color"])["color"]

    np.testing.assert_array_equal(image(shadows=True, shadow_map_size=256), image())
    assert facet.Material().casts_shadows and not facet.Material(casts_shadows=False).casts_shadows
    with pytest.raises(facet.Error, match="casts_shadows"):
        facet.Material(casts_shadows=0)


def test_a_mirror_reflects_the_scene():
    # A mirror in the plane z = 0 (black itself, all reflection) and a red square in front of
    # it: with reflections the mirror shows the square too, so more of the image is red.
    scene = facet.Scene()
    mirror, faces, _ = quad(half=3)
    scene.add_mesh(mirror, faces, material=facet.Material(
        (0, 0, 0), "blinn_phong", specular_color=(0, 0, 0), shininess=1e5, reflectivity=1.0,
        reflects_scene=True))
    square, _, _ = quad(z=1.0, half=0.3)
    red = facet.Material((1, 0, 0), "unlit", cull="none")  # the mirror shows its back
    scene.add_mesh(square + np.array([0, 0.6, 0], np.float32), faces, material=red)
    camera = facet.Camera.look_at((0.0, -2.0, 4.0), (0, 0, 0), (0, 1, 0), 60.0, 0.1, 100.0)

    def red_pixels(**settings):
        color = facet.Renderer(64, 64, **settings).render(scene, camera, ["color"])["color"]
        return int(((color[..., 0] > 200) & (color[..., 1] < 50)).sum())

    direct, mirrored = red_pixels(reflections=False), red_pixels(reflection_scale=1.0)
    assert direct > 20 and mirrored > direct + 20
    assert facet.Material(reflects_scene=True).reflects_scene
    renderer = facet.Renderer(8, 8)
    assert renderer.reflections and renderer.reflection_scale == 0.5
    with pytest.raises(facet.Error, match="reflection scale"):
        facet.Renderer(8, 8, reflection_scale=0)
    with pytest.raises(facet.Error, match="reflects_scene"):
        facet.Material(reflects_scene=1)


def test_two_mirror_planes_each_have_their_pass():
    # A floor mirror (y = 0) and a wall mirror (x = -3.5) beside it, a red box before them.
    # The floor shows the same whether the wall is a mirror or not (its pass draws the wall
    # black either way: a mirror that reflects no environment); the wall shows what a render of
    # the scene mirrored through x = -3.5 shows there.
    def mirror(reflects=True):
        return facet.Material((0, 0, 0), "blinn_phong", specular_color=(0, 0, 0), shininess=1e6,
                              reflectivity=1.0, reflects_scene=reflects, cull="none")

    floor = (np.array([[-3, 0, -4], [3, 0, -4], [3, 0, 4], [-3, 0, 4]], np.float32),
             np.array([[0, 2, 1], [0, 3, 2]], np.int64))
    wall = (np.array([[-3.5, 0, -5], [-3.5, 4, -5], [-3.5, 4, 3], [-3.5, 0, 3]], np.float32),
            np.array([[0, 2, 1], [0, 3, 2]], np.int64))
    corners = [[x, y, z] for x in (-1.7, -0.7) for y in (0.3, 1.3) for z in (-0.5, 0.5)]
    box = (np.array(corners, np.float32),
           np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                     [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]], np.int64))

    def mirrored(mesh):  # through the wall's plane: x -> -7 - x (winding reversed)
        vertices = mesh[0].copy()
        vertices[:, 0] = -7 - vertices[:, 0]
        return vertices, mesh[1][:, ::-1].copy()

    def render(meshes):
        scene = facet.Scene()
        scene.ambient = (0, 0, 0)
        for (vertices, faces), material in meshes:
            scene.add_mesh(vertices, faces, material=material)
        camera = facet.Camera.look_at((0, 2, 6), (0, 0.5, 0), (0, 1, 0), 50.0, 0.5, 40.0)
        renderer = facet.Renderer(160, 120, reflection_scale=1.0, background=(0.1, 0.2, 0.6, 1))
        return renderer.render(scene, camera, ["color"])["color"].astype(int)

    red = facet.Material((0.9, 0.1, 0.1), "unlit", cull="none")
    white = facet.Material((1, 1, 1), "unlit", cull="none")
    dark = facet.Material((0, 0, 0), "unlit", cull="none")
    one = render([(floor, mirror()), (wall, mirror(False)), (box, red)])
    two = render([(floor, mirror()), (wall, mirror()), (box, red)])
    reference = render([(floor, mirror(False)), (mirrored(floor), mirror(False)), (box, red),
                        (mirrored(box), red)])
    on_floor = render([(floor, white), (wall, dark), (box, dark)])[..., 0] == 255
    on_wall = render([(floor, dark), (wall, white), (box, dark)])[..., 0] == 255
    assert on_floor.sum() > 5000 and on_wall.sum() > 1000
    assert (np.abs(one - two).max(axis=2)[on_floor] > 8).sum() == 0
    assert (np.abs(two - reference).max(axis=2)[on_wall] > 24).sum() < on_wall.sum() // 50
    assert (two[..., 2][on_wall] > 100).sum() > 100  # the wall shows the sky, not black


def test_stats_of_the_last_frame():
    scene = facet.Scene()
    scene.add_mesh(*quad()[:2])
    renderer = facet.Renderer(32, 32, threads=2)
    renderer.render(scene, front_camera())
    assert renderer.stats["triangles_in"] == 2 and renderer.stats["drawn"] == 2
    assert (renderer.width, renderer.height, renderer.threads, renderer.msaa) == (32, 32, 2, 1)
    # The tile size chosen for a lit frame (its tiles hold floats), or the one asked for.
    assert renderer.stats["tile_size"] == 64
    sixteen = facet.Renderer(32, 32, tile_size=16)
    sixteen.render(scene, front_camera())
    assert sixteen.stats["tile_size"] == 16


def test_stats_time_every_pass():
    # The shadow maps' and the extra outputs' passes are timed apart, inside the total; a frame
    # without them spends nothing on them.
    scene = facet.Scene()
    scene.add_mesh(*quad()[:2])
    scene.add_light(facet.Light.directional((0, 0, -1)))
    plain = facet.Renderer(32, 32)
    plain.render(scene, front_camera(), ["color"])
    stats = plain.stats
    assert stats["ms_shadows"] == 0 and stats["ms_reflections"] == 0
    assert stats["ms_extra_outputs"] == 0 and not stats["display_referred"]
    assert 0 <= stats["ms_resolve"] <= stats["ms_raster"] <= stats["ms_total"]
    shadowed = facet.Renderer(32, 32, shadows=True, shadow_map_size=256)
    shadowed.render(scene, front_camera(), ["color", "normal"])
    stats = shadowed.stats
    assert stats["ms_shadows"] > 0 and stats["ms_extra_outputs"] > 0
    assert stats["ms_total"] >= stats["ms_shadows"] + stats["ms_extra_outputs"]
    # A frame of display values (the normals view) is rounded, not encoded.
    normals = facet.Scene()
    normals.add_mesh(*quad()[:2], material=facet.Material((1, 1, 1), "normals"))
    plain.render(normals, front_camera(), ["color"])
    assert plain.stats["display_referred"]


def test_msaa_blends_edge_pixels_and_keeps_ids_whole():
    # A quad's silhouette: at 1 sample every pixel is the quad's or the background's; at 4 the
    # edge pixels lie between, the inside stays the quad's, and the ids never blend.
    vertices, faces, _ = quad(half=0.37)
    turn = np.radians(20.0)  # slanted edges, not along rows and columns
    rotation = np.array([[np.cos(turn), -np.sin(turn), 0], [np.sin(turn), np.cos(turn), 0],
                         [0, 0, 1]])
    vertices = np.asarray(vertices, np.float32) @ rotation.T.astype(np.float32)
    scene = facet.Scene()
    node = scene.add_mesh(vertices, faces, material=unlit((1.0, 1.0, 1.0)))
    frames = {}
    for samples in (1, 4):
        renderer = facet.Renderer(64, 48, msaa=samples)
        assert renderer.msaa == samples
        frames[samples] = renderer.render(scene, front_camera(), ["color", "instance"],
                                          color_format="float")
    one, four = frames[1]["color"][..., 0], frames[4]["color"][..., 0]
    assert set(np.unique(one)) <= {0.0, 1.0}
    partial = (four > 0.0) & (four < 1.0)
    assert partial.sum() > 20
    assert set(np.unique(four[partial] * 4)) <= {1.0, 2.0, 3.0}  # k of the 4 samples
    inside = (one[1:-1, 1:-1] == 1) & (one[:-2, 1:-1] == 1) & (one[2:, 1:-1] == 1) \
        & (one[1:-1, :-2] == 1) & (one[1:-1, 2:] == 1)
    assert inside.sum() > 50 and np.all(four[1:-1, 1:-1][inside] == 1.0)
    assert set(np.unique(frames[4]["instance"])) <= {0, node}
    assert np.array_equal(frames[4]["instance"], frames[1]["instance"])


def test_write_png(tmp_path):
    image = np.zeros((20, 30, 4), np.uint8)
    image[..., 0] = 255
    image[..., 3] = 255
    facet.write_png(tmp_path / "red.png", image)
    facet.write_png(str(tmp_path / "rgb.png"), image[..., :3])
    for name in ("red.png", "rgb.png"):
        data = (tmp_path / name).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n"
        width, height = int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
        assert (width, height) == (30, 20)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["red.png", "rgb.png"]  # no leftovers
