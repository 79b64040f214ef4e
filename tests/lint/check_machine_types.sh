#!/bin/sh
# A machine's own types and constants - what core/machines/<name>/ declares at namespace scope
# in its headers (struct, class, enum, using X =, constexpr kX: FlyingSawSpec, CutPlan,
# kAxisCount, ...) - appear in core/, devices/, ui/, plots/ and app/ only inside that machine's
# own folders (core/machines/<name>/, devices/machines/<name>/, ui/machines/<name>/) and the
# registry files. Elsewhere the generic layers would know a machine. Strings and // comments are
# not code and are left out of the search. Names declared at namespace scope by more than one
# machine folder would be ambiguous: they are refused too.
# Usage: check_machine_types.sh SOURCE_DIR   (exit 0 clean, 1 offenders listed, 2 set-up error)
set -u
cd "$1" || exit 2
registry='^(ui/machines/register_machine_uis\.cpp|core/machines/register_machines\.cpp|devices/machines/sim_rig_registry\.cpp|devices/machines/can_cell_registry\.cpp):'
code=$(mktemp) && names=$(mktemp) && all=$(mktemp) || exit 2
trap 'rm -f "$code" "$names" "$all"' EXIT
# Every code line as FILE:LINE:TEXT, string literals emptied and // comments cut.
find core devices app ui plots \( -name '*.h' -o -name '*.cpp' \) | sort | while read -r f; do
    sed -e 's/"\([^"\\]\|\\.\)*"/""/g' -e 's|//.*||' "$f" | grep -n . | sed "s|^|$f:|"
done > "$code"
declared() { # the names a machine folder declares at namespace scope (column 0) in its headers
    grep -rhoE '^(struct|class|enum class|enum) [A-Z][A-Za-z0-9_]*|^using [A-Z][A-Za-z0-9_]* =|^inline constexpr [^=(]*\bk[A-Z][A-Za-z0-9_]*' \
        "$1" --include=*.h | sed 's/ =$//' | grep -oE '[A-Za-z0-9_]+$' | sort -u
}
folders=$(ls -d core/machines/*/ 2>/dev/null)
[ -n "$folders" ] || { echo "no machine folders under core/machines/"; exit 2; }
status=0
for d in $folders; do declared "$d"; done | sort | uniq -d > "$all"
if [ -s "$all" ]; then
    echo "declared by more than one machine folder (one owner per name):"
    cat "$all"
    status=1
fi
for d in $folders; do
    folder=$(basename "$d")
    declared "$d" > "$names"
    [ -s "$names" ] || continue
    own="^(core/machines/$folder/|devices/machines/$folder/|ui/machines/$folder/)"
    bad=$(grep -Ev "$own" "$code" | grep -Ev "$registry" | grep -wFf "$names")
    if [ -n "$bad" ]; then
        echo "machine \"$folder\": its types or constants outside its folders and the registries:"
        echo "$bad"
        status=1
    fi
done
[ "$status" -eq 0 ] && echo "machine types: $(for d in $folders; do declared "$d"; done | wc -l) names, each only in its machine's folders and the registries"
exit $status
