"""resharp.read_mesh() and resharp.write_mesh(): round trips through every format, and every
hostile file of tests/data/bad refused with the exception, file and place its manifest names."""

import csv

import numpy as np
import pytest

import resharp
from conftest import BAD_FILES, EXAMPLE


def manifest():
    with open(BAD_FILES / "MANIFEST.tsv", newline="") as rows:
        return [row for row in csv.reader(rows, delimiter="\t") if not row[0].startswith("#")]


def test_reads_the_example_welded_and_as_a_soup(example):
    V, F = example
    assert V.dtype == np.float64 and F.dtype == np.int32
    assert len(F) == 39748 and F.max() == len(V) - 1
    points, soup = resharp.read_mesh(str(EXAMPLE), weld=False)
    assert len(points) == 3 * len(F) and np.array_equal(soup.ravel(), np.arange(len(points)))
    # The soup's points, looked up through the welded faces, are the same corners.
    assert np.array_equal(points.reshape(-1, 3, 3), V[F])


@pytest.mark.parametrize("name, ascii", [("m.stl", False), ("m.stl", True), ("m.ply", False),
                                         ("m.ply", True), ("m.obj", False), ("m.off", False)])
def test_round_trip_through_a_file(example, tmp_path, name, ascii):
    V, F = example
    resharp.write_mesh(tmp_path / name, V, F, ascii=ascii)
    V2, F2 = resharp.read_mesh(tmp_path / name)
    assert np.array_equal(V2, V) and np.array_equal(F2, F)


def test_restored_points_survive_a_ply_round_trip(example, tmp_path):
    r = resharp.restore(*example)
    resharp.write_mesh(tmp_path / "r.ply", r.vertices, r.faces)
    # Unwelded: as the file orders them (welding orders vertices by first use).
    V2, F2 = resharp.read_mesh(tmp_path / "r.ply", weld=False)
    assert np.array_equal(V2, r.vertices) and np.array_equal(F2, r.faces)


@pytest.mark.parametrize("name, kind, place, reason", manifest())
def test_a_hostile_file_is_refused_naming_file_and_place(name, kind, place, reason):
    path = BAD_FILES / name
    expected = resharp.ParseError if kind == "parse" else resharp.ReadError
    with pytest.raises(expected) as caught:
        resharp.read_mesh(path)
    error = caught.value
    assert isinstance(error, OSError) and str(path) in str(error) and reason in str(error)
    assert error.path == str(path)
    if kind == "parse":
        assert isinstance(error, ValueError)
        unit, number = place.split()
        assert (error.line, error.byte) == \
            ((int(number), None) if unit == "line" else (None, int(number)))
        assert f"{unit} {number}:" in str(error)


def test_a_file_that_cannot_be_written(example, tmp_path):
    V, F = example
    for target in (tmp_path / "missing" / "m.stl", tmp_path / "m.xyz"):
        with pytest.raises(resharp.WriteError) as caught:
            resharp.write_mesh(target, V, F)
        assert isinstance(caught.value, OSError) and caught.value.path == str(target)
    assert list(tmp_path.iterdir()) == []


def test_a_failed_write_leaves_an_existing_file_unchanged(example, tmp_path):
    V, F = example
    target = tmp_path / "m.stl"
    target.write_bytes(b"before")
    with pytest.raises(resharp.InvalidInput):
        resharp.write_mesh(target, V, F + len(V))
    assert target.read_bytes() == b"before"
