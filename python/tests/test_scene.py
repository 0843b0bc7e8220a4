"""Scenes built in code: every shipped scene rebuilt call by call from its tables renders
the same bytes as the file; errors name the call; values drawn as blades."""

import os
import tomllib

import numpy as np
import pytest

import cga

SCENES = os.path.join(os.path.dirname(__file__), "..", "..", "cga-trace", "scenes")
SHIPPED = sorted(f for f in os.listdir(SCENES) if f.endswith(".toml")) if os.path.isdir(SCENES) else []


def rebuilt(tables):
    """The scene of a file's tables, built by the calls a user would write."""
    scene = cga.Scene().camera(**tables["camera"])
    if "render" in tables:
        scene.settings(**tables["render"])
    if "environment" in tables:
        scene.environment(**tables["environment"])
    for name, fields in tables.get("materials", {}).items():
        scene.material(name, **fields)
    for light in tables.get("lights", []):
        scene.light(**light)
    for obj in tables.get("objects", []):
        obj = dict(obj)
        kind = obj.pop("type")
        getattr(scene, kind.replace("-", "_"))(**obj)
    return scene


@pytest.mark.parametrize("name", [f for f in SHIPPED if f != "assembly.toml"])
def test_a_scene_built_in_code_renders_the_files_bytes(name, monkeypatch):
    # assembly.toml includes other files, which a scene in code does by Python's own means.
    monkeypatch.chdir(SCENES)
    text = open(name).read()
    kinds = {o["type"] for o in tomllib.loads(text).get("objects", [])}
    options = dict(width=24, spp=2)
    from_file = cga.Scene.parse(text, name).render(**options)
    from_code = rebuilt(tomllib.loads(text)).render(**options)
    assert np.array_equal(from_file.srgb, from_code.srgb), (name, kinds)


def test_every_object_kind_is_built_by_some_shipped_scene():
    kinds = set()
    for name in SHIPPED:
        kinds |= {o["type"] for o in tomllib.load(open(os.path.join(SCENES, name), "rb")).get("objects", [])}
    assert set(cga.scene.KINDS) - kinds <= {"point", "point-pair", "line", "plane-patch", "ruled", "mesh"} or not SHIPPED


def test_an_error_names_the_call_that_wrote_the_field():
    scene = cga.Scene().camera(position=[0.0, -8.0, 2.0], look_at=[0, 0, 0.5], width=32, height=24)
    scene.sphere(centre=[0, 0, 0.5], radius=1.0, material={"colour": [1.0, 0, 0]})
    scene.sphere(centre=[1, 0, 0.5], radius=-1.0, material={"colour": [1.0, 0, 0]})
    with pytest.raises(cga.SceneError, match=r"`radius`.*\[object 2 \(scene\.sphere\(…\)\)\]"):
        scene.render()
    with pytest.raises(cga.ValueError, match="no object kind"):
        scene.add("teapot")
    with pytest.raises(TypeError):
        scene.light(position=object()).toml()


def test_values_are_drawn_as_what_they_are():
    p = cga.up(np.array([[0.0, 0, 0], [1.0, 0, 0], [0, 1.0, 0]]))
    scene = cga.Scene().camera(position=[0.5, -6.0, 1.0], look_at=[0.5, 0.0, 0.0], width=40, height=30)
    scene.settings(ambient=1.0).light(position=[0.0, -4.0, 4.0])
    scene.draw(p[0] ^ p[1] ^ p[2], material={"colour": [1.0, 1.0, 1.0]}, tube=0.05)
    scene.draw(p, material={"colour": [1.0, 0.2, 0.2]}, size=0.1)
    assert scene.toml().count("[[objects]]") == 4
    assert scene.render().srgb.max() > 0


def test_csg_and_clips_are_built_in_code():
    """A sphere bored through along the view: the bore shows the background; a clip on the
    same sphere (``clip=``) shows its inside."""
    scene = cga.Scene().camera(position=[0.0, -8.0, 0.0], look_at=[0, 0, 0], fov=30.0, width=33, height=33)
    scene.light(position=[-4.0, -6.0, 8.0]).settings(background=[0.0, 0.0, 0.0])
    sphere = {"type": "sphere", "centre": [0.0, 0.0, 0.0], "radius": 1.5}
    bore = {"type": "cylinder", "p1": [0.0, -3.0, 0.0], "p2": [0.0, 3.0, 0.0], "radius": 0.5}
    scene.csg(operation="difference", objects=[sphere, bore], material={"colour": [0.9, 0.3, 0.2]})
    picture = scene.render(spp=1).linear
    assert picture[16, 16].max() == 0.0
    assert picture[16, 10].max() > 0.0
    whole = cga.Scene().camera(position=[0.0, -8.0, 0.0], look_at=[0, 0, 0], fov=30.0, width=33, height=33)
    whole.light(position=[-4.0, -6.0, 8.0]).sphere(
        centre=[0.0, 0.0, 0.0], radius=1.5, material={"colour": [0.9, 0.3, 0.2]},
        clip={"plane": {"point": [0.0, 0.0, 0.0], "normal": [0.0, -1.0, 0.0]}},
    )
    assert whole.render(spp=1).linear[16, 16].max() > 0.0
    with pytest.raises(cga.SceneError, match="bounds a solid"):
        scene.csg(operation="union", objects=[sphere, {"type": "disk", "centre": [0, 0, 0], "normal": [0, 0, 1], "radius": 1.0}], material={"colour": [1.0, 1.0, 1.0]}).build()


def test_a_capped_swept_surface_is_a_csg_part():
    """An evolved surface with ``caps=True`` bounds a solid: a ball taken from its top shows
    the ball's inside where the cap was; without caps it is refused."""
    def tube(caps):
        return {
            "type": "evolved", "caps": caps,
            "c1": {"centre": [0.0, 0.0, -1.0], "normal": [0.0, 0.0, 1.0], "radius": 1.0},
            "c2": {"centre": [0.0, 0.0, 1.0], "normal": [0.0, 0.0, 1.0], "radius": 1.0},
        }
    ball = {"type": "sphere", "centre": [0.0, 0.0, 1.0], "radius": 0.5, "material": {"colour": [0.0, 0.0, 1.0], "ks": 0.0}}
    scene = cga.Scene().camera(position=[0.0, 0.0, 8.0], look_at=[0, 0, 0], up=[0, 1, 0], fov=30.0, width=33, height=33)
    scene.light(position=[0.0, 0.0, 8.0]).settings(background=[0.0, 0.0, 0.0])
    scene.csg(operation="difference", objects=[tube(True), ball], material={"colour": [1.0, 0.0, 0.0], "ks": 0.0})
    picture = scene.render(spp=1).linear
    centre, rim = picture[16, 16], picture[16, 10]
    assert centre[2] > 0.0 and centre[0] == 0.0, centre
    assert rim[0] > 0.0 and rim[2] == 0.0, rim
    with pytest.raises(cga.SceneError, match="bounds a solid"):
        bare = cga.Scene().camera(position=[0.0, 0.0, 8.0], look_at=[0, 0, 0], up=[0, 1, 0], width=8, height=8)
        bare.csg(operation="difference", objects=[tube(False), ball], material={"colour": [1.0, 0.0, 0.0]}).build()
