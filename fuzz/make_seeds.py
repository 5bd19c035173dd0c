#!/usr/bin/env python3
"""Seed corpora for the fuzz targets, one folder per target under OUT (default
build-fuzz/seeds): the example scenes (scenes/), the test data (tests/data), the bad-input
corpus (tests/bad_inputs), small hand-made files in every variant a loader knows (ASCII and
binary PLY/STL, OBJ with MTL, images in each format through oiiotool) and, when
../shared/data is beside the checkout, the small Khronos glTF samples with their buffers
embedded as data: URIs. Standard library only (oiiotool for the image seeds).

    fuzz/make_seeds.py [OUT]

The committed corpora (fuzz/corpus/) are these seeds after fuzzing, minimised with
libFuzzer's -merge=1; docs/robustness.md has the whole procedure.
"""
import base64
import json
import pathlib
import shutil
import struct
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
SHARED = ROOT.parent / "shared" / "data"
MAX_SEED_BYTES = 120_000  # larger files mutate slowly (a 400 KB GLB ran 3 inputs a second)


def put(out, target, name, data):
    folder = out / target
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_bytes(data if isinstance(data, bytes) else data.encode())


def copy_small(out, target, files):
    for f in sorted(files):
        if f.is_file() and f.stat().st_size <= MAX_SEED_BYTES:
            put(out, target, f"{f.parent.name}_{f.name}", f.read_bytes())


def toml_seeds(out):
    copy_small(out, "fuzz_toml_scene", ROOT.glob("scenes/*.toml"))
    copy_small(out, "fuzz_toml_scene", ROOT.glob("tests/bad_inputs/toml/*.toml"))


