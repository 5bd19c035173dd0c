#!/usr/bin/env python3
"""Sweep the index of refraction of the seminar's glass spheres and plot the renders in a grid.

The scene is scenes/spheres_refraction.toml (EDAN30 assignment 1: its green spheres are
glass), read with tomllib into a dict; each render changes the glass's `ior` and hands the
dict to glint.load_dict, so the scene is the file's in every other way. With Matplotlib
installed (python3-matplotlib) the grid is a figure with each index in its title; without
it, the renders are tiled into one image that Glint writes.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/ior_sweep.py -o ior_sweep.png

At n = 1 the glass bends nothing: only its transparency and tint show. As n grows each sphere
is a stronger ball lens (focal length nR / 2(n - 1) from its centre), so what is seen through
it shrinks and turns upside down.
"""

import argparse
import pathlib
import tomllib

import numpy as np

import glint

SCENE = pathlib.Path(__file__).resolve().parents[2] / "scenes" / "spheres_refraction.toml"


def srgb(linear):
    """Display values of linear radiance (IEC 61966-2-1), clipped to [0, 1]."""
    c = np.clip(linear, 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)


def render_sweep(iors, width, height, spp, threads):
    description = tomllib.loads(SCENE.read_text())
    glass = next(m for m in description["materials"] if m["name"] == "green")
    images = []
    for ior in iors:
        glass["ior"] = ior
        scene = glint.load_dict(description, base_dir=SCENE.parent)
        images.append(np.asarray(glint.render(scene, width=width, height=height, spp=spp, threads=threads)))
    return images


def save_grid(images, iors, columns, out):
    rows = -(-len(images) // columns)
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        height, width, channels = images[0].shape
        grid = np.zeros((rows * height, columns * width, channels), dtype=np.float32)
        for i, image in enumerate(images):
            r, c = divmod(i, columns)
            grid[r * height:(r + 1) * height, c * width:(c + 1) * width] = image
        glint.Image(grid).save(out)
        return
    figure, axes = plt.subplots(rows, columns, figsize=(3 * columns, 2.4 * rows), squeeze=False)
    for axis in axes.flat:
        axis.axis("off")
    for axis, image, ior in zip(axes.flat, images, iors):
        axis.imshow(srgb(image))
        axis.set_title(f"n = {ior:g}")
    figure.tight_layout()
    figure.savefig(out, dpi=100)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--iors", default="1.0,1.1,1.2,1.33,1.5,1.8,2.0,2.42",
                        help="the indices of refraction, comma-separated")
    parser.add_argument("--width", type=int, default=320)
    parser.add_argument("--height", type=int, default=240)
    parser.add_argument("--spp", type=int, default=4)
    parser.add_argument("--threads", type=int, default=0, help="0: every core")
    parser.add_argument("--columns", type=int, default=4)
    parser.add_argument("-o", "--output", default="ior_sweep.png")
    args = parser.parse_args()
    iors = [float(v) for v in args.iors.split(",")]
    images = render_sweep(iors, args.width, args.height, args.spp, args.threads)
    save_grid(images, iors, args.columns, args.output)
    print(f"{args.output}: {len(images)} renders, n = {', '.join(f'{n:g}' for n in iors)}")


if __name__ == "__main__":
    main()
