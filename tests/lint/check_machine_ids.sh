#!/bin/sh
# A machine's id string may appear in ui/, plots/ and app/gui only inside that machine's own
# folders (ui/machines/<id>/, app/gui/machines/<id>/) and the registry files; elsewhere it is a
# machine kind compared as a string (issue 9). The ids are the folder names under ui/machines/.
# Also refuses the helpers that compared the kind before the machine modules.
# Usage: check_machine_ids.sh SOURCE_DIR   (exit 0 clean, 1 offenders listed, 2 set-up error)
set -u
cd "$1" || exit 2
registry='^(ui/machines/register_machine_uis\.cpp|ui/machines/machines\.cmake):'
# The ids: the GUI folders, and every core module's id constant (machines without a GUI yet).
ids=$( (for d in ui/machines/*/; do basename "$d"; done
        sed -n 's/.*constexpr const char\* k[A-Za-z]*Id = "\([a-z0-9_]*\)".*/\1/p' core/machines/*/*.h) |
      sort -u)
n=$(echo "$ids" | grep -c .)
if [ "$n" -lt 2 ]; then
    echo "expected at least the two shipped machines under ui/machines/, found: $ids"
    exit 2
fi
status=0
for id in $ids; do
    # Its own folders: ui/machines/<id>/ and, in the core, the module's folder (the one file
    # that defines the id constant); everything else names the machine through the constant.
    core=$(grep -rlF -- "\"$id\"" core/machines | head -1 | xargs -r dirname)
    own="^(ui/machines/$id/|${core:-core/machines/none}/)"
    bad=$(grep -rnF -I -- "\"$id\"" core devices app ui plots | grep -Ev "$own" | grep -Ev "$registry")
    if [ -n "$bad" ]; then
        echo "machine id \"$id\" outside its folders and the registries:"
        echo "$bad"
        status=1
    fi
done
old=$(grep -rnE -I 'isProfileCutterJob|kProfileCutterMachine|kProfileMachine' ui plots app/gui)
if [ -n "$old" ]; then
    echo "machine kind helpers that compare strings:"
    echo "$old"
    status=1
fi
[ "$status" -eq 0 ] && echo "machine ids: $(echo $ids) only in their folders and the registries"
exit $status
