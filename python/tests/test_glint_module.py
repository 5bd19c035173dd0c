"""The Python module against the command line it shares its library with.

Run by ctest (Python.Module) with PYTHONPATH at the built module, GLINT_CLI the glint program
and GLINT_SOURCE_DIR the checkout.
"""

import os
import pathlib
import subprocess

import numpy as np
import pytest

import glint

SOURCE = pathlib.Path(os.environ["GLINT_SOURCE_DIR"])
CLI = os.environ["GLINT_CLI"]
SPHERES = SOURCE / "scenes" / "spheres.toml"


def read_pfm(path):
    """RGB floats of a little-endian PFM file, top row first."""
    data = pathlib.Path(path).read_bytes()
    header, width_height, scale, pixels = data.split(b"\n", 3)
    assert header == b"PF" and float(scale) < 0, "a little-endian colour PFM"
    width, height = (int(v) for v in width_height.split())
    rgb = np.frombuffer(pixels, dtype="<f4", count=width * height * 3).reshape(height, width, 3)
    return rgb[::-1]


def test_a_render_equals_the_command_line_render_bit_for_bit(tmp_path):
    for scene_file, settings in [(SPHERES, ["--spp", "4"]), (SOURCE / "scenes" / "cornell_area.toml", ["--spp", "1"])]:
        out = tmp_path / (scene_file.stem + ".pfm")
        subprocess.run([CLI, "render", str(scene_file), "--width", "64", "--height", "48", *settings,
                        "--threads", "2", "-q", "-o", str(out)], check=True)
        image = glint.render(glint.load(scene_file), width=64, height=48, spp=int(settings[1]), threads=2)
        pixels = np.asarray(image)
        assert pixels.dtype == np.float32 and pixels.shape == (48, 64, 3)
        assert image.channels == ["R", "G", "B"]
        expected = read_pfm(out)
        assert np.array_equal(pixels, expected), f"{scene_file.name}: {np.abs(pixels - expected).max()} apart"


def test_the_built_in_scene_renders_as_glint_render_with_no_file(tmp_path):
    out = tmp_path / "default.pfm"
    subprocess.run([CLI, "render", "--width", "64", "--height", "48", "-q", "-o", str(out)], check=True)
    scene = glint.default_scene()
    assert scene.spp == 4
    assert np.array_equal(np.asarray(glint.render(scene, width=64, height=48)), read_pfm(out))


def test_the_same_settings_give_the_same_image_whatever_the_thread_count():
    scene = glint.load(SPHERES)
    one = np.asarray(glint.render(scene, width=40, height=30, threads=1))
    two = np.asarray(glint.render(scene, width=40, height=30, threads=2))
    assert np.array_equal(one, two)
    assert one.any(), "the spheres are lit"


