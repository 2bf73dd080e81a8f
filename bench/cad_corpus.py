#!/usr/bin/env python3
"""Measures resharp on the CAD corpus (examples/cad/*.json) and writes its section of docs/results.md.

    python3 bench/cad_corpus.py [--build build] [--scratch /tmp/resharp-cad] [--cells 50 100 200]
                                [--parts NAME ...] [--raw FILE] [--from-raw FILE]

Each part is sampled as it is and turned off the grid axes (ROTATION, about the origin) at each
number of cells along its bounding box's longest side (`resharp simulate --solid --cells`),
restored by `resharp restore` with default options, and scored against its exact solid by
`resharp evaluate --solid` (the "cad" block: distances in bounding-box diagonals, Edge F-score at
tau = 0.1 % of the diagonal, sharp edges by a 30 degree dihedral). Only the section between the
CAD-corpus markers of the page is rewritten (appended if the page has none). Python 3 stdlib
only; offline; every number in the section comes from these runs.
"""

import argparse
import datetime
import glob
import json
import math
import os
import sys

from results import CAD_BEGIN, CAD_END, git_head, load, machine, run, write_section

ROTATION = {"axis": [2, -1, 3], "degrees": 27}
# Parts whose every face is a plane: the CTest subset (tests/cli) checks these are not made worse.
PLANE_ONLY = ["stepped_block", "chamfered_block", "hex_prism"]
# (key, label, higher is better)
MEASURES = [("chamfer", "Chamfer", False), ("hausdorff", "Hausdorff", False),
            ("normal_consistency", "normal consistency", True),
            ("edge_chamfer_distance", "ECD", False), ("edge_f1", "Edge F-score", True)]


def solid_file(root, scratch, part, rotated):
    """The part's solid file, or a copy of it turned off the grid axes."""
    path = os.path.join(root, "examples", "cad", part + ".json")
    if not rotated:
        return path
    # The files allow // comments; json does not: drop them (they never follow code on a line).
    with open(path) as f:
        text = "\n".join(line for line in f if not line.strip().startswith("//"))
    solid = json.loads(text)
    turned = {"solid": {"union": [solid["solid"]], "rotate": ROTATION}}
    out = os.path.join(scratch, part + "_rotated.json")
    with open(out, "w") as f:
        json.dump(turned, f, indent=1)
    return out


def measure(exe, solid, scratch, name, cells, simulate_flags=(), in_process=False):
    """One run: simulated (with `simulate_flags`, e.g. a mesher), restored, evaluated.
    `in_process`: restored by `resharp evaluate --restore` (the same restore() with default
    options, the same output), which then also tells why sharp edges are missed
    (cad.crease_losses)."""
    mesh, oracle = mesh_files(scratch, name)
    run([exe, "simulate", "--solid", solid, "-o", mesh, "--oracle", oracle, "-q", "--cells",
         str(cells)] + list(simulate_flags))
    return score(exe, solid, scratch, name, cells, in_process)


def mesh_files(scratch, name):
    """The mesh and its oracle of run `name`."""
    return os.path.join(scratch, name + ".ply"), os.path.join(scratch, name + "_oracle.ply")


def score(exe, solid, scratch, name, cells, in_process=False):
    """The mesh of run `name` (mesh_files(), on the grid of `cells` cells) restored and scored
    against `solid`; `in_process` as for measure()."""
    mesh, oracle = mesh_files(scratch, name)
    restored = os.path.join(scratch, name + "_restored.ply")
    report = os.path.join(scratch, name + "_report.json")
    scores = os.path.join(scratch, name + "_evaluate.json")
    grid = ["--cells", str(cells)]
    if not in_process:
        run([exe, "restore", mesh, "-o", restored, "--report", report, "-q"])
    run([exe, "evaluate", "--input", mesh, "--oracle", oracle, "--solid", solid, "--output",
         restored, "--json", scores, "-q"] + grid + (["--restore"] if in_process else []))
    e = load(scores)
    return {"triangles_in": e["validity"]["input"]["triangles"],
            "flipped_by_origin": e.get("flipped_by_origin"),
            "cad": e["cad"], "flipped": e["flipped_triangles"],
            "turned_against_input": e["turned_against_input"],
            "self_intersections": e["self_intersections"],
            "self_intersections_input": e["self_intersections_input"],
            "restoration_rate": e["restoration_rate"]}


