"""resharp.restore() on numpy arrays: what it gives back, in which dtypes, and that every
accepted layout and dtype of the same mesh gives the same result."""

import gc

import numpy as np
import pytest

import resharp
from conftest import EXAMPLE


def same(a, b):
    return (np.array_equal(a.vertices, b.vertices) and np.array_equal(a.faces, b.faces)
            and np.array_equal(a.source_face, b.source_face))


@pytest.fixture(scope="module")
def restored(example):
    V, F = example
    return resharp.restore(V, F, segmentation=True)


def test_restores_the_example_without_moving_an_input_vertex(example, restored):
    V, F = example
    r = restored
    inserted = r.report["restoration"]
    assert inserted["edge_points_inserted"] > 2000
    assert len(r.vertices) == len(V) + inserted["edge_points_inserted"] + \
        inserted["corner_points_inserted"]
    assert np.array_equal(r.vertices[:len(V)], V)
    assert r.report["output"] == {"vertices": len(r.vertices), "triangles": len(r.faces)}
    assert r.report["input"]["triangles"] == len(F)


def test_output_arrays_are_typed_and_shaped_as_documented(example, restored):
    r = restored
    assert r.vertices.dtype == np.float64 and r.vertices.shape[1] == 3
    assert r.faces.dtype == np.int32 and r.faces.shape[1] == 3
    assert r.source_face.dtype == np.int32 and r.source_face.shape == (len(r.faces),)
    assert r.faces.min() >= 0 and r.faces.max() < len(r.vertices)
    # Faces stay in input order, each replaced in place by its pieces.
    assert np.all(np.diff(r.source_face) >= 0)
    assert r.source_face[0] == 0 and r.source_face[-1] == len(example[1]) - 1


def test_output_arrays_are_resharps_memory_handed_over(restored):
    for array in (restored.vertices, restored.faces, restored.source_face):
        assert not array.flags.owndata and array.base is not None  # no copy was made
        assert array.flags.c_contiguous and array.flags.writeable


def test_output_outlives_the_result():
    V, F = resharp.read_mesh(EXAMPLE)
    r = resharp.restore(V, F)
    vertices, expected = r.vertices, r.vertices.copy()
    del r
    gc.collect()
    assert np.array_equal(vertices, expected)


def test_segmentation_labels_match_the_report(example, restored):
    V, F = example
    s = restored.segmentation
    assert s.is_edge_vertex.dtype == np.bool_ and s.is_edge_vertex.shape == (len(V),)
    assert s.vertex_patch.dtype == np.int32 and s.vertex_patch.shape == (len(V),)
    assert s.face_patch.dtype == np.int32 and s.face_patch.shape == (len(F),)
    assert s.face_role.dtype == np.uint8 and s.face_role.shape == (len(F),)
    report = restored.report
    assert s.is_edge_vertex.sum() == report["edge_segmentation"]["edge_vertices"]
    assert np.count_nonzero(s.face_role == 1) == report["classification"]["edge_triangles"]
    assert np.count_nonzero(s.face_role == 2) == report["classification"]["corner_triangles"]
    patches = report["feature_segmentation"]["feature_patches"]
    assert s.face_patch.max() == patches - 1
    # The faces of chamfer bands carry no patch, and each is an edge or corner triangle.
    in_bands = s.face_patch == -1
    assert in_bands.sum() > 1000 and np.all(s.face_role[in_bands] != 0)


def test_no_segmentation_unless_asked(example):
    assert resharp.restore(*example).segmentation is None


def test_float32_vertices_read_as_their_float64_values(example):
    V, F = example
    V32 = (V * 1.1).astype(np.float32)
    assert same(resharp.restore(V32, F), resharp.restore(V32.astype(np.float64), F))


@pytest.mark.parametrize("dtype", [np.int64, np.uint32, np.uint64])
def test_every_index_dtype_gives_the_same_result(example, restored, dtype):
    V, F = example
    assert same(resharp.restore(V, F.astype(dtype)), restored)


def test_any_memory_layout_gives_the_same_result(example, restored):
    V, F = example
    wide = np.zeros((len(V), 5))
    wide[:, 1:4] = V
    assert not wide[:, 1:4].flags.c_contiguous
    assert same(resharp.restore(wide[:, 1:4], np.asfortranarray(F)), restored)


def test_restored_arrays_go_back_in(restored):
    again = resharp.restore(restored.vertices, restored.faces)
    assert np.array_equal(again.vertices[:len(restored.vertices)], restored.vertices)


def test_weld_makes_a_soup_the_welded_mesh(example, restored):
    points, soup = resharp.read_mesh(EXAMPLE, weld=False)
    assert len(points) == 3 * len(soup) and len(points) > len(example[0])
    assert same(resharp.restore(points, soup, weld=True), restored)
    # Unwelded, every triangle is on its own: nothing to restore.
    alone = resharp.restore(points, soup)
    assert alone.report["restoration"]["edge_points_inserted"] == 0


def test_thread_count_does_not_change_the_output(example, restored):
    assert same(resharp.restore(*example, threads=1), restored)
    assert same(resharp.restore(*example, threads=2), restored)


def test_options_reach_the_library(example, restored):
    assert restored.report["restoration"]["corner_points_inserted"] > 0
    strict = resharp.restore(*example, spike_angle=1.0)
    assert strict.report["restoration"]["corner_points_inserted"] == 0


def test_flags_reach_the_library(example):
    V, F = example
    doubled = np.concatenate([F, F[:1]])
    assert resharp.restore(V, doubled).report["mesh_repair"]["duplicate_faces_removed"] == 1
    kept = resharp.restore(V, doubled, keep_duplicate_faces=True)
    assert kept.report["mesh_repair"]["duplicate_faces_removed"] == 0


def test_paper_applies_the_papers_choices(example, restored):
    paper = resharp.restore(*example, paper=True)
    assert same(paper, resharp.restore(*example, curvature_feature="signed", normals="angle-weighted",
                                       curved_region_faces=0, merge_over_sharp_borders=True,
                                       unconfirmed_border_angle=180.0, smooth_border_angle=0.0))
    assert not same(paper, restored)


def test_weld_map_points_each_given_vertex_at_its_welded_row(example):
    V, F = example
    used = V[F.reshape(-1)]  # a soup: three points per triangle, then one no face uses
    points = np.concatenate([used, [[1e3, 1e3, 1e3]]])
    soup = np.arange(len(used), dtype=np.int32).reshape(-1, 3)
    r = resharp.restore(points, soup, weld=True)
    assert r.welded_vertex.shape == (len(points),) and r.welded_vertex.dtype == np.int32
    assert np.array_equal(r.vertices[r.welded_vertex[:-1]], used)
    assert r.welded_vertex[-1] == -1
    assert resharp.restore(V, F).welded_vertex is None
