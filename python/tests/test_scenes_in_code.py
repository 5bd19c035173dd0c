"""Scenes described in Python (glint.Scene, glint.load_dict) against the same scenes in TOML."""

import inspect
import os
import pathlib
import tomllib

import numpy as np
import pytest

import glint

SOURCE = pathlib.Path(os.environ["GLINT_SOURCE_DIR"])
SCENES = SOURCE / "scenes"

SMALL_SCENE_TOML = """
[render]
width = 48
height = 36
spp = 4
max_depth = 6

[camera]
position = [0, 2, 7]
look_at = [0, 1, 0]
fov = 40

[background]
color = [0.1, 0.12, 0.2]

[world]
ambient_light = 0.05

[[materials]]
name = "red"
diffuse = [0.8, 0.1, 0.1]
specular = 0.4
shininess = 40

[[materials]]
name = "glass"
diffuse = 0.02
transparency = 0.95
ior = 1.45

[[lights]]
type = "point"
position = [4, 6, 4]
intensity = 60

[[objects]]
type = "plane"
size = 8
material = "red"

[[objects]]
type = "sphere"
center = [0, 1, 0]
radius = 1
material = "glass"
"""


def small_scene_in_code():
    scene = glint.Scene()
    scene.set_render(width=48, height=36, spp=4, max_depth=6)
    scene.set_camera(position=(0, 2, 7), look_at=(0, 1, 0), fov=40)
    scene.set_background(color=(0.1, 0.12, 0.2))
    scene.set_world(ambient_light=0.05)
    scene.add_material(name="red", diffuse=(0.8, 0.1, 0.1), specular=0.4, shininess=40)
    scene.add_material(name="glass", diffuse=0.02, transparency=0.95, ior=1.45)
    scene.add_light(type="point", position=(4, 6, 4), intensity=60)
    scene.add_plane(size=8, material="red")
    scene.add_sphere(center=(0, 1, 0), radius=1, material="glass")
    return scene


def replay(description, base_dir):
    """A scene built call by call from a TOML file's tables: set_<table>, add_<array entry>."""
    adders = {"textures": "add_texture", "materials": "add_material", "lights": "add_light",
              "shapes": "add_shape", "objects": "add_object"}
    scene = glint.Scene(base_dir=base_dir)
    for section, value in description.items():
        if section in adders:
            for entry in value:
                getattr(scene, adders[section])(**entry)
        else:
            getattr(scene, "set_" + section)(**value)
    return scene


def test_a_scene_built_in_code_equals_the_same_scene_in_toml(tmp_path):
    path = tmp_path / "small.toml"
    path.write_text(SMALL_SCENE_TOML)
    from_file = np.asarray(glint.render(glint.load(path), threads=2))
    scene = small_scene_in_code()
    assert scene.to_dict() == tomllib.loads(SMALL_SCENE_TOML), "the same description"
    from_code = np.asarray(glint.render(scene, threads=2))
    assert from_code.shape == (36, 48, 3)
    assert np.array_equal(from_code, from_file)
    assert from_code.std() > 0.01, "the scene shows something"


@pytest.mark.parametrize("scene_file", sorted(SCENES.glob("*.toml")), ids=lambda p: p.name)
def test_every_example_scene_built_in_code_renders_as_its_file(scene_file):
    description = tomllib.loads(scene_file.read_text())
    settings = dict(width=24, height=18, threads=2)
    expected = np.asarray(glint.render(glint.load(scene_file), **settings))
    for scene in (replay(description, SCENES), glint.load_dict(description, base_dir=SCENES)):
        assert np.array_equal(np.asarray(glint.render(scene, **settings)), expected)


def test_a_scene_changed_after_a_render_renders_the_change():
    scene = small_scene_in_code()
    before = np.asarray(glint.render(scene))
    scene.set_background(color=(1, 1, 1))
    after = np.asarray(glint.render(scene))
    assert np.array_equal(after[0, 0], [1, 1, 1]) and not np.array_equal(before, after)
    scene.set_render(width=10)
    assert (scene.width, scene.height, scene.spp) == (10, 36, 4)


