#!/usr/bin/env bash
# Installs the viewer's npm packages (three.js and esbuild at the exact versions of
# apps/resharp/viewer/package-lock.json) into apps/resharp/viewer/node_modules. Called by
# install-deps.sh. Safe to run again: skipped when the locked versions are already installed
# and esbuild runs.
set -euo pipefail
cd "$(dirname "$0")/../apps/resharp/viewer"
is_installed() {
    node -e '
        const lock = require("./package-lock.json").packages;
        for (const name of ["three", "esbuild"]) {
            const installed = require(`./node_modules/${name}/package.json`).version;
            if (installed !== lock[`node_modules/${name}`].version) process.exit(1);
        }' 2>/dev/null &&
        node node_modules/esbuild/bin/esbuild --version >/dev/null 2>&1
}
if is_installed; then
    echo "install-viewer-deps: npm packages present"
    exit 0
fi
npm ci --ignore-scripts --no-audit --no-fund --loglevel=error
is_installed || { echo "install-viewer-deps: npm ci did not install three and esbuild" >&2; exit 1; }
echo "install-viewer-deps: npm packages installed"
