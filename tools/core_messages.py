#!/usr/bin/python3
"""Prints a C++ file that lists the English texts the layers below the GUI write for the
operator, as printf templates and the words that go into them:
- the motion engine's events: the templates of core/engine's event calls (emitf, setState,
  note, refuse, enterFault, endRun, and the snprintfC pieces they are built from) and the words
  passed into them (the commands', stop categories', drive states' names, the tools' words,
  the motion sources' faults and phases) and the items of the engine thread's real-time line
  (core/engine/realtime_thread.cpp);
- the job's validation sentences and the planners' refusals (messageC, core/common/c_format.h,
  and fixed `.problem = "..."` texts);
- the simulated cell's line in the status bar (the rigs' description());
- the CAN master's events and faults (devices/canopen: messageC templates, the EMCY and SDO
  abort tables, the bus states), the CAN cell's list of its nodes (devices/machines/can_cells.cpp)
  and the GUI's CAN link states (app/gui/can_link.cpp).
core is pure C++ without Qt; the GUI translates such a text by finding the template it was
formatted from (ui/panels/engine_text.cpp), in the "CoreMessage" context.
tools/update_translations.sh writes the file to resources/i18n/core_messages.cpp, which the GUI
compiles; gui.translations_complete fails when it is stale. A template with two conversions
side by side ("%s%s") is refused: the GUI could not split their values again."""
import os
import re
import sys

CALL = re.compile(r"\b(?:emitf|setState|note|refuse|enterFault|endRun|snprintfC)\s*\(")
LITERAL = re.compile(r'"((?:[^"\\]|\\.)*)"')
SPEC = re.compile(r"%[-+ #0]*\d*(?:\.\d+)?(?:l|ll|z|h)?[diuxXfgeEsc%]")
# Functions whose returned literals are words inside the events: the names of the commands,
# the stop categories, the drive states, the command modes, the motion sources and their
# phases (the states' names are told by the GUI's own state words, ui/panels/run_words.h).
WORD_FUNCTIONS = re.compile(
    r"const char\* (?:toString\((?:CommandType|StopCategory|MotionSourceKind|AxisCommandMode|"
    r"DriveState|SawPhase|QrPhase|SliderPhase|FollowerState|SyncState)\b[^)]*\)"
    r"|(?:latchedReason|unitSingular|madeNounPlural)\([^)]*\))\s*\{")
# Texts a motion source or a module hands the engine for its events: faults, the reason
# supervision is off, the run terms' words (RunTerms::tool, ::process_ok, ::process_lost); and
# a plan's fixed problem texts (.problem = "...").
ASSIGNED = re.compile(r"(?:\.fault|\.problem|\.unsupervised_reason|\bk\w*Reason|\.tool"
                      r"|\.process_(?:ok|lost)|std::string (?:tool|process_ok|process_lost))"
                      r"\s*=\s*((?:\"(?:[^\"\\\\]|\\\\.)*\"|[^;\"])*);")
MESSAGE = re.compile(r"\bmessageC\s*\(")
# The CAN layer's words: its tables of EMCY and SDO abort texts, the bus error frame's words and
# the names of the bus, NMT and CiA 402 states.
CAN_WORDS = re.compile(r"(?:constexpr Entry kTable\[\] = \{|\bappend\(r\.text,)")
# The machines' external sensors ("line encoder"), named in the CAN cell's line.
SENSOR_NAMES = re.compile(r"sensorNames\(\) const override \{ return \{([^}]*)\}")
CAN_WORD_FUNCTIONS = re.compile(
    r"const char\* toString\((?:BusState|NmtState|NmtCommand|Cia402State)\b[^)]*\)\s*\{")
DESCRIPTION = re.compile(r"std::string description\(\) const override\s*\{")
ENGINE_FILES = ("engine_commands.cpp", "engine_cycle.cpp", "engine_sequencing.cpp",
                "engine_supervision.cpp", "engine_telemetry.cpp", "motion_engine.cpp")
# The engine thread's real-time line (core/engine/realtime_thread.cpp): items joined by "; ".
REALTIME_ITEM = re.compile(r"\bline\.item\s*\(")


def balanced(text, start):
    """The text from start (just after an opening parenthesis) to its closing one."""
    depth, i = 1, start
    while i < len(text) and depth:
        c = text[i]
        if c == '"':
            i += 1
            while text[i] != '"':
                i += 2 if text[i] == "\\" else 1
        elif c == "(":
            depth += 1
        elif c == ")":
            depth -= 1
        i += 1
    return text[start:i - 1]


def literals(args):
    """The string literals of a call's arguments, adjacent pieces joined."""
    out, last_end, current = [], None, None
    for m in LITERAL.finditer(args):
        if current is not None and args[last_end:m.start()].strip() == "":
            current += m.group(1)
        else:
            if current is not None:
                out.append(current)
            current = m.group(1)
        last_end = m.end()
    if current is not None:
        out.append(current)
    return out


