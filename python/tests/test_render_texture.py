"""Render textures: a frame rendered into a facet.RenderTexture reads back as arrays and shows
on the meshes of later frames that use its texture; its depth, its mip chain, its errors, and
its lock against frames in other threads."""
import threading
import time

import numpy as np
import pytest

import facet
from scenes import front_camera, icosphere, quad, unlit

RED, GREEN, BLUE, WHITE = (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)


def flat_view():
    """Looks down -Z at a 2 x 2 square centred on the origin: quad() fills a square image."""
    return facet.Camera.orthographic((0, 0, 1), (0, 0, 0), height=2, near=0.5, far=1.5)


def quadrants():
    """Red top left, green top right, blue bottom left, white bottom right."""
    scene = facet.Scene()
    vertices, faces, _ = quad(half=0.5)
    for color, (x, y) in ((RED, (-0.5, 0.5)), (GREEN, (0.5, 0.5)), (BLUE, (-0.5, -0.5)),
                          (WHITE, (0.5, -0.5))):
        scene.add_mesh(vertices + np.array([x, y, 0], np.float32), faces, material=unlit(color))
    return scene


def screen(texture, half=1.0):
    """A scene of one unlit quad showing texture (its top row at the top)."""
    vertices, faces, uvs = quad(half=half)
    scene = facet.Scene()
    scene.add_mesh(vertices, faces, uvs=uvs, texture=texture, material=unlit())
    return scene


def test_a_later_frame_shows_the_image_rendered_into_the_texture():
    target = facet.RenderTexture(32, 32)
    assert (target.width, target.height, target.color_format) == (32, 32, "uint8")
    assert not target.mipmaps and not target.depth and target.color
    facet.Renderer(8, 8).render_to(target, quadrants(), flat_view())
    image = target.read_color()
    assert image.shape == (32, 32, 4) and image.dtype == np.uint8
    # Row 0 is the top, as in render's color.
    for (row, column), color in (((8, 8), RED), ((8, 24), GREEN), ((24, 8), BLUE),
                                 ((24, 24), WHITE)):
        assert tuple(image[row, column]) == tuple(255 * np.array(color)) + (255,)
    assert target.texture.width == 32 and target.texture.levels == 1

    scene = screen(target.texture)
    shown = facet.Renderer(32, 32).render(scene, flat_view(), ["color"])["color"]
    assert np.abs(shown.astype(int) - image).max() <= 1
    assert tuple(shown[8, 24]) == (0, 255, 0, 255)

    # Rendered into again, the same scene shows the new frame.
    facet.Renderer(8, 8, background=(1, 0, 1)).render_to(target, facet.Scene(), flat_view())
    assert tuple(target.read_color()[16, 16]) == (255, 0, 255, 255)
    shown = facet.Renderer(32, 32).render(scene, flat_view(), ["color"])["color"]
    assert tuple(shown[8, 24]) == (255, 0, 255, 255)


def test_a_magnified_texture_keeps_its_edges():
    target = facet.RenderTexture(8, 8)
    facet.Renderer(8, 8).render_to(target, quadrants(), flat_view())
    shown = facet.Renderer(64, 64).render(screen(target.texture), flat_view(), ["color"])["color"]
    # Eight pixels a texel: the outer pixels' centres lie within half a texel of the edge, where
    # the sampler clamps instead of blending in the far side's texels (repeat would mix the top
    # row with the bottom's blue and white).
    for row, column, color in ((0, 0, RED), (0, 63, GREEN), (63, 0, BLUE), (63, 63, WHITE)):
        assert tuple(shown[row, column]) == tuple(255 * np.array(color)) + (255,)


def test_float_color_is_linear_and_samples_as_it_was_rendered():
    target = facet.RenderTexture(16, 16, color_format="float")
    scene = facet.Scene()
    vertices, faces, _ = quad()
    scene.add_mesh(vertices, faces, material=unlit((0.5, 0.25, 1.0)))
    facet.Renderer(8, 8, exposure=1).render_to(target, scene, flat_view())  # x 2: above 1 kept
    image = target.read_color()
    assert image.shape == (16, 16, 4) and image.dtype == np.float32
    assert image[5, 9] == pytest.approx((1.0, 0.5, 2.0, 1.0), abs=1e-6)
    shown = facet.Renderer(16, 16).render(screen(target.texture), flat_view(), ["color"],
                                          color_format="float")["color"]
    assert shown[5, 9] == pytest.approx((1.0, 0.5, 2.0, 1.0), abs=1e-5)


