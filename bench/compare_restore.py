#!/usr/bin/env python3
"""Compares restore() time of two resharp builds on the same meshes, side by side.

    python3 bench/compare_restore.py BASE_EXE NEW_EXE MESH... [--runs 7] [--threads 1] [--stages]
                                     [--max-steal SECONDS]

Runs `restore` of each build in turn (A B A B ...) on each mesh, reads restore()'s own total
time from the JSON report (file reading and writing excluded), and prints per mesh the median
of each build, the ratio of medians NEW / BASE and that of the fastest runs (which a machine
shared with others disturbs least). With --stages, also the median time of each
stage the reports name (a stage one build lacks shows as -). Python 3 stdlib only.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile


def stolen_seconds():
    """CPU time the hypervisor gave other guests so far, summed over this machine's CPUs (the
    steal column of /proc/stat; 0 where there is none)."""
    try:
        with open("/proc/stat") as f:
            fields = f.readline().split()
        return int(fields[8]) / os.sysconf("SC_CLK_TCK")
    except (OSError, IndexError, ValueError):
        return 0.0


def restore_times(exe, mesh, threads, scratch, max_steal):
    """restore()'s total and per-stage seconds, from the report of one run, and how many runs
    were taken again because the hypervisor stole more than max_steal seconds of CPU time
    meanwhile (at most 20; then the last run counts)."""
    report = os.path.join(scratch, "report.json")
    out = os.path.join(scratch, "out.stl")
    for retry in range(21):
        before = stolen_seconds()
        subprocess.run([exe, "restore", mesh, "-o", out, "--report", report, "--threads",
                        str(threads)], check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        if max_steal is None or stolen_seconds() - before <= max_steal:
            break
    with open(report) as f:
        times = json.load(f)["time_seconds"]
    return times["total"], times.get("stages", {}), retry


def stage_table(mesh, base_stages, new_stages):
    """Markdown rows: each stage's median time in each build, milliseconds."""
    def median_ms(runs, stage):
        values = [run[stage] for run in runs if stage in run]
        return f"{1000 * statistics.median(values):.1f}" if values else "-"
    names = sorted({name for run in base_stages + new_stages for name in run})
    return [f"| {os.path.basename(mesh)}: {name} | {median_ms(base_stages, name)} | "
            f"{median_ms(new_stages, name)} |" for name in names]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("meshes", nargs="+")
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--stages", action="store_true", help="also each stage's medians")
    parser.add_argument("--max-steal", type=float, default=None,
                        help="take a run again while the hypervisor stole more CPU seconds "
                             "than this during it (shared machines; /proc/stat's steal time)")
    args = parser.parse_args()
    stage_rows = []
    with tempfile.TemporaryDirectory() as scratch:
        print("| mesh | base median (s) | new median (s) | new / base | ratio of fastest |")
        print("| --- | --- | --- | --- | --- |")
        for mesh in args.meshes:
            base, new, base_stages, new_stages, retries = [], [], [], [], 0
            for _ in range(args.runs):
                for exe, totals, stage_runs in ((args.base, base, base_stages),
                                                (args.new, new, new_stages)):
                    total, stages, retried = restore_times(exe, mesh, args.threads, scratch,
                                                           args.max_steal)
                    totals.append(total)
                    stage_runs.append(stages)
                    retries += retried
            b, n = statistics.median(base), statistics.median(new)
            fastest = min(new) / min(base)
            print(f"| {os.path.basename(mesh)} | {b:.4f} | {n:.4f} | {n / b:.3f} | {fastest:.3f} |",
                  flush=True)
            if args.max_steal is not None:
                print(f"({retries} runs taken again for steal time)", file=sys.stderr)
            stage_rows += stage_table(mesh, base_stages, new_stages)
        if args.stages:
            print("\n| mesh: stage | base median (ms) | new median (ms) |\n| --- | --- | --- |")
            print("\n".join(stage_rows))


if __name__ == "__main__":
    main()