def test_the_array_views_the_image_without_a_copy_and_outlives_the_scene(tmp_path):
    scene = glint.load(SPHERES)
    assert (scene.width, scene.height, scene.spp, scene.integrator) == (640, 480, 4, "whitted")
    image = glint.render(scene, width=16, height=12, spp=1)
    del scene
    view = np.asarray(image)
    view[0, 0] = [1.0, 2.0, 3.0]
    assert np.array_equal(np.asarray(image)[0, 0], [1.0, 2.0, 3.0]), "the array is the image's memory"
    del image
    assert view[0, 0, 2] == 3.0, "the array keeps the image alive"
    # What save() writes is what the array holds.
    image = glint.render(glint.load(SPHERES), width=16, height=12, spp=1)
    image.save(tmp_path / "saved.pfm")
    assert np.array_equal(read_pfm(tmp_path / "saved.pfm"), np.asarray(image))
    image.save(tmp_path / "saved.png")
    assert (tmp_path / "saved.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_mistake_in_a_scene_file_raises_scene_error_at_its_line(tmp_path):
    bad = tmp_path / "typo.toml"
    bad.write_text('[[materials]]\nname = "red"\ndifuse = 0.5\n')
    with pytest.raises(glint.SceneError, match=r"typo\.toml:3:1: unknown key 'difuse' .*did you mean 'diffuse'"):
        glint.load(bad)
    with pytest.raises(glint.SceneError, match="no such scene file"):
        glint.load(tmp_path / "missing.toml")


def test_bad_settings_raise_value_error_naming_the_keyword(tmp_path):
    scene = glint.load(SPHERES)
    cases = [
        (dict(spp=5), r"^spp: expected a square number"),
        (dict(width=0), r"^width: expected an integer from 1 to 16384; got 0"),
        (dict(threads=-1), r"^threads: expected 0 \(all cores\)"),
        (dict(seed=-3), r"^seed: expected a non-negative integer; got -3"),
        (dict(integrator="photon"), r"^integrator: expected one of .*whitted.*; got 'photon'"),
    ]
    for settings, message in cases:
        with pytest.raises(ValueError, match=message):
            glint.render(scene, **settings)
    with pytest.raises(TypeError):
        glint.render(scene, 64)  # settings are keywords
    with pytest.raises(TypeError, match="unexpected keyword argument 'samples'"):
        glint.render(scene, samples=4)
    with pytest.raises(TypeError, match=r"^spp: expected an integer; got 2\.5"):
        glint.render(scene, spp=2.5)
    with pytest.raises(TypeError, match=r"^integrator: expected a string; got 3"):
        glint.render(scene, integrator=3)
    with pytest.raises(ValueError, match=r"^light_samples: expected an integer from 1 to 1024; got 0"):
        glint.render(scene, light_samples=0)
    with pytest.raises(glint.ImageError, match="unknown.*extension|extension"):
        glint.render(scene, width=4, height=3, spp=1).save(tmp_path / "x.unknown")


def test_aovs_are_named_channels_after_the_colour(tmp_path):
    scene = glint.load(SPHERES)
    image = glint.render(scene, width=32, height=24, spp=1, aov="albedo,depth")
    assert image.channels == ["R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "Z"]
    pixels = np.asarray(image)
    assert pixels.shape == (24, 32, 7)
    depth = image.channel("Z")
    assert depth.shape == (24, 32) and np.array_equal(depth, pixels[..., 6])
    assert np.isinf(depth[0, 0]), "the sky is at no distance"
    assert ((depth > 0) & np.isfinite(depth)).any(), "the spheres and floor are at some distance"
    depth[0, 0] = -1.0
    assert np.asarray(image)[0, 0, 6] == -1.0, "a channel is a view of the image"
    # Adaptive sampling (at most spp, a power of 4) gives its pixels' sample counts.
    adaptive = glint.render(scene, width=32, height=24, spp=16, adaptive=True, adaptive_threshold=0.05, aov="spp")
    counts = adaptive.channel("spp")
    assert counts.min() >= 1 and counts.max() <= 16 and counts.min() < counts.max()
    # The colour is the same image a render without AOVs gives.
    plain = np.asarray(glint.render(scene, width=32, height=24, spp=1))
    assert np.array_equal(pixels[..., :3], plain)
    with pytest.raises(KeyError, match="no channel 'depth'; the image has R, G, B, albedo.R"):
        image.channel("depth")


def test_cmake_install_puts_the_module_where_debians_python_finds_it(tmp_path):
    prefix = tmp_path / "prefix"
    subprocess.run([os.environ["CMAKE_COMMAND"], "--install", os.environ["GLINT_BUILD_DIR"], "--prefix", str(prefix),
                    "--component", "python"], check=True, capture_output=True)
    installed = prefix / os.environ["GLINT_PYTHON_INSTALL_DIR"]
    env = dict(os.environ, PYTHONPATH=str(installed))
    code = "import glint; print(glint.__file__); glint.render(glint.default_scene(), width=4, height=3).save('x.exr')"
    out = subprocess.run(["/usr/bin/python3", "-c", code], check=True, capture_output=True, text=True, env=env,
                         cwd=tmp_path)
    assert pathlib.Path(out.stdout.strip()).parent == installed
    assert (tmp_path / "x.exr").stat().st_size > 0
    # /usr/local is the default prefix; its dist-packages folder is on Debian's python3 path.
    paths = subprocess.run(["/usr/bin/python3", "-c", "import sys; print('\\n'.join(sys.path))"], check=True,
                           capture_output=True, text=True).stdout.split()
    assert "/usr/local/" + os.environ["GLINT_PYTHON_INSTALL_DIR"] in paths


def test_a_crop_is_the_region_of_the_full_render(tmp_path):
    scene = glint.load(SPHERES)
    full = np.asarray(glint.render(scene, width=40, height=30, spp=1))
    crop = glint.render(scene, width=40, height=30, spp=1, crop="5,7,25,30")
    assert np.array_equal(np.asarray(crop), full[7:30, 5:25])
    quarter = glint.render(scene, width=40, height=30, spp=1, crop="0.5,0.5,1,1")
    assert np.array_equal(np.asarray(quarter), full[15:, 20:])
    with pytest.raises(ValueError, match=r"^crop 0,0,41,30: the region reaches past the 40×30 image"):
        glint.render(scene, width=40, height=30, crop="0,0,41,30")
