#!/usr/bin/env python3
"""Regenerates docs/results.md: the results table of resharp on the four benchmark parts.

    python3 bench/results.py [--build build] [--scratch /tmp/resharp-results] [--runs 5]

For each part it runs `resharp simulate` on examples/<part>/job.json, times `resharp restore
--threads 1` (median of --runs runs, default options and --paper), and runs
`resharp evaluate --restore` four times (ours, the paper's variant, exact normals, the oracle's
bands with exact normals), each scoring the ideal points on the exact junction of the job's
surfaces and, beside them, the first-order (eq. 5.2) ones. Python 3 stdlib
only; every number in the page comes from these runs. `--raw FILE` keeps those runs;
`--from-raw FILE` writes the page again from them, for edits to the template's analysis.
"""

import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys

PARTS = ["mech", "frogface", "cavity", "impeller"]
# Paper, Table 1 and section 6: triangles, restoration rate (%), stage times (s).
PAPER = {
    "mech": (277524, "100", 0.037, 0.116, 0.084, 0.237),
    "frogface": (255792, "96", 0.047, 0.100, 0.069, 0.216),
    "cavity": (272152, "79", 0.053, 0.147, 0.084, 0.284),
    "impeller": (382254, "-", 0.069, 0.168, 0.116, 0.353),
}
GOALS = {"mech": 99.5, "frogface": 98.0, "cavity": 92.0, "impeller": None}
VARIANTS = [  # (row name, extra evaluate flags)
    ("ours", []),
    ("paper's choices (--paper)", ["--paper"]),
    ("exact normals (placement ceiling)", ["--exact-normals"]),
    ("oracle bands and normals (split ceiling)", ["--oracle-bands"]),
]
EDGE_SEG = ["curvature", "edge segmentation"]
FEATURE_SEG = ["feature segmentation"]
RESTORATION = ["classification", "feature normals", "sharp points", "guard", "split", "harm check"]
CAUSES = ["beyond_chord", "no_feature_patch", "same_patch", "no_edge_vertex", "corner_not_detected",
          "not_detected", "not_inserted", "placed_far"]


# The section bench/cad_corpus.py writes into the page; kept when this script rewrites it.
CAD_BEGIN = "<!-- cad-corpus: begin (bench/cad_corpus.py writes this section) -->"
CAD_END = "<!-- cad-corpus: end -->"
# Written by hand from scratch counts on single rows; kept as it is, like the sections above.
CAD_DIAGNOSIS_BEGIN = "<!-- cad-diagnosis: begin (written by hand; kept by bench/results.py) -->"
CAD_DIAGNOSIS_END = "<!-- cad-diagnosis: end -->"


# The sections bench/mesher_results.py writes, one per mesher (openvdb: OpenVDB's volumeToMesh,
# bench/openvdb_mesh.cpp); kept as the CAD corpus section.
MESHER_SECTIONS = ["surface-nets", "midpoint", "mc", "openvdb"]


def mesher_markers(mesher):
    """The begin and end markers of the page's section for `mesher`."""
    return (f"<!-- mesher-results {mesher}: begin (bench/mesher_results.py writes this "
            "section) -->", f"<!-- mesher-results {mesher}: end -->")


def marked_section(page, begin, end):
    """The section of `page` (text) from marker `begin` to marker `end`, or "" if it has none."""
    if begin not in page or end not in page:
        return ""
    return begin + page.split(begin, 1)[1].split(end, 1)[0] + end


def cad_section(page):
    """The CAD corpus section of `page` (text), or "" if it has none."""
    return marked_section(page, CAD_BEGIN, CAD_END)


def kept_sections(page):
    """The sections other scripts write into `page`, in page order, as one text."""
    sections = [cad_section(page), marked_section(page, CAD_DIAGNOSIS_BEGIN, CAD_DIAGNOSIS_END)]
    sections += [marked_section(page, *mesher_markers(m)) for m in MESHER_SECTIONS]
    return "\n\n".join(sorted((s for s in sections if s), key=page.index))


def write_section(page_path, text, begin, end):
    """Replaces the page's section between `begin` and `end` with `text`, or appends it."""
    page = open(page_path).read() if os.path.exists(page_path) else ""
    old = marked_section(page, begin, end)
    page = page.replace(old, text) if old else page.rstrip("\n") + "\n\n" + text + "\n"
    with open(page_path, "w") as f:
        f.write(page)


def run(cmd):
    print("+", " ".join(cmd), file=sys.stderr, flush=True)
    subprocess.run(cmd, check=True)


def load(path):
    with open(path) as f:
        return json.load(f)


