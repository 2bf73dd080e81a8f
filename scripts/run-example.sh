#!/usr/bin/env bash
# Installs the dependencies, builds the resharp binary and the Python module alone (no tests, no
# benchmarks: that is scripts/test.sh's work, in the same build/), makes the module importable
# by /usr/bin/python3 through .venv (scripts/install-python.sh), and restores the shipped
# example mesh, printing the summary. The restored mesh, its report, its segmentation and a
# viewer page land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
BUILD_DIR=build TARGETS="resharp_cli resharp_python" bash scripts/build.sh
BUILD_DIR=build bash scripts/install-python.sh
mkdir -p out
./build/resharp restore examples/bracket.stl -o out/bracket-restored.stl \
    --report out/bracket-report.json --segments out/bracket-segments.ply \
    --html out/bracket-view.html
echo "Restored mesh: out/bracket-restored.stl; detected segments: out/bracket-segments.ply"
echo "Before and after, in any browser: out/bracket-view.html"
