#!/usr/bin/python3
"""The operator station under random real input (issue 21's monkey test).

The real `cutcell` binary under Xvfb with openbox gets random X events from xdotool (XTEST,
through the X server): clicks (left, sometimes right), drags — a share of them across the
window's splitter handles, found in its accessibility tree —, mouse wheel turns and keys
(F1-F12, Tab, Enter, Escape, digits, separators, letters, arrows). The seed makes a run
repeatable. A crash fails the run: a signal, a sanitizer report or any exit the monkey did not
ask for (a random click on File -> Quit is answered, the program restarted and counted).

Run as: dbus-run-session -- /usr/bin/python3 monkey.py --cutcell BIN --job FILE
        --seconds 600 --seed 1 [--size 1280x720] [--locale de_DE.UTF-8]
Exit 0 = no crash, 1 = a crash (the last events and the program's output are printed), 77 = a
tool is missing (skipped).
"""
import os
import random
import shutil
import signal
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import operator_walkthrough as walk  # noqa: E402  (Desk: Xvfb, openbox, AT-SPI, the process)

# Never the keys that end the program on purpose (Ctrl+Q) or open the file dialogs' modal
# loops for good (Ctrl+O waits on a dialog the monkey answers with Escape anyway).
KEYS = (["F%d" % n for n in range(1, 13)] + ["ctrl+shift+F1"] * 2 +
        ["Tab"] * 6 + ["shift+Tab"] * 3 + ["Return"] * 3 + ["Escape"] * 4 + ["space"] * 2 +
        ["Up", "Down", "Left", "Right", "Page_Up", "Page_Down", "Home", "End", "BackSpace",
         "Delete", "comma", "period", "minus"] +
        [str(d) for d in range(10)] + list("aeEx") + ["ctrl+s", "ctrl+z", "ctrl+a"])
SANITIZER_MARKS = ("ERROR: AddressSanitizer", "runtime error:", "ERROR: LeakSanitizer",
                   "SUMMARY: UndefinedBehaviorSanitizer")


class Crash(Exception):
    pass


