#!/usr/bin/env bash
# Bad input to the renderer: every case must exit non-zero, print a message naming the file and
# the place, and leave no output file behind.
# Usage: bad_input.sh RENDERER SOURCE_DIR COMPLETE_RENDERER
# (RENDERER is chapter 01's; the options of later chapters are tried on COMPLETE_RENDERER.)
set -u
renderer=$1
source_dir=$2
complete_renderer=$3
chapter01_renderer=$renderer
source "$(dirname "$0")/harness.sh"

# expect_failure NAME EXPECTED_TEXT... -- ARGS: runs the renderer with ARGS (output to
# $work/out.png unless ARGS say otherwise) and checks exit status (1), message and output.
expect_failure() {
    local name=$1; shift
    local expected=()
    while [ "$1" != "--" ]; do expected+=("$1"); shift; done
    shift
    rm -rf "$work/out.png" "$work/report"
    local message status
    message=$("$renderer" "$@" 2>&1 >/dev/null)
    status=$?
    local ok=1
    if [ $status -ne 1 ]; then echo "FAIL [$name]: exit status $status, not 1 (README: every usage error is 1)"; ok=0; fi
    for text in "${expected[@]}"; do
        if ! grep -qF -- "$text" <<<"$message"; then echo "FAIL [$name]: message lacks '$text'"; ok=0; fi
    done
    if [ -e "$work/out.png" ] || ls "$work"/out.png.* >/dev/null 2>&1; then echo "FAIL [$name]: an output file was left"; ok=0; fi
    if [ -e "$work/report" ]; then echo "FAIL [$name]: a report folder was left"; ok=0; fi
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
# The options a later chapter declares: chapter 01's renderer does not know them; the complete
# renderer checks them (on the command line and in the scene's "render" block) and refuses them
# for an integrator that does not read them.
expect_failure "an option of a later chapter" "--mlt-sigma" -- render "$work/good.json" --mlt-sigma 0.1 --out "$work/out.png"
renderer=$complete_renderer
expect_failure "large-step probability out of range" "--mlt-large-step" "probability" -- render "$work/good.json" --integrator mlt --mlt-large-step 2 --out "$work/out.png"
expect_failure "negative small-step size" "--mlt-sigma" "(0, 1]" -- render "$work/good.json" --integrator mlt --mlt-sigma -0.1 --out "$work/out.png"
expect_failure "chain count that is not a whole number" "--mlt-chains" -- render "$work/good.json" --integrator mlt --mlt-chains 1.5 --out "$work/out.png"
expect_failure "an option the integrator does not read" "--mlt-sigma" "is an option of mlt, mlt-multiplexed" "pt-mis" -- render "$work/good.json" --integrator pt-mis --mlt-sigma 0.1 --out "$work/out.png"
echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\"}], \"render\": {\"mlt_sigma\": 5} }" > "$work/bad-mlt-option.json"
expect_failure "an integrator option out of range in the scene" "bad-mlt-option.json" "/render/mlt_sigma" -- render "$work/bad-mlt-option.json" --integrator mlt --out "$work/out.png"
echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\"}], \"accelerator\": {\"type\": \"octree\"} }" > "$work/unknown-accelerator.json"
expect_failure "unknown accelerator in the scene" "unknown-accelerator.json: /accelerator/type" "octree" -- render "$work/unknown-accelerator.json" --out "$work/out.png"
expect_failure "unknown accelerator on the command line" "--accel" "did you mean" -- render "$work/good.json" --accel brutforce --out "$work/out.png"
echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\"}], \"textures\": {\"filter\": \"nearest\"} }" > "$work/nearest.json"
expect_failure "unknown texture filter in the scene" "nearest.json: /textures/filter" "bilinear, trilinear" -- render "$work/nearest.json" --out "$work/out.png"
expect_failure "unknown texture filter on the command line" "--texture-filter" "bilinear, trilinear" -- render "$work/good.json" --texture-filter nearest --out "$work/out.png"
expect_failure "impossible tile size" "--texture-tile-size" "not 3" -- render "$work/good.json" --texture-tile-size 3 --out "$work/out.png"
# Light samplers (chapters 03 and 10): an unknown one, and one named for an integrator that does
# not choose lights at shading points.
expect_failure "unknown light sampler" "--light-sampler" "did you mean" -- render "$work/good.json" --integrator pt-mis --light-sampler bhv --out "$work/out.png"
expect_failure "a light sampler for bdpt" "--light-sampler" "bdpt does not choose lights through a light sampler" -- render "$work/good.json" --integrator bdpt --light-sampler bvh --out "$work/out.png"
echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\"}], \"render\": {\"light_sampler\": \"tree\"} }" > "$work/light-tree.json"
# A sampler (chapter 09) for an integrator whose numbers are not a pixel's samples: light tracing
# and the Markov chains refuse it; bdpt takes it.
expect_failure "a sampler for mlt" "--sampler" "mlt draws its numbers from its own streams" -- render "$work/good.json" --integrator mlt --sampler sobol --out "$work/out.png"
expect_failure "a sampler for light tracing" "--sampler" "light-tracing draws its numbers from its own streams" -- render "$work/good.json" --integrator light-tracing --sampler zsobol --out "$work/out.png"
expect_failure "unknown light sampler in the scene" "light-tree.json: /render/light_sampler" "tree" -- render "$work/light-tree.json" --out "$work/out.png"
expect_failure "a compare run naming an unknown sampler" "--integrators" "bvhh" -- compare "$work/good.json" --integrators pt-mis@bvhh --spp 1 --out "$work/report"
renderer=$chapter01_renderer
echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\"}], \"textures\": {\"layout\": \"tiled\"} }" > "$work/tiled.json"
expect_failure "texture layout of a later chapter" "tiled.json: /textures/layout" "introduced in chapter 08" -- render "$work/tiled.json" --out "$work/out.png"
echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\"}], \"accelerator\": {\"type\": \"kdtree\"} }" > "$work/kdtree.json"
expect_failure "accelerator of a later chapter" "/accelerator/type" "introduced in chapter 06" -- render "$work/kdtree.json" --out "$work/out.png"
expect_failure "integrator of a later chapter" "introduced in chapter 03" -- render "$work/good.json" --integrator pt-mis --out "$work/out.png"
expect_failure "output folder that does not exist" "$work/no/such/folder/out.png" -- render "$work/good.json" --out "$work/no/such/folder/out.png"
expect_failure "unknown output format" "out.tiff" -- render "$work/good.json" --out "$work/out.tiff"
expect_failure "missing scene file" "nothing-here.json" -- render "$work/nothing-here.json" --out "$work/out.png"
expect_failure "absurd resolution" "--width" -- render "$work/good.json" --width 100000 --height 100000 --out "$work/out.png"

# expect_warning NAME EXPECTED_TEXT... -- ARGS: the run succeeds but warns with every text.
expect_warning() {
    local name=$1; shift
    local expected=()
    while [ "$1" != "--" ]; do expected+=("$1"); shift; done
    shift
    local message status ok=1
    message=$("$renderer" "$@" 2>&1 >/dev/null)
    status=$?
    if [ $status -ne 0 ]; then echo "FAIL [$name]: exit status $status"; ok=0; fi
    for text in "${expected[@]}"; do
        if ! grep -qF -- "$text" <<<"$message"; then echo "FAIL [$name]: message lacks '$text'"; ok=0; fi
    done
    if [ $ok -eq 1 ]; then echo "ok   [$name] (warning): $message"; else echo "     message was: $message"; failures=$((failures + 1)); fi
}

# Issue 8's list, case by case.
echo '[1, 2, 3]' > "$work/not-an-object.json"
expect_failure "JSON that is not an object" "not-an-object.json: /" "expected an object" -- render "$work/not-an-object.json" --out "$work/out.png"
echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\"}], \"render\": {\"spp\": \"many\"} }" > "$work/wrong-type.json"
expect_failure "wrong JSON type" "wrong-type.json" "/render/spp" "expected a whole number" -- render "$work/wrong-type.json" --out "$work/out.png"
echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\", \"transform\": {\"rotate\": {\"axis\": [0, \"y\", 0], \"degrees\": 9}}}] }" > "$work/deep-wrong-type.json"
expect_failure "wrong JSON type, deep" "deep-wrong-type.json" "/meshes/0/transform/rotate/axis/1" -- render "$work/deep-wrong-type.json" --out "$work/out.png"
echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\"}], \"rendr\": {} }" > "$work/unknown-key.json"
expect_warning "unknown key" "unknown-key.json" "/rendr" "did you mean 'render'" -- render "$work/unknown-key.json" --spp 1 --quiet --out "$work/warned.png"
echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\"}], \"lights\": [{\"type\": \"point\", \"position\": [0, 1, 0]}] }" > "$work/point-light.json"
expect_failure "light of a later chapter" "point-light.json" "/lights/0/type" "introduced in chapter 03" -- render "$work/point-light.json" --out "$work/out.png"
echo '{"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov_vertical_degrees": 40, "resolution": [100000, 100000]}, "meshes": [{"file": "tri.obj"}]}' > "$work/huge.json"
expect_failure "absurd resolution in the scene" "huge.json" "/camera/resolution" -- render "$work/huge.json" --out "$work/out.png"

printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 3//1 2//1 1/' > "$work/cut.obj"
echo "{ $camera, \"meshes\": [{\"file\": \"cut.obj\"}] }" > "$work/cut.json"
expect_failure "truncated OBJ" "cut.obj:6" -- render "$work/cut.json" --out "$work/out.png"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n' > "$work/bad-index.obj"
echo "{ $camera, \"meshes\": [{\"file\": \"bad-index.obj\"}] }" > "$work/bad-index.json"
expect_failure "OBJ index out of range" "bad-index.obj:5" "out of range" -- render "$work/bad-index.json" --out "$work/out.png"
printf 'mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$work/no-mtl.obj"
echo "{ $camera, \"meshes\": [{\"file\": \"no-mtl.obj\"}] }" > "$work/no-mtl.json"
expect_failure "missing MTL file" "no-mtl.obj:1" "nowhere.mtl" -- render "$work/no-mtl.json" --out "$work/out.png"
printf 'mtllib bad-value.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl paint\nf 1 2 3\n' > "$work/bad-value.obj"
printf 'newmtl paint\nKd 0.5 half 0.5\n' > "$work/bad-value.mtl"
echo "{ $camera, \"meshes\": [{\"file\": \"bad-value.obj\"}] }" > "$work/bad-value.json"
expect_failure "malformed MTL value" "bad-value.mtl:2" "half" -- render "$work/bad-value.json" --out "$work/out.png"

# Corrupt and truncated images: a reference for compare (every chapter), a texture (chapter 02).
echo "not an image" > "$work/garbage.exr"
expect_failure "corrupt reference image" "garbage.exr" -- compare "$work/good.json" --integrators pt-naive --spp 1 --reference "$work/garbage.exr" --out "$work/report"
"$renderer" render "$work/good.json" --spp 1 --quiet --out "$work/whole.exr" >/dev/null 2>&1
head -c 200 "$work/whole.exr" > "$work/cut.exr"
expect_failure "truncated reference image" "cut.exr" -- compare "$work/good.json" --integrators pt-naive --spp 1 --reference "$work/cut.exr" --out "$work/report"
# compare --make-reference: one integrator, a budget, an EXR (whose header keeps the seed).
expect_failure "reference from two integrators" "--integrators" "one integrator" -- compare "$work/good.json" --integrators pt-naive,pt-naive --spp 1 --make-reference "$work/out.png"
expect_failure "reference without a budget" "--time/--spp/--target-error" -- compare "$work/good.json" --integrators pt-naive --make-reference "$work/out.png"
expect_failure "reference not in EXR" "out.png" "OpenEXR" -- compare "$work/good.json" --integrators pt-naive --spp 1 --make-reference "$work/out.png"
expect_failure "target error without --make-reference" "--target-error" "only --make-reference" -- compare "$work/good.json" --integrators pt-naive --spp 1 --target-error 0.1 --out "$work/report"
chapter02="$(dirname "$renderer")/ch02"
if [ -x "$chapter02" ]; then
    head -c -12 "$work/good.png" > "$work/cut.png"  # without its IEND chunk
    echo "{ $camera, \"meshes\": [{\"file\": \"tri.obj\"}], \"materials\": {\"paint\": {\"type\": \"diffuse\", \"albedo_texture\": \"cut.png\"}} }" > "$work/cut-texture.json"
    renderer_saved=$renderer; renderer=$chapter02
    expect_failure "truncated texture (ch02)" "cut-texture.json" "/materials/paint/albedo_texture" "cut.png" "truncated" -- render "$work/cut-texture.json" --out "$work/out.png"
    renderer=$renderer_saved
else
    echo "skip [truncated texture]: no chapter 02 renderer beside $renderer"
fi

# Options.
expect_failure "absurd sample count" "--spp" "absurd" -- render "$work/good.json" --spp 2000000000000 --out "$work/out.png"
expect_failure "sample count beyond 64 bits" "--spp" -- render "$work/good.json" --spp 100000000000000000000 --out "$work/out.png"
expect_failure "negative thread count" "--threads" -- render "$work/good.json" --threads -1 --out "$work/out.png"
expect_failure "negative time" "--time" -- render "$work/good.json" --time -1 --out "$work/out.png"
expect_failure "output under a file, not a folder" "good.json/out.png" "not a folder" -- render "$work/good.json" --out "$work/good.json/out.png"
mkdir -p "$work/folder.png"
expect_failure "output path that is a folder" "folder.png" "is a folder" -- render "$work/good.json" --out "$work/folder.png"

# Usage errors of the command line itself: exit status 1 as well (not the parser's own codes).
expect_failure "unknown option" "--bogus" -- render "$work/good.json" --bogus --out "$work/out.png"
expect_failure "no subcommand" "subcommand" --
expect_failure "no scene" "scene is required" -- render --out "$work/out.png"
expect_failure "--time with --spp" "--time" "--spp" -- render "$work/good.json" --time 1 --spp 4 --out "$work/out.png"
version=$("$renderer" --version 2>&1); status=$?
if [ $status -eq 0 ] && grep -q "^FreezeRay .* [0-9][0-9.]* (chapters\? 01" <<<"$version"; then
    echo "ok   [--version] (exit 0): $version"
else
    echo "FAIL [--version]: exit $status, printed '$version'"; failures=$((failures + 1))
fi

if [ $failures -ne 0 ]; then echo "$failures bad-input case(s) failed"; exit 1; fi
echo "every bad-input case was refused cleanly"
