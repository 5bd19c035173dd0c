#!/usr/bin/env python3
"""Instructions per camera sample, stage by stage, of one whole `glint render` process, as
Valgrind's callgrind counts them: the same numbers on every run of the same binary and scene,
where this project's shared machines move CPU times by +-30 % (docs/performance.md,
"Counting instructions").

    bench/instruction_profile.py GLINT SCENE [--width W --height H] [-- MORE GLINT OPTIONS]

GLINT must be a build Valgrind can decode: Valgrind 3.19 (Debian 12) stops at AVX-512, so
configure one with -DGLINT_NATIVE=OFF -DCMAKE_CXX_FLAGS="-march=haswell -g" (the whole
command is in docs/performance.md, "Counting instructions"). The render runs on one thread.
Stages are inclusive counts of the functions that begin them; "shading and the rest" is the
render minus the stages listed above it (integrator, BSDFs, lights, film).
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

# (stage, the function names that begin it), in the order of a render.
STAGES = [
    ("load the scene", ["glint::app::load_scene("]),
    ("prepare (BVH builds)", ["glint::RenderScene::RenderScene(glint::Scene)"]),
    ("render", ["glint::Integrator::render(glint::RenderScene const&"]),
    ("  camera samples and rays", ["glint::Integrator::start_camera_sample(", "glint::Camera::generate_rays("]),
    ("  closest hits, packets", ["glint::RenderScene::intersect_packet("]),
    ("  shadow rays, packets", ["glint::RenderScene::occluded_packet("]),
    ("  closest hits, single rays", ["glint::RenderScene::intersect(glint::Ray&, glint::Hit&)"]),
    ("  shadow rays, single rays", ["glint::RenderScene::occluded(glint::Ray const&"]),
    ("  surface interactions", ["glint::RenderScene::interaction(glint::Ray const&"]),
    ("write the image", ["glint::write_image("]),
]
LINE = re.compile(r"^\s*([\d,]+) \(\s*[\d.]+%\)\s+(.*)$")


def inclusive_counts(callgrind_out):
    """Largest inclusive count of each stage's functions: callgrind_annotate lists a function
    once per file its code came from ("file:function"), and the largest entry is the whole
    function. The name must follow the colon, so that lambdas and templates that merely
    mention it are not taken for it."""
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", callgrind_out],
                          check=True, capture_output=True, text=True).stdout
    total = 0
    best = {}
    for line in text.splitlines():
        m = LINE.match(line)
        if not m:
            continue
        count, name = int(m.group(1).replace(",", "")), m.group(2)
        if "PROGRAM TOTALS" in name:
            total = count
            continue
        for _, names in STAGES:
            for n in names:
                if ":" + n in name:
                    best[n] = max(best.get(n, 0), count)
    return total, best


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("glint")
    parser.add_argument("scene")
    parser.add_argument("--width", type=int)
    parser.add_argument("--height", type=int)
    parser.add_argument("more", nargs="*", help="further options for glint render")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="glint-callgrind-") as work:
        out = os.path.join(work, "callgrind.out")
        command = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", args.glint, "render", args.scene,
                   "-o", os.path.join(work, "image.png"), "--threads", "1"]
        if args.width:
            command += ["--width", str(args.width)]
        if args.height:
            command += ["--height", str(args.height)]
        run = subprocess.run(command + args.more, capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"glint under valgrind failed:\n{run.stderr[-2000:]}")
        final = re.search(r"(\d+)x(\d+), (\d+) spp", run.stdout)
        if not final:
            sys.exit(f"no 'WxH, N spp' line in glint's output:\n{run.stdout}")
        samples = int(final.group(1)) * int(final.group(2)) * int(final.group(3))
        total, best = inclusive_counts(out)
    print(f"{args.scene}: {final.group(0)}, {samples:,} camera samples, {total / 1e6:,.0f} M instructions in all")
    print("| stage | M instructions | per sample | share of the process |")
    print("|---|---:|---:|---:|")
    render = sum(best.get(n, 0) for n in dict(STAGES)["render"])
    listed = 0
    for stage, names in STAGES:
        count = sum(best.get(n, 0) for n in names)
        if stage.startswith("  "):
            listed += count
        print(f"| {stage} | {count / 1e6:,.1f} | {count / samples:,.0f} | {100 * count / total:.1f} % |")
        if stage == "  surface interactions":
            rest = render - listed
            print(f"|   shading and the rest | {rest / 1e6:,.1f} | {rest / samples:,.0f} "
                  f"| {100 * rest / total:.1f} % |")


if __name__ == "__main__":
    main()
