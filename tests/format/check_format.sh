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
# One clang-format process for every file (one per file took a minute of CI): each violation is
# reported as "FILE:LINE:COL: error: code should be clang-formatted".
out=$(clang-format --dry-run --Werror "${files[@]}" 2>&1) || true
mapfile -t badfiles < <(grep -oE '^[^:]+:[0-9]+:[0-9]+: error' <<<"$out" | cut -d: -f1 | sort -u || true)
for f in "${badfiles[@]}"; do echo "not formatted: $f (clang-format -i $f)" >&2; done
if [[ ${#badfiles[@]} -eq 0 ]] && grep -q "error" <<<"$out"; then echo "$out" >&2; echo "check_format: clang-format failed" >&2; exit 1; fi
echo "check_format: ${#files[@]} files, ${#badfiles[@]} not formatted"
[[ ${#badfiles[@]} -eq 0 ]]
