#!/usr/bin/env bash
# Every chapter declares its own options through the registry, so `chNN render --help` shows
# exactly the options of chapters 01..NN, and an option reaches the integrator that reads it.
# Usage: chapter_options.sh SOURCE_DIR CH01 CH03 CH04 CH05 FREEZERAY
set -u
source_dir=$1 ch01=$2 ch03=$3 ch04=$4 ch05=$5 freezeray=$6
source "$(dirname "$0")/harness.sh"

# has RENDERER OPTION yes|no: whether `render --help` lists OPTION.
has() {
    local help
    help=$("$1" render --help 2>&1)
    if grep -qF -- "$2" <<<"$help"; then found=yes; else found=no; fi
    if [ "$found" = "$3" ]; then
        echo "ok   [$(basename "$1") lists $2: $3]"
    else
        echo "FAIL [$(basename "$1") lists $2: $found, expected $3]"
        failures=$((failures + 1))
    fi
}

for option in --mlt-large-step --mlt-sigma --mlt-bootstrap --mlt-chains --bdpt-strategies; do
    has "$ch01" "$option" no
    has "$ch03" "$option" no
done
has "$ch04" --bdpt-strategies yes
has "$ch04" --mlt-sigma no
for option in --mlt-large-step --mlt-sigma --mlt-bootstrap --mlt-chains --bdpt-strategies; do
    has "$ch05" "$option" yes
    has "$freezeray" "$option" yes
done
# The options common to every renderer stay.
for renderer in "$ch01" "$ch05"; do has "$renderer" --accel yes; has "$renderer" --spp yes; done
# --help names each option's chapter and the accelerators.
if "$ch05" render --help 2>&1 | grep -q "Options of chapter 05" && "$ch01" render --help 2>&1 | grep -q "bruteforce"; then
    echo "ok   [--help groups the options by chapter and lists the accelerators]"
else
    echo "FAIL [--help groups the options by chapter and lists the accelerators]"; failures=$((failures + 1))
fi

# An option reaches the integrator: a scene's "render" block sets mlt's bootstrap, the command
# line overrides it (an mlt render's notes say how many bootstrap paths it used).
python3 - "$source_dir/scenes/cornell-box/scene.json" "$work/scene.json" <<'PY'
import json, os, sys
scene = json.load(open(sys.argv[1]))
folder = os.path.dirname(os.path.abspath(sys.argv[1]))
for mesh in scene["meshes"]:
    mesh["file"] = os.path.join(folder, mesh["file"])
scene.setdefault("render", {})["mlt_bootstrap"] = 300
json.dump(scene, open(sys.argv[2], "w"))
PY
mlt_notes() {
    "$freezeray" render "$work/scene.json" --integrator mlt --spp 1 --width 16 --height 16 --mlt-chains 8 "$@" \
        --out "$work/mlt.pfm" 2>&1 >/dev/null
}
for case in "300:" "500:--mlt-bootstrap 500"; do
    expected=${case%%:*} arguments=${case#*:}
    # shellcheck disable=SC2086
    notes=$(mlt_notes $arguments)
    if grep -q "from $expected paths" <<<"$notes"; then
        echo "ok   [mlt uses $expected bootstrap paths (${arguments:-the scene's render block})]"
    else
        echo "FAIL [mlt uses $expected bootstrap paths (${arguments:-the scene's render block})]: $notes"
        failures=$((failures + 1))
    fi
done

if [ $failures -ne 0 ]; then echo "$failures failures"; exit 1; fi
echo "every renderer shows exactly its chapters' options"
