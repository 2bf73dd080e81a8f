#!/usr/bin/env python3
"""Compares restore() time of two resharp builds on the same meshes, side by side.

    python3 bench/compare_restore.py BASE_EXE NEW_EXE MESH... [--runs 7] [--threads 1]

Runs `restore` of each build in turn (A B A B ...) on each mesh, reads restore()'s own total
time from the JSON report (file reading and writing excluded), and prints per mesh the median
of each build and the ratio of medians NEW / BASE. Python 3 stdlib only.
"""

import argparse
import json
import os
import statistics
import subprocess
import tempfile


def restore_seconds(exe, mesh, threads, scratch):
    report = os.path.join(scratch, "report.json")
    out = os.path.join(scratch, "out.stl")
    subprocess.run([exe, "restore", mesh, "-o", out, "--report", report, "--threads",
                    str(threads)], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(report) as f:
        return json.load(f)["time_seconds"]["total"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("meshes", nargs="+")
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--threads", type=int, default=1)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        print(f"| mesh | base median (s) | new median (s) | new / base |")
        print(f"| --- | --- | --- | --- |")
        for mesh in args.meshes:
            base, new = [], []
            for _ in range(args.runs):
                base.append(restore_seconds(args.base, mesh, args.threads, scratch))
                new.append(restore_seconds(args.new, mesh, args.threads, scratch))
            b, n = statistics.median(base), statistics.median(new)
            print(f"| {os.path.basename(mesh)} | {b:.4f} | {n:.4f} | {n / b:.3f} |", flush=True)


if __name__ == "__main__":
    main()
