"""Bad arrays are refused with one clear message naming the array (and the element), as
resharp.InvalidInput, a ValueError; nothing is written for them."""

import numpy as np
import pytest

import resharp
from conftest import quad_strip

V, F = quad_strip()


def refused(vertices, faces, match):
    with pytest.raises(resharp.InvalidInput, match=match) as caught:
        resharp.restore(vertices, faces)
    assert isinstance(caught.value, ValueError) and isinstance(caught.value, resharp.Error)
    return str(caught.value)


def test_the_strip_itself_is_accepted():
    r = resharp.restore(V, F)
    assert np.array_equal(r.vertices, V) and np.array_equal(r.faces, F)


@pytest.mark.parametrize("shape", [(10, 2), (10,), (10, 3, 1), (3, 10)])
def test_vertices_of_the_wrong_shape(shape):
    message = refused(np.zeros(shape), F, r"^vertices: expected a numpy array of shape \(#V, 3\)")
    assert message.endswith("got shape " + str(shape))


@pytest.mark.parametrize("shape", [(8, 4), (24,), (8, 3, 1)])
def test_faces_of_the_wrong_shape(shape):
    refused(V, np.zeros(shape, dtype=np.int32), r"^faces: expected a numpy array of shape \(#F, 3\)")


@pytest.mark.parametrize("dtype", [np.int64, np.int32, np.float16, np.complex128, np.bool_,
                                   object, ">f8"])
def test_vertices_of_the_wrong_dtype(dtype):
    message = refused(V.astype(dtype), F, r"^vertices: expected dtype float32 or float64, got ")
    assert message.endswith(str(np.dtype(dtype)))


@pytest.mark.parametrize("dtype", [np.float64, np.float32, np.int16, np.uint8, np.bool_, ">i4"])
def test_faces_of_the_wrong_dtype(dtype):
    refused(V, F.astype(dtype), r"^faces: expected dtype int32, int64, uint32 or uint64, got ")


@pytest.mark.parametrize("value", [[[0, 0, 0]], (1, 2, 3), "mesh", None, 3.0])
def test_vertices_that_are_not_an_array(value):
    message = refused(value, F, r"^vertices: expected a numpy array of shape \(#V, 3\), got ")
    assert message.endswith(type(value).__name__)


def test_faces_that_are_not_an_array():
    refused(V, F.tolist(), r"^faces: expected a numpy array of shape \(#F, 3\), got list$")


@pytest.mark.parametrize("value, shown", [(np.nan, "nan"), (np.inf, "inf"), (-np.inf, "-inf")])
def test_non_finite_coordinates_name_the_element(value, shown):
    bad = V.copy()
    bad[7, 2] = value
    refused(bad, F, rf"^vertices\[7, 2\] = {shown}: coordinates must be finite$")


def test_non_finite_float32_coordinates_name_the_element():
    bad = V.astype(np.float32)
    bad[3, 0] = np.nan
    refused(bad, F, r"^vertices\[3, 0\] = nan")


def test_an_unused_vertex_must_be_finite_too():
    bad = np.concatenate([V, [[np.nan, 0, 0]]])
    refused(bad, F, r"^vertices\[10, 0\] = nan")


@pytest.mark.parametrize("dtype", [np.int32, np.int64, np.uint32, np.uint64])
def test_an_index_past_the_vertices_names_the_element(dtype):
    bad = F.astype(dtype)
    bad[5, 1] = len(V)
    refused(V, bad, rf"^faces\[5, 1\] = 10: out of range for 10 vertices$")


@pytest.mark.parametrize("dtype", [np.int32, np.int64])
def test_a_negative_index_is_refused_not_counted_from_the_end(dtype):
    bad = F.astype(dtype)
    bad[0, 0] = -1
    refused(V, bad, r"^faces\[0, 0\] = -1: out of range for 10 vertices$")


def test_an_index_that_would_wrap_to_32_bits_is_refused():
    bad = F.astype(np.int64)
    bad[2, 2] = 2**32 + 1  # 1 once cut to 32 bits: it must not slip through as vertex 1
    refused(V, bad, rf"^faces\[2, 2\] = {2**32 + 1}: out of range")


def test_no_faces():
    refused(V, np.zeros((0, 3), dtype=np.int32), "no triangles")


def test_welding_checks_the_arrays_first():
    bad = F.copy()
    bad[1, 1] = 99
    with pytest.raises(resharp.InvalidInput, match=r"^faces\[1, 1\] = 99"):
        resharp.restore(V, bad, weld=True)


def test_write_mesh_refuses_bad_arrays_and_writes_nothing(tmp_path):
    bad = V.copy()
    bad[0, 0] = np.nan
    target = tmp_path / "out.stl"
    with pytest.raises(resharp.InvalidInput, match=r"^vertices\[0, 0\] = nan"):
        resharp.write_mesh(target, bad, F)
    with pytest.raises(resharp.InvalidInput, match=r"^faces: expected"):
        resharp.write_mesh(target, V, F[:, :2])
    assert list(tmp_path.iterdir()) == []
