"""restore()'s keywords are the options of `resharp restore --help`: the same names ('_' for
'-'), the same defaults and the same help text, so the two cannot drift apart; and the
signature and docstring show them."""

import inspect
import re

import numpy as np
import pytest

import resharp
from conftest import quad_strip

# The command line's own options, which are about files, batches and the run, not the method;
# --html only in builds with the viewer.
RUN_OPTIONS = {"help", "output", "report", "segments", "ascii", "quiet", "jobs", "recursive"}
VIEWER_OPTIONS = {"html"}
MODULE_KEYWORDS = {"weld", "segmentation"}


def words(text):
    return " ".join(text.split())


@pytest.fixture(scope="module")
def cli_options(cli):
    """`resharp restore --help` as {name: (default or None, help)} for the method's options,
    and the set of the other options' names."""
    text = cli("restore", "--help")
    before, method = text.split("\nMethod options:\n")
    method = method.split("\n\n")[0]
    options = {}
    # An entry: "  --name[,--alias][ TYPE][=default][{false}][ Excludes: ...]" then its help, on the same
    # line after two spaces or on the lines below.
    for entry in re.split(r"\n(?=  --)", method.strip("\n")):
        head = re.match(r"\s*--([a-z-]+)(?:,--[a-z-]+)?(?: (?:\{[^}]*\}|[A-Z]+\b))?(?:=(\S+))?"
                        r"(\{false\})?"
                        r"(?: Excludes:(?: --[a-z-]+)+)?", entry)
        assert head, entry
        options[head[1].replace("-", "_")] = (head[2], words(entry[head.end():]))
    others = {name.replace("-", "_") for name in re.findall(r"^\s+(?:-\w,)?--([a-z-]+)",
                                                            before, re.M)}
    return options, others


def test_the_keywords_are_the_method_options(cli_options):
    options, others = cli_options
    assert resharp.KEYWORDS.keys() - MODULE_KEYWORDS == options.keys()
    assert others - VIEWER_OPTIONS == RUN_OPTIONS


def test_every_default_is_the_command_lines(cli_options):
    options, _ = cli_options
    for name, (shown, _) in options.items():
        entry = resharp.KEYWORDS[name]
        default = entry["default"]
        if entry["type"] == "tuple":  # grid: none, inferred
            assert shown is None and default is None, name
        elif shown is None:  # a flag: not given
            assert entry["type"] == "bool" and default is False, name
        elif entry["type"] == "str":
            assert shown == default, name
        elif entry["type"] == "int":
            assert type(default) is int and int(shown) == default, name
        else:
            assert type(default) is float and float(shown) == default, name


def test_every_help_text_is_the_command_lines(cli_options):
    options, _ = cli_options
    for name, (_, help_text) in options.items():
        assert help_text == words(resharp.KEYWORDS[name]["help"]), name


def test_the_signature_shows_every_keyword_with_its_default():
    parameters = inspect.signature(resharp.restore).parameters
    assert list(parameters)[:2] == ["vertices", "faces"]
    shown = {name: p.default for name, p in parameters.items()
             if p.kind is inspect.Parameter.KEYWORD_ONLY}
    assert shown == {name: entry["default"] for name, entry in resharp.KEYWORDS.items()}


def test_the_docstring_explains_every_keyword():
    doc = words(resharp.restore.__doc__)
    for name, entry in resharp.KEYWORDS.items():
        assert f"{name} (" in doc and words(entry["help"]) in doc, name


def test_the_defaults_are_the_librarys():
    V, F = quad_strip()
    defaults = {name: entry["default"] for name, entry in resharp.KEYWORDS.items()}
    given = resharp.restore(V, F, **defaults)
    assert given.report["output"] == resharp.restore(V, F).report["output"]


def test_an_unknown_keyword_is_a_type_error():
    V, F = quad_strip()
    with pytest.raises(TypeError, match="unexpected keyword argument 'region_anlge'"):
        resharp.restore(V, F, region_anlge=6.0)


@pytest.mark.parametrize("name, value, expected", [
    ("region_angle", "6", "region_angle must be a number, got str"),
    ("region_angle", True, "region_angle must be a number, got bool"),
    ("tiny_patch", 2.5, "tiny_patch must be an int, got float"),
    ("keep_duplicate_faces", 1, "keep_duplicate_faces must be True or False, got int"),
    ("weld", "yes", "weld must be True or False, got str"),
    ("normals", 1, "normals must be a str, got int"),
])
def test_a_value_of_the_wrong_type_is_a_type_error(name, value, expected):
    V, F = quad_strip()
    with pytest.raises(TypeError, match=expected):
        resharp.restore(V, F, **{name: value})


@pytest.mark.parametrize("name, value, expected", [
    ("normals", "best", "normals must be one of 'fit', 'angle-weighted', got 'best'"),
    ("tiny_patch", -1, "tiny_patch must not be negative"),
    ("threads", 2**40, "threads is out of range"),
    ("harm_rounds", 0, "harm rounds must be at least 1"),
    ("spike_angle", 0.0, "spike angle must lie in"),
    ("region_angle", float("nan"), "region growing angle must lie in"),
])
def test_a_value_out_of_range_is_invalid_input(name, value, expected):
    V, F = quad_strip()
    with pytest.raises(resharp.InvalidInput, match=expected):
        resharp.restore(V, F, **{name: value})


def test_numpy_scalars_and_any_letter_case_are_accepted():
    V, F = quad_strip()
    resharp.restore(V, F, region_angle=np.float32(6), tiny_patch=np.int64(10),
                    keep_duplicate_faces=np.bool_(True), normals="Angle-Weighted")


def test_paper_excludes_the_choices_it_makes():
    V, F = quad_strip()
    with pytest.raises(resharp.InvalidInput, match="normals cannot be given with paper=True"):
        resharp.restore(V, F, paper=True, normals="fit")
    resharp.restore(V, F, paper=True, region_angle=6.0)  # not one of the paper's choices


def test_the_cli_refuses_paper_with_the_same_options(cli):
    message = cli("restore", "in.stl", "-o", "out.stl", "--paper", "--normals", "fit", expect=1)
    assert "--normals excludes --paper" in message
