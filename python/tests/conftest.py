"""Shared fixtures. CTest sets RESHARP_CLI (the `resharp` executable) and RESHARP_SOURCE_DIR;
run by hand, PYTHONPATH=<build>/python and RESHARP_CLI=<build>/resharp are needed."""

import os
import pathlib
import subprocess

import numpy as np
import pytest

import resharp

SOURCE_DIR = pathlib.Path(
    os.environ.get("RESHARP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
EXAMPLE = SOURCE_DIR / "examples" / "bracket.stl"
BAD_FILES = SOURCE_DIR / "tests" / "data" / "bad"


@pytest.fixture(scope="session")
def example():
    """The shipped example, welded: (V float64, F int32)."""
    return resharp.read_mesh(EXAMPLE)


@pytest.fixture(scope="session")
def cli():
    """Runs `resharp ARGS...` and gives its stdout, failing the test unless it exits with
    `expect` (0 by default)."""
    path = os.environ.get("RESHARP_CLI")
    assert path, "RESHARP_CLI must name the resharp executable"

    def run(*args, expect=0):
        done = subprocess.run([path, *map(str, args)], capture_output=True, text=True)
        assert done.returncode == expect, done.stderr
        return done.stdout if expect == 0 else done.stderr

    return run


def quad_strip(columns=4):
    """A flat strip of 2 * columns triangles in z = 0, welded: (V float64, F int32)."""
    xs = np.arange(columns + 1, dtype=np.float64)
    vertices = np.concatenate([np.stack([xs, np.zeros_like(xs), np.zeros_like(xs)], 1),
                               np.stack([xs, np.ones_like(xs), np.zeros_like(xs)], 1)])
    faces = []
    for i in range(columns):
        a, b, c, d = i, i + 1, columns + 1 + i, columns + 2 + i
        faces += [[a, b, d], [a, d, c]]
    return vertices, np.array(faces, dtype=np.int32)
