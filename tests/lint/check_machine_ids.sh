#!/bin/sh
# A machine's id may appear in core/, devices/, ui/, plots/ and app/ only inside that machine's
# own folders - core/machines/<name>/, devices/machines/<name>/, ui/machines/<name>/, one folder
# name per machine in every layer - and the registry files; elsewhere it would be a machine kind
# compared as a string. Checked: the id as a string ("flying_saw") and the constant that holds
# it (kFlyingSawId). The ids are the core modules' id constants; a machine's folder name is the
# core folder that defines its constant. Also refuses the helpers that compared the kind before
# the machine modules.
# Usage: check_machine_ids.sh SOURCE_DIR   (exit 0 clean, 1 offenders listed, 2 set-up error)
set -u
cd "$1" || exit 2
registry='^(ui/machines/register_machine_uis\.cpp|ui/machines/machines\.cmake|core/machines/register_machines\.cpp|devices/machines/sim_rig_registry\.cpp|devices/machines/can_cell_registry\.cpp):'
defs=$(grep -rHE 'constexpr const char\* k[A-Za-z]*Id = "[a-z0-9_]*"' core/machines)
n=$(echo "$defs" | grep -c .)
if [ "$n" -lt 5 ]; then
    echo "expected the id constants of the five shipped machines under core/machines/, found:"
    echo "$defs"
    exit 2
fi
status=0
ids=""
for line in $(echo "$defs" | sed -n 's|^core/machines/\([a-z0-9_]*\)/[^:]*:.*constexpr const char\* \(k[A-Za-z]*Id\) = "\([a-z0-9_]*\)".*|\1,\2,\3|p'); do
    folder=${line%%,*}
    rest=${line#*,}
    constant=${rest%%,*}
    id=${rest#*,}
    ids="$ids $id"
    for d in ui/machines devices/machines; do
        if [ ! -d "$d/$folder" ]; then
            echo "machine \"$id\": no folder $d/$folder (one folder name per machine in every layer)"
            status=1
        fi
    done
    own="^(core/machines/$folder/|devices/machines/$folder/|ui/machines/$folder/)"
    bad=$( (grep -rnF -I -- "\"$id\"" core devices app ui plots
            grep -rnwF -I -- "$constant" core devices app ui plots) |
          grep -Ev "$own" | grep -Ev "$registry")
    if [ -n "$bad" ]; then
        echo "machine \"$id\" ($constant) outside its folders and the registries:"
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
[ "$status" -eq 0 ] && echo "machine ids:$ids only in their folders and the registries"
exit $status
