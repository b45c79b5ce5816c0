#!/usr/bin/env bash
# Usage: scripts/check-format.sh [BASE]
#
# Checks that the C++ lines changed since BASE (default: origin/main, else main) are
# formatted as .clang-format says, with Debian's clang-format (`git clang-format`).
# Only changed lines, in changed files: existing code is not reformatted in bulk, and a
# one-line fix does not drag its whole file into the diff. Uncommitted changes count.
# Exit 0: all formatted. Exit 1: prints the diff that would fix it; apply it with
# `git clang-format $(git merge-base BASE HEAD)`. Exit 2: could not check.
set -euo pipefail
cd "$(git rev-parse --show-toplevel)"

base="${1:-}"
if [ -z "$base" ]; then
  for candidate in origin/main main; do
    if git rev-parse -q --verify "$candidate^{commit}" >/dev/null; then base="$candidate"; break; fi
  done
fi
if [ -z "$base" ] || ! git rev-parse -q --verify "$base^{commit}" >/dev/null; then
  echo "check-format: no base commit (${base:-origin/main or main}); give one: $0 BASE" >&2
  exit 2
fi
if ! command -v git-clang-format >/dev/null; then
  echo "check-format: git-clang-format not found (apt-get install clang-format)" >&2
  exit 2
fi

# This branch's changes only, not what BASE gained since the branch forked from it.
fork="$(git merge-base "$base" HEAD)"
status=0
out="$(git clang-format --diff --extensions cpp,cc,h,hpp "$fork" 2>&1)" || status=$?
# Debian's git-clang-format 14 exits 0 even when it prints a diff: look at what it printed.
if [ "$status" -eq 0 ] && grep -q '^diff --git' <<<"$out"; then status=1; fi
case "$status" in
  0) echo "check-format: C++ lines changed since $base ($(git rev-parse --short "$fork")) are formatted" ;;
  1) printf '%s\n' "$out"
     echo "check-format: the lines above differ from .clang-format; fix with: git clang-format $fork" >&2 ;;
  *) printf '%s\n' "$out" >&2
     echo "check-format: git clang-format failed ($status)" >&2
     status=2 ;;
esac
exit "$status"