def time_restore(exe, mesh, scratch, part, runs, extra):
    """Median stage times (s) over `runs` single-threaded runs."""
    reports = []
    for i in range(runs):
        report = os.path.join(scratch, f"{part}_time_{i}.json")
        run([exe, "restore", mesh, "-o", os.path.join(scratch, f"{part}_timed.ply"), "--report",
             report, "--threads", "1", "-q"] + extra)
        reports.append(load(report)["time_seconds"])
    stages = {name: statistics.median(r["stages"][name] for r in reports)
              for name in reports[0]["stages"]}
    stages["total"] = statistics.median(r["total"] for r in reports)
    return stages


def evaluate_part(exe, root, scratch, part, runs):
    job = os.path.join(root, "examples", part, "job.json")
    mesh = os.path.join(scratch, f"{part}.ply")
    oracle = os.path.join(scratch, f"{part}_oracle.ply")
    run([exe, "simulate", job, "-o", mesh, "--oracle", oracle, "-q"])
    result = {"times": time_restore(exe, mesh, scratch, part, runs, []),
              "times_paper": time_restore(exe, mesh, scratch, part, runs, ["--paper"]),
              "rows": {}}
    for name, flags in VARIANTS:
        out = os.path.join(scratch, f"{part}_{len(result['rows'])}.json")
        run([exe, "evaluate", "--input", mesh, "--oracle", oracle, "--job", job, "--restore",
             "--json", out, "-q"] + flags)
        result["rows"][name] = load(out)
    return result


def pct(x):
    return "-" if x is None else f"{100 * x:.2f}"


def mm(x, digits=4):
    return "-" if x is None else f"{x:.{digits}f}"


def surface_cells(s):
    n, d = s["edges_ndc"], s["edges_dihedral"]
    return [mm(s["chamfer_l1"]), f"{s['chamfer_l2']:.2e}", mm(s["hausdorff"], 3),
            mm(s["hausdorff_p99"]), f"{s['normal_consistency']:.4f}",
            f"{n['ecd']:.2e}" if n["ecd"] is not None else "-", f"{n['ef1']:.3f}",
            f"{d['ecd']:.2e}" if d["ecd"] is not None else "-", f"{d['ef1']:.3f}"]


def quality_table(results):
    head = ["part", "row", "triangles", "rate % (paper)", "rate %", "rate % (first order)",
            "edges %", "corners %",
            "det. P %", "det. R %", "false ins.", "max new dist", "CD-L1", "CD-L2", "HD",
            "HD99", "NC", "ECD", "EF1", "ECD 30°", "EF1 30°", "flipped", "self-int.",
            "non-manif.", "boundary", "min angle °"]
    lines = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    for part, r in results.items():
        ours = r["rows"]["ours"]
        vin = ours["validity"]["input"]
        lines.append("| " + " | ".join(
            [part, "input, no restoration", str(vin["triangles"]), PAPER[part][1],
             pct(ours["restoration_rate_input"]), "0", "-", "-", "-", "-", "-", "-"] +
            surface_cells(ours["surface"]["input"]) +
            [str(ours["flipped_triangles_input"]), str(vin["self_intersections"]),
             str(vin["nonmanifold_edges"]), str(vin["boundary_edges"]),
             f"{vin['min_angle_deg']:.2f}"]) + " |")
        for name, _ in VARIANTS:
            j = r["rows"][name]
            v = j["validity"]["output"]
            lines.append("| " + " | ".join(
                [part, name, str(v["triangles"]), PAPER[part][1], pct(j["restoration_rate"]),
                 pct(j["restoration_rate_first_order"]),
                 pct(j["restoration_rate_edges"]), pct(j["restoration_rate_corners"]),
                 pct(j["detection_precision"]), pct(j["detection_recall"]),
                 str(j["false_insertions"]), mm(j["max_new_vertex_distance"], 3)] +
                surface_cells(j["surface"]["output"]) +
                [str(j["flipped_triangles"]), str(j["self_intersections"]),
                 str(j["nonmanifold_edges"]), str(j["boundary_edges"]),
                 f"{v['min_angle_deg']:.2f}"]) + " |")
    return "\n".join(lines)


def time_table(results, key):
    head = ["part", "triangles (ours / paper)", "edge-based seg. (ours / paper)",
            "feature-based seg.", "restoration", "mesh building (extra)", "total (ours / paper)"]
    lines = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    for part, r in results.items():
        t, p = r[key], PAPER[part]
        tri = r["rows"]["ours"]["validity"]["input"]["triangles"]
        lines.append("| " + " | ".join([
            part, f"{tri:,} / {p[0]:,}",
            f"{sum(t[s] for s in EDGE_SEG):.4f} / {p[2]:.3f}",
            f"{sum(t[s] for s in FEATURE_SEG):.4f} / {p[3]:.3f}",
            f"{sum(t[s] for s in RESTORATION):.4f} / {p[4]:.3f}",
            f"{t['mesh building']:.4f}", f"{t['total']:.4f} / {p[5]:.3f}"]) + " |")
    return "\n".join(lines)


