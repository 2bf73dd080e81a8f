#!/usr/bin/env bash
# Checks that every tracked C++ file is formatted with the checked-in .clang-format.
# Exits non-zero and lists the files that deviate. Fix with:
#   git ls-files '*.cpp' '*.h' | xargs clang-format -i
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "check-format: clang-format is not installed" >&2; exit 1; }
deviating=()
while IFS= read -r file; do
    if ! clang-format --dry-run --Werror "$file" >/dev/null 2>&1; then deviating+=("$file"); fi
done < <(git ls-files '*.cpp' '*.h')
if [[ ${#deviating[@]} -gt 0 ]]; then
    printf 'check-format: not formatted with .clang-format:\n'; printf '  %s\n' "${deviating[@]}"
    exit 1
fi
echo "check-format: every C++ file is formatted"