def is_text(s):
    """A text for the operator: a word of three letters outside the % specs, or a number with
    its unit ("%.1f mm/s")."""
    rest = SPEC.sub("", s)
    return re.search(r"[A-Za-z]{3,}", rest) is not None or (
        SPEC.search(s) is not None and re.search(r"[A-Za-z]", rest) is not None)


def body(text, start):
    depth, i = 1, start
    while depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return text[start:i - 1]


def sources(source_dir, layer):
    for root, _, files in sorted(os.walk(os.path.join(source_dir, layer))):
        for name in sorted(files):
            if name.endswith((".cpp", ".h")):
                with open(os.path.join(root, name), encoding="utf-8") as f:
                    yield os.path.relpath(os.path.join(root, name), source_dir), f.read()


def first_argument(args):
    """A call's first argument (up to the first comma outside parentheses and literals)."""
    depth, i = 0, 0
    while i < len(args):
        c = args[i]
        if c == '"':
            i += 1
            while args[i] != '"':
                i += 2 if args[i] == "\\" else 1
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "," and depth == 0:
            return args[:i]
        i += 1
    return args


def message_templates(text):
    """messageC's templates: every literal of its format argument (a?"x":"y" gives both)."""
    for m in MESSAGE.finditer(text):
        yield from literals(first_argument(balanced(text, m.end())))


def messages(source_dir):
    found = []

    def add(s):
        if is_text(s) and s not in found:
            if re.search(r"%[-+ #0]*\d*(?:\.\d+)?(?:l|ll|z|h)?[a-zA-Z]%", s):
                sys.exit(f"two specs without text between them in \"{s}\": their captures "
                         "could not be told apart; write whole sentences")
            found.append(s)

    for path, text in sources(source_dir, "core"):
        if os.path.basename(path) in ENGINE_FILES and "/engine/" in path:
            for m in CALL.finditer(text):
                for s in literals(balanced(text, m.end())):
                    add(s)
        if path.endswith(os.path.join("engine", "realtime_thread.cpp")):
            for m in REALTIME_ITEM.finditer(text):
                for s in literals(balanced(text, m.end())):
                    add(s)
        for m in WORD_FUNCTIONS.finditer(text):
            for s in literals(body(text, m.end())):
                add(s)
        for m in SENSOR_NAMES.finditer(text):
            for s in literals(m.group(1)):
                add(s)
        for m in ASSIGNED.finditer(text):
            for s in literals(m.group(1)):
                add(s)
        # The job's validation sentences (messageC, core/common/c_format.h): the template only.
        for s in message_templates(text):
            add(s)
    add("tool")  # toolName() without a program
    # The status bar's line on the cell (EngineRig::description): the simulated rigs' own
    # words and the GUI rigs' templates around them.
    for root, _, files in sorted(os.walk(os.path.join(source_dir, "devices", "machines"))):
        for name in sorted(files):
            with open(os.path.join(root, name), encoding="utf-8") as f:
                text = f.read()
            for m in DESCRIPTION.finditer(text):
                for s in literals(body(text, m.end())):
                    add(s)
    for name in ("sim_rig.cpp", "can_rig.cpp"):
        with open(os.path.join(source_dir, "app", "gui", name), encoding="utf-8") as f:
            text = f.read()
        for m in DESCRIPTION.finditer(text):
            for s in literals(body(text, m.end())):
                add(s)
    # The CAN master (devices/canopen) and the GUI's CAN link (app/gui/can_link.cpp).
    can = list(sources(source_dir, os.path.join("devices", "canopen")))
    for path in ("app/gui/can_link.cpp", "devices/machines/can_cells.cpp"):
        with open(os.path.join(source_dir, path), encoding="utf-8") as f:
            can.append((path, f.read()))
    for path, text in can:
        for s in message_templates(text):
            add(s)
        for m in CAN_WORDS.finditer(text):
            args = body(text, m.end()) if text[m.end() - 1] == "{" else balanced(text, m.end())
            for s in literals(args):
                add(s)
        for m in CAN_WORD_FUNCTIONS.finditer(text):
            for s in literals(body(text, m.end())):
                add(s)
    return found


def main():
    source_dir = sys.argv[1] if len(sys.argv) > 1 else "."
    out = ["// Generated by tools/core_messages.py (tools/update_translations.sh): do not edit.",
           "// core's texts for the operator (printf templates) and the words inside them, for",
           "// lupdate and for the GUI's matcher (ui/panels/engine_text.cpp).",
           "#include <QtGlobal>", "", "namespace CutCell::ui {", "",
           "extern const char* const kCoreMessages[];", "extern const int kCoreMessageCount;", "",
           "const char* const kCoreMessages[] = {"]
    found = messages(source_dir)
    for s in found:
        out.append('    QT_TRANSLATE_NOOP("CoreMessage", "%s"),' % s)
    out += ["};", "const int kCoreMessageCount = %d;" % len(found), "", "} // namespace CutCell::ui"]
    print("\n".join(out))


if __name__ == "__main__":
    main()
