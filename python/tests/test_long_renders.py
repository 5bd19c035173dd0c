"""Renders that take a while (progress, Ctrl-C), glint.explain, and images made from arrays."""

import json
import os
import pathlib
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import glint

SOURCE = pathlib.Path(os.environ["GLINT_SOURCE_DIR"])
CLI = os.environ["GLINT_CLI"]
SPHERES = SOURCE / "scenes" / "spheres.toml"


def test_progress_reports_tiles_up_to_the_total_and_draws_a_bar(capsys):
    reports = []
    glint.render(glint.load(SPHERES), width=320, height=240, spp=16, progress=lambda done, total: reports.append(
        (done, total)))
    assert reports, "progress was reported"
    totals = {total for _, total in reports}
    assert len(totals) == 1 and reports[-1] == (totals.pop(),) * 2, "the last report is every tile"
    assert all(a[0] < b[0] for a, b in zip(reports, reports[1:])), "done only grows"

    glint.render(glint.load(SPHERES), width=64, height=48, spp=1, progress=True)
    err = capsys.readouterr().err
    assert "100.0%" in err and "elapsed" in err, "the bar is drawn on sys.stderr"
    assert err.endswith("\r"), "and its line cleared at the end"
    glint.render(glint.load(SPHERES), width=64, height=48, spp=1, progress=False)
    assert capsys.readouterr().err == ""
    with pytest.raises(TypeError, match="progress: expected True, False or a callable"):
        glint.render(glint.load(SPHERES), progress="yes")


def test_an_exception_in_the_progress_callable_stops_the_render():
    def fail(done, total):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        glint.render(glint.load(SPHERES), width=320, height=240, spp=64, progress=fail)


def test_ctrl_c_interrupts_a_render_with_keyboard_interrupt_and_python_goes_on():
    # A shell may start Python with SIGINT ignored (a background job); Python's own handler
    # is what a user at a terminal or in a notebook has.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        scene = glint.load(SPHERES)
        timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
        start = time.monotonic()
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            glint.render(scene, width=640, height=480, spp=1024, threads=2)  # a minute or more uninterrupted
        elapsed = time.monotonic() - start
        timer.join()
    finally:
        signal.signal(signal.SIGINT, previous)
    assert elapsed < 10, f"the render stopped {elapsed:.1f} s after it started"
    assert np.asarray(glint.render(scene, width=8, height=6, spp=1)).shape == (6, 8, 3), "Python goes on"


def test_explain_returns_what_glint_explain_json_prints():
    scene = glint.load(SPHERES)
    for pixel, sample in [((320, 240), None), ((100, 300), 2), ((5, 5), 0)]:
        args = [CLI, "explain", str(SPHERES), "--pixel", f"{pixel[0]},{pixel[1]}", "--json"]
        if sample is not None:
            args += ["--sample", str(sample)]
        expected = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
        explained = glint.explain(scene, pixel=pixel, sample=sample)
        assert explained == expected
    rays = glint.explain(scene, pixel=(320, 240), sample=0)["samples"][0]["rays"]
    assert rays[0]["kind"] == "camera" and rays[0]["parent"] is None and rays[0]["hit"]["t"] > 0
    assert any(ray["kind"] == "shadow" for ray in rays), "the hit is lit by the point lights"
    # The value is the rendered pixel's.
    small = glint.explain(scene, pixel=(3, 2), width=8, height=6, spp=1)
    assert np.allclose(small["value"], np.asarray(glint.render(scene, width=8, height=6, spp=1))[2, 3])


def test_explain_refuses_a_pixel_or_sample_that_does_not_exist():
    scene = glint.load(SPHERES)
    with pytest.raises(ValueError, match=r"pixel \(640, 0\) is outside the 640×480 image \(columns 0 to 639"):
        glint.explain(scene, pixel=(640, 0))
    with pytest.raises(ValueError, match=r"sample 4: this render takes 4 samples per pixel, 0 to 3"):
        glint.explain(scene, pixel=(0, 0), sample=4)
    with pytest.raises(ValueError, match=r"^spp: expected a square number"):
        glint.explain(scene, pixel=(0, 0), spp=3)


def test_an_image_made_from_an_array_is_saved_by_glints_writer(tmp_path):
    pixels = np.linspace(0, 2, 4 * 5 * 3, dtype=np.float64).reshape(4, 5, 3)
    image = glint.Image(pixels)
    assert (image.width, image.height, image.channels) == (5, 4, ["R", "G", "B"])
    assert np.array_equal(np.asarray(image), pixels.astype(np.float32))
    image.save(tmp_path / "a.exr")
    again = glint.Image(np.asarray(image)[:, :, 0])
    assert again.channels == ["Y"] and np.asarray(again).shape == (4, 5, 1)
    assert glint.Image(np.zeros((2, 2, 2)), channels=["u", "v"]).channel("v").shape == (2, 2)
    with pytest.raises(ValueError, match="2 channels: name them"):
        glint.Image(np.zeros((2, 2, 2)))
    with pytest.raises(ValueError, match="shape \\(height, width\\)"):
        glint.Image(np.zeros(3))


def test_the_example_ior_sweep_writes_its_grid(tmp_path):
    out = tmp_path / "sweep.png"
    subprocess.run([sys.executable, str(SOURCE / "examples" / "python" / "ior_sweep.py"), "--iors", "1.0,1.5,2.0",
                    "--width", "40", "--height", "30", "--spp", "1", "--columns", "2", "-o", str(out)], check=True,
                   env=dict(os.environ))
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
