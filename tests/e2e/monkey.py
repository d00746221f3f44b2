#!/usr/bin/env python3
"""Random input for the editor (issue 72): seeded keys, clicks, drags, wheel and palette commands,
about 100 a minute, on one document, under the X display and environment the caller set up
(tests/e2e/editor_monkey_e2e.sh: Xvfb, the validation layer, a private state folder, the trace).

It watches for aborts and crashes, stalls (no frame within 10 s of an input), validation messages,
memory growth, and afterwards checks the invariants: the document is saved through the palette,
`patchwork info` reopens it with every join within tolerance, and a second save of the reopened
file is byte-identical. A failure prints the seed and the last actions, and writes every action to
ACTIONS so that `monkey.py --replay ACTIONS …` plays them again, with the same pauses.

One editor runs every document given, in turn: the first is opened on the command line, the others
through the palette's `open` (each after the previous one is saved), each with its own random
stream, seeded by the seed and the document's name.

Usage: monkey.py --bin PATCHWORK --work DIR --seed N --seconds S [--replay ACTIONS] DOC...
Exit status: 0 passed, 1 a fault was found.
"""
import argparse
import json
import os
import random
import shlex
import shutil
import subprocess
import sys
import time

STALL_SECONDS = 10.0
KEYS = (list("abcdefghijklmnopqrstuvwxyz0123456789") +
        ["Escape", "Escape", "Return", "Tab", "Delete", "BackSpace", "space", "Left", "Right", "Up", "Down",
         "F1", "F2", "F3", "F4", "F5", "F6", "F7", "F8", "F9", "F10", "F12", "KP_1", "KP_3", "KP_7",
         "ctrl+z", "ctrl+z", "ctrl+y", "ctrl+shift+z", "ctrl+a", "ctrl+d", "ctrl+i", "ctrl+l", "ctrl+n",
         "ctrl+o", "ctrl+s", "ctrl+shift+s", "ctrl+1", "ctrl+3", "ctrl+7", "alt+a", "alt+h", "alt+z",
         "shift+a", "shift+d", "shift+h", "shift+Tab", "plus", "minus", "bracketleft", "bracketright"])
# Palette commands: {p} a patch number, {q} another, {e}/{f} an edge, {c} a curve, {n} a net,
# {x} a small number, {k} a continuity. Refusals are fine: only faults count.
COMMANDS = [
    "undo", "redo", "undo", "move 0 0 {x}", "move {x} 0 0", "rotate Z {a}", "scale {s}", "select patch {p}",
    "select all", "select none", "split u {t}", "split v {t}", "join {p}:{e} {q}:{f} {k}", "unjoin {p}:{e}",
    "flip", "mirror X", "mirror Z", "duplicate", "delete", "add-patch", "add-sphere", "add-curve",
    "slide n {x}", "net-basis 0 bezier", "net-basis 0 bspline", "fill-hole {p}:{e} {q}:{f}",
    "blend {p}:{e} {q}:{f} {k}", "revolve {p}:{e} Z {a}", "extrude {p}:{e} {x}", "project c{c} {p}",
    "trim {p} c{c} keep", "trim {p} c{c} remove", "intersect {p} {q}", "untrim {p}", "bake c{c}",
    "split-ring {p} u {t}", "set tess.level {l}", "tess-fixed equal {l}", "curve-through 0,0,0 1,0,0 1,1,{x}",
    "loft c{c} c{c}", "select patch {p}; split u {t}", "view front", "view top", "frame",
]


class Fault(Exception):
    pass


