#!/usr/bin/env bash
# Bad input to the renderer: every case must exit non-zero, print a message naming the file and
# the place, and leave no output file behind.
# Usage: bad_input.sh RENDERER SOURCE_DIR
set -u
renderer=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# expect_failure NAME EXPECTED_TEXT... -- ARGS: runs the renderer with ARGS (output to
# $work/out.png unless ARGS say otherwise) and checks exit status, message and output.
expect_failure() {
    local name=$1; shift
    local expected=()
    while [ "$1" != "--" ]; do expected+=("$1"); shift; done
    shift
    rm -f "$work/out.png"
    local message status
    message=$("$renderer" "$@" 2>&1 >/dev/null)
    status=$?
    local ok=1
    if [ $status -eq 0 ]; then echo "FAIL [$name]: exit status 0"; ok=0; fi
    for text in "${expected[@]}"; do
        if ! grep -qF -- "$text" <<<"$message"; then echo "FAIL [$name]: message lacks '$text'"; ok=0; fi
    done
    if [ -e "$work/out.png" ] || ls "$work"/out.png.* >/dev/null 2>&1; then echo "FAIL [$name]: an output file was left"; ok=0; fi
    if [ $ok -eq 1 ]; then echo "ok   [$name] (exit $status): $message"; else echo "     message was: $message"; failures=$((failures + 1)); fi
}

# A valid little scene to break in different ways.
cat > "$work/tri.obj" <<'OBJ'
mtllib tri.mtl
v 0 0 0
v 1 0 0
v 0 1 0
usemtl paint
f 1 2 3
OBJ
printf 'newmtl paint\nKd 0.5 0.5 0.5\nKe 1 1 1\n' > "$work/tri.mtl"
camera='"camera": {"position": [0.2, 0.2, 2], "look_at": [0.2, 0.2, 0], "fov_vertical_degrees": 40, "resolution": [8, 8]}'
echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\"}] }" > "$work/good.json"

# Sanity: the good scene renders (so the failures below are caused by what each case breaks).
if ! "$renderer" render "$work/good.json" --spp 1 --quiet --out "$work/good.png" >/dev/null 2>&1 || [ ! -s "$work/good.png" ]; then
    echo "FAIL [good scene]: the unbroken scene does not render"; failures=$((failures + 1))
else
    echo "ok   [good scene] renders"
fi

echo "{ $camera, \"meshes\": [{\"file\": \"missing.obj\"}] }" > "$work/missing-obj.json"
expect_failure "missing OBJ" "missing-obj.json" "/meshes/0/file" "missing.obj" -- render "$work/missing-obj.json" --out "$work/out.png"

printf '{\n  "camera": {\n    "position": [0, 0, 1],,\n  }\n}\n' > "$work/malformed.json"
expect_failure "malformed JSON" "malformed.json:3:" "malformed JSON" -- render "$work/malformed.json" --out "$work/out.png"

echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\"}], \"materials\": {\"paint\": {\"type\": \"velvet\"}} }" > "$work/unknown-material.json"
expect_failure "unknown material type" "unknown-material.json" "/materials/paint/type" "velvet" -- render "$work/unknown-material.json" --out "$work/out.png"

printf 'mtllib textured.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl paint\nf 1 2 3\n' > "$work/textured.obj"
printf 'newmtl paint\nKd 0.5 0.5 0.5\nmap_Kd no-such-texture.png\n' > "$work/textured.mtl"
echo "{ $camera, \"meshes\": [{\"file\": \"textured.obj\"}] }" > "$work/missing-texture.json"
expect_failure "texture that does not exist" "textured.mtl:3" "no-such-texture.png" -- render "$work/missing-texture.json" --out "$work/out.png"

expect_failure "negative sample count" "--spp" -- render "$work/good.json" --spp -5 --out "$work/out.png"
expect_failure "zero sample count" "--spp" -- render "$work/good.json" --spp 0 --out "$work/out.png"
expect_failure "unknown integrator" "--integrator" "pt-nope" -- render "$work/good.json" --integrator pt-nope --out "$work/out.png"
expect_failure "integrator of a later chapter" "introduced in chapter 03" -- render "$work/good.json" --integrator pt-mis --out "$work/out.png"
expect_failure "output folder that does not exist" "$work/no/such/folder/out.png" -- render "$work/good.json" --out "$work/no/such/folder/out.png"
expect_failure "unknown output format" "out.tiff" -- render "$work/good.json" --out "$work/out.tiff"
expect_failure "missing scene file" "nothing-here.json" -- render "$work/nothing-here.json" --out "$work/out.png"
expect_failure "absurd resolution" "--width" -- render "$work/good.json" --width 100000 --height 100000 --out "$work/out.png"

if [ $failures -ne 0 ]; then echo "$failures bad-input case(s) failed"; exit 1; fi
echo "every bad-input case was refused cleanly"
