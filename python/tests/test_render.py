"""Scenes rendered through the library's pipeline: the same picture as the command line
writes, as arrays, and written atomically."""

import os
import subprocess

import numpy as np
import pytest

import cga

HERE = os.path.dirname(__file__)
SCENES = os.path.join(HERE, "..", "..", "cga-trace", "scenes")

FIRST = """
[camera]
position = [0.0, -8.0, 2.0]
look_at = [0.0, 0.0, 0.5]
width = 32
height = 24

[[lights]]
position = [-4.0, -6.0, 8.0]

[[objects]]
type = "sphere"
centre = [0.0, 0.0, 1.0]
radius = 1.0
material = { colour = [0.9, 0.1, 0.1] }

[[objects]]
type = "plane"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
material = { colour = [0.6, 0.6, 0.6], kr = 0.3 }
"""

SKY_BALL = """
[[objects]]
type = "sphere"
centre = [2.0, 0.0, 2.8]
radius = 0.5
material = { colour = [0.2, 0.9, 0.2] }
"""

def test_a_scene_renders_to_arrays():
    picture = cga.Scene.parse(FIRST).render()
    assert picture.size == (32, 24)
    linear, srgb = picture.linear, picture.srgb
    assert linear.shape == (24, 32, 3) and srgb.shape == (24, 32, 3) and srgb.dtype == np.uint8
    ball = linear[12, 16]
    assert ball[0] > 4 * max(ball[1], ball[2]), ball  # red, at the centre
    assert np.all(linear[0, 3] == 0), "the sky (top row) is the background"
    assert picture.rays[0] == 32 * 24


def test_options_override_the_scene():
    scene = cga.Scene.parse(FIRST)
    assert scene.render(width=16).size == (16, 12)
    normals = scene.render(aov="normal").linear
    assert normals.max() <= 1.0
    with pytest.raises(cga.SceneError, match="aov"):
        scene.render(aov="shiny")


def test_bad_scenes_are_refused_with_the_file_line_and_field():
    with pytest.raises(cga.SceneError, match=r"bad\.toml:3:"):
        cga.Scene.parse("[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = 5\n", "bad.toml")


def test_save_writes_the_png_the_command_line_writes(tmp_path):
    path = tmp_path / "first.toml"
    path.write_text(FIRST)
    ours = tmp_path / "ours.png"
    cga.Scene.load(str(path)).render().save(str(ours))
    assert ours.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert cga.Scene.load(str(path)).render()._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"
    # An output that is the scene itself (here through a link) is refused, and the scene survives.
    link = tmp_path / "link.png"
    link.symlink_to(path)
    with pytest.raises(cga.SceneError, match="same file"):
        cga.Scene.load(str(path)).render().save(str(link))
    assert path.read_text() == FIRST


@pytest.mark.skipif(not os.path.isdir(SCENES), reason="the repository's shipped scenes")
def test_a_shipped_scene_renders():
    picture = cga.Scene.load(os.path.join(SCENES, "primitives.toml")).render(width=40)
    assert picture.size[0] == 40 and picture.linear.max() > 0


def test_objects_draw_as_pictures():
    sphere = cga.Sphere.from_centre_radius([0, 0, 0.0], 1.0)
    circle = cga.Circle.from_centre_normal_radius([0, 0, 1.5], [0, 0, 1.0], 0.8)
    line = cga.Line.through([-2.0, 0, 0], [2.0, 0, 0])
    picture = cga.draw([sphere, circle, line], labels=["S", None, "L"], width=64, height=48)
    srgb = picture.srgb
    assert srgb.shape == (48, 64, 3) and srgb.max() > 0
    # Every object kind shows in a notebook; a versor has no picture (its text shows instead).
    assert circle._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"
    assert cga.Rotor.from_axis_angle([0, 0, 1.0], 0.5)._repr_png_() is None
    with pytest.raises(TypeError):
        cga.draw([sphere, "not a blade"])
    with pytest.raises(cga.SceneError, match="colour"):
        cga.draw([sphere], colours=["no such colour"])


def test_adaptive_sampling_takes_the_first_samples_or_all():
    scene = cga.Scene.parse(FIRST)
    first, every = scene.render(spp=4).linear, scene.render(spp=16).linear
    adaptive = scene.render(spp=16, adaptive=0.3).linear
    took_first = np.all(adaptive == first, axis=-1)
    took_all = np.all(adaptive == every, axis=-1)
    # Each pixel is its first 4 samples' mean or all 16's; the sphere's edge takes all.
    assert np.all(took_first | took_all)
    assert 0 < np.count_nonzero(~took_first) < took_first.size // 4
    with pytest.raises(cga.ValueError, match=r"adaptive.*\[0, 3\]"):
        scene.render(spp=16, adaptive=4.0)
    # First samples as many as spp: nothing adapts.
    assert np.array_equal(scene.render(spp=16, adaptive=0.3, adaptive_min=16).linear, every)