def worse(result):
    """The measures on which the restored mesh is worse than its input."""
    cad = result["cad"]
    out = []
    for key, label, higher_better in MEASURES:
        a, b = cad["input"][key], cad["output"][key]
        if a is None or b is None:
            continue
        if (b < a) if higher_better else (b > a):
            out.append(label)
    return out


def num(x, style):
    """`style`: "score" (3 decimals), "nc" (4 decimals) or "length" (2 significant digits)."""
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    return {"score": f"{x:.3f}", "nc": f"{x:.4f}", "length": f"{x:.1e}"}[style]


def arrow(cad, key, style="score"):
    return f"{num(cad['input'][key], style)} -> {num(cad['output'][key], style)}"


def stray_share(measures):
    """Length of sharp edges farther than 1 % of the diagonal from every true one, over the true
    length."""
    true, stray = measures["true_crease_length"], measures.get("stray_crease_length")
    return stray / true if true and stray is not None else None


def rows(results):
    for part in sorted(results):
        for orientation in ("aligned", "rotated"):
            for cells, result in sorted(results[part][orientation].items(), key=lambda x: int(x[0])):
                yield part, orientation, int(cells), result


def table(results, columns):
    """One row per run; `columns`: (header, function of the run's result giving the cell)."""
    lines = ["| part | axes | cells | " + " | ".join(h for h, _ in columns) + " |",
             "| --- " * (3 + len(columns)) + "|"]
    for part, orientation, cells, r in rows(results):
        cells_text = " | ".join(f(r) for _, f in columns)
        lines.append(f"| {part} | {orientation} | {cells} | {cells_text} |")
    return "\n".join(lines)


def change(key, style="score"):
    return lambda r: arrow(r["cad"], key, style)


EDGE_COLUMNS = [("Edge F-score", change("edge_f1")), ("precision", change("edge_precision")),
                ("recall", change("edge_recall")),
                ("ECD", change("edge_chamfer_distance", "length")),
                ("crease length / true", change("crease_length_ratio")),
                ("stray / true", lambda r: " -> ".join(
                    num(stray_share(r["cad"][side]), "score") for side in ("input", "output")))]
SURFACE_COLUMNS = [("Chamfer", change("chamfer", "length")),
                   ("Hausdorff", change("hausdorff", "length")),
                   ("normal consistency", change("normal_consistency", "nc")),
                   ("worse than input", lambda r: ", ".join(worse(r)) or "-"),
                   ("flipped / self-intersections",
                    lambda r: f"{r['flipped']} / {r['self_intersections']}")]


def goals_table(results):
    lines = ["| cells | rows | Edge F-score >= 0.98 | crease length within 5 % | "
             "no measure worse than input | lowest Edge F-score (part) | "
             "largest stray / true (part) |",
             "| --- | --- | --- | --- | --- | --- | --- |"]
    by_cells = {}
    for part, orientation, cells, r in rows(results):
        by_cells.setdefault(cells, []).append((part, orientation, r))
    for cells in sorted(by_cells):
        group = by_cells[cells]
        ef1 = [(r["cad"]["output"]["edge_f1"], f"{p} {o}") for p, o, r in group]
        ratio_ok = sum(1 for _, _, r in group
                       if r["cad"]["output"]["crease_length_ratio"] is not None
                       and abs(r["cad"]["output"]["crease_length_ratio"] - 1) <= 0.05)
        lowest = min(ef1)
        strays = [(stray_share(r["cad"]["output"]) or 0.0, f"{p} {o}") for p, o, r in group]
        stray = max(strays)
        lines.append(f"| {cells} | {len(group)} | {sum(1 for x, _ in ef1 if x >= 0.98)} | "
                     f"{ratio_ok} | {sum(1 for _, _, r in group if not worse(r))} | "
                     f"{lowest[0]:.3f} ({lowest[1]}) | "
                     f"{stray[0]:.3f} ({stray[1] if stray[0] > 0 else 'none'}) |")
    return "\n".join(lines)


def worse_list(results):
    """For each measure, the runs on which restoring made it worse."""
    by_measure = {label: [] for _, label, _ in MEASURES}
    for part, orientation, cells, r in rows(results):
        for label in worse(r):
            by_measure[label].append(f"{part} {orientation} {cells}")
    lines = [f"- {label}: " + (", ".join(runs) if runs else "none")
             for label, runs in by_measure.items()]
    return "\n".join(lines)


