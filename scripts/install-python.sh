#!/usr/bin/env bash
# Makes the Python module built in BUILD_DIR (default: build; CMake target resharp_python)
# importable by the Python it was built for (Debian's /usr/bin/python3) without touching that
# Python, which Debian manages (PEP 668): a virtual environment in .venv that sees the system's
# packages (python3-numpy, python3-pytest) and, through a .pth file, BUILD_DIR/python. The module
# is not copied, so a rebuild is picked up at once. Safe to run again. Afterwards, in any shell:
#   source .venv/bin/activate; python3 -c "import resharp"
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=$(realpath "${BUILD_DIR:-build}")
if [[ ! -f "$build_dir/python/resharp/__init__.py" ]]; then
    echo "install-python: no Python module in $build_dir: build the resharp_python target" >&2
    exit 1
fi
python=$(sed -n 's/^Python_EXECUTABLE:[A-Z]*=//p' "$build_dir/CMakeCache.txt")
if [[ ! -x .venv/bin/python3 ]]; then
    "$python" -m venv --system-site-packages --without-pip .venv
fi
site=$(.venv/bin/python3 -c 'import sysconfig; print(sysconfig.get_path("purelib"))')
echo "$build_dir/python" >"$site/resharp-build.pth"
version=$(.venv/bin/python3 -c 'import resharp; print(resharp.__version__)')
echo "install-python: resharp $version for $python in .venv (source .venv/bin/activate)"
