#!/usr/bin/python3
"""Every text the GUI shows has its German translation (issue 21).

Runs lupdate over ui/, app/, plots/, core's form labels (tools/core_labels.py) and the engine's
event texts (tools/core_messages.py) into a copy of resources/i18n/cutcell_de.ts (as
tools/update_translations.sh would) and fails on any text that is new in the code and not in
the catalogue, any unfinished translation, any translation whose placeholders (%1..%9, %n,
%L1) differ from its source's, and any engine text ("CoreMessage") whose printf conversions
(%s, %.3f, ...) are not its source's in the same order (the GUI fills them in that order).
Exit 77 (skipped) without lupdate.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

SOURCE_DIR = sys.argv[1]
LUPDATE = os.environ.get("LUPDATE", "/usr/lib/qt6/bin/lupdate")
CATALOGUE = os.path.join(SOURCE_DIR, "resources", "i18n", "cutcell_de.ts")
PLACEHOLDER = re.compile(r"%L?\d|%n")
PRINTF = re.compile(r"%[-+ #0]*\d*(?:\.\d+)?(?:ll|l|z|h)?[diuxXfgeEsc%]")


def messages(path):
    for ctx in ET.parse(path).getroot().findall("context"):
        name = ctx.find("name").text
        for m in ctx.findall("message"):
            yield name, m


def main():
    if not os.access(LUPDATE, os.X_OK):
        print(f"SKIP: {LUPDATE} missing (package qt6-l10n-tools)")
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        # core's form labels: the committed extract must be today's (tools/core_labels.py).
        labels = subprocess.run([sys.executable, os.path.join(SOURCE_DIR, "tools", "core_labels.py"),
                                 SOURCE_DIR], capture_output=True, text=True, check=True).stdout
        with open(os.path.join(SOURCE_DIR, "resources", "i18n", "core_labels.cpp")) as f:
            if f.read() != labels:
                print("resources/i18n/core_labels.cpp is stale: run tools/update_translations.sh")
                return 1
        events = subprocess.run([sys.executable, os.path.join(SOURCE_DIR, "tools",
                                                                "core_messages.py"), SOURCE_DIR],
                                capture_output=True, text=True, check=True).stdout
        with open(os.path.join(SOURCE_DIR, "resources", "i18n", "core_messages.cpp")) as f:
            if f.read() != events:
                print("resources/i18n/core_messages.cpp is stale: run tools/update_translations.sh")
                return 1
        copy = os.path.join(tmp, "cutcell_de.ts")
        shutil.copy(CATALOGUE, copy)
        run = subprocess.run([LUPDATE, "-no-obsolete", "-locations", "none", "-I", SOURCE_DIR,
                              os.path.join(SOURCE_DIR, "ui"), os.path.join(SOURCE_DIR, "app"),
                              os.path.join(SOURCE_DIR, "plots"),
                              os.path.join(SOURCE_DIR, "resources", "i18n", "core_labels.cpp"),
                              os.path.join(SOURCE_DIR, "resources", "i18n", "core_messages.cpp"),
                              "-target-language", "de_DE",
                              "-ts", copy], capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stdout, run.stderr)
            return 1
        committed = {(c, m.find("source").text) for c, m in messages(CATALOGUE)}
        problems = []
        total = 0
        for context, m in messages(copy):
            total += 1
            source = m.find("source").text
            where = f"{context}: \"{source}\""
            if (context, source) not in committed:
                problems.append(f"not in the catalogue (run tools/update_translations.sh): {where}")
                continue
            tr = m.find("translation")
            if tr.get("type") == "unfinished":
                problems.append(f"unfinished: {where}")
                continue
            forms = [f.text or "" for f in tr.findall("numerusform")] if m.get("numerus") == "yes" \
                else [tr.text or ""]
            for form in forms:
                if not form.strip():
                    problems.append(f"empty translation: {where}")
                elif sorted(PLACEHOLDER.findall(form)) != sorted(PLACEHOLDER.findall(source)) and \
                        not (m.get("numerus") == "yes" and "%n" in source):
                    problems.append(f"placeholders differ: {where} -> \"{form}\"")
                elif context == "CoreMessage" and PRINTF.findall(form) != PRINTF.findall(source):
                    problems.append(f"printf conversions differ (or their order): {where} -> "
                                    f"\"{form}\"")
        for p in problems:
            print(p)
        print(f"{total} texts, {len(problems)} problems")
        return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