class Monkey:
    def __init__(self, desk, rng):
        self.desk = desk
        self.rng = rng
        self.events = []  # the last ones, for a crash's report
        self.counts = {"click": 0, "right click": 0, "drag": 0, "splitter drag": 0, "wheel": 0,
                       "key": 0, "restart": 0}
        self.handles = []

    def note(self, what):
        self.events.append("%7.1f s  %s" % (time.time() - self.t0, what))
        del self.events[:-40]

    def point(self):
        return self.rng.randrange(self.desk.width), self.rng.randrange(self.desk.height)

    def find_handles(self):
        """The gaps between the children of each split pane: where its handles are."""
        self.handles = []
        for pane in self.desk.nodes("split pane"):
            kids = []
            for i in range(pane.get_child_count()):
                c = pane.get_child_at_index(i)
                if c is None:
                    continue
                e = c.get_extents(walk.Atspi.CoordType.SCREEN)
                if e.width > 0 and e.height > 0:
                    kids.append(e)
            kids.sort(key=lambda e: (e.x, e.y))
            for a, b in zip(kids, kids[1:]):
                if b.x >= a.x + a.width:  # side by side: a vertical handle
                    self.handles.append(("x", (a.x + a.width + b.x) // 2, a.y + a.height // 2))
                elif b.y >= a.y + a.height:  # one above the other
                    self.handles.append(("y", a.x + a.width // 2, (a.y + a.height + b.y) // 2))

    def step(self):
        d, r = self.desk, self.rng
        kind = r.choices(["click", "right click", "drag", "splitter drag", "wheel", "key"],
                         [30, 3, 8, 6, 12, 41])[0]
        if kind == "splitter drag" and not self.handles:
            kind = "drag"
        if kind in ("click", "right click"):
            x, y = self.point()
            d.xdo("mousemove", str(x), str(y), "click", "1" if kind == "click" else "3")
            self.note("%s at %d,%d" % (kind, x, y))
        elif kind == "drag":
            (x, y), (x2, y2) = self.point(), self.point()
            d.xdo("mousemove", str(x), str(y), "mousedown", "1", "mousemove", str(x2), str(y2),
                  "mouseup", "1")
            self.note("drag %d,%d -> %d,%d" % (x, y, x2, y2))
        elif kind == "splitter drag":
            axis, x, y = r.choice(self.handles)
            x2, y2 = (self.point()[0], y) if axis == "x" else (x, self.point()[1])
            d.xdo("mousemove", str(x), str(y), "mousedown", "1", "mousemove", str((x + x2) // 2),
                  str((y + y2) // 2), "mousemove", str(x2), str(y2), "mouseup", "1")
            self.note("splitter drag %d,%d -> %d,%d" % (x, y, x2, y2))
        elif kind == "wheel":
            x, y = self.point()
            button = r.choice(["4", "5"])
            d.xdo("mousemove", str(x), str(y), "click", "--repeat", str(r.randint(1, 4)), button)
            self.note("wheel %s at %d,%d" % ("up" if button == "4" else "down", x, y))
        else:
            key = r.choice(KEYS)
            d.xdo("key", key)
            self.note("key " + key)
        self.counts[kind] += 1

    def check(self):
        app = self.desk.app
        code = app.poll()
        self.desk.log.flush()
        with open(os.path.join(self.desk.work, "cutcell.log"), errors="replace") as f:
            text = f.read()
        marks = [m for m in SANITIZER_MARKS if m in text]
        if marks:
            raise Crash("sanitizer report (%s)" % ", ".join(marks))
        if code is None:
            return
        if code < 0:
            raise Crash("cutcell died of signal %s" % signal.Signals(-code).name)
        if code != 0:
            raise Crash("cutcell exited with %d" % code)
        # A clean exit: the monkey found File -> Quit (and answered its question). Again.
        self.note("cutcell quit (exit 0): started again")
        self.counts["restart"] += 1
        self.desk.procs.remove(app)
        self.desk.start_app()
        time.sleep(3)
        self.find_handles()

    def run(self, seconds):
        self.t0 = time.time()
        end = self.t0 + seconds
        n = 0
        while time.time() < end:
            self.step()
            n += 1
            time.sleep(self.rng.uniform(0.02, 0.25))
            if n % 10 == 0:
                self.check()
            if n % 150 == 0:  # the layout changed under the drags: find the handles again
                try:
                    self.find_handles()
                except Exception:
                    pass
        self.check()
        return n


def main():
    def options(ap):
        ap.add_argument("--seconds", type=float, default=600)
        ap.add_argument("--seed", type=int, default=1)

    args = walk.desk_arguments(options)
    work = tempfile.mkdtemp(prefix="cutcell-monkey-")
    args.job_copy = os.path.join(work, os.path.basename(args.job))
    shutil.copy(args.job, args.job_copy)
    print("monkey: %s at %s, %s, %g s, seed %d" % (os.path.basename(args.job), args.size,
                                                   args.locale, args.seconds, args.seed))
    desk = walk.Desk(args, work)
    monkey = Monkey(desk, random.Random(args.seed))
    try:
        desk.start()
        desk.one("push button", lambda n: bool(n), "the window's first button")
        monkey.find_handles()
        print("  splitter handles found: %d" % len(monkey.handles))
        n = monkey.run(args.seconds)
    except (Crash, walk.StepFailed) as e:
        shot = desk.screenshot(os.path.join(work, "crash.png"))
        desk.stop()
        print("FAILED: %s" % e)
        print("--- the last events ---\n" + "\n".join(monkey.events))
        if shot:
            print("the screen: " + shot)
        with open(os.path.join(work, "cutcell.log"), errors="replace") as f:
            print("--- cutcell's output (last lines) ---\n" + "".join(f.readlines()[-60:]))
        return 1
    desk.stop()
    print("  %d events in %.0f s: %s" % (n, args.seconds, ", ".join(
        "%s %d" % kv for kv in monkey.counts.items())))
    shutil.rmtree(work, ignore_errors=True)
    print("PASSED: no crash")
    return 0


if __name__ == "__main__":
    sys.exit(main())
