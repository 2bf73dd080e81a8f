#!/usr/bin/env python3
"""Restores a mesh file and its reorderings; prints the inserted points and faces of each.

    PYTHONPATH=build/python python3 bench/order_variants.py MESH [MESH ...]

The variants (docs/robustness.md, issue 12): faces shuffled, vertices renumbered, each face's
corners rotated, every face turned inside out. resharp promises the same restoration for each,
so every line of a mesh should read the same. One thread, default options; needs numpy and the
Python module.
"""

import sys

import numpy as np

import resharp


def variants(vertices, faces, rng):
    """(name, vertices, faces) of the mesh and of each reordering of it."""
    yield "as read", vertices, faces
    yield "faces shuffled", vertices, faces[rng.permutation(len(faces))]
    order = rng.permutation(len(vertices))
    new_index = np.empty(len(vertices), dtype=np.int64)
    new_index[order] = np.arange(len(vertices))
    yield "vertices renumbered", vertices[order], new_index[faces].astype(np.int32)
    yield "corners rotated", vertices, faces[:, [1, 2, 0]]
    yield "inside out", vertices, faces[:, [0, 2, 1]]


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    rng = np.random.default_rng(7)
    for path in sys.argv[1:]:
        vertices, faces = resharp.read_mesh(path)
        for name, v, f in variants(vertices, faces, rng):
            result = resharp.restore(v, f, threads=1)
            print(f"{path}: {name}: {len(result.vertices) - len(v)} points, "
                  f"{len(result.faces)} faces")


if __name__ == "__main__":
    main()
