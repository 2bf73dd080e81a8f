#!/usr/bin/env python3
"""Measures restore()'s promise on every mesher's output; writes the table in docs/robustness.md.

    python3 bench/corpus.py [--build build] [--scratch DIR] [--parts NAME ...] [--meshers NAME ...]
                            [--raw FILE] [--from-raw FILE] [--check]

Each part (examples/NAME/job.json: the four benchmark parts and the V-carving example) is
simulated once per mesher (`resharp simulate --mesher mc|bisect|midpoint|surface-nets`, and
marching cubes with SEAMS grid planes written twice, `--seam-duplicates`), restored by `resharp
restore` with default options (its --report gives the restoration counts), and scored by
`resharp evaluate` against the simulator's oracle (faces turned against the input, faces flipped
against the exact surface, boundary and non-manifold edges,
CGAL's exact self-intersections, input and output). Only the section between the corpus markers
of the page is rewritten (put before the readers' part if the page has none).

--check writes nothing but prints one line per run and exits 1 when any run failed or did harm,
or, with an on-surface mesher, flipped a face against the exact surface: the CTest subset
(tests/corpus) runs it on the small bracket part. Python 3 stdlib only; offline;
every number in the table comes from these runs.
"""

import argparse
import datetime
import json
import os
import subprocess
import sys
import tempfile

from results import git_head, load, machine, run

PARTS = ["mech", "frogface", "cavity", "impeller", "vcarve"]
SEAMS = 8  # grid planes whose triangles are written twice in the seam-duplicates run
MESHERS = {  # name: resharp simulate's flags
    "mc": ["--mesher", "mc"],
    "bisect": ["--mesher", "bisect"],
    "midpoint": ["--mesher", "midpoint"],
    "surface-nets": ["--mesher", "surface-nets"],
    "mc-seams": ["--mesher", "mc", "--seam-duplicates", str(SEAMS)],
}
# Meshers whose vertices lie off the surface by up to half a cell: their faces flipped against the
# exact surface are reported, not failed (--check), since the input itself is that far off it.
OFF_SURFACE = {"midpoint", "surface-nets"}
RESTORE_TIMEOUT = 600  # s: a restore running longer counts as not finishing
BEGIN = "<!-- corpus: begin (bench/corpus.py writes this section) -->"
END = "<!-- corpus: end -->"
READERS_HEADING = "# Robustness of the mesh readers"


def restore(exe, mesh, restored, report):
    """Runs resharp restore; gives (finished, exit code or "timeout", wall seconds)."""
    cmd = [exe, "restore", mesh, "-o", restored, "--report", report, "-q"]
    print("+", " ".join(cmd), file=sys.stderr, flush=True)
    start = datetime.datetime.now()
    try:
        code = subprocess.run(cmd, timeout=RESTORE_TIMEOUT).returncode
    except subprocess.TimeoutExpired:
        code = "timeout"
    seconds = (datetime.datetime.now() - start).total_seconds()
    return code == 0, code, seconds

def measure(exe, root, scratch, part, mesher):
    """Simulates, restores and evaluates one part with one mesher; gives the run's numbers."""
    job = os.path.join(root, "examples", part, "job.json")
    name = os.path.join(scratch, f"{part}_{mesher}")
    # PLY keeps the simulator's doubles: STL's float32 would move every vertex off the surface
    # for every mesher alike.
    mesh, oracle, restored = name + ".ply", name + "_oracle.ply", name + "_restored.ply"
    report, scores = name + "_report.json", name + "_evaluate.json"
    run([exe, "simulate", job, "-o", mesh, "--oracle", oracle, "-q"] + MESHERS[mesher])
    finished, code, seconds = restore(exe, mesh, restored, report)
    result = {"part": part, "mesher": mesher, "finished": finished, "exit": code,
              "wall_seconds": seconds}
    if not finished:
        return result
    run([exe, "evaluate", "--input", mesh, "--oracle", oracle, "--job", job, "--output", restored,
         "--json", scores, "-q"])
    r, e = load(report), load(scores)
    valid_in, valid_out = e["validity"]["input"], e["validity"]["output"]
    result.update({
        "triangles_in": r["input"]["triangles"],
        "triangles_out": r["output"]["triangles"],
        "turned_against_input": e["turned_against_input"],
        "flipped": e["flipped_triangles"],
        "flipped_input": e["flipped_triangles_input"],
        "boundary_added": valid_out["boundary_edges"] - valid_in["boundary_edges"],
        "nonmanifold_added": valid_out["nonmanifold_edges"] - valid_in["nonmanifold_edges"],
        "inconsistent_added": valid_out["inconsistent_edges"] - valid_in["inconsistent_edges"],
        "self_intersections_added": e["self_intersections"] - e["self_intersections_input"],
        "self_intersections_input": e["self_intersections_input"],
        "edge_points": r["restoration"]["edge_points_inserted"],
        "corner_points": r["restoration"]["corner_points_inserted"],
        "undone_points": r["harm_check"]["undone_points"],
        "harm_rounds": r["harm_check"]["rounds"],
        "duplicates_removed": r["mesh_repair"]["duplicate_faces_removed"],
        "output_unchanged": r["output_unchanged"],
        "restore_seconds": r["time_seconds"]["total"],
        "restoration_rate": e["restoration_rate"],
    })
    return result