class Monkey:
    def __init__(self, a):
        self.a = a
        self.rng = None
        self.doc = a.docs[0]
        self.actions = []  # (pause, kind, args) as played
        self.proc = None
        self.trace_path = os.environ.get("PATCHWORK_EDITOR_TRACE") or os.path.join(a.work, "trace.json")
        os.environ["PATCHWORK_EDITOR_TRACE"] = self.trace_path
        self.err_path = os.path.join(a.work, "editor.err")
        self.restarts = 0
        self.baseline_rss = None
        self.peak_rss = 0

    # --- the editor --------------------------------------------------------------------------
    def trace(self):
        try:
            with open(self.trace_path) as f:
                return json.load(f)
        except (OSError, ValueError):
            return None

    def start(self):
        if os.path.exists(self.trace_path):
            os.remove(self.trace_path)
        # A start after a killed editor would offer its autosave for recovery (a modal): the
        # harness removes it (recovery has its own tests).
        state = os.path.join(os.environ.get("XDG_STATE_HOME", ""), "patchwork")
        if os.path.isdir(state):
            for f in os.listdir(state):
                if f.startswith("autosave-"):
                    os.remove(os.path.join(state, f))
        with open(self.err_path, "a") as err:
            self.proc = subprocess.Popen([self.a.bin, self.doc], cwd=self.a.work, stdout=subprocess.DEVNULL,
                                         stderr=err)
        t0 = time.time()
        while time.time() - t0 < 90:
            self.check_alive("starting")
            t = self.trace()
            if t and t.get("frame", 0) >= 2:
                self.size = t["window"]
                return
            time.sleep(0.1)
        raise Fault("the editor did not draw its first frames within 90 s")

    def check_alive(self, when):
        rc = self.proc.poll()
        if rc is None:
            return True
        if rc == 0:  # quit through the menu or a prompt: not a fault, start again
            self.restarts += 1
            self.start()
            return False
        tail = open(self.err_path, errors="replace").read()[-3000:]
        raise Fault(f"the editor died {when} (exit status {rc}{', signal ' + str(-rc) if rc < 0 else ''})\n{tail}")

    def rss_mb(self):
        try:
            for line in open(f"/proc/{self.proc.pid}/status"):
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) / 1024.0
        except OSError:
            pass
        return 0.0

    def wait_frame(self, after, what):
        t0 = time.time()
        while time.time() - t0 < STALL_SECONDS:
            if not self.check_alive(what):
                return
            t = self.trace()
            if t and t.get("frame", 0) > after:
                return t
            time.sleep(0.05)
        raise Fault(f"stall: no frame for {STALL_SECONDS:.0f} s after {what}")

    def check(self, t, what):
        if t is None:
            return
        if t.get("validationMessages", 0):
            raise Fault(f"validation messages after {what}")
        rss = self.rss_mb()
        self.peak_rss = max(self.peak_rss, rss)
        if self.baseline_rss is None and len(self.actions) >= 20:
            self.baseline_rss = rss
        if self.baseline_rss and rss > 2 * self.baseline_rss + 512:
            raise Fault(f"memory grew from {self.baseline_rss:.0f} MB to {rss:.0f} MB")

    # --- actions ------------------------------------------------------------------------------
    def move(self, x, y):
        # `mousemove --sync` waits for the pointer to move: to where it already is, it waits ~15 s.
        if (x, y) == getattr(self, "mouse", None):
            return
        self.mouse = (x, y)
        self.xdo("mousemove", "--sync", x, y)

    def xdo(self, *args):
        subprocess.run(["xdotool", *map(str, args)], check=False, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)

    def random_action(self):
        r, rng = self.rng.random(), self.rng
        w, h = self.size
        pt = lambda: (rng.randrange(0, w), rng.randrange(0, h))
        if r < 0.28:
            return ("key", [rng.choice(KEYS)])
        if r < 0.50:
            x, y = pt()
            mods = rng.choice(["", "", "", "shift", "ctrl", "alt"])
            return ("click", [x, y, rng.choice([1, 1, 1, 3]), mods])
        if r < 0.68:
            (x0, y0), (x1, y1) = pt(), pt()
            return ("drag", [x0, y0, x1, y1, rng.choice([1, 1, 2, 3]), rng.choice(["", "", "shift", "ctrl", "alt"])])
        if r < 0.78:
            x, y = pt()
            return ("wheel", [x, y, rng.choice([4, 5]), rng.randrange(1, 6)])
        return ("palette", [self.random_command()])

    def random_command(self):
        rng = self.rng
        t = self.trace() or {}
        n = max(1, t.get("patches", 1))
        fill = {
            "p": rng.randrange(n), "q": rng.randrange(n), "c": rng.randrange(max(1, t.get("curves", 1))),
            "e": rng.choice(["u0", "u1", "v0", "v1"]), "f": rng.choice(["u0", "u1", "v0", "v1"]),
            "x": round(rng.uniform(-1, 1), 3), "t": round(rng.uniform(0.05, 0.95), 3),
            "s": round(rng.uniform(0.5, 1.5), 3), "a": rng.choice([30, 90, 180, 360]),
            "k": rng.choice(["C0", "C1", "G1", "C2", "G2"]), "l": rng.randrange(1, 40),
        }
        return rng.choice(COMMANDS).format(**fill)

    def play(self, kind, args):
        if kind == "key":
            self.xdo("key", "--clearmodifiers", args[0])
        elif kind == "click":
            x, y, button, mods = args
            self.move(x, y)
            if mods:
                self.xdo("keydown", mods)
            self.xdo("click", button)
            if mods:
                self.xdo("keyup", mods)
        elif kind == "drag":
            x0, y0, x1, y1, button, mods = args
            self.move(x0, y0)
            if mods:
                self.xdo("keydown", mods)
            self.xdo("mousedown", button)
            for i in range(1, 9):
                time.sleep(0.02)
                self.xdo("mousemove", x0 + (x1 - x0) * i // 8, y0 + (y1 - y0) * i // 8)
            self.mouse = (x1, y1)
            self.xdo("mouseup", button)
            if mods:
                self.xdo("keyup", mods)
        elif kind == "wheel":
            x, y, button, n = args
            self.move(x, y)
            self.xdo("click", "--repeat", n, "--delay", 30, button)
        elif kind == "palette":
            # Typing goes to the palette only once it is open: on a slow frame (a heavy document on
            # lavapipe) keys sent earlier reach the view as shortcuts.
            self.xdo("key", "F3")
            t0 = time.time()
            while time.time() - t0 < 3:
                t = self.trace() or {}
                if t.get("palette") and t.get("modal") == "palette":
                    break
                time.sleep(0.05)
            else:
                return  # a modal or the lesson kept it closed: the action is a key press only
            time.sleep(0.1)
            self.xdo("type", "--delay", 15, args[0])
            time.sleep(0.2)
            self.xdo("key", "Return")

    def describe(self, i, pause, kind, args):
        return f"{i:5d}  +{pause:.2f}s  {kind} {' '.join(shlex.quote(str(v)) for v in args)}"

    # --- the run ------------------------------------------------------------------------------
    def run(self):
        """Every document in turn; returns the number that failed (each failure printed)."""
        failed = 0
        self.start()
        for n, doc in enumerate(self.a.docs):
            self.doc, self.actions = doc, []
            self.rng = random.Random(f"{self.a.seed}:{os.path.basename(doc)}")
            try:
                if n:
                    self.open(doc)
                self.run_one()
                print(f"monkey: {os.path.basename(doc)} seed {self.a.seed}: {len(self.actions)} actions, "
                      f"{self.restarts} restarts after a quit, peak {self.peak_rss:.0f} MB: passed", flush=True)
            except (Fault, subprocess.TimeoutExpired) as e:
                failed += 1
                self.report(e)
                if self.proc.poll() is None:
                    self.proc.kill()
                    self.proc.wait()
                if n + 1 < len(self.a.docs):
                    self.doc = self.a.docs[n + 1]
                    self.start()
        if self.proc.poll() is None:
            self.quit()
        return failed

    def report(self, e):
        shot = os.path.join(self.a.work, f"failure-{os.path.basename(self.doc)}-{self.a.seed}.png")
        if shutil.which("import") and subprocess.run(["import", "-window", "root", shot], capture_output=True).returncode == 0:
            print(f"monkey: screenshot {shot}")
        log = os.path.join(self.a.work, f"actions-{os.path.basename(self.doc)}-{self.a.seed}.jsonl")
        with open(log, "w") as f:
            for act in self.actions:
                f.write(json.dumps(act) + "\n")
        print(f"monkey: FAIL on {self.doc} with seed {self.a.seed}: {e}")
        print(f"monkey: the last actions (all {len(self.actions)} in {log}; replay with "
              f"monkey.py --replay {log} --bin … --work … {self.doc}):")
        for i, (pause, kind, args) in enumerate(self.actions[-30:], start=max(0, len(self.actions) - 30)):
            print("  " + self.describe(i, pause, kind, args), flush=True)

    def open(self, doc):
        self.close_dialogs()
        self.play("palette", [f"open {doc}"])
        t0 = time.time()
        while time.time() - t0 < 60:
            self.check_alive("opening " + doc)
            t = self.trace() or {}
            if t.get("file") == doc and not t.get("palette"):
                return
            time.sleep(0.1)
        raise Fault(f"`open {doc}` did not open it in 60 s (modal {t.get('modal')!r}, error {t.get('error')!r})")

    def quit(self):
        # Saved, so the document is unmodified: Ctrl+Q quits without a prompt.
        self.close_dialogs()
        self.xdo("key", "ctrl+q")
        try:
            rc = self.proc.wait(30)
        except subprocess.TimeoutExpired:
            raise Fault(f"Ctrl+Q did not quit (modal: {(self.trace() or {}).get('modal')!r})")
        if rc != 0:
            raise Fault(f"the editor quit with exit status {rc}")

    def run_one(self):
        plan = None
        if self.a.replay:
            plan = [json.loads(line) for line in open(self.a.replay) if line.strip()]
        t_end = time.time() + self.a.seconds
        i = 0
        while (plan is not None and i < len(plan)) or (plan is None and time.time() < t_end):
            if plan is not None:
                pause, kind, args = plan[i]
            else:
                pause = round(self.rng.uniform(0.1, 1.0), 2)
                kind, args = self.random_action()
            self.actions.append((pause, kind, args))
            time.sleep(pause)
            t_start = time.time()
            what = self.describe(i, pause, kind, args).strip()
            t0 = self.trace() or {}
            self.check_alive("before " + what)
            self.play(kind, args)
            self.move(2 + i % 3, 2)  # an event, so that a frame follows
            t = self.wait_frame(t0.get("frame", 0), what)
            self.check(t, what)
            if os.environ.get("MONKEY_VERBOSE"):
                print(f"  {time.time() - t_start:6.1f}s {what}", flush=True)
            i += 1
        self.finish()

    def close_dialogs(self):
        for _ in range(12):
            self.check_alive("while closing dialogs")
            t = self.trace() or {}
            if t.get("modal") == "error" or t.get("error"):
                self.xdo("key", "Return")
            elif t.get("modal") == "unsaved":
                self.xdo("key", "Escape")
            elif t.get("modal") or t.get("palette") or t.get("help"):
                self.xdo("key", "Escape")
            elif t.get("presentation"):
                self.xdo("key", "F5")
            elif t.get("mode") not in (None, "", "Idle", "idle"):
                self.xdo("key", "Escape")
            else:
                break
            time.sleep(0.4)

    def finish(self):
        """Closes what is open and saves through the palette; then the invariants."""
        stem = os.path.splitext(os.path.basename(self.doc))[0]
        out = os.path.join(self.a.work, f"{stem}-out.patchwork")
        again = os.path.join(self.a.work, f"{stem}-again.patchwork")
        for p in (out, again):
            if os.path.exists(p):
                os.remove(p)
        self.close_dialogs()
        self.play("palette", [f"save {out}"])
        t0 = time.time()
        while not os.path.exists(out) and time.time() - t0 < 60:
            self.check_alive("saving")
            t = self.trace() or {}
            if t.get("error"):
                raise Fault(f"the document could not be saved: {t['error']}")
            time.sleep(0.2)
        if not os.path.exists(out):
            t = self.trace() or {}
            raise Fault(f"the palette's save wrote nothing in 60 s (modal {t.get('modal')!r}, palette {t.get('palette')!r}, "
                        f"mode {t.get('mode')!r}, lesson {t.get('lesson')!r})")
        info = subprocess.run([self.a.bin, "info", out], capture_output=True, text=True)
        if info.returncode != 0:
            raise Fault(f"the saved document does not reopen:\n{info.stdout}{info.stderr}")
        tol = [l for l in info.stdout.splitlines() if l.strip().startswith("out of tolerance")]
        if not tol or not tol[0].split()[3] == "0":
            raise Fault(f"joins out of tolerance after the run: {tol}")
        conv = subprocess.run([self.a.bin, "convert", out, again], capture_output=True, text=True)
        if conv.returncode != 0:
            raise Fault(f"the saved document cannot be saved again:\n{conv.stderr}")
        if open(out, "rb").read() != open(again, "rb").read():
            raise Fault("the saved document changes when it is reopened and saved again")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--bin", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--seconds", type=float, default=60)
    p.add_argument("--replay")
    p.add_argument("docs", nargs="+")
    a = p.parse_args()
    os.makedirs(a.work, exist_ok=True)
    m = Monkey(a)
    try:
        failed = m.run()
    except (Fault, subprocess.TimeoutExpired) as e:
        m.report(e)
        failed = 1
    finally:
        if m.proc and m.proc.poll() is None:
            m.proc.kill()
            m.proc.wait()
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
