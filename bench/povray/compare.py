#!/usr/bin/env python3
"""Whole-process wall time of Glint and POV-Ray 3.7 on matched Whitted scenes (issue 13):
each program started from nothing, loading its scene, rendering 640x480 on 2 threads and
writing a PNG, as a user runs it. Best of --runs runs each, alternated.

    bench/povray/compare.py [--glint build/glint] [--dragon PLY] [--runs 3] [--threads 2]

Scenes (this folder): two_spheres (1 spp) and dragon (the 202,520-triangle Stanford dragon,
9 spp), plus a 1x1 render of two_spheres for the cost of starting up. POV-Ray's 9 samples
are +AM1 +R3 +A0.0: its 3x3 supersampling wherever a pixel differs from a neighbour at all.
Needs `povray` (Debian: apt-get install povray).
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def best_time(command, cwd, runs):
    best = float("inf")
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run(command, cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        best = min(best, time.perf_counter() - start)
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--glint", default=os.path.join(ROOT, "build", "glint"))
    parser.add_argument("--dragon", default=os.path.join(ROOT, "..", "shared", "data", "meshes",
                                                         "stanford_dragon_res2.ply"))
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    if not shutil.which("povray"):
        sys.exit("povray not found (Debian: apt-get install povray)")
    if not os.path.exists(args.dragon):
        sys.exit(f"{args.dragon}: not found (the shared Stanford meshes)")
    work = tempfile.mkdtemp(prefix="glint-povray-")
    try:
        for name in ("common.inc", "two_spheres.pov", "two_spheres.toml", "dragon.pov"):
            shutil.copy(os.path.join(HERE, name), work)
        with open(os.path.join(HERE, "dragon.toml.in")) as f:
            text = f.read().replace("DRAGON_PLY", os.path.abspath(args.dragon))
        with open(os.path.join(work, "dragon.toml"), "w") as f:
            f.write(text)
        with open(os.path.join(work, "dragon.inc"), "w") as f:
            subprocess.run([sys.executable, os.path.join(HERE, "ply_to_pov.py"), args.dragon, "Dragon"], stdout=f,
                           check=True)
        cases = [("two_spheres", 640, 480, 1), ("dragon", 640, 480, 9), ("two_spheres", 1, 1, 1)]
        print(f"| scene | size | spp | Glint s | POV-Ray s | POV-Ray / Glint |")
        print(f"|---|---|---:|---:|---:|---:|")
        for scene, width, height, spp in cases:
            glint = [args.glint, "render", f"{scene}.toml", "-o", f"glint_{scene}.png", "-q", "--threads",
                     str(args.threads), "--width", str(width), "--height", str(height), "--spp", str(spp)]
            antialias = ["+A0.0", "+AM1", "+R3"] if spp == 9 else ["-A"]
            pov = ["povray", f"+I{scene}.pov", f"+Opov_{scene}.png", "+FN", f"+W{width}", f"+H{height}",
                   f"+WT{args.threads}", "-D", "-P", "-V", "-GA"] + antialias
            glint_s = pov_s = float("inf")
            for _ in range(args.runs):  # alternated, so load from other processes hits both alike
                glint_s = min(glint_s, best_time(glint, work, 1))
                pov_s = min(pov_s, best_time(pov, work, 1))
            print(f"| {scene} | {width}x{height} | {spp} | {glint_s:.3f} | {pov_s:.3f} | {pov_s / glint_s:.1f} |")
        if os.environ.get("GLINT_POVRAY_KEEP"):
            print(f"images in {work}")
            work = None
    finally:
        if work:
            shutil.rmtree(work)


if __name__ == "__main__":
    main()