EDGE_KEYS = ["boundary_added", "nonmanifold_added", "inconsistent_added",
             "self_intersections_added"]


def harm(result):
    """What the run did wrong by the promise of issue 11: not finishing, a face turned against
    the input, an edge defect or a self-intersection added."""
    if not result["finished"]:
        return [f"restore did not finish (exit {result['exit']})"]
    keys = ["turned_against_input"] + EDGE_KEYS
    return [f"{key} {result[key]}" for key in keys if result[key] > 0]


def flipped_runs(results, meshers):
    """The finished runs of these meshers with faces flipped against the exact surface."""
    return [f"{r['part']} {r['mesher']} {r['flipped']}" for r in results
            if r["finished"] and r["mesher"] in meshers and r["flipped"] > 0]


def table(results):
    lines = ["| part | mesher | triangles in | finishes (restore s) | turned against the input | "
             "flipped against the exact surface (input's own) | "
             "boundary / non-manifold / inconsistent edges added | self-intersections added "
             "(input's) | edge / corner points | points undone (rounds) | duplicates removed | "
             "restoration rate |",
             "| --- " * 12 + "|"]
    for r in results:
        head = f"| {r['part']} | {r['mesher']} |"
        if not r["finished"]:
            lines.append(f"{head} - | no (exit {r['exit']}, {r['wall_seconds']:.0f} s) |"
                         + " - |" * 8)
            continue
        lines.append(
            f"{head} {r['triangles_in']:,} | yes ({r['restore_seconds']:.2f}) | "
            f"{r['turned_against_input']} | {r['flipped']} ({r['flipped_input']}) | "
            f"{r['boundary_added']:,} / {r['nonmanifold_added']:,} / {r['inconsistent_added']:,} | "
            f"{r['self_intersections_added']} ({r['self_intersections_input']}) | "
            f"{r['edge_points']:,} / {r['corner_points']} | "
            f"{r['undone_points']} ({r['harm_rounds']}) | {r['duplicates_removed']:,} | "
            f"{100 * r['restoration_rate']:.1f} % |")
    return "\n".join(lines)