def test_a_data_texture_reads_back_the_values_a_normals_frame_wrote():
    # The normals shading shows a +Z normal as (0.5, 0.5, 1), stored as the codes 128, 128, 255.
    scene = facet.Scene()
    vertices, faces, _ = quad()
    normals = np.tile(np.array([0, 0, 1], np.float32), (4, 1))
    scene.add_mesh(vertices, faces, normals=normals, material=facet.Material(shading="normals"))
    shown = {}
    for srgb in (True, False):
        target = facet.RenderTexture(8, 8, srgb_texture=srgb)
        assert target.srgb_texture == srgb
        facet.Renderer(8, 8).render_to(target, scene, flat_view())
        assert tuple(target.read_color()[4, 4]) == (128, 128, 255, 255)
        shown[srgb] = facet.Renderer(8, 8).render(screen(target.texture), flat_view(), ["color"],
                                                  color_format="float")["color"][4, 4]
    # As data: the code / 255 itself; as sRGB: the code decoded to linear light.
    assert shown[False][:3] == pytest.approx((128 / 255, 128 / 255, 1.0), abs=1e-6)
    assert shown[True][:3] == pytest.approx((0.2158605, 0.2158605, 1.0), abs=1e-6)


def sphere_scene():
    vertices, faces = icosphere(2)
    scene = facet.Scene()
    scene.add_mesh(vertices, faces)
    return scene


def test_depth_is_window_depth_and_matches_the_renderers_depth_output():
    scene = sphere_scene()
    camera = front_camera(distance=3.0)
    near, far = camera.near, camera.far
    target = facet.RenderTexture(64, 48, depth=True)
    facet.Renderer(8, 8).render_to(target, scene, camera)
    window = target.read_depth()
    assert window.shape == (48, 64) and window.dtype == np.float32
    expected = facet.Renderer(64, 48).render(scene, camera, ["depth"])["depth"]
    drawn = expected > 0
    assert np.array_equal(window < 1, drawn)
    assert drawn.sum() > 500
    view_depth = near * far / (far - window[drawn] * (far - near))
    np.testing.assert_allclose(view_depth, expected[drawn], rtol=2e-3)
    assert view_depth.min() == pytest.approx(2.0, abs=0.02)  # the sphere's front at distance 2

    # The depth texture samples as grey (d, d, d, 1).
    shown = facet.Renderer(64, 48).render(screen(target.depth_texture, half=4), front_camera(3.0),
                                          ["color"], color_format="float")["color"]
    unshown = facet.Renderer(64, 48).render(screen(target.texture, half=4), front_camera(3.0),
                                            ["color"])["color"]
    assert shown.shape == (48, 64, 4) and unshown.shape == (48, 64, 4)
    grey = shown[24, 32, 0]
    assert shown[24, 32, 1] == grey and shown[24, 32, 2] == grey and shown[24, 32, 3] == 1
    # A square 8 units wide at distance 3 with fov 60 fills the view: its middle shows the
    # depth texture's middle, where the sphere is nearest.
    assert grey == pytest.approx(window[23:25, 31:33].mean(), abs=0.01)


def test_a_depth_only_target_has_no_color_and_the_same_depth():
    scene = sphere_scene()
    both = facet.RenderTexture(40, 30, depth=True)
    depth_only = facet.RenderTexture(40, 30, depth=True, color=False)
    renderer = facet.Renderer(8, 8)
    renderer.render_to(both, scene, front_camera())
    renderer.render_to(depth_only, scene, front_camera())
    assert depth_only.texture is None and depth_only.depth_texture is not None
    assert np.array_equal(both.read_depth(), depth_only.read_depth())
    with pytest.raises(facet.Error, match="keeps no color"):
        depth_only.read_color()
    with pytest.raises(facet.Error, match="keeps no depth"):
        facet.RenderTexture(8, 8).read_depth()
    assert facet.RenderTexture(8, 8).depth_texture is None


def stripes(size):
    """Alternate black and white columns one texel wide."""
    image = np.zeros((size, size, 4), np.uint8)
    image[:, 1::2, :3] = 255
    image[..., 3] = 255
    return image


@pytest.mark.parametrize("mipmaps", [True, False])
def test_mipmaps_average_the_image_where_it_is_drawn_small(mipmaps):
    target = facet.RenderTexture(64, 64, mipmaps=mipmaps)
    assert target.texture.levels == (7 if mipmaps else 1)
    facet.Renderer(8, 8).render_to(target, screen(stripes(64)), flat_view())
    image = target.read_color()
    assert image[:, 0::2, :3].max() <= 1 and image[:, 1::2, :3].min() >= 254

    # Drawn 10 pixels wide, each pixel covers 6.4 texels: the mip chain gives the stripes'
    # average, linear 0.5 (sRGB 188), everywhere; the image alone gives whatever two texels
    # the pixel centre falls between.
    shown = facet.Renderer(10, 10).render(screen(target.texture), flat_view(), ["color"])["color"]
    grey = shown[..., 0].astype(int)
    if mipmaps:
        assert np.abs(grey - 188).max() <= 2
    else:
        assert grey.max() - grey.min() > 100


