#!/usr/bin/env bash
# Renders docs/bracket-before-after.png, the README's picture: a convex corner of the shipped
# example before and after restoration, with the wireframe on, as the viewer page shows it in
# headless Chromium. Needs build/resharp (scripts/build.sh) and Chromium (install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
./build/resharp view examples/bracket.stl -o "$scratch/view.html"
# The corner where the right face (x = 40), the step's riser (y = 11) and the top (z = 15) meet;
# '#bare' hides the controls. The second shot turns the band colours off and the wireframe on.
node tests/viewer/check_page.mjs --chromium "$(command -v chromium)" --page "$scratch/view.html" \
    --hash '#bare&camera=46.5,5,19.5,40,11,14' --size 900x400 \
    --shots ';show-bands,show-wireframe' --save-png "$scratch/shot.png" >/dev/null
mv "$scratch/shot-1.png" docs/bracket-before-after.png
echo "render-readme-picture: docs/bracket-before-after.png"
