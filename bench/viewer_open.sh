#!/usr/bin/env bash
# How long a viewer page of about one million triangles takes to open: mech simulated at
# h = 0.29 mm (1,025,900 triangles), restored with --html, then opened RUNS times (default 5)
# in headless Chromium with software WebGL (SwiftShader) by tests/viewer/check_page.mjs, a fresh
# browser each time. Prints the medians, in seconds since navigation started, of: HTML parsed,
# meshes decoded from base64, scene built, first frame shown. Needs build/resharp.
#
# Usage: bench/viewer_open.sh [RUNS]
set -euo pipefail
runs=${1:-5}
cd "$(dirname "$0")/.."
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
./build/resharp simulate examples/mech/job.json --pitch 0.29 -o "$scratch/mech.stl" -q
./build/resharp restore "$scratch/mech.stl" -o "$scratch/restored.stl" --html "$scratch/page.html" -q
for ((run = 1; run <= runs; ++run)); do
    node tests/viewer/check_page.mjs --chromium "$(command -v chromium)" \
        --page "$scratch/page.html" --timeout 600 >"$scratch/run$run.json"
done
node -e '
    const fs = require("fs");
    const [dir, runs, bytes] = process.argv.slice(1);
    const reports = [];
    for (let run = 1; run <= Number(runs); ++run)
        reports.push(JSON.parse(fs.readFileSync(`${dir}/run${run}.json`)).viewer);
    const median = (key) => {
        const values = reports.map((r) => r.timing[key]).sort((a, b) => a - b);
        return (values[values.length >> 1] / 1000).toFixed(2);
    };
    console.log(`page: ${(Number(bytes) / 1e6).toFixed(1)} MB, ${reports[0].inputTriangles} input and ` +
        `${reports[0].restoredTriangles} restored triangles; ${runs} runs, medians in seconds`);
    console.log("| HTML parsed | decoded | scene built | first frame shown |");
    console.log(`| ${median("parsedMs")} | ${median("decodedMs")} | ${median("builtMs")} | ${median("shownMs")} |`);
' "$scratch" "$runs" "$(stat -c %s "$scratch/page.html")"