def causes_table(results, first_order=False):
    """Miss causes per row, on the exact junction or (first_order) on the eq. 5.2 points."""
    head = ["part", "row", "ideal edges", "ideal corners", "missed"] + CAUSES
    lines = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    for part, r in results.items():
        for name, _ in VARIANTS:
            j = r["rows"][name]
            if first_order:
                j = j["first_order"]
            c, ip = j["miss_causes"], j["ideal_points"]
            missed = (ip["edges"] - ip["restored_edges"]) + (ip["corners"] - ip["restored_corners"])
            cells = [f"{c['edges'][k]} + {c['corners'][k]}" for k in CAUSES]
            lines.append("| " + " | ".join([part, name, str(ip["edges"]), str(ip["corners"]),
                                            str(missed)] + cells) + " |")
    return "\n".join(lines)


def apart_cell(ip):
    """Ideal points counted apart from the exact-junction rate, by cause."""
    apart = ip["counted_apart"]
    return " / ".join(str(apart[k]["edges"] + apart[k]["corners"])
                      for k in ["not_bounding", "sampled_surface", "unsolved"])


def goals_table(results):
    lines = ["| part | goal | ours | met | ours, first order (eq. 5.2) | counted apart (not bounding "
             "/ sampled / unsolved) | restored by an input vertex | beyond their chord | ours "
             "within reach | exact normals within reach | split ceiling (oracle) | split ceiling, "
             "first order | flipped | self-intersections |",
             "|" + " --- |" * 14]
    for part, r in results.items():
        j, goal = r["rows"]["ours"], GOALS[part]
        rate = 100 * j["restoration_rate"]
        met = "-" if goal is None else ("yes" if rate >= goal else "no")
        ip = j["ideal_points"]
        beyond = f"{ip['beyond_chord']} of {ip['edges'] + ip['corners']}"
        exact = r["rows"]["exact normals (placement ceiling)"]["restoration_rate_within_reach"]
        ceiling = r["rows"]["oracle bands and normals (split ceiling)"]
        lines.append(f"| {part} | {'-' if goal is None else f'>= {goal}%'} | {rate:.2f}% | {met} "
                     f"| {pct(j['restoration_rate_first_order'])}% | {apart_cell(ip)} "
                     f"| {ip['restored_by_input_vertices']} | {beyond} "
                     f"| {pct(j['restoration_rate_within_reach'])}% | {pct(exact)}% "
                     f"| {pct(ceiling['restoration_rate'])}% "
                     f"| {pct(ceiling['restoration_rate_first_order'])}% "
                     f"| {j['flipped_triangles']} | {j['self_intersections']} |")
    return "\n".join(lines)


def machine():
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    load = os.getloadavg()
    return (f"{model}, {os.cpu_count()} cores, {platform.system()} {platform.release()}; "
            f"load average {load[0]:.2f} / {load[1]:.2f} / {load[2]:.2f} at the end of the run "
            f"(the machine is shared with other engineers' builds)")


def git_head(root):
    try:
        return subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], check=True,
                              capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(root, "build"))
    parser.add_argument("--scratch", default="/tmp/resharp-results")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--parts", nargs="*", default=PARTS)
    parser.add_argument("--output", default=os.path.join(root, "docs", "results.md"))
    parser.add_argument("--raw", help="also write every JSON result here")
    parser.add_argument("--from-raw", help="run nothing: write the page from a file that --raw "
                        "wrote (after editing the template's analysis)")
    args = parser.parse_args()
    if args.from_raw:
        with open(args.from_raw) as f:
            raw = json.load(f)
    else:
        exe = os.path.join(args.build, "resharp")
        os.makedirs(args.scratch, exist_ok=True)
        results = {p: evaluate_part(exe, root, args.scratch, p, args.runs) for p in args.parts}
        raw = {"run": {"date": datetime.date.today().isoformat(), "machine": machine(),
                       "commit": git_head(root), "runs": args.runs},
               "results": results}
    if args.raw:
        with open(args.raw, "w") as f:
            json.dump(raw, f, indent=1)
    results, run = raw["results"], raw["run"]
    settings = next(iter(results.values()))["rows"]["ours"]["settings"]
    template_path = os.path.join(root, "bench", "results_template.md")
    with open(template_path) as f:
        page = f.read()
    page = page.format(
        date=run["date"], machine=run["machine"], commit=run["commit"],
        runs=run["runs"], settings=json.dumps(settings), goals=goals_table(results),
        quality=quality_table(results), times=time_table(results, "times"),
        times_paper=time_table(results, "times_paper"), causes=causes_table(results),
        causes_first=causes_table(results, first_order=True))
    if os.path.exists(args.output):
        with open(args.output) as f:
            kept = kept_sections(f.read())
        if kept:
            page = page.rstrip("\n") + "\n\n" + kept + "\n"
    with open(args.output, "w") as f:
        f.write(page)
    print(f"wrote {args.output}", file=sys.stderr)


if __name__ == "__main__":
    main()
