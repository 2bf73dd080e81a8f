#!/usr/bin/env python3
"""Writes the hostile mesh files of tests/data/bad/ and MANIFEST.tsv, which says for each file
the exception read_mesh must throw ("parse": ParseError, "read": ReadError), the location in
its message ("line N", "byte N", or "-") and a substring of the reason.

Run from anywhere: python3 tests/data/bad/make_bad_files.py. Python 3 standard library only.
The generated files are committed; rerunning must reproduce them byte for byte."""

import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
FILES = {}     # name -> bytes
MANIFEST = []  # (name, kind, location, reason)


def bad(name, data, kind, location, reason):
    if isinstance(data, str):
        data = data.encode("latin-1")
    if data is not None:
        FILES[name] = data
    MANIFEST.append((name, kind, location, reason))


# ---------------------------------------------------------------- STL
TRI = (0, 0, 0, 1, 0, 0, 0, 1, 0)


def stl_record(coords=TRI):
    return struct.pack("<3f", 0, 0, 1) + struct.pack("<9f", *coords) + b"\0\0"


def binary_stl(count, records, header=b"binary STL"):
    return header.ljust(80, b"\0") + struct.pack("<I", count) + b"".join(records)


FACET = "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n"

bad("stl_empty.stl", b"", "parse", "byte 0", "file is empty")
bad("stl_truncated_header.stl", b"\x01" * 40, "parse", "byte 0", "file truncated")
bad("stl_binary_truncated.stl", binary_stl(2, [stl_record()]), "parse", "byte 80",
    "header promises 2 triangles (100 bytes) but only 50 bytes follow")
bad("stl_binary_count_huge.stl", binary_stl(0xFFFFFFFF, [stl_record()]), "parse", "byte 80",
    "header promises 4294967295 triangles")
bad("stl_binary_zero_triangles.stl", binary_stl(0, []), "parse", "byte 80",
    "binary STL holds no triangles")
bad("stl_binary_trailing_bytes.stl", binary_stl(1, [stl_record()]) + b"garbage", "parse",
    "byte 134", "7 unexpected bytes after the last of 1 triangles")
bad("stl_binary_nan.stl", binary_stl(1, [stl_record((float("nan"),) + TRI[1:])]), "parse",
    "byte 96", "NaN or infinite")
bad("stl_binary_inf.stl",
    binary_stl(2, [stl_record(), stl_record(TRI[:8] + (float("inf"),))]), "parse",
    "byte 178", "vertex coordinate of triangle 1 is NaN or infinite")
bad("stl_solid_header_truncated.stl",
    binary_stl(3, [stl_record(), stl_record()], header=b"solid from a CAD exporter"), "parse",
    "byte 80", "header promises 3 triangles")
bad("stl_ascii_nan.stl", "solid x\n" + FACET.replace("vertex 1 0 0", "vertex 1 nan 0") +
    "endsolid x\n", "parse", "line 5", "NaN or infinite")
bad("stl_ascii_four_vertices.stl", "solid x\n" + FACET.replace(" endloop", "  vertex 1 1 0\n endloop") +
    "endsolid x\n", "parse", "line 7", "more than 3 vertices")
bad("stl_ascii_two_vertices.stl", "solid x\n" + FACET.replace("  vertex 0 1 0\n", "") +
    "endsolid x\n", "parse", "line 6", "facet has 2 vertices")
bad("stl_ascii_garbage_number.stl", "solid x\n" + FACET.replace("vertex 0 1 0", "vertex 0 1 abc") +
    "endsolid x\n", "parse", "line 6", "expected a number for vertex coordinate, found 'abc'")
bad("stl_ascii_truncated.stl", "solid x\n" + FACET[:58], "parse", "line 5",
    "missing vertex coordinate (unexpected end of file)")
bad("stl_ascii_no_endsolid.stl", "solid x\n" + FACET, "parse", "line 8", "missing 'endsolid'")
bad("stl_ascii_no_facets.stl", "solid x\nendsolid x\n", "parse", "line 2",
    "ASCII STL holds no triangles")
bad("stl_ascii_overflow.stl", "solid x\n" + FACET.replace("vertex 1 0 0", "vertex 1e999 0 0") +
    "endsolid x\n", "parse", "line 5", "vertex coordinate out of range")

# ---------------------------------------------------------------- OBJ
SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"

bad("obj_empty.obj", "", "parse", "line 1", "file is empty")
bad("obj_index_zero.obj", SQUARE + "f 0 1 2\n", "parse", "line 5", "vertex index 0")
bad("obj_index_out_of_range.obj", SQUARE + "f 1 2 9\n", "parse", "line 5",
    "vertex index 9 out of range (4 vertices defined so far)")
bad("obj_negative_out_of_range.obj", SQUARE + "f -1 -2 -5\n", "parse", "line 5",
    "vertex index -5 out of range")
bad("obj_forward_reference.obj", "f 1 2 3\n" + SQUARE, "parse", "line 1",
    "vertex index 1 out of range (0 vertices defined so far)")
