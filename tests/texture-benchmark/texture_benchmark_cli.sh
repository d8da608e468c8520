#!/usr/bin/env bash
# texture-benchmark's command line: on a copy of scenes/texture-plane with a 1024 x 1024 texture,
# it prints one JSON object per configuration (the scene's one texture), the cache model finds that tiles make a bilinear
# lookup read fewer distinct cache lines than rows do (4 x 4 tiles of 4-byte texels: each lookup's
# four texels share one line unless they straddle a tile's edge; rows: two lines unless they
# straddle the image's), the access map is a PNG of two panels side by side, and bad input is
# refused with a message and exit status 1.
# Usage: texture_benchmark_cli.sh TEXTURE_BENCHMARK REPOSITORY
set -u
benchmark=$1
repository=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$repository/scenes/texture-plane/scene.json" "$repository/scenes/texture-plane/make_scene.py" "$work/"
(cd "$work" && python3 make_scene.py --size 1024) || { echo "FAIL: make_scene.py"; exit 1; }

failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

output=$("$benchmark" "$work/scene.json" --spp 1 --reps 1 --json \
         --configs linear/bilinear,tiled/bilinear,linear/trilinear,tiled/trilinear 2>&1) || fail "exit status $? ($output)"
lines=$(grep -c '^{' <<< "$output")
[ "$lines" -eq 4 ] || fail "expected 4 JSON lines, got $lines: $output"
python3 - "$output" <<'PYTHON' || failures=$((failures + 1))
import json, sys
rows = {r["configuration"]: r for r in (json.loads(l) for l in sys.argv[1].splitlines() if l.startswith("{"))}
problems = []
for name, row in rows.items():
    # Bilinear: four texels. Trilinear: eight between two levels, four where the texture is
    # magnified (level 0 alone) and near the horizon (the last level); some of each here.
    texels = row["texels_per_lookup"]
    if name.endswith("bilinear") and abs(texels - 4.0) > 1e-9:
        problems.append(f"{name}: {texels} texels per lookup, not 4")
    if name.endswith("trilinear") and not 4.0 < texels < 8.0:
        problems.append(f"{name}: {texels} texels per lookup, not between 4 and 8")
    if not row["storage"].startswith(name.split("/")[0]) or "8-bit sRGB" not in row["storage"]:
        problems.append(f"{name}: storage '{row['storage']}'")
    if row["textures"] != 1:
        problems.append(f"{name}: {row['textures']} textures, not the scene's one")
if not rows["tiled/bilinear"]["lines_per_lookup"] < rows["linear/bilinear"]["lines_per_lookup"]:
    problems.append("tiles do not reduce the lines a bilinear lookup reads: "
                    f"{rows['tiled/bilinear']['lines_per_lookup']} vs {rows['linear/bilinear']['lines_per_lookup']}")
if not rows["tiled/trilinear"]["memory_mib"] > rows["tiled/bilinear"]["memory_mib"]:
    problems.append("the MIP levels take no memory")
for p in problems:
    print("FAIL: " + p)
sys.exit(1 if problems else 0)
PYTHON

# The access map of a tile near the image's bottom (the texture magnified: neighbouring pixels
# read neighbouring texels): two panels and a gap, the same crop in both.
map_output=$("$benchmark" "$work/scene.json" --spp 1 --reps 1 --configs linear/bilinear,tiled/bilinear \
             --access-map "$work/map.png" --map-tile 16,15 2>&1) || fail "access map: exit status $? ($map_output)"
python3 - "$work/map.png" "$map_output" <<'PYTHON' || failures=$((failures + 1))
import re, struct, sys
with open(sys.argv[1], "rb") as f:
    header = f.read(24)
problems = []
if header[:8] != b"\x89PNG\r\n\x1a\n":
    problems.append("the access map is no PNG")
else:
    width, height = struct.unpack(">II", header[16:24])
    if not (width > 2 * height * 0.9 and height > 100):
        problems.append(f"the access map is {width} x {height}: not two panels side by side")
crops = re.findall(r"texels (\[\d+, \d+\] x \[\d+, \d+\]): (\d+) texels read, (\d+) cache lines", sys.argv[2])
if len(crops) != 2 or crops[0][:2] != crops[1][:2]:
    problems.append(f"the panels do not show the same texels read: {crops}")
elif not int(crops[1][2]) < int(crops[0][2]):
    problems.append(f"tiles do not bring fewer lines into the caches than rows: {crops}")
for p in problems:
    print("FAIL: " + p)
sys.exit(1 if problems else 0)
PYTHON

expect_error() {  # NAME TEXT -- ARGS
    local name=$1 text=$2; shift 3
    local message status
    message=$("$benchmark" "$@" 2>&1 >/dev/null); status=$?
    [ "$status" -eq 1 ] || fail "[$name] exit status $status, not 1"
    grep -qF -- "$text" <<< "$message" || fail "[$name] message lacks '$text': $message"
}
expect_error "unknown layout" "unknown layout in 'rows/bilinear'" -- "$work/scene.json" --configs rows/bilinear
expect_error "unknown filter" "unknown filter in 'tiled/nearest'" -- "$work/scene.json" --configs tiled/nearest
expect_error "tile size of rows" "only tiled textures have a tile size" -- "$work/scene.json" --configs linear/bilinear/8
expect_error "impossible tile size" "not '3'" -- "$work/scene.json" --configs tiled/bilinear/3
expect_error "tile size that is no number" "not 'x'" -- "$work/scene.json" --configs tiled/bilinear/x
expect_error "unknown texel format" "expected auto or float" -- "$work/scene.json" --texel-format half
expect_error "missing scene" "nothing.json" -- "$work/nothing.json"
expect_error "tile outside the image" "32 x 16 tiles" -- "$work/scene.json" --access-map "$work/m.png" --map-tile 40,0
expect_error "map in no folder" "no-folder" -- "$work/scene.json" --access-map "$work/no-folder/m.png"
[ "$failures" -eq 0 ] && echo "texture-benchmark: all checks passed"
exit $((failures > 0))
