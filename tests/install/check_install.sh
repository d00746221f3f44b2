#!/usr/bin/env bash
# ctest `packaging_install`: installs the build in BUILD_DIR into a temporary prefix with
# `cmake --install` and checks what packaging/ puts there: the binary (its --version), the desktop
# entry (desktop-file-validate, where installed), the icon and the MIME type (xmllint and
# update-mime-database, where installed) and the man page (names `export` and the version; groff
# formats it without a warning, where installed).
# The build's cache says which parts it has: no desktop entry without the editor
# (PATCHWORK_BUILD_EDITOR), no man page with PATCHWORK_BUILD_MANPAGE=OFF.
# Usage: check_install.sh BUILD_DIR   ($CMAKE: the cmake to run, default: cmake on PATH)
set -euo pipefail
build=${1:?usage: check_install.sh BUILD_DIR}
cmake=${CMAKE:-cmake}
cache=$build/CMakeCache.txt

fail() {
  echo "check_install: $*" >&2
  exit 1
}
[[ -f $cache ]] || fail "$cache: not a configured CMake build"

# cache_value NAME DEFAULT: the build's cached value of NAME, or DEFAULT where unset or empty.
cache_value() {
  local v
  v=$(sed -n "s/^$1:[A-Z]*=//p" "$cache" | head -n 1)
  echo "${v:-$2}"
}
is_on() {
  case "${1^^}" in ON | TRUE | YES | Y | 1) return 0 ;; *) return 1 ;; esac
}

version=$(cache_value CMAKE_PROJECT_VERSION "")
[[ -n $version ]] || fail "$cache: no CMAKE_PROJECT_VERSION"
datarootdir=$(cache_value CMAKE_INSTALL_DATAROOTDIR share)
bindir=$(cache_value CMAKE_INSTALL_BINDIR bin)
datadir=$(cache_value CMAKE_INSTALL_DATADIR "$datarootdir")
mandir=$(cache_value CMAKE_INSTALL_MANDIR "$datarootdir/man")

prefix=$(mktemp -d "${TMPDIR:-/tmp}/patchwork-install.XXXXXX")
trap 'rm -rf "$prefix"' EXIT

if ! log=$(env -u DESTDIR "$cmake" --install "$build" --prefix "$prefix/usr" 2>&1); then
  echo "$log" >&2
  fail "cmake --install $build failed"
fi

bin=$prefix/usr/$bindir/patchwork
desktop=$prefix/usr/$datadir/applications/patchwork.desktop
icon=$prefix/usr/$datadir/icons/hicolor/scalable/apps/patchwork.svg
mime=$prefix/usr/$datadir/mime/packages/patchwork.xml
man=$prefix/usr/$mandir/man1/patchwork.1

expected=("$bin" "$icon" "$mime")
if is_on "$(cache_value PATCHWORK_BUILD_EDITOR ON)"; then expected+=("$desktop"); fi
if is_on "$(cache_value PATCHWORK_BUILD_MANPAGE ON)"; then expected+=("$man"); fi
for f in "${expected[@]}"; do
  [[ -s $f ]] || fail "${f#"$prefix"/usr/}: not installed (cmake --install said: $log)"
done
[[ -x $bin ]] || fail "$bin: not executable"

# The installed binary runs and reports the project's version.
out=$("$bin" --version) || fail "$bin --version: exit $?"
[[ $out == "patchwork $version" ]] || fail "$bin --version printed '$out', expected 'patchwork $version'"

if [[ -f $desktop ]]; then
  grep -qx 'Exec=patchwork %f' "$desktop" || fail "$desktop: no 'Exec=patchwork %f'"
  grep -qx 'MimeType=application/x-patchwork;' "$desktop" || fail "$desktop: no MimeType application/x-patchwork"
  if command -v desktop-file-validate >/dev/null 2>&1; then
    # Hints (Graphics and Education are both main categories) are printed, not failed.
    desktop-file-validate "$desktop" || fail "$desktop: desktop-file-validate failed"
  else
    echo "check_install: desktop-file-validate not installed (package desktop-file-utils): desktop entry not validated"
  fi
fi

if command -v xmllint >/dev/null 2>&1; then
  xmllint --noout "$icon" "$mime" || fail "xmllint: $icon or $mime is not well-formed XML"
fi
if command -v update-mime-database >/dev/null 2>&1; then
  # (Its note that the temporary prefix is not in XDG_DATA_DIRS is expected: kept quiet.)
  mime_log=$(update-mime-database "$prefix/usr/$datadir/mime" 2>&1) || fail "update-mime-database rejected $mime: $mime_log"
  grep -qx 'application/x-patchwork:\*\.patchwork' "$prefix/usr/$datadir/mime/globs" ||
    fail "update-mime-database: *.patchwork does not map to application/x-patchwork"
  grep -qx 'application/x-patchwork application/json' "$prefix/usr/$datadir/mime/subclasses" ||
    fail "update-mime-database: application/x-patchwork is not a sub-class of application/json"
fi

if [[ -f $man ]]; then
  grep -q 'export' "$man" || fail "$man: does not mention the export command"
  grep -qF "patchwork $version" "$man" || fail "$man: does not mention the version $version"
  grep -q '^\.SS "patchwork export ' "$man" || fail "$man: no section for the export command"
  if command -v groff >/dev/null 2>&1; then
    warnings=$(groff -k -man -Tutf8 -ww -z "$man" 2>&1) || fail "groff could not format $man: $warnings"
    [[ -z $warnings ]] || fail "groff warns about $man: $warnings"
  fi
fi

echo "check_install: ok (${#expected[@]} files under $prefix/usr, version $version)"