def test_values_are_copied_when_given_and_numpy_values_are_numbers():
    scene = small_scene_in_code()
    position = [0, 2, 7]
    scene.set_camera(position=position)
    position[0] = 100  # changes nothing: the scene holds a copy
    reference = np.asarray(glint.render(small_scene_in_code()))
    assert np.array_equal(np.asarray(glint.render(scene)), reference)
    scene.set_camera(position=np.array([0.0, 2.0, 7.0]), fov=np.float32(40), look_at=np.arange(3) * [0, 1, 0])
    scene.set_render(spp=np.int64(4), max_depth=np.array(6))
    scene.set_world(ambient_light=np.float64(0.05), emission_lights=np.bool_(True))
    assert np.array_equal(np.asarray(glint.render(scene)), reference)


def test_a_mistake_in_code_raises_scene_error_at_the_line_that_made_it():
    scene = small_scene_in_code()
    line = inspect.currentframe().f_lineno + 1
    scene.add_sphere(center=(0, 1, 0), radius=-1, material="glass")
    with pytest.raises(glint.SceneError) as error:
        glint.render(scene)
    assert str(error.value) == f"{__file__}:{line}: objects[2].radius is -1; expected a positive radius"

    scene = small_scene_in_code()
    line = inspect.currentframe().f_lineno + 1
    scene.add_material(name="blue", difuse=(0.1, 0.1, 0.8))
    with pytest.raises(glint.SceneError, match=rf"^{__file__}:{line}: unknown key 'difuse' .*did you mean 'diffuse'"):
        glint.render(scene)

    scene = small_scene_in_code()
    line = inspect.currentframe().f_lineno + 1
    scene.add_sphere(radius=1, material="gold")
    with pytest.raises(glint.SceneError, match=rf"^{__file__}:{line}: objects\[2\]\.material is the string \"gold\"; expected the name of a material"):
        glint.render(scene)

    line = inspect.currentframe().f_lineno + 2
    with pytest.raises(glint.SceneError, match=rf'^{__file__}:{line}: camera\.fov is the string "wide"; expected a number'):
        glint.load_dict({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": "wide"}})


def test_values_python_cannot_describe_raise_type_error():
    scene = glint.Scene()
    with pytest.raises(TypeError, match=r"^objects\[0\]\.center is \{1, 2\} \(set\); expected a number"):
        scene.add_sphere(center={1, 2}, radius=1)
    with pytest.raises(TypeError, match=r"^camera\.look_at\[1\] is None"):
        scene.set_camera(look_at=[0, None, 0])
    with pytest.raises(TypeError, match=r"its type is 'sphere'"):
        scene.add_sphere(type="box")
    with pytest.raises(TypeError, match=r"has the key 1; keys are strings"):
        glint.load_dict({"camera": {1: 2}})
    with pytest.raises(TypeError, match=r"spheres\.toml is not described in code; describe a scene in code"):
        glint.load(SCENES / "spheres.toml").add_sphere(radius=1)
    assert glint.load(SCENES / "spheres.toml").to_dict() is None


def test_meshes_and_textures_from_files_resolve_against_base_dir():
    scene = glint.load_dict(tomllib.loads((SCENES / "bunny_glass.toml").read_text()), base_dir=SCENES)
    assert scene.width > 0
    with pytest.raises(glint.SceneError, match=r"background\.file .* \(looked for .*/docs/assets/venice_sunset_1k\.hdr\)"):
        glint.load_dict(tomllib.loads((SCENES / "bunny_glass.toml").read_text()), base_dir=SOURCE / "docs")


def test_the_builders_warnings_are_python_warnings():
    scene = glint.Scene()
    scene.set_camera(position=(0, 0, 5), look_at=(0, 0, 0))
    with pytest.warns(UserWarning, match=r"the scene has no \[\[objects\]\]"):
        glint.render(scene, width=4, height=3)
    assert len(scene.warnings) == 1
    scene.add_sphere(radius=1, material="m")
    scene.add_material(name="m")
    with pytest.warns(UserWarning, match=r"no \[\[lights\]\] and no ambient light"):
        glint.render(scene, width=4, height=3)
