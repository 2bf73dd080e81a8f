"""resharp.restore() gives what `resharp restore` gives, byte for byte: on the shipped example
with the defaults, and with each option set to another value than its default, through the
keyword and through the flag."""

import json

import pytest

import resharp
from conftest import EXAMPLE, SOURCE_DIR

OPTIONS = {name: entry for name, entry in resharp.KEYWORDS.items()
           if name not in ("weld", "segmentation")}


def without_times(report):
    return {key: value for key, value in report.items() if key != "time_seconds"}


def python_restore(path, **options):
    r = resharp.restore(*resharp.read_mesh(EXAMPLE), **options)
    resharp.write_mesh(path, r.vertices, r.faces)
    return r


@pytest.mark.parametrize("extension", ["stl", "ply"])
def test_same_bytes_and_report_as_the_cli(cli, tmp_path, extension):
    cli("restore", EXAMPLE, "-q", "-o", tmp_path / f"cli.{extension}",
        "--report", tmp_path / "cli.json")
    r = python_restore(tmp_path / f"py.{extension}")
    assert (tmp_path / f"py.{extension}").read_bytes() == \
        (tmp_path / f"cli.{extension}").read_bytes()
    cli_report = json.loads((tmp_path / "cli.json").read_text())
    assert without_times(r.report) == without_times(cli_report)
    assert r.report["time_seconds"].keys() == cli_report["time_seconds"].keys()


# A value other than the default for every option, and the mesh on which it changes the output
# or the report: the shipped example where it does, else tests/data/relief_hang.stl (simulator
# seams with duplicate faces, faces the harm check undoes).
BRACKET, RELIEF = EXAMPLE, SOURCE_DIR / "tests" / "data" / "relief_hang.stl"
OTHER_VALUES = {
    "paper": (True, BRACKET),
    "curvature_feature": ("signed", BRACKET),
    "normals": ("angle-weighted", BRACKET),
    "max_fit_correction": (1.0, BRACKET),
    "max_fit_residual": (1.0, BRACKET),
    "kmeans_tolerance": (1.0, BRACKET),
    "max_kmeans_iterations": (1, BRACKET),
    "bridge_walk": (1, BRACKET),
    "flat_spread": (5.0, BRACKET),
    "region_angle": (6.0, BRACKET),
    "tiny_patch": (12, BRACKET),
    "band_interior_fraction": (0.3, RELIEF),
    "merge_angle": (7.5, BRACKET),
    "curved_region_faces": (150, BRACKET),
    "merge_over_sharp_borders": (True, RELIEF),
    "unconfirmed_border_angle": (90.0, RELIEF),
    "smooth_border_angle": (30.0, RELIEF),
    "smooth_continuation_angle": (0.0, RELIEF),
    "placement": ("tangent-planes", BRACKET),
    "spike_angle": (75.0, BRACKET),
    "thin_angle": (60.0, RELIEF),
    "fold_angle": (100.0, BRACKET),
    "no_crossing_check": (True, RELIEF),
    "harm_rounds": (1, RELIEF),
    "keep_duplicate_faces": (True, RELIEF),
    "threads": (1, BRACKET),
    "vertex_placement": ("near", BRACKET),
    "grid": (0.5, BRACKET),
}
# Options that change neither: the thread count by design; the harm check's crossing test finds
# no crossing on either mesh (their reports' harm_check.crossing is 0), so skipping it changes
# nothing there.
# A grid alone bounds moves only, and the bracket (exact crossings) takes the exact path.
NO_EFFECT = {"threads", "no_crossing_check", "grid"}


@pytest.fixture(scope="module")
def defaults():
    """The default restoration of each mesh, by path."""
    return {path: resharp.restore(*resharp.read_mesh(path)) for path in (BRACKET, RELIEF)}


def test_every_option_has_another_value_to_try():
    assert OTHER_VALUES.keys() == OPTIONS.keys()


@pytest.mark.parametrize("name", OPTIONS)
def test_each_keyword_does_what_its_flag_does(cli, tmp_path, defaults, name):
    value, mesh = OTHER_VALUES[name]
    flag = ["--" + name.replace("_", "-")] + ([] if value is True else [str(value)])
    cli("restore", mesh, "-q", "-o", tmp_path / "cli.ply", "--report", tmp_path / "cli.json",
        *flag)
    r = resharp.restore(*resharp.read_mesh(mesh), **{name: value})
    resharp.write_mesh(tmp_path / "py.ply", r.vertices, r.faces)
    assert (tmp_path / "py.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    assert without_times(r.report) == without_times(json.loads((tmp_path / "cli.json").read_text()))
    default = defaults[mesh]
    changed = (r.faces.shape != default.faces.shape or not (r.faces == default.faces).all()
               or without_times(r.report) != without_times(default.report))
    assert changed == (name not in NO_EFFECT)
