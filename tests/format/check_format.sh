#!/usr/bin/env bash
# The C++ sources follow .clang-format (clang-format 14, Debian's clang-format package): any file
# that clang-format would change fails this test, naming the file. Exit 77 (skipped) without
# clang-format. Usage: check_format.sh REPO_ROOT
set -euo pipefail
root=${1:?repository root}
command -v clang-format >/dev/null 2>&1 || { echo "clang-format is not installed: skipped"; exit 77; }
cd "$root"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files -co --exclude-standard -- 'core/*' 'render/*' 'ui/*' 'app/*' 'tests/*' 'bench/*' 'fuzz/*' |
                       grep -E '\.(cpp|hpp|h)$' || true)
else  # an unpacked source tree
  mapfile -t files < <(find core render ui app tests bench fuzz -name node_modules -prune -o -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print)
fi
[[ ${#files[@]} -gt 100 ]] || { echo "only ${#files[@]} sources found under $root" >&2; exit 1; }
bad=0
for f in "${files[@]}"; do
  if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then
    echo "not formatted: $f (clang-format -i $f)" >&2
    bad=$((bad + 1))
  fi
done
echo "check_format: ${#files[@]} files, $bad not formatted"
[[ $bad -eq 0 ]]
