#!/usr/bin/env python3
"""Writes the binary files of the bad-input corpus (standard library only).

The files are committed; run this only to change or regenerate them:
    python3 tests/bad_inputs/make_binary_inputs.py
Each is a few hundred bytes at most and broken in exactly one way (see expected.txt).
"""
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def write(rel, data):
    with open(os.path.join(HERE, rel), "wb") as f:
        f.write(data)


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def png(width, height, rows, colour_type=2):
    ihdr = struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)  # 8-bit RGB (2) or grey (0)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) + png_chunk(b"IDAT", zlib.compress(rows)) +
            png_chunk(b"IEND", b""))


# --- images (textures and environments) ---
good = png(4, 4, b"".join(b"\x00" + b"\x80\x40\x20" * 4 for _ in range(4)))
write("image/truncated.png", good[:45])  # signature, IHDR and half of the IDAT chunk
# 2^31-1 × 2^31-1 pixels claimed by a 60-byte file: must be refused, not allocated.
write("image/huge_dimensions.png", png(0x7FFFFFFF, 0x7FFFFFFF, b"\x00\x80\x40\x20"))
write("image/zero_width.png", png(0, 4, b"\x00"))
# A valid 2×2 grey image: fine as a texture, refused as a normal map (not RGB).
write("image/grey_2x2.png", png(2, 2, b"\x00\x80\x80" * 2, colour_type=0))
# OpenEXR: magic, version 2, then a header cut off inside the first attribute.
write("image/truncated.exr", b"\x76\x2f\x31\x01" + struct.pack("<I", 2) + b"channels\x00chlist\x00" +
      struct.pack("<I", 37) + b"B\x00")
# Radiance HDR with a header claiming 100000 × 100000 pixels and only a few bytes of data.
write("image/huge_dimensions.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n\x02\x02\x00")
# Readable Radiance HDR images (flat RGBE rows: stb reads rows narrower than 8 unencoded) of
# shapes that a named layout refuses: a square one as equirect, a 2:1 one as angmap.
def flat_hdr(width, height):
    return b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width) + b"\x80\x80\x80\x81" * (width * height)
write("image/square_4x4.hdr", flat_hdr(4, 4))
write("image/wide_4x2.hdr", flat_hdr(4, 2))

# --- STL ---
# Binary STL: 80-byte header, a count of 1000 triangles, and one 50-byte triangle.
tri = struct.pack("<12fH", 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0)
write("stl/truncated_binary.stl", b"\0" * 80 + struct.pack("<I", 1000) + tri)
# A count of 2^32-1: 214 GB of triangles claimed by a 134-byte file.
write("stl/huge_count.stl", b"\0" * 80 + struct.pack("<I", 0xFFFFFFFF) + tri)
write("stl/header_only.stl", b"\0" * 80)
# One triangle whose vertices are NaN.
nan = float("nan")
write("stl/nan_vertex.stl", b"\0" * 80 + struct.pack("<I", 1) +
      struct.pack("<12fH", 0, 0, 1, nan, nan, nan, nan, 0, 0, 0, nan, 0, 0))

# --- PLY binary ---
def ply_header(fmt, vertices, faces, extra=""):
    return ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
            "element face %d\nproperty list uchar int vertex_indices\n%send_header\n" %
            (fmt, vertices, faces, extra)).encode()


verts = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
face = struct.pack("<B3i", 3, 0, 1, 2)
write("ply/binary_truncated.ply", ply_header("binary_little_endian", 3, 1) + verts[:20])
write("ply/binary_counts_too_large.ply", ply_header("binary_little_endian", 3000000, 1000000) + verts + face)
write("ply/binary_index_out_of_range.ply",
      ply_header("binary_little_endian", 3, 1) + verts + struct.pack("<B3i", 3, 0, 1, 99999))
write("ply/binary_negative_index.ply",
      ply_header("binary_little_endian", 3, 1) + verts + struct.pack("<B3i", 3, 0, -5, 2))
write("ply/binary_huge_list.ply",
      ply_header("binary_little_endian", 3, 1) + verts + struct.pack("<B3i", 255, 0, 1, 2))
write("ply/binary_big_endian_truncated.ply", ply_header("binary_big_endian", 3, 1) + struct.pack(">5f", 0, 0, 0, 1, 0))

# --- GLB ---
def glb(json_doc, bin_chunk=None, total=None, json_len=None, magic=b"glTF", version=2):
    j = json.dumps(json_doc, separators=(",", ":")).encode()
    j += b" " * (-len(j) % 4)
    body = struct.pack("<I4s", len(j) if json_len is None else json_len, b"JSON") + j
    if bin_chunk is not None:
        b = bin_chunk + b"\0" * (-len(bin_chunk) % 4)
        body += struct.pack("<I4s", len(b), b"BIN\0") + b
    length = 12 + len(body) if total is None else total
    return magic + struct.pack("<II", version, length) + body


tri_bin = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)


def tri_doc(count=3, byte_length=36, buffer_length=36, offset=0):
    return {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": buffer_length}],
        "bufferViews": [{"buffer": 0, "byteLength": byte_length}],
        "accessors": [{"bufferView": 0, "byteOffset": offset, "componentType": 5126, "count": count, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}],
    }


write("glb/bad_magic.glb", glb(tri_doc(), tri_bin, magic=b"glTf"))
write("glb/truncated_header.glb", b"glTF\x02\x00\x00")
write("glb/truncated_body.glb", glb(tri_doc(), tri_bin)[:60])
write("glb/length_past_end.glb", glb(tri_doc(), tri_bin, total=4096))
write("glb/json_chunk_length_past_end.glb", glb(tri_doc(), tri_bin, json_len=0x7FFFFFF0))
write("glb/version1.glb", glb(tri_doc(), tri_bin, version=1))
write("glb/bin_chunk_short.glb", glb(tri_doc(buffer_length=360, byte_length=360), tri_bin))
write("glb/accessor_count_overflow.glb", glb(tri_doc(count=0x7FFFFFFF), tri_bin))
write("glb/empty_json_chunk.glb", b"glTF" + struct.pack("<II", 2, 20) + struct.pack("<I4s", 0, b"JSON"))
