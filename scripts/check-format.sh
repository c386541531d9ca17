#!/usr/bin/env bash
# Fails, naming each file, when a C++ source of the repository does not match .clang-format as
# Debian 12's clang-format 14 writes it (the version is pinned: another version formats some
# constructs differently). To fix: clang-format-14 -i <file>.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
formatter="${CLANG_FORMAT:-clang-format-14}"
if ! command -v "$formatter" >/dev/null; then
  echo "check-format: $formatter is missing (scripts/install-deps.sh installs it)" >&2
  exit 1
fi
cd "$root"
bad=0
checked=0
while IFS= read -r -d '' file; do
  checked=$((checked + 1))
  if ! "$formatter" --dry-run -Werror "$file" >/dev/null 2>&1; then
    echo "FAILED: $file does not match .clang-format (run: $formatter -i $file)"
    bad=$((bad + 1))
  fi
done < <(git ls-files -z -- '*.h' '*.cxx' '*.cu' '*.cuh')
echo "check-format: $checked files, $bad not formatted"
[ "$bad" -eq 0 ]
