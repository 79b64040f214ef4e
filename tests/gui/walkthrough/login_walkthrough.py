#!/usr/bin/python3
"""User levels at the operator station driven by real X input events (issue 25).

Under Xvfb with openbox, the real `cutcell` binary opens a production record that holds an
administrator, an operator and an engineer (added with `cutcell-cli users add`, as the README
says). xdotool types and clicks as an operator's keyboard and mouse would; the window is read
back through its accessibility tree (AT-SPI). Steps: logged out, the Start reason asks for a
log-in and a parameter field takes no typing (the job saved with Ctrl+S keeps its value); the
E-STOP (F1) works without a log-in; a wrong password typed into the operator column is refused;
the operator logs in (Start then asks for Enable) and still cannot type into an engineer's
field (the feed-hold deceleration); logs out; the engineer logs in and types a new value, which
the saved job holds. The audit trail
(`cutcell-cli audit --csv`) then lists the E-STOP by "(not logged in)", the failed and the good
log-ins and the engineer's change. After every step the E-STOP button lies wholly on screen.

Run as: dbus-run-session -- /usr/bin/python3 login_walkthrough.py --cutcell BIN --cli CLI
        --job FILE --size 1280x720
Exit 0 = every step held, 1 = a step failed (named), 77 = a tool is missing (skipped).
"""
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import operator_walkthrough as walk  # noqa: E402  (Desk: Xvfb, openbox, AT-SPI, the process)

from operator_walkthrough import StepFailed, estop_on_screen, reason_says  # noqa: E402

PASSWORDS = {"ada": "ada-pass-1", "olga": "olga-pass-1", "eve": "eve-pass-1"}
# An engineer's parameter on the Cycle & devices page, named by its label for AT-SPI.
FIELD, KEY, LABEL, TYPED = "Feed hold deceleration", "engine.feed_hold_decel_s", "s", "0.75"


def add_users(cli, db):
    steps = [("ada", "administrator", "ada-pass-1\n"),
             ("olga", "operator", "ada-pass-1\nolga-pass-1\n"),
             ("eve", "engineer", "ada-pass-1\neve-pass-1\n")]
    for name, level, stdin in steps:
        args = [cli, "users", "add", name, "--level", level, "--db", db]
        if name != "ada":
            args += ["--admin", "ada"]
        r = subprocess.run(args, input=stdin, text=True, capture_output=True, timeout=60)
        if r.returncode != 0:
            raise StepFailed("cutcell-cli users add %s: %s" % (name, r.stderr.strip()))


def field(desk, name, role, what):
    return desk.one(role, lambda n: n == name, what)


def log_in(desk, name, password):
    user = field(desk, "User", "text", "the log-in's user field")
    desk.click(user)
    desk.key("ctrl+a")
    desk.type(name)
    secret = field(desk, "Password", "password text", "the log-in's password field")
    desk.click(secret)
    desk.type(password)
    desk.key("Return")


def logged_in_as(desk, name, level, seconds=10):
    desk.one("label", lambda n: n == "%s (%s)" % (name, level), "the panel showing %s" % name)


def engineer_field(desk):
    """The engineer's field on its page (its tab clicked first)."""
    tabs = [t for t in desk.nodes("page tab") if t.get_name() == "Cycle & devices"]
    if not tabs:
        raise StepFailed("no Cycle & devices tab")
    desk.click(tabs[0])
    time.sleep(0.5)
    return desk.one("spin button", lambda n: n == FIELD, "the field " + FIELD)


def type_into(desk, node, text):
    desk.click(node)
    desk.key("ctrl+a")
    desk.type(text)
    desk.key("Tab")
    time.sleep(0.5)


def saved_value(desk, step):
    job = walk.save_and_read(desk, step)
    return job["engine"]["feed_hold_decel_s"]


def walkthrough(desk, cli, db):
    desk.wait(lambda: desk.app_root() is not None, 30, "cutcell on the accessibility bus")
    desk.one("push button", lambda n: n.startswith("EMERGENCY"), "the main window")
    reason_says(desk, ["log in to run"], 90, "opened logged out")
    estop_on_screen(desk, "opened logged out")
    field = engineer_field(desk)
    before = saved_value(desk, "logged out: save")
    type_into(desk, field, TYPED)
    if saved_value(desk, "logged out: typed") != before:
        raise StepFailed("logged out, typing changed " + KEY)
    desk.key("F1")
    reason_says(desk, ["E-STOP pressed"], 5, "E-STOP (F1) logged out")
    estop_on_screen(desk, "E-STOP (F1) logged out")
    desk.key("ctrl+shift+F1")
    reason_says(desk, ["EMERGENCY STOP latched"], 5, "Release (Ctrl+Shift+F1)")
    desk.key("F4")
    reason_says(desk, ["log in to run"], 20, "Reset (F4): log in again")
    log_in(desk, "olga", "not her password")
    desk.one("label", lambda n: "wrong" in n, "the refusal of a wrong password")
    estop_on_screen(desk, "wrong password")
    log_in(desk, "olga", PASSWORDS["olga"])
    logged_in_as(desk, "olga", "operator")
    reason_says(desk, ["press Enable"], 20, "operator logged in: Start asks for Enable")
    estop_on_screen(desk, "operator logged in")
    type_into(desk, engineer_field(desk), TYPED)
    if saved_value(desk, "operator: typed") != before:
        raise StepFailed("the operator's typing changed " + KEY)
    desk.click(desk.one("push button", lambda n: n == "Log out", "the Log out button"))
    reason_says(desk, ["log in to run"], 20, "logged out again")
    log_in(desk, "eve", PASSWORDS["eve"])
    logged_in_as(desk, "eve", "engineer")
    type_into(desk, engineer_field(desk), TYPED)
    after = saved_value(desk, "engineer: typed")
    if after != float(TYPED):
        raise StepFailed("the engineer's %s %s was saved as %r" % (KEY, TYPED, after))
    estop_on_screen(desk, "engineer changed " + KEY)
    time.sleep(2.5)  # the trail writes a typed value once the typing settles (2 s)
    r = subprocess.run([cli, "audit", "--csv", "--db", db], capture_output=True, text=True,
                       timeout=60)
    trail = r.stdout
    for needed in (",(not logged in),emergency stop,", ",olga,login failed,olga,",
                   ",olga,login,olga,", ",eve,login,eve,",
                   ",eve,parameter changed,%s,%s,%s," % (KEY, format(before, "g"), TYPED)):
        if needed not in trail:
            raise StepFailed("the audit trail has no line with %r:\n%s" % (needed, trail))
    print("  audit trail: %d events" % (len(trail.splitlines()) - 1))


def main():
    def options(ap):
        ap.add_argument("--cli", required=True)

    args = walk.desk_arguments(options)
    work = tempfile.mkdtemp(prefix="cutcell-login-")
    args.job_copy = os.path.join(work, os.path.basename(args.job))
    shutil.copy(args.job, args.job_copy)
    # The station's record (and its users) in this walk's own data folder.
    os.environ["XDG_DATA_HOME"] = os.path.join(work, "data")
    db = os.path.join(work, "data", "cutcell", "production.db")
    print("login walkthrough: %s at %s" % (os.path.basename(args.job), args.size))
    desk = walk.Desk(args, work)
    try:
        add_users(args.cli, db)
        desk.start()
        walkthrough(desk, args.cli, db)
        if desk.app.poll() is not None:
            raise StepFailed("cutcell exited with %s" % desk.app.returncode)
    except StepFailed as e:
        return walk.failed(desk, work, e)
    return walk.passed(desk, work)


if __name__ == "__main__":
    sys.exit(main())