def test_adaptive_sampling_by_corners_is_povray_method_2():
    scene = cga.Scene.parse(FIRST)
    # Nothing differs by more than 3: every pixel is the mean of its four corners, the same
    # at any spp (this scene has no lens or area light), the picture as smooth as that.
    flat = scene.render(spp=16, adaptive=3.0, adaptive_method="corners")
    assert np.array_equal(flat.linear, scene.render(spp=64, adaptive=3.0, adaptive_method="corners").linear)
    assert flat.rays[0] == (flat.size[0] + 1) * (flat.size[1] + 1)
    cut = scene.render(spp=16, adaptive=0.1, adaptive_method="corners")
    every = scene.render(spp=64).linear
    assert flat.rays[0] < cut.rays[0] < every.shape[0] * every.shape[1] * 16
    assert np.abs(cut.linear - every).mean() < np.abs(flat.linear - every).mean()
    with pytest.raises(cga.ValueError, match="adaptive_method"):
        scene.render(spp=16, adaptive_method="edges")


def test_a_transparent_background_gives_rgba(tmp_path):
    # The first scene with a ball in the sky, whose edge is against nothing.
    scene = cga.Scene.parse(FIRST + SKY_BALL)
    opaque = scene.render(spp=16)
    picture = scene.render(spp=16, background="transparent")
    linear, srgb, alpha = picture.linear, picture.srgb, picture.coverage
    assert linear.shape == (24, 32, 4) and srgb.shape == (24, 32, 4) and srgb.dtype == np.uint8
    assert alpha.shape == (24, 32) and np.array_equal(linear[..., 3], alpha)
    assert opaque.coverage is None and opaque.linear.shape == (24, 32, 3)
    # The sky sees through; the balls and the floor are opaque; the sky ball's edge partly.
    assert np.all(alpha[0] == 0) and np.all(linear[0] == 0) and np.all(srgb[0] == 0)
    assert alpha[12, 16] == 1 and alpha[-1, 0] == 1
    assert np.count_nonzero((alpha > 0) & (alpha < 1)) > 5
    # Over black, premultiplied colours are the opaque picture's, to the bit.
    assert np.array_equal(linear[..., :3], opaque.linear)
    # The PNG's straight colours: where opaque, the opaque picture's; alpha the coverage.
    whole = alpha == 1
    assert np.array_equal(srgb[whole][:, :3], opaque.srgb[whole])
    assert np.array_equal(srgb[..., 3], np.floor(alpha * 255 + 0.5).astype(np.uint8))
    # The coverage AOV shows the same coverage.
    assert np.array_equal(scene.render(spp=16, aov="coverage").linear[..., 0], alpha)
    # Written with an alpha channel (PNG colour type 6, RGBA); HDR, which has none, refused.
    png = tmp_path / "t.png"
    picture.save(str(png))
    assert png.read_bytes()[25] == 6 and picture._repr_png_()[25] == 6
    picture.save(str(tmp_path / "t.exr"))
    with pytest.raises(cga.SceneError, match=r"t\.hdr.*transparent"):
        picture.save(str(tmp_path / "t.hdr"))
    assert not (tmp_path / "t.hdr").exists()
    with pytest.raises(cga.SceneError, match="transparent"):
        scene.render(background="clear")
    # A colour background in place of the scene's, as a name or linear values.
    assert scene.render(background=[0.0, 0.0, 1.0]).linear[0, 3, 2] == 1.0
    assert scene.render(background="white").srgb[0, 3, 0] == 240


def test_scenes_and_figures_take_a_transparent_background():
    built = cga.Scene().camera(position=[0.0, -8.0, 2.0], look_at=[0.0, 0.0, 0.5], width=32, height=24)
    built.settings(background="transparent", spp=4).sphere(
        centre=[0.0, 0.0, 1.0], radius=1.0, material={"colour": [0.9, 0.1, 0.1]}, label="S")
    assert 'background = "transparent"' in built.toml()
    picture = built.render()
    assert picture.linear.shape == (24, 32, 4) and picture.coverage[0, 0] == 0
    sphere = cga.Sphere.from_centre_radius([0, 0, 0.0], 1.0)
    drawn = cga.draw([sphere], labels=["S"], width=64, height=48, background="transparent")
    srgb = drawn.srgb
    assert srgb.shape == (48, 64, 4) and srgb[0, 0, 3] == 0 and srgb[24, 32, 3] == 255
    # The label is opaque where drawn: pixels outside the sphere's coverage with alpha 255.
    assert np.count_nonzero((drawn.coverage == 0) & (srgb[..., 3] == 255)) > 10
    assert cga.draw([sphere], width=16, height=12).srgb.shape == (12, 16, 3)


@pytest.mark.skipif(not os.path.isdir(SCENES), reason="the repository's shipped scenes")
def test_blur_samples_average_lens_rays_per_sample():
    scene = cga.Scene.load(os.path.join(SCENES, "lens.toml"))
    reference = scene.render(width=48, spp=256).linear
    one = scene.render(width=48, spp=4, adaptive=0.3, adaptive_method="corners")
    blurred = scene.render(width=48, spp=4, adaptive=0.3, adaptive_method="corners", blur_samples=16)
    # Each corner the mean of 16 lens rays: a blur is no longer noise that cuts every square.
    assert np.sqrt(np.mean((blurred.linear - reference) ** 2)) < 0.5 * np.sqrt(np.mean((one.linear - reference) ** 2))
    # Plain samples: 4 samples of 4 lens rays cast the camera rays of 16 samples.
    assert scene.render(width=48, spp=4, blur_samples=4).rays[0] == scene.render(width=48, spp=16).rays[0]
    for bad in (0, 257):
        with pytest.raises(cga.ValueError, match="blur_samples"):
            scene.render(width=48, blur_samples=bad)