def embed_gltf(path):
    """The glTF JSON at `path` with its buffers (and images up to 64 KB) as data: URIs."""
    doc = json.loads(path.read_text())
    for buffer in doc.get("buffers", []):
        uri = buffer.get("uri", "")
        if uri and not uri.startswith("data:"):
            data = (path.parent / uri).read_bytes()
            buffer["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    for image in doc.get("images", []):
        uri = image.get("uri", "")
        if uri and not uri.startswith("data:"):
            data = (path.parent / uri).read_bytes()
            if len(data) <= 65536:
                mime = "image/png" if uri.endswith(".png") else "image/jpeg"
                image["uri"] = f"data:{mime};base64," + base64.b64encode(data).decode()
    return json.dumps(doc, indent=1)


def gltf_seeds(out):
    copy_small(out, "fuzz_gltf", ROOT.glob("tests/bad_inputs/gltf/*.gltf"))
    copy_small(out, "fuzz_gltf", ROOT.glob("tests/data/*.gltf"))  # animated_quads: node animations
    copy_small(out, "fuzz_glb", ROOT.glob("tests/bad_inputs/glb/*.glb"))
    if not SHARED.is_dir():
        print(f"make_seeds: {SHARED} not found: no Khronos glTF samples in the seeds")
        return
    for path in sorted(SHARED.glob("gltf/*/glTF/*.gltf")):
        text = embed_gltf(path)
        if len(text) <= MAX_SEED_BYTES:
            put(out, "fuzz_gltf", path.name, text)
    copy_small(out, "fuzz_glb", SHARED.glob("gltf/*/glTF-Binary/*.glb"))


CUBE_OBJ = """# a unit cube: quads, texture coordinates, normals, two groups and two materials
mtllib model.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 -1
vn 0 0 1
vn 0 -1 0
vn 0 1 0
vn -1 0 0
vn 1 0 0
g front
usemtl red
f 1/1/1 4/4/1 3/3/1 2/2/1
f 5/1/2 6/2/2 7/3/2 8/4/2
g rest
usemtl glass
f 1/1/3 2/2/3 6/3/3 5/4/3
f 4//4 8//4 7//4 3//4
f -8 -4 -1 -5
f 2 3 7 6
"""
CUBE_MTL = """newmtl red
Kd 0.8 0.1 0.1
Ks 0.2 0.2 0.2
Ns 32
Ke 0 0 0
map_Kd assets/kenney_prototype_orange_checker_1024.png
newmtl glass
Kd 0 0 0
Ks 1 1 1
Ni 1.5
d 0.1
Tr 0.9
illum 7
"""
SEPARATOR = "\n# ---- model.mtl ----\n"


def obj_seeds(out):
    target = "fuzz_obj_mtl"
    put(out, target, "cube.obj", CUBE_OBJ + SEPARATOR + CUBE_MTL)
    put(out, target, "cube_no_mtl.obj", CUBE_OBJ)
    put(out, target, "triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvc 1 0 0\nf 1 2 3\n")
    put(out, target, "vertex_colours.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nl 1 2\np 3\nf 1 2 3\n")
    for f in sorted(ROOT.glob("tests/bad_inputs/obj/*.obj")):
        text = f.read_text(errors="replace")
        mtl = f.with_suffix(".mtl")
        put(out, target, f.name, text + (SEPARATOR + mtl.read_text() if mtl.exists() else ""))


def ply_header(fmt, nv, nf, extra_vertex=""):
    return (f"ply\nformat {fmt} 1.0\ncomment seed\nelement vertex {nv}\n"
            f"property float x\nproperty float y\nproperty float z\n{extra_vertex}"
            f"element face {nf}\nproperty list uchar int vertex_indices\nend_header\n")


def ply_seeds(out):
    target = "fuzz_ply"
    copy_small(out, target, [ROOT / "tests/data/icosphere.ply"])
    copy_small(out, target, ROOT.glob("tests/bad_inputs/ply/*.ply"))
    verts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    extra = ("property float nx\nproperty float ny\nproperty float nz\n"
             "property uchar red\nproperty uchar green\nproperty uchar blue\n"
             "property float s\nproperty float t\n")
    ascii = ply_header("ascii", 4, 2, extra) + "".join(
        f"{x} {y} {z} 0 0 1 {255 * x} {255 * y} 128 {x} {y}\n" for x, y, z in verts) + "3 0 1 2\n4 0 2 3 0\n"
    put(out, target, "quad_ascii.ply", ascii)
    for fmt, endian in (("binary_little_endian", "<"), ("binary_big_endian", ">")):
        body = b"".join(struct.pack(endian + "3f3f3B2f", x, y, z, 0, 0, 1, 255 * x, 255 * y, 128, x, y)
                        for x, y, z in verts)
        body += struct.pack(endian + "B3i", 3, 0, 1, 2) + struct.pack(endian + "B3i", 3, 0, 2, 3)
        put(out, target, f"quad_{fmt}.ply", ply_header(fmt, 4, 2, extra).encode() + body)


def stl_seeds(out):
    target = "fuzz_stl"
    copy_small(out, target, ROOT.glob("tests/bad_inputs/stl/*.stl"))
    tris = [((0, 0, 1), [(0, 0, 0), (1, 0, 0), (0, 1, 0)]), ((1, 0, 0), [(0, 0, 0), (0, 1, 0), (0, 0, 1)])]
    text = "solid seed\n" + "".join(
        f"facet normal {n[0]} {n[1]} {n[2]}\n outer loop\n" + "".join(f"  vertex {x} {y} {z}\n" for x, y, z in v)
        + " endloop\nendfacet\n" for n, v in tris) + "endsolid seed\n"
    put(out, target, "two_ascii.stl", text)
    binary = b"seed binary stl".ljust(80, b" ") + struct.pack("<I", len(tris))
    for n, v in tris:
        binary += struct.pack("<3f", *n) + b"".join(struct.pack("<3f", *p) for p in v) + struct.pack("<H", 0)
    put(out, target, "two_binary.stl", binary)


# The fuzz target takes the extension from the first byte: index in its kExtensions list.
IMAGE_EXTENSIONS = [".png", ".jpg", ".exr", ".hdr", ".pfm", ".tga", ".bmp", ".tif", ".ppm", ".gif"]


def image_seeds(out):
    target = "fuzz_image"

    def put_image(name, path):
        prefix = bytes([IMAGE_EXTENSIONS.index(path.suffix)])
        put(out, target, name, prefix + path.read_bytes())

    for f in sorted(ROOT.glob("tests/bad_inputs/image/*")) + [ROOT / "tests/data/left_opaque_right_clear.png",
                                                             ROOT / "scenes/assets/kenney_prototype_orange_checker_1024.png"]:
        if f.suffix in IMAGE_EXTENSIONS and f.stat().st_size <= MAX_SEED_BYTES:
            put_image(f"{f.parent.name}_{f.name}", f)
    if not shutil.which("oiiotool"):
        print("make_seeds: oiiotool not found: no generated image seeds")
        return
    variants = {  # name: (extension, oiiotool arguments after the pattern)
        "rgb8.png": (".png", ["-d", "uint8"]), "rgba16.png": (".png", ["-d", "uint16"]),
        "grey.png": (".png", ["--ch", "R", "-d", "uint8"]), "rgb.jpg": (".jpg", []),
        "grey.jpg": (".jpg", ["--ch", "R"]), "progressive.jpg": (".jpg", ["--attrib:type=int", "jpeg:progressive", "1"]),
        "half.exr": (".exr", ["-d", "half"]), "float.exr": (".exr", ["-d", "float"]),
        "tiled_piz.exr": (".exr", ["-d", "half", "--tile", "8", "8", "--compression", "piz"]),
        "rgba_dwaa.exr": (".exr", ["-d", "half", "--compression", "dwaa"]),
        "crop_b44.exr": (".exr", ["-d", "half", "--compression", "b44", "--crop", "12x6+2+1"]),
        "rgb.hdr": (".hdr", []), "rgba.tga": (".tga", []),
        "rgb.bmp": (".bmp", []), "rgb16.tif": (".tif", ["-d", "uint16"]), "rgb.ppm": (".ppm", []),
    }
    # OpenImageIO 2.4 reads PFM but cannot write it: 4×2 RGB floats, bottom row first.
    pfm = b"PF\n4 2\n-1.0\n" + struct.pack("<24f", *[(i % 7) / 6.0 for i in range(24)])
    put(out, target, "rgb.pfm", bytes([IMAGE_EXTENSIONS.index(".pfm")]) + pfm)
    with tempfile.TemporaryDirectory() as tmp:
        for name, (ext, args) in variants.items():
            channels = "4" if "rgba" in name else "3"
            path = pathlib.Path(tmp) / ("seed" + ext)
            pattern = ["--pattern", "checker:width=4:height=4", "16x8", channels]
            subprocess.run(["oiiotool", *pattern, *args, "-o", str(path)], check=True)
            put_image(name, path)


def main():
    out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "build-fuzz" / "seeds"
    for step in (toml_seeds, gltf_seeds, obj_seeds, ply_seeds, stl_seeds, image_seeds):
        step(out)
    for folder in sorted(out.iterdir()):
        print(f"{folder.name}: {len(list(folder.iterdir()))} seeds")


if __name__ == "__main__":
    main()
