#!/usr/bin/python3
"""The operator station driven by real X input events (issue 21's walkthrough).

Under Xvfb with a window manager (openbox), the real `cutcell` binary gets a shipped job (a copy,
so that Ctrl+S writes it); xdotool types and presses keys as an operator's keyboard and mouse
would (XTEST events through the X server, not Qt events). What the window shows is read from its
accessibility tree (AT-SPI over a private D-Bus session): after every step the EMERGENCY STOP
button must lie wholly on the screen, and the Start reason says what the machine does.

Steps: the first typeable decimal field of the machine's parameter pages (topmost on the first
page that has one; a catalogue section's greyed dimensions are skipped) takes "2,5"-style and
"2.5"-style input and letters (the job file, saved with Ctrl+S, must hold the typed value; letters change
nothing); Enable (F2), Home (F3), Start (F5), Feed hold (F6), Resume (F7), E-STOP (F1), Release
(Ctrl+Shift+F1), Reset (F4), Enable, Home, the cut recovery's "Resume from stop" where the
machine offers it (clicked with the mouse), Abort (F8 twice), Save As (Ctrl+Shift+S, a path
typed into the file dialog).

Run as: dbus-run-session -- /usr/bin/python3 operator_walkthrough.py --cutcell BIN --job FILE
        --size 1280x720 --locale de_DE.UTF-8
Exit 0 = every step held, 1 = a step failed (named), 77 = a tool is missing (skipped).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

SKIP = 77
STARTED = time.monotonic()  # the steps print their time since the start (a slow step shows)


def skip(why):
    print("SKIP: " + why)
    sys.exit(SKIP)


try:
    import gi

    gi.require_version("Atspi", "2.0")
    from gi.repository import Atspi
except (ImportError, ValueError) as e:  # python3-gi / gir1.2-atspi-2.0 missing
    Atspi = None
    ATSPI_ERROR = str(e)


class StepFailed(Exception):
    pass


# What the walkthrough reads on screen, in the GUI's languages. Under a German locale the GUI
# speaks German (ui/language.h: it follows the desktop); each German fragment is checked
# against the catalogue's translation of the text it comes from before the walk starts, so a
# changed translation fails here, named, not as a timeout half-way.
WORDS = {
    # fragment: (German fragment, the catalogue source the fragment is taken from)
    "Job": ("Auftrag", "Job"),
    "Start:": ("Start:", "Start: %1"),
    "E-STOP pressed": ("NOT-HALT betätigt",
                       "E-STOP pressed: remove the hazard, then Release E-STOP and Reset."),
    "EMERGENCY": ("NOT-HALT", "EMERGENCY\nSTOP  [%1]"),
    "Feed hold": ("Halt", "Feed hold"),
    "Resume from stop": ("Ab Halt fortsetzen", "Resume from stop"),
    "press Home": ("Referenzieren drücken", "axes not homed - press Home"),
    "homing": ("Referenzieren läuft", "homing in progress"),
    "running": ("läuft", "the cut is running"),
    "feed hold": ("Vorschub halt", "feed hold - press Resume or Abort"),
    "EMERGENCY STOP latched": ("NOT-HALT gespeichert", "EMERGENCY STOP latched - press Reset"),
    "press Enable": ("Freigeben drücken", "drives disabled - press Enable"),
}
LANGUAGE = "en"


def w(fragment):
    """The fragment as the GUI shows it in its language."""
    return WORDS[fragment][0] if LANGUAGE == "de" else fragment


def check_words(catalogue):
    """Each German fragment lies in the catalogue's translation of its source."""
    import xml.etree.ElementTree as ET

    translations = {}
    for ctx in ET.parse(catalogue).getroot().findall("context"):
        for m in ctx.findall("message"):
            translations.setdefault(m.find("source").text, []).append(
                m.find("translation").text or "")
    for english, (german, source) in WORDS.items():
        source = source.replace("\\n", "\n")
        if english not in source:
            raise StepFailed("walkthrough table: %r is not in its source %r" % (english, source))
        found = translations.get(source)
        if not found:
            raise StepFailed("walkthrough table: %r is not in %s" % (source, catalogue))
        if not any(german in t for t in found):
            raise StepFailed("walkthrough table: %r is not in the German of %r: %r"
                             % (german, source, found))


