#!/usr/bin/env bash
# Checks that the C++ of src/ and tests/ is formatted as .clang-format says (clang-format 14,
# Debian's clang-format package); names the files that are not and exits 1. To format them:
#   scripts/check-format.sh --fix
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
if ! command -v clang-format >/dev/null 2>&1; then
  echo "check-format: clang-format is missing (apt-get install clang-format)" >&2
  exit 1
fi
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  # New files too (not yet added), so that a check before the commit sees what CI will see.
  mapfile -t files < <(git ls-files --cached --others --exclude-standard 'src/*.cpp' 'src/*.hpp' 'tests/*.cpp' 'tests/*.hpp')
else
  mapfile -t files < <(find src tests -name '*.cpp' -o -name '*.hpp')
fi
if [[ "${1:-}" == "--fix" ]]; then
  clang-format -i "${files[@]}"
  exit 0
fi
# One run over all files; --Werror makes every change it would make an error naming the file.
if ! report="$(clang-format --dry-run --Werror "${files[@]}" 2>&1)"; then
  echo "check-format: not formatted as .clang-format says (scripts/check-format.sh --fix):" >&2
  printf '%s\n' "$report" | grep -E ': (error|warning):' | cut -d: -f1 | sort -u | sed 's/^/  /' >&2
  exit 1
fi
echo "check-format: ${#files[@]} files formatted"
