#!/usr/bin/env bash
# Formats the C++ sources with clang-format and the repository's .clang-format.
# Only git-tracked *.h and *.cc files are touched: clang-format treats any other file (Markdown,
# TOML, CMake, CSV) as C++ and reflows it into nonsense, so never run it on anything else.
# Usage: scripts/format.sh           format in place
#        scripts/format.sh --check   change nothing; list the files that need formatting, exit 1
set -euo pipefail
cd "$(dirname "$0")/.."
mode=format
case "${1:-}" in
  "") ;;
  --check) mode=check ;;
  *) echo "usage: scripts/format.sh [--check]" >&2; exit 2 ;;
esac
command -v clang-format > /dev/null || { echo "clang-format not found" >&2; exit 2; }
mapfile -d '' files < <(git ls-files -z -- '*.h' '*.cc')
[ ${#files[@]} -gt 0 ] || exit 0
if [ "$mode" = format ]; then
  clang-format -i --style=file -- "${files[@]}"
  exit 0
fi
status=0
for f in "${files[@]}"; do
  if ! clang-format --style=file --dry-run --Werror -- "$f" > /dev/null 2>&1; then
    echo "$f"
    status=1
  fi
done
exit $status