bad("obj_garbage_index.obj", SQUARE + "f 1 2 three\n", "parse", "line 5",
    "expected an integer for vertex index, found 'three'")
bad("obj_bad_slashes.obj", SQUARE + "f 1/1/1 2// 3\n", "parse", "line 5",
    "malformed face corner '2//'")
bad("obj_unknown_record.obj", SQUARE + "vx 1 2 3\nf 1 2 3\n", "parse", "line 5",
    "unknown OBJ record 'vx'")
bad("obj_two_corner_face.obj", SQUARE + "f 1 2\n", "parse", "line 5", "face has 2 corners")
bad("obj_nan_vertex.obj", "v 0 0 0\nv NaN 0 0\nv 0 1 0\nf 1 2 3\n", "parse", "line 2",
    "NaN or infinite")
bad("obj_short_vertex.obj", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", "parse", "line 2",
    "missing vertex coordinate")
bad("obj_no_faces.obj", SQUARE, "parse", "line 4", "OBJ holds no faces")
bad("obj_binary_garbage.obj", b"\x00\x01\x02\xff v f\n", "parse", "line 1",
    "unknown OBJ record '????'")
bad("obj_huge_index.obj", SQUARE + "f 1 2 99999999999999999999999\n", "parse", "line 5",
    "vertex index out of range")

# ---------------------------------------------------------------- PLY
VERTS3 = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
FACES1 = "element face 1\nproperty list uchar int vertex_indices\n"


def ply_binary(elements, body, fmt="binary_little_endian"):
    header = ("ply\nformat %s 1.0\n%send_header\n" % (fmt, elements)).encode()
    return header, header + body


def verts_le(xs=(0.0, 1.0, 0.0)):
    return b"".join(struct.pack("<3f", x, float(i == 2), 0.0) for i, x in enumerate(xs))


ASCII_PLY = ("ply\nformat ascii 1.0\n" + VERTS3 + FACES1 +
             "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")  # body starts on line 10

bad("ply_empty.ply", "", "parse", "line 1", "file is empty")
bad("ply_bad_magic.ply", "plyx\nformat ascii 1.0\nend_header\n", "parse", "line 1",
    "not a PLY file")
bad("ply_bad_format.ply", ASCII_PLY.replace("ascii", "binary"), "parse", "line 2",
    "unknown PLY format 'binary'")
bad("ply_no_end_header.ply", "ply\nformat ascii 1.0\n" + VERTS3, "parse", "line 6",
    "missing 'end_header'")
bad("ply_unknown_type.ply", ASCII_PLY.replace("property float y", "property real y"), "parse",
    "line 5", "unknown PLY type 'real'")
bad("ply_no_z.ply", ASCII_PLY.replace("property float z\n", ""), "parse", "line 8",
    "vertex element has no scalar 'z' property")
bad("ply_no_face_element.ply", "ply\nformat ascii 1.0\n" + VERTS3 + "end_header\n0 0 0\n",
    "parse", "line 7", "header declares no 'face' element")
bad("ply_count_exceeds_file.ply",
    ply_binary(VERTS3.replace("vertex 3", "vertex 1000000000") + FACES1, verts_le())[1],
    "parse", "line 3", "element 'vertex' promises 1000000000 rows of at least 12 bytes")
bad("ply_ascii_count_exceeds_file.ply", ASCII_PLY.replace("face 1", "face 1000000000000000"),
    "parse", "line 7", "element 'face' promises 1000000000000000 rows")
header, data = ply_binary(VERTS3 + FACES1.replace("uchar", "uint"),
                          verts_le() + struct.pack("<I3i", 0xFFFFFFFF, 0, 1, 2))
bad("ply_list_count_overflow.ply", data, "parse", "byte %d" % (len(header) + 36 + 4 + 12),
    "file truncated")
header, data = ply_binary(VERTS3 + FACES1.replace("uchar", "int"),
                          verts_le() + struct.pack("<i3i", -3, 0, 1, 2))
bad("ply_negative_list_count.ply", data, "parse", "byte %d" % (len(header) + 36),
    "negative length of list 'vertex_indices'")
bad("ply_two_corner_face.ply", ASCII_PLY.replace("3 0 1 2", "2 0 1 1"), "parse", "line 13",
    "face has 2 corners")
header, data = ply_binary(VERTS3 + FACES1, verts_le() + struct.pack("<B3i", 3, 0, 1, 7))
bad("ply_index_out_of_range.ply", data, "parse", "byte %d" % (len(header) + 36 + 1 + 8),
    "vertex index 7 out of range (3 vertices)")
header, data = ply_binary(VERTS3 + FACES1, verts_le() + struct.pack("<B3i", 3, 0, 1, 2))
bad("ply_truncated_body.ply", data[:-3], "parse", "byte %d" % (len(header) + 36 + 1 + 8),
    "file truncated")
bad("ply_trailing_bytes.ply", data + b"\0\0", "parse", "byte %d" % len(data),
    "2 unexpected bytes after the last element")
header, nan_data = ply_binary(VERTS3 + FACES1,
                              verts_le((0.0, float("nan"), 0.0)) + struct.pack("<B3i", 3, 0, 1, 2))
