"""Restores the sharp edges and corners that grid-based machining simulation (tri-dexel, voxel,
Z-map) turns into thin chamfer bands when it meshes a workpiece, on numpy arrays.

    import resharp
    V, F = resharp.read_mesh("part.stl")           # welded: (#V, 3) float64, (#F, 3) int32
    r = resharp.restore(V, F, region_angle=6.0)    # every option of `resharp restore`
    resharp.write_mesh("restored.stl", r.vertices, r.faces)
    print(r.report["restoration"]["edge_points_inserted"])

restore() releases the GIL while it works, so other Python threads run meanwhile. Errors are
resharp.Error subclasses: InvalidInput (a ValueError: bad array, option or mesh), ReadError and
WriteError (OSErrors, with the file in `path`) and ParseError (a malformed file: `path`, and
`line` or `byte`).
"""

import inspect as _inspect
import json as _json
import textwrap as _textwrap
from dataclasses import dataclass as _dataclass
from typing import Optional as _Optional

import numpy as _np

from . import _resharp
from ._resharp import Error, InvalidInput, ParseError, ReadError, WriteError, __version__

__all__ = [
    "restore", "read_mesh", "write_mesh", "RestoreResult", "Segmentation",
    "Error", "InvalidInput", "ReadError", "ParseError", "WriteError", "KEYWORDS",
]


@_dataclass(frozen=True)
class Segmentation:
    """What was detected, on the input mesh (the welded one with weld=True); -1 is no patch."""

    is_edge_vertex: _np.ndarray  #: (#V,) bool: edge vertices of the edge-based segmentation
    #: (#V,) int32: feature patch of each vertex, or -1 (a near-surface mesh's: the patches its
    #: moved mesh was restored with, a vertex moved onto another patch's face in that patch)
    vertex_patch: _np.ndarray
    face_patch: _np.ndarray      #: (#F,) int32: feature patch of each face, -1 in the bands
    face_role: _np.ndarray       #: (#F,) uint8: 0 untouched, 1 edge triangle, 2 corner triangle


@_dataclass(frozen=True)
class RestoreResult:
    """What restore() gives back. The arrays are resharp's own memory, handed over uncopied."""

    #: (#V', 3) float64: the input vertices first and in order (the welded ones with
    #: weld=True), then the points inserted on sharp edges and corners: row i < #V is input
    #: vertex i. Input vertices keep their positions, except on a near-surface mesh
    #: (report["vertices"]), where some move within their grid cell or along their grid edge.
    vertices: _np.ndarray
    #: (#F', 3) int32: the input faces in order, each unchanged or replaced in place by its
    #: pieces (exact duplicate faces removed unless keep_duplicate_faces=True).
    faces: _np.ndarray
    #: (#F',) int32: for each output face, the input face (row of `faces` given) it was cut from.
    source_face: _np.ndarray
    #: With weld=True, (#V,) int32: for each row of the vertices given, the row of `vertices`
    #: it was welded into (-1 for a vertex no face uses); None otherwise.
    welded_vertex: _Optional[_np.ndarray]
    #: Every count and stage time, under the keys of `resharp restore --report`'s JSON.
    report: dict
    #: With segmentation=True, what was detected; None otherwise.
    segmentation: _Optional[Segmentation]


#: restore()'s keywords: name -> dict(default, type, choices, help), in the order of
#: `resharp restore --help` after the module's own weld and segmentation.
KEYWORDS = {entry.pop("name"): entry for entry in _resharp.keywords()}


def restore(vertices, faces, **options):
    r = _resharp.restore(vertices, faces, **options)
    labels = r["segmentation"]
    return RestoreResult(
        vertices=r["vertices"],
        faces=r["faces"],
        source_face=r["source_face"],
        welded_vertex=r["welded_vertex"],
        report=_json.loads(r["report"]),
        segmentation=Segmentation(**labels) if labels is not None else None,
    )


def _keyword_doc(name, entry):
    kind = entry["type"]
    if entry["choices"] is not None:
        kind = " | ".join(repr(choice) for choice in entry["choices"])
    return _textwrap.fill(f"{name} ({kind}, default {entry['default']!r}): {entry['help']}.",
                          width=96, initial_indent="    ", subsequent_indent="        ",
                          break_on_hyphens=False, break_long_words=False)


restore.__signature__ = _inspect.Signature(
    [_inspect.Parameter("vertices", _inspect.Parameter.POSITIONAL_OR_KEYWORD),
     _inspect.Parameter("faces", _inspect.Parameter.POSITIONAL_OR_KEYWORD)]
    + [_inspect.Parameter(name, _inspect.Parameter.KEYWORD_ONLY, default=entry["default"])
       for name, entry in KEYWORDS.items()],
    return_annotation=RestoreResult)
restore.__doc__ = """Restores the sharp edges and corners of a mesh made by grid-based machining
simulation (paper sections 3-5), without moving an input vertex unless vertices='near' or
'midpoint' (measured with the default 'auto'): then within their grid cells (issue 14).

    vertices: (#V, 3) float32 or float64 numpy array, any memory layout (read once).
    faces: (#F, 3) int32, int64, uint32 or uint64 numpy array of indices into vertices,
        counter-clockwise seen from outside.

Returns a RestoreResult (vertices, faces, source_face, welded_vertex, report, segmentation).
Ctrl-C stops it between two stages and raises KeyboardInterrupt.
Raises InvalidInput (a ValueError) naming the array and element for a wrong shape or dtype,
a NaN or infinite coordinate or an index out of range, and naming the option for a value
out of range; TypeError for an unknown keyword or a value of the wrong type.

Keywords (the options of `resharp restore`, '_' for '-', with the library's defaults; a flag
of the command line is a bool here, True meaning given):
""" + "\n".join(_keyword_doc(name, entry) for name, entry in KEYWORDS.items())


def read_mesh(path, weld=True):
    """Reads a mesh file (STL binary or ASCII, OBJ, PLY, OFF, by extension) as numpy arrays
    (vertices (#V, 3) float64, faces (#F, 3) int32), welded as the command line welds it;
    weld=False gives the file's points as they are (STL: three per triangle).
    Raises ReadError or ParseError naming the file and the line or byte."""
    return _resharp.read_mesh(path, weld)


def write_mesh(path, vertices, faces, *, ascii=False):
    """Writes the mesh to `path` in the format its extension names (STL and PLY binary unless
    ascii=True), atomically: on failure no file is created and an existing one is unchanged.
    Raises InvalidInput for bad arrays (as restore() does), WriteError naming the file."""
    _resharp.write_mesh(path, vertices, faces, ascii=ascii)
