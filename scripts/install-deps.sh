#!/usr/bin/env bash
# Installs every Debian package resharp needs to build, test, benchmark and fuzz, then the
# viewer's npm packages (install-viewer-deps.sh). Safe to run again: apt-get skips what is
# already installed.
set -euo pipefail

packages=(
    build-essential cmake ninja-build
    libeigen3-dev libtbb-dev libcli11-dev nlohmann-json3-dev
    libcgal-dev libgmp-dev libmpfr-dev
    libopenvdb-dev libboost-iostreams-dev  # OpenVDB as another mesher, in a test
    libgtest-dev libgmock-dev libbenchmark-dev
    clang clang-format libclang-rt-dev
    python3
    python3-dev python3-venv pybind11-dev python3-pybind11 python3-numpy python3-pytest
    chromium  # the viewer's tests and benchmark: headless, software WebGL
)
# The viewer's page is bundled by node at build time; a Node.js that came with its own npm is
# kept, Debian's is installed only where there is none.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then packages+=(nodejs npm); fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi

export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null
echo "install-deps: all packages present"
bash "$(dirname "$0")/install-viewer-deps.sh"