def section(raw):
    run_info, results = raw["run"], raw["results"]
    cells = " ".join(str(c) for c in run_info["cells"])
    return "\n".join([
        CAD_BEGIN,
        "## CAD corpus: input and restored against the exact solid",
        "",
        f"Generated by `python3 bench/cad_corpus.py` on {run_info['date']} at commit "
        f"{run_info['commit']}; machine: {run_info['machine']}.",
        "",
        "The parts are our own CSG solids, `examples/cad/*.json` (format: "
        "`src/resharp/sim/csg_file.h`), each sampled as it is (*aligned*) and turned "
        f"{ROTATION['degrees']} degrees about the axis {tuple(ROTATION['axis'])} (*rotated*), "
        f"at {cells} cells along the longest side of its bounding box (`resharp simulate "
        "--solid P.json --cells N`: marching cubes with every vertex on the exact surface), "
        "restored by `resharp restore` with default options, and scored by `resharp evaluate "
        "--solid P.json --cells N` (`eval/cad_metrics.h`, `eval/exact_creases.h`). Each cell "
        "reads *input -> restored*. Distances are in bounding-box diagonals; the exact surface "
        "is sampled on a ray grid of pitch h/4. *Edge F-score*: F-score of precision (share of "
        "the mesh's sharp-edge length within tau = 0.1 % of the diagonal of a true sharp edge) "
        "and recall (share of the true sharp-edge length within tau of a mesh sharp edge); mesh "
        "sharp edges are edges whose faces meet at more than 30 degrees, true ones the curves "
        "where two surfaces of the solid meet at more than 30 degrees on its boundary. *ECD*: "
        "Edge Chamfer Distance, the mean squared distance between the two both ways, summed "
        "(Chen et al. 2022). *Crease length / true*: the mesh's sharp-edge length over the true "
        "one; *stray / true*: the length of the mesh's sharp edges farther than 1 % of the "
        "diagonal from every true one (creases where the part is smooth or flat) over the true "
        "length. *Worse than input*: the measures of Chamfer, Hausdorff, normal consistency, ECD "
        "and Edge F-score on which the restored mesh is worse. Plane-only parts: "
        f"{', '.join(PLANE_ONLY)}.",
        "",
        "### Goals (issue 13): rows meeting each",
        "",
        goals_table(results),
        "",
        "Runs on which the restored mesh is worse than its input, by measure (plane-only parts: "
        "the CTest subset in `tests/cli/restore_cli_test.cpp` checks two of them at 50 cells):",
        "",
        worse_list(results),
        "",
        "### Sharp edges",
        "",
        table(results, EDGE_COLUMNS),
        "",
        "### Surface",
        "",
        table(results, SURFACE_COLUMNS),
        "",
        CAD_END,
    ])


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parts = sorted(os.path.splitext(os.path.basename(p))[0]
                   for p in glob.glob(os.path.join(root, "examples", "cad", "*.json")))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(root, "build"))
    parser.add_argument("--scratch", default="/tmp/resharp-cad")
    parser.add_argument("--cells", type=int, nargs="*", default=[50, 100, 200])
    parser.add_argument("--parts", nargs="*", default=parts)
    parser.add_argument("--output", default=os.path.join(root, "docs", "results.md"))
    parser.add_argument("--raw", help="also write every result here as JSON")
    parser.add_argument("--from-raw", help="run nothing: write the section from a --raw file")
    args = parser.parse_args()
    if args.from_raw:
        raw = load(args.from_raw)
    else:
        exe = os.path.join(args.build, "resharp")
        os.makedirs(args.scratch, exist_ok=True)
        commit = git_head(root)  # before the runs: the tree may move while they run
        results = {}
        for part in args.parts:
            results[part] = {}
            for orientation in ("aligned", "rotated"):
                solid = solid_file(root, args.scratch, part, orientation == "rotated")
                results[part][orientation] = {
                    str(n): measure(exe, solid, args.scratch, f"{part}_{orientation}_{n}", n)
                    for n in args.cells}
        raw = {"run": {"date": datetime.date.today().isoformat(), "machine": machine(),
                       "commit": commit, "cells": args.cells},
               "results": results}
    if args.raw:
        with open(args.raw, "w") as f:
            json.dump(raw, f, indent=1)
    write_section(args.output, section(raw), CAD_BEGIN, CAD_END)
    print(f"wrote the CAD corpus section of {args.output}", file=sys.stderr)


if __name__ == "__main__":
    main()