def test_bad_sizes_and_options_raise():
    for width, height in ((0, 0), (100000, 8), (8, -1)):
        with pytest.raises(facet.Error, match=r"outside 1x1 \.\. 8192x8192"):
            facet.RenderTexture(width, height)
    with pytest.raises(facet.Error, match="neither color nor depth"):
        facet.RenderTexture(8, 8, color=False)
    with pytest.raises(facet.Error, match="color_format must be 'uint8' or 'float'"):
        facet.RenderTexture(8, 8, color_format="half")
    renderer = facet.Renderer(8, 8)
    with pytest.raises(facet.Error, match="render_to: target must be a facet.RenderTexture"):
        renderer.render_to("target", facet.Scene())
    with pytest.raises(facet.Error, match="render_to: scene must be a facet.Scene"):
        renderer.render_to(facet.RenderTexture(8, 8), None)
    vertices, faces, uvs = quad()
    with pytest.raises(facet.Error, match="got a RenderTexture"):
        facet.Scene().add_mesh(vertices, faces, uvs=uvs, texture=facet.RenderTexture(8, 8))
    with pytest.raises(facet.Error, match="a texture needs uvs"):
        facet.Scene().add_mesh(vertices, faces, texture=facet.RenderTexture(8, 8).texture)


def test_a_frame_cannot_sample_its_own_target():
    target = facet.RenderTexture(16, 16)
    renderer = facet.Renderer(8, 8, background=(0, 1, 0))
    renderer.render_to(target, facet.Scene(), flat_view())
    with pytest.raises(facet.Error, match="samples the render texture it would be rendered into"):
        renderer.render_to(target, screen(target.texture), flat_view())
    assert tuple(target.read_color()[8, 8]) == (0, 255, 0, 255)  # untouched
    # The renderer and the target go on working.
    renderer.render_to(target, quadrants(), flat_view())
    assert tuple(target.read_color()[4, 4]) == (255, 0, 0, 255)


def test_frames_in_other_threads_never_see_half_a_frame():
    target = facet.RenderTexture(64, 64)
    shown = screen(target.texture)
    red, blue = facet.Scene(), facet.Scene()
    vertices, faces, _ = quad()
    red.add_mesh(vertices, faces, material=unlit(RED))
    blue.add_mesh(vertices, faces, material=unlit(BLUE))
    writer = facet.Renderer(8, 8, threads=1)
    writer.render_to(target, red, flat_view())
    stop = threading.Event()

    def rewrite():
        while not stop.is_set():
            for scene in (blue, red):
                writer.render_to(target, scene, flat_view())

    thread = threading.Thread(target=rewrite)
    thread.start()
    try:
        reader = facet.Renderer(64, 64, threads=1)
        for _ in range(40):
            for image in (reader.render(shown, flat_view(), ["color"])["color"],
                          target.read_color()):
                colors = np.unique(image.reshape(-1, 4), axis=0)
                assert len(colors) == 1, colors  # all red or all blue
    finally:
        stop.set()
        thread.join()


def test_targets_sampling_each_other_in_two_threads_do_not_deadlock():
    first, second = facet.RenderTexture(4, 4), facet.RenderTexture(4, 4)
    shows_first, shows_second = screen(first.texture), screen(second.texture)

    together = threading.Barrier(2)
    camera = flat_view()

    # Each frame locks its target and the target its scene samples: a circle of two threads
    # each holding one and waiting for the other's would stop both for good. A second of tiny
    # frames gives the two many chances to meet there.
    def render(target, scene):
        renderer = facet.Renderer(4, 4, threads=1)
        together.wait()
        until = time.monotonic() + 1.0
        while time.monotonic() < until:
            renderer.render_to(target, scene, camera)

    threads = [threading.Thread(target=render, args=(second, shows_first), daemon=True),
               threading.Thread(target=render, args=(first, shows_second), daemon=True)]
    for thread in threads:
        thread.start()
    deadline = time.monotonic() + 30
    for thread in threads:
        thread.join(timeout=max(0.0, deadline - time.monotonic()))
    assert not any(thread.is_alive() for thread in threads)
