#!/usr/bin/env bash
# Shared by the editor end-to-end tests: a private Xvfb display (optionally with a window manager),
# the editor's environment (validation layer on, trace file, private state directory), and helpers
# to read the editor's trace, wait for a condition in it and start the editor.
# Expects BIN and WORK to be set; the caller's `set -euo pipefail` applies.
LOG=$WORK/log.txt
: > "$LOG"
say() { echo "e2e: $*" | tee -a "$LOG"; }
fail() {
    say "FAIL: $*"
    command -v import >/dev/null && import -window root "$WORK/failure.png" 2>/dev/null && say "screenshot: $WORK/failure.png"
    [ -f "$WORK/editor.err" ] && tail -20 "$WORK/editor.err"
    [ -f "$WORK/trace.json" ] && python3 -c "import json; t=json.load(open('$WORK/trace.json')); print({k: t[k] for k in t if k not in ('points', 'world')})"
    exit 1
}
# A missing tool skips the test (exit 77) on a developer's machine; in CI (CI set), where
# scripts/install_deps.sh --tests installs every one of them, it fails instead, so that a broken
# install step cannot pass as a skipped editor test.
missing_tool() {
    echo "e2e: $1 missing"
    [ -n "${CI:-}" ] && exit 1
    exit 77
}
for tool in Xvfb xdotool python3; do command -v $tool >/dev/null || missing_tool $tool; done

# Xvfb picks a free display number itself (-displayfd) so parallel runs cannot collide; E2E_SCREEN
# sets its size (default 1280x800).
Xvfb -displayfd 3 -screen 0 ${E2E_SCREEN:-1280x800}x24 -nolisten tcp 3>"$WORK/display" >"$WORK/xvfb.log" 2>&1 &
XVFB=$!
for i in $(seq 100); do [ -s "$WORK/display" ] && break; sleep 0.1; done
DNUM=$(head -1 "$WORK/display" | tr -d '[:space:]')
[ -n "$DNUM" ] || { kill "$XVFB" 2>/dev/null; echo "e2e: Xvfb did not start"; cat "$WORK/xvfb.log"; exit 1; }
EDITOR_PID=""
WM_PID=""
cleanup() {
    [ -n "$EDITOR_PID" ] && kill -9 "$EDITOR_PID" 2>/dev/null || true
    [ -n "$WM_PID" ] && kill "$WM_PID" 2>/dev/null || true
    kill "$XVFB" 2>/dev/null || true
}
trap cleanup EXIT
export DISPLAY=:$DNUM
for i in $(seq 50); do xdotool getmouselocation >/dev/null 2>&1 && break; sleep 0.1; done
# E2E_WINDOW_MANAGER=openbox: a window manager, so that windows can be minimised and restored.
if [ -n "${E2E_WINDOW_MANAGER:-}" ]; then
    command -v "$E2E_WINDOW_MANAGER" >/dev/null || missing_tool "$E2E_WINDOW_MANAGER"
    "$E2E_WINDOW_MANAGER" >"$WORK/wm.log" 2>&1 &
    WM_PID=$!
    sleep 1
fi

export XDG_STATE_HOME=$WORK/state
export PATCHWORK_VALIDATION=1
export PATCHWORK_EDITOR_TRACE=$WORK/trace.json
export PATCHWORK_WINDOW_SIZE=1200x760
export PATCHWORK_EDITOR_VIEW=front
export PATCHWORK_AUTOSAVE_SECONDS=1.5

trace() { python3 -c "import json,sys; t=json.load(open('$WORK/trace.json')); print(eval(sys.argv[1]))" "$1"; }
# wait_for EXPR [seconds]: polls the trace until the Python expression over t is true.
wait_for() {
    local expr=$1 secs=${2:-30}
    for i in $(seq $((secs * 10))); do
        if [ -f "$WORK/trace.json" ] && python3 - "$expr" "$WORK/trace.json" <<'PY' 2>/dev/null; then return 0; fi
import json, sys
t = json.load(open(sys.argv[2]))
sys.exit(0 if eval(sys.argv[1]) else 1)
PY
        kill -0 "$EDITOR_PID" 2>/dev/null || fail "editor exited while waiting for: $expr"
        sleep 0.1
    done
    fail "timed out waiting for: $expr"
}
start_editor() {
    rm -f "$WORK/trace.json"
    "$BIN" "$@" >>"$WORK/editor.out" 2>>"$WORK/editor.err" &
    EDITOR_PID=$!
    wait_for "t['frame'] >= 2" 90
    WID=$(xdotool search --sync --pid "$EDITOR_PID" --name Patchwork | head -1)
}
check_validation() {
    [ "$(trace "t['validationMessages']")" = "0" ] || fail "validation messages reported"
    if grep -qi "validation" "$WORK/editor.err"; then fail "validation output on stderr"; fi
}

# click_item NAME: clicks the centre of a traced ImGui item (window coordinates; no window manager).
click_item() {
    read -r CX CY < <(trace "' '.join(str(round(v)) for v in t['items']['$1'])")
    xdotool mousemove --sync $CX $CY
    sleep 0.2
    xdotool click 1
}

# quit_editor: Ctrl+Q; discards unsaved changes if the prompt comes; the editor must exit with 0
# and have printed no validation message.
quit_editor() {
    xdotool key ctrl+q
    for i in $(seq 100); do kill -0 "$EDITOR_PID" 2>/dev/null || break; sleep 0.1; done
    if kill -0 "$EDITOR_PID" 2>/dev/null; then
        wait_for "t['modal'] == 'unsaved'"
        click_item unsaved.discard
        for i in $(seq 100); do kill -0 "$EDITOR_PID" 2>/dev/null || break; sleep 0.1; done
    fi
    kill -0 "$EDITOR_PID" 2>/dev/null && fail "editor did not quit"
    local rc=0
    wait "$EDITOR_PID" || rc=$?
    EDITOR_PID=""
    [ "$rc" = "0" ] || fail "editor exit code $rc"
    if grep -qi "validation" "$WORK/editor.err"; then fail "validation output on stderr"; fi
}