bad("ply_nan.ply", nan_data, "parse", "byte %d" % (len(header) + 12),
    "property 'x' is NaN or infinite")
be_verts = b"".join(struct.pack(">3f", float(i == 1), float(i == 2), 0.0) for i in range(3))
header, data = ply_binary(VERTS3 + FACES1, be_verts + struct.pack(">B3i", 3, 0, 1, 5),
                          fmt="binary_big_endian")
bad("ply_big_endian_bad_index.ply", data, "parse", "byte %d" % (len(header) + 36 + 1 + 8),
    "vertex index 5 out of range")
bad("ply_uchar_overflow.ply", ASCII_PLY.replace("3 0 1 2", "300 0 1 2"), "parse", "line 13",
    "value 300 of property 'vertex_indices' out of range for uchar")
header, data = ply_binary("element junk 1\nproperty list int double d\n" + VERTS3 + FACES1,
                          struct.pack("<i", 1 << 30) + verts_le() + struct.pack("<B3i", 3, 0, 1, 2))
bad("ply_skipped_list_overflow.ply", data, "parse", "byte %d" % (len(header) + 4),
    "list of 1073741824 values runs past the end of the file")
bad("ply_garbage_value.ply", ASCII_PLY.replace("1 0 0\n", "1 O 0\n"), "parse", "line 11",
    "expected a number for y, found 'O'")
bad("ply_missing_values.ply", ASCII_PLY.replace("3 0 1 2\n", "3 0 1\n"), "parse", "line 13",
    "missing value of property 'vertex_indices' (unexpected end of file)")

# ---------------------------------------------------------------- OFF
OFF_SQUARE = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"  # vertices on lines 3-6 after "OFF\n4 1 0\n"

bad("off_empty.off", "", "parse", "line 1", "file is empty")
bad("off_bad_header.off", "OFFX\n4 1 0\n" + OFF_SQUARE + "3 0 1 2\n", "parse", "line 1",
    "expected an 'OFF' header, found 'OFFX'")
bad("off_negative_count.off", "OFF\n-4 1 0\n" + OFF_SQUARE + "3 0 1 2\n", "parse", "line 2",
    "negative count")
bad("off_count_exceeds_file.off", "OFF\n4 100000000 0\n" + OFF_SQUARE + "3 0 1 2\n", "parse",
    "line 2", "more than the")
bad("off_too_few_numbers.off", "OFF\n4 1 0\n0 0 0\n1 0\n1 1 0\n0 1 0\n3 0 1 2\n", "parse",
    "line 4", "missing vertex coordinate")
bad("off_missing_counts.off", "OFF\n", "parse", "line 1",
    "missing vertex count (unexpected end of file)")
bad("off_face_too_few_indices.off", "OFF\n4 1 0\n" + OFF_SQUARE + "3 0 1\n", "parse", "line 7",
    "face lists 2 of its 3 vertex indices")
bad("off_index_out_of_range.off", "OFF\n4 1 0\n" + OFF_SQUARE + "3 0 1 4\n", "parse", "line 7",
    "vertex index 4 out of range (4 vertices)")
bad("off_two_corner_face.off", "OFF\n4 1 0\n" + OFF_SQUARE + "2 0 1\n", "parse", "line 7",
    "face has 2 corners")
bad("off_truncated_faces.off", "OFF\n4 2 0\n" + OFF_SQUARE + "3 0 1 2\n", "parse", "line 7",
    "file ends after 1 of 2 faces")
bad("off_nan.off", "OFF\n4 1 0\n0 0 0\n1 0 inf\n1 1 0\n0 1 0\n3 0 1 2\n", "parse", "line 4",
    "NaN or infinite")
bad("off_garbage_index.off", "OFF\n4 1 0\n" + OFF_SQUARE + "3 0 1 x\n", "parse", "line 7",
    "expected an integer for vertex index, found 'x'")
bad("off_trailing_data.off", "OFF\n4 1 0\n" + OFF_SQUARE + "3 0 1 2\nextra\n", "parse",
    "line 8", "unexpected data after the last face")
bad("off_no_faces.off", "OFF\n4 0 0\n" + OFF_SQUARE, "parse", "line 2", "OFF holds no faces")

# ---------------------------------------------------------------- not a mesh file at all
bad("unknown_extension.xyz", binary_stl(1, [stl_record()]), "read", "-",
    "unknown extension '.xyz'")
bad("no_extension", binary_stl(1, [stl_record()]), "read", "-", "no file extension")
bad("does_not_exist.stl", None, "read", "-", "no such file")


def main():
    for name, data in FILES.items():
        with open(os.path.join(HERE, name), "wb") as f:
            f.write(data)
    with open(os.path.join(HERE, "MANIFEST.tsv"), "w", newline="\n") as f:
        f.write("# file\texception\tlocation\treason (written by make_bad_files.py)\n")
        for row in MANIFEST:
            f.write("\t".join(row) + "\n")
    print("wrote %d files and MANIFEST.tsv" % len(FILES))


if __name__ == "__main__":
    main()