def section(raw):
    info, results = raw["run"], raw["results"]
    harmed = [f"{r['part']} {r['mesher']}: {', '.join(harm(r))}" for r in results if harm(r)]
    on_surface = set(MESHERS) - OFF_SURFACE
    return "\n".join([
        BEGIN,
        "## The corpus in numbers: every mesher, every benchmark part",
        "",
        f"Generated by `python3 bench/corpus.py` on {info['date']} at commit {info['commit']}; "
        f"machine: {info['machine']}.",
        "",
        "Each part (`examples/NAME/job.json`) is simulated once per mesher (`resharp simulate "
        "--mesher`: *mc*, marching cubes with every vertex on the exact ray crossing; *bisect*, "
        "8 bisection steps along the grid edge, as CAMotics; *midpoint*, grid-edge midpoints, as "
        "plain voxel carving; *surface-nets*, one vertex per cell at the mean of its crossings, "
        "as OpenVDB's `volumeToMesh` at adaptivity 0; *mc-seams*, marching cubes with the "
        f"triangles on {SEAMS} grid planes written twice, `--seam-duplicates {SEAMS}`, as "
        "parallel meshing jobs leave them), restored by `resharp restore` with default options "
        "on all cores, and scored by `resharp evaluate` against the simulator's oracle. "
        "*Flipped*: output faces cut by the restoration turned against the exact surface "
        "(`src/resharp/eval/validity.h`): a non-positive dot product with the exact normal at one of their "
        "input vertices, confirmed at their centroid (a vertex on an edge has one of its two "
        "surfaces' normals); faces with a vertex off the surface (midpoint, surface nets, moved "
        "vertices) judged at their centroid instead; there turned more than 90 degrees against every "
        "exact sample as near as the nearest plus their vertices' offset from the surface and "
        "the sampling pitch "
        "(in brackets: the input's "
        "own faces that already are, from the mesher). *Added* counts are output minus input "
        "(negative where removing duplicate faces took seams' edges away); self-intersections "
        "are intersecting face pairs by CGAL's exact predicates. *Points undone*: points the harm "
        "check withdrew, over its rounds. *Restoration rate*: share of the ideal points on the "
        "exact junction restored within 0.05 h (docs/results.md). Restore times are single "
        "runs, not benchmarks. OpenVDB's own `volumeToMesh` is tested apart, on solids the "
        "simulator sampled at h/8 (`tests/pipeline/openvdb_test.cpp`).",
        "",
        table(results),
        "",
        "Runs that did not finish, turned a face against the input, or added an edge defect or "
        "a self-intersection: " + ("; ".join(harmed) if harmed else "none") + ". Faces "
        "flipped against the exact surface, a stricter test than the input's (a face can agree "
        "with the input and not with the truth where the input is too coarse to show it): on "
        "the on-surface meshers " + ("; ".join(flipped_runs(results, on_surface)) or "none")
        + "; on the off-surface ones (midpoint, surface-nets) "
        + ("; ".join(flipped_runs(results, OFF_SURFACE)) or "none") + ". An off-surface "
        "face lies as far off the surface as its mesher put its vertices, so beside an edge it "
        "can lie nearer the other face of the edge than its own: one on the top of a convex "
        "edge, overhanging the wall by the mesher's offset, is turned 90 degrees or a little "
        "more against the wall's normal; it counts only if it also turns against the top's "
        "(`src/resharp/eval/validity.h`).",
        END,
    ])


def write_section(page_path, text):
    with open(page_path) as f:
        page = f.read()
    if BEGIN in page and END in page:
        before, rest = page.split(BEGIN, 1)
        after = rest.split(END, 1)[1]
        page = before + text + after
    elif READERS_HEADING in page:
        before, after = page.split(READERS_HEADING, 1)
        page = before + text + "\n\n" + READERS_HEADING + after
    else:
        page = page.rstrip("\n") + "\n\n" + text + "\n"
    with open(page_path, "w") as f:
        f.write(page)


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(root, "build"), help="build directory")
    parser.add_argument("--scratch", help="folder for the meshes (default: a temporary one)")
    parser.add_argument("--parts", nargs="+", default=PARTS, help="examples/NAME/job.json")
    parser.add_argument("--meshers", nargs="+", default=list(MESHERS), choices=list(MESHERS))
    parser.add_argument("--raw", help="also write every number as JSON here")
    parser.add_argument("--from-raw", help="write the table from this JSON, running nothing")
    parser.add_argument("--check", action="store_true",
                        help="write no table; exit 1 when a run failed or did harm")
    args = parser.parse_args()

    if args.from_raw:
        raw = load(args.from_raw)
    else:
        exe = os.path.join(args.build, "resharp")
        with tempfile.TemporaryDirectory(prefix="resharp-corpus-") as temporary:
            scratch = args.scratch or temporary
            os.makedirs(scratch, exist_ok=True)
            results = [measure(exe, root, scratch, part, mesher)
                       for part in args.parts for mesher in args.meshers]
        raw = {"run": {"date": datetime.date.today().isoformat(), "commit": git_head(root),
                       "machine": machine()},
               "results": results}
        if args.raw:
            with open(args.raw, "w") as f:
                json.dump(raw, f, indent=1)
    if args.check:
        failed = False
        for r in raw["results"]:
            problems = harm(r)
            note = ""
            if r["finished"] and r["mesher"] not in OFF_SURFACE and r["flipped"] > 0:
                problems.append(f"flipped against the exact surface {r['flipped']}")
            failed = failed or bool(problems)
            if r["finished"] and r["mesher"] in OFF_SURFACE:
                note = f" (flipped {r['flipped']} ({r['flipped_input']}): reported, not failed)"
            print(f"{r['part']} {r['mesher']}: " + (", ".join(problems) if problems else "no harm")
                  + note)
        return 1 if failed else 0
    write_section(os.path.join(root, "docs", "robustness.md"), section(raw))
    return 0


if __name__ == "__main__":
    sys.exit(main())