class Desk:
    """Xvfb, openbox, the AT-SPI bus and the cutcell process of one walkthrough."""

    def __init__(self, args, work):
        self.args = args
        self.work = work
        self.width, self.height = (int(v) for v in args.size.split("x"))
        self.procs = []
        self.display = None
        self.app = None
        self.reason_label = None
        self.log = open(os.path.join(work, "cutcell.log"), "w")

    def start(self):
        for n in range(90, 140):
            if not os.path.exists("/tmp/.X11-unix/X%d" % n) and not os.path.exists(
                "/tmp/.X%d-lock" % n
            ):
                self.display = ":%d" % n
                break
        env = dict(os.environ, DISPLAY=self.display)
        self.env = env
        self.spawn(["Xvfb", self.display, "-screen", "0", "%dx%dx24" % (self.width, self.height),
                    "-nolisten", "tcp"], env)
        self.wait(lambda: os.path.exists("/tmp/.X11-unix/X" + self.display[1:]), 10, "Xvfb up")
        self.spawn(["openbox"], env)
        for launcher in ("/usr/libexec/at-spi-bus-launcher", "/usr/lib/at-spi2-core/at-spi-bus-launcher"):
            if os.path.exists(launcher):
                self.spawn([launcher, "--launch-immediately"], env)
                break
        time.sleep(1.0)
        self.start_app()

    def start_app(self):
        """The cutcell process on this display (again after it quit, for the monkey)."""
        app_env = dict(self.env, QT_LINUX_ACCESSIBILITY_ALWAYS_ON="1", LC_ALL=self.args.locale,
                       LANG=self.args.locale, HOME=self.work,
                       XDG_CONFIG_HOME=os.path.join(self.work, "config"),
                       QT_LOGGING_RULES="qt.accessibility.atspi=false")
        app_env.pop("QT_QPA_PLATFORM", None)
        self.app = subprocess.Popen([self.args.cutcell, self.args.job_copy, "-platform", "xcb"],
                                    env=app_env, stdout=self.log, stderr=subprocess.STDOUT)
        self.procs.append(self.app)

    def spawn(self, cmd, env):
        self.procs.append(subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL,
                                           stderr=subprocess.DEVNULL))

    def screenshot(self, path):
        """The whole screen as PNG (xwd, netpbm), for a failure's report."""
        try:
            xwd = subprocess.run(["xwd", "-root", "-silent"], env=self.env, capture_output=True,
                                 timeout=10).stdout
            pnm = subprocess.run(["xwdtopnm"], input=xwd, capture_output=True, timeout=10).stdout
            png = subprocess.run(["pnmtopng"], input=pnm, capture_output=True, timeout=10).stdout
            with open(path, "wb") as f:
                f.write(png)
            return path
        except (OSError, subprocess.SubprocessError):
            return None

    def stop(self):
        for p in reversed(self.procs):
            if p.poll() is None:
                p.terminate()
                try:
                    p.wait(5)
                except subprocess.TimeoutExpired:
                    p.kill()
        self.log.close()

    def wait(self, cond, seconds, what):
        end = time.time() + seconds
        while time.time() < end:
            try:
                if cond():
                    return
            except Exception:  # the tree changes under us while the window rebuilds
                pass
            time.sleep(0.1)
        now = ""
        if self.app is not None:
            try:
                now = " (the Start reason now: %r)" % self.start_reason()
            except Exception:
                pass
        raise StepFailed("timed out after %g s waiting for: %s%s" % (seconds, what, now))

    # --- X input (xdotool: XTEST events through the server) ---
    def xdo(self, *args):
        subprocess.run(["xdotool"] + list(args), env=self.env, check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    def key(self, *keys):
        self.xdo("key", "--delay", "60", *keys)

    def type(self, text):
        self.xdo("type", "--delay", "40", text)

    def visible_rect(self, node):
        """The part of the screen where the node can be seen: its scroll area's viewport."""
        top, bottom = 0, self.height
        a = node
        for _ in range(30):
            try:
                a = a.get_parent()
                role = a.get_role_name() if a is not None else None
            except Exception:
                break
            if a is None:
                break
            if role in ("scroll pane", "viewport"):
                e = a.get_extents(Atspi.CoordType.SCREEN)
                top, bottom = max(top, e.y), min(bottom, e.y + e.height)
                break
        return top, bottom

    def scroll_into_view(self, node):
        """Turns the mouse wheel over the node's scroll area until the node is in view, as an
        operator would (the forms and the operator column's lower part scroll on a short
        screen)."""
        top, bottom = self.visible_rect(node)
        for _ in range(60):
            e = node.get_extents(Atspi.CoordType.SCREEN)
            if e.y >= top and e.y + e.height <= bottom:
                return
            x = min(max(e.x + e.width // 2, 0), self.width - 1)
            down = e.y + e.height > bottom
            y = bottom - 20 if down else top + 20
            self.xdo("mousemove", str(x), str(y), "click", "5" if down else "4")
            time.sleep(0.1)
        raise StepFailed("%r stays out of view after scrolling" % node.get_name())

    def click(self, node):
        self.scroll_into_view(node)
        e = node.get_extents(Atspi.CoordType.SCREEN)
        self.xdo("mousemove", str(e.x + e.width // 2), str(e.y + e.height // 2), "click", "1")

    # --- the accessibility tree ---
    def app_root(self):
        desktop = Atspi.get_desktop(0)
        for i in range(desktop.get_child_count()):
            a = desktop.get_child_at_index(i)
            if a is not None and a.get_name() == "cutcell":
                return a
        return None

    def nodes(self, role=None, name=None, showing=True):
        out = []

        def walk(a, depth):
            if a is None or depth > 40:
                return
            try:
                r = a.get_role_name()
                n = a.get_name() or ""
                st = a.get_state_set()
            except Exception:
                return
            if (role is None or r == role) and (name is None or name(n)) and (
                not showing or st.contains(Atspi.StateType.SHOWING)
            ):
                out.append(a)
            try:
                children = [a.get_child_at_index(i) for i in range(a.get_child_count())]
            except Exception:  # the application went away or rebuilt this part
                return
            for c in children:
                walk(c, depth + 1)

        walk(self.app_root(), 0)
        return out

    def one(self, role, name, what):
        found = []
        self.wait(lambda: found.extend(self.nodes(role, name)) or found, 20, what)
        return found[0]

    def start_reason(self):
        """The Start reason under the operator's buttons ("" when Start is free). Its label is
        found once and then read directly: a walk of the whole tree takes about a second, longer
        than the quick-return cutter's whole run."""
        if self.reason_label is not None:
            try:
                return self.reason_label.get_name() or ""
            except Exception:
                self.reason_label = None
        labels = self.nodes("label", lambda n: n.startswith(w("Start:")) or n.startswith(w("E-STOP pressed")))
        if labels:
            self.reason_label = labels[0]
        return labels[0].get_name() if labels else ""


def estop_on_screen(desk, step):
    button = desk.one("push button", lambda n: n.startswith(w("EMERGENCY")), "the E-STOP button")
    e = button.get_extents(Atspi.CoordType.SCREEN)
    inside = e.x >= 0 and e.y >= 0 and e.x + e.width <= desk.width and e.y + e.height <= desk.height
    print("  %5.1f s  %-34s E-STOP at %d,%d %dx%d  | %s" % (time.monotonic() - STARTED, step, e.x, e.y,
                                                          e.width, e.height, desk.start_reason()))
    if not inside or e.width < 100 or e.height < 60:
        raise StepFailed("%s: the E-STOP button at %d,%d %dx%d is not wholly on the %dx%d screen"
                         % (step, e.x, e.y, e.width, e.height, desk.width, desk.height))


def reason_says(desk, words, seconds, step):
    desk.wait(lambda: any(word in desk.start_reason() for word in words), seconds,
              "%s: Start reason with %s" % (step, " or ".join(words)))


def leaves(tree, path=""):
    if isinstance(tree, dict):
        for k, v in tree.items():
            yield from leaves(v, path + "." + k if path else k)
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            yield from leaves(v, "%s[%d]" % (path, i))
    else:
        yield path, tree


def changed_numbers(before, after):
    a = dict(leaves(before))
    return [(k, a.get(k), v) for k, v in leaves(after)
            if isinstance(v, (int, float)) and not isinstance(v, bool) and a.get(k) != v]


def saved_job(desk):
    with open(desk.args.job_copy) as f:
        return json.load(f)


def save_and_read(desk, step):
    stamp = os.path.getmtime(desk.args.job_copy)
    desk.key("ctrl+s")
    desk.wait(lambda: os.path.getmtime(desk.args.job_copy) != stamp, 10, step + ": Ctrl+S wrote the job")
    return saved_job(desk)


def type_numbers(desk):
    """Types into the first typeable decimal field of the machine's parameter pages."""
    # The form's tabs on screen (the other machines' pages are hidden tabs of no size).
    tabs = [t for t in desk.nodes("page tab")
            if t.get_extents(Atspi.CoordType.SCREEN).width > 0]
    names = [t.get_name() for t in tabs]
    if w("Job") not in names:
        raise StepFailed("no Job tab among the form's tabs %s" % names)
    for page in tabs[names.index(w("Job")) + 1:]:
        desk.click(page)
        time.sleep(0.5)
        try:
            return type_on_page(desk, page)
        except NoField as e:
            print("  (%s)" % e)
    raise StepFailed("no typeable decimal field on any page of %s" % names)


class NoField(Exception):
    pass


def type_on_page(desk, page):
    candidates, seen = [], []
    for sb in desk.nodes("spin button"):
        try:
            cur = sb.get_current_value()  # an Atspi.Accessible implements Value itself
            shown = sb.get_text(0, -1)  # a decimal field shows its decimals ("0,0850")
        except Exception as e:
            seen.append("%r: %s" % (sb.get_name(), e))
            continue
        seen.append("%r %r" % (sb.get_name(), shown))
        e = sb.get_extents(Atspi.CoordType.SCREEN)
        st = sb.get_state_set()
        # In the form column on the left (not the recovery box), typeable, a decimal field.
        if (e.width > 0 and e.y >= 0 and e.x < desk.width * 0.45 and sb.get_name()
                and st.contains(Atspi.StateType.ENABLED)
                and not st.contains(Atspi.StateType.READ_ONLY)
                and ("." in shown or "," in shown)):
            decimals = len(shown.replace(",", ".").split(".")[-1].strip())
            candidates.append((e.y, sb, cur, decimals))
    if not candidates:
        raise NoField("no typeable decimal field on the %r page: %s" % (page.get_name(), seen))
    # The topmost (in view without scrolling the form); the values move by one and two units of
    # its last decimal (0.1 mm on a length in m): the job stays plannable.
    _, sb, cur, decimals = min(candidates, key=lambda c: c[0])
    label = sb.get_name()
    unit = 10.0 ** -decimals
    first, second = round(cur + unit, decimals), round(cur + 2 * unit, decimals)
    fmt = "%%.%df" % decimals
    before = save_and_read(desk, "before typing")
    results = []
    for typed, expect in (((fmt % first).replace(".", ","), first), (fmt % second, second)):
        desk.click(sb)
        desk.key("ctrl+a")
        desk.type(typed)
        desk.key("Return")
        after = save_and_read(desk, "typed %s" % typed)
        changes = changed_numbers(before, after)
        # One key, or a few that follow it (a square tube's width and height), all to the value.
        if not changes or any(abs(c[2] - expect) > unit * 1e-3 for c in changes):
            raise StepFailed("typed %r into %r (page %r): expected one stored number %g, "
                             "the job file changed %s" % (typed, label, page.get_name(), expect,
                                                          changes))
        results.append("%r -> %s = %g" % (typed, ", ".join(c[0] for c in changes), expect))
    # Letters: refused, nothing stored.
    desk.click(sb)
    desk.key("ctrl+a")
    desk.type("abc")
    desk.key("Return")
    time.sleep(0.3)
    desk.key("ctrl+s")
    time.sleep(1.0)
    if changed_numbers(after, saved_job(desk)):
        raise StepFailed("letters typed into %r changed the job: %s"
                         % (label, changed_numbers(after, saved_job(desk))))
    results.append("'abc' -> nothing stored")
    print("  typed into %r on %r: %s" % (label, page.get_name(), "; ".join(results)))


def walkthrough(desk):
    desk.wait(lambda: desk.app_root() is not None, 30, "cutcell on the accessibility bus")
    desk.one("push button", lambda n: n.startswith(w("EMERGENCY")), "the main window")
    desk.wait(lambda: w("press Enable") in desk.start_reason(), 90, "the plan loaded ('press Enable')")
    estop_on_screen(desk, "opened")
    type_numbers(desk)
    estop_on_screen(desk, "typed numbers")
    reason_says(desk, [w("press Enable")], 90, "replanned")
    desk.key("F2")
    reason_says(desk, [w("press Home")], 20, "Enable (F2)")
    estop_on_screen(desk, "Enable (F2)")
    desk.key("F3")
    desk.wait(lambda: desk.start_reason().strip() in ("Start:", "Start: ready", ""), 90,
              "Home (F3): Start free")
    estop_on_screen(desk, "Home (F3)")
    hold = desk.one("push button", lambda n: n.startswith(w("Feed hold")), "the Feed hold button")
    desk.key("F5")
    reason_says(desk, [w("running")], 20, "Start (F5)")
    # At once: the quick-return cutter's three strokes take 2.8 s.
    desk.wait(lambda: hold.get_state_set().contains(Atspi.StateType.ENABLED), 5,
              "Feed hold (F6): the button enabled while running")
    desk.key("F6")
    reason_says(desk, [w("feed hold")], 20, "Feed hold (F6)")
    estop_on_screen(desk, "Feed hold (F6)")
    estop_on_screen(desk, "Start (F5)")
    desk.key("F7")
    reason_says(desk, [w("running")], 20, "Resume (F7)")
    estop_on_screen(desk, "Resume (F7)")
    # 1.5 s into the resumed run (the saw's carriage then homes from wherever it was: see below)
    time.sleep(1.5)
    desk.key("F1")
    reason_says(desk, [w("E-STOP pressed")], 5, "E-STOP (F1)")
    estop_on_screen(desk, "E-STOP (F1)")
    desk.key("ctrl+shift+F1")
    reason_says(desk, [w("EMERGENCY STOP latched")], 5, "Release (Ctrl+Shift+F1)")
    estop_on_screen(desk, "Release (Ctrl+Shift+F1)")
    desk.key("F4")
    reason_says(desk, [w("press Enable")], 20, "Reset (F4)")
    estop_on_screen(desk, "Reset (F4)")
    desk.key("F2")
    reason_says(desk, [w("press Home")], 20, "Enable again (F2)")
    desk.key("F3")
    # The longest homing of a shipped job: the flying saw's carriage over its whole 2500 mm
    # stroke at engine.home_speed_mm_s = 150 mm/s, 17 s (at the 20 mm/s it had, 125 s: on a
    # slow host the E-STOP above fell later in the run and a clean-clone CI timed out here).
    desk.wait(lambda: w("press Home") not in desk.start_reason() and w("homing") not in
              desk.start_reason(), 120, "Home again (F3): homed")
    estop_on_screen(desk, "Home again (F3)")
    resume = desk.nodes("push button", lambda n: n == w("Resume from stop"))
    if resume and resume[0].get_state_set().contains(Atspi.StateType.ENABLED):
        desk.click(resume[0])
        reason_says(desk, [w("running")], 20, "Resume from stop (mouse)")
        estop_on_screen(desk, "Resume from stop (mouse)")
        time.sleep(1.5)
    else:
        print("  (no cut recovery for this machine: its motion is not a path in time)")
        desk.key("F5")
        reason_says(desk, [w("running")], 20, "Start again (F5)")
        time.sleep(1.0)
    desk.key("F8", "F8")
    desk.wait(lambda: w("running") not in desk.start_reason(), 20,
              "Abort (F8 twice)")
    estop_on_screen(desk, "Abort (F8 twice)")
    target = os.path.join(desk.work, "saved as.json")
    desk.key("ctrl+shift+s")
    time.sleep(1.5)
    desk.key("ctrl+a")
    desk.type(target)
    desk.key("Return")
    desk.wait(lambda: os.path.exists(target), 10, "Save As wrote %s" % target)
    with open(target) as f:
        json.load(f)
    estop_on_screen(desk, "Save As (Ctrl+Shift+S)")


def desk_arguments(extra=None):
    """The options of a real-input run (and the caller's own); skips (77) when a tool it needs
    is missing: AT-SPI for Python, Xvfb, openbox, xdotool or a D-Bus session."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--cutcell", required=True)
    ap.add_argument("--job", required=True)
    ap.add_argument("--size", default="1280x720")
    ap.add_argument("--locale", default="C.UTF-8")
    if extra:
        extra(ap)
    args = ap.parse_args()
    if Atspi is None:
        skip("no AT-SPI for Python (python3-gi, gir1.2-atspi-2.0): " + ATSPI_ERROR)
    for tool in ("Xvfb", "openbox", "xdotool"):
        if not shutil.which(tool):
            skip(tool + " not installed (tools/setup.sh installs it)")
    if not os.environ.get("DBUS_SESSION_BUS_ADDRESS"):
        skip("no D-Bus session: run under dbus-run-session")
    return args


def main():
    args = desk_arguments()
    # The GUI follows the desktop's language (no choice is stored in the fresh HOME).
    global LANGUAGE
    LANGUAGE = "de" if args.locale.startswith("de") else "en"
    catalogue = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                             "resources", "i18n", "cutcell_de.ts")
    try:
        check_words(catalogue)
    except StepFailed as e:
        print("FAILED: %s" % e)
        return 1
    work = tempfile.mkdtemp(prefix="cutcell-walk-")
    args.job_copy = os.path.join(work, os.path.basename(args.job))
    shutil.copy(args.job, args.job_copy)
    print("walkthrough: %s at %s, %s (GUI in %s)" % (os.path.basename(args.job), args.size,
                                                      args.locale, LANGUAGE))
    desk = Desk(args, work)
    try:
        desk.start()
        walkthrough(desk)
        if desk.app.poll() is not None:
            raise StepFailed("cutcell exited with %s" % desk.app.returncode)
    except StepFailed as e:
        return failed(desk, work, e)
    return passed(desk, work)


def failed(desk, work, e):
    """A failed walk's report: the step, the screen, cutcell's last lines. Returns 1."""
    shot = desk.screenshot(os.path.join(work, "failed.png"))
    desk.stop()
    print("FAILED: %s" % e)
    if shot:
        print("the screen at the failure: " + shot)
    with open(os.path.join(work, "cutcell.log"), errors="replace") as f:
        print("--- cutcell's output (last lines) ---\n" + "".join(f.readlines()[-20:]))
    return 1


def passed(desk, work):
    desk.stop()
    shutil.rmtree(work, ignore_errors=True)
    print("PASSED")
    return 0


if __name__ == "__main__":
    sys.exit(main())
