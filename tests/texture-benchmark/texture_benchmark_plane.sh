#!/usr/bin/env bash
# The texture benchmark's measurement: texture-plane with its 8192 x 8192 texture (made here, in
# OUT/texture-plane, by the scene's make_scene.py), every layout and filter, 8-bit texels, one run;
# JSON lines in OUT/texture-benchmark-plane.jsonl, and on standard output.
# Usage: texture_benchmark_plane.sh TEXTURE_BENCHMARK REPOSITORY OUT
set -eu
benchmark=$1
repository=$2
out=$3
mkdir -p "$out/texture-plane"
cp "$repository/scenes/texture-plane/scene.json" "$repository/scenes/texture-plane/make_scene.py" "$out/texture-plane/"
[ -f "$out/texture-plane/ground.png" ] || (cd "$out/texture-plane" && python3 make_scene.py)
configs=linear/bilinear,tiled/bilinear,linear/trilinear,tiled/trilinear
"$benchmark" "$out/texture-plane/scene.json" --spp 4 --reps 5 --configs "$configs" --json \
    > "$out/texture-benchmark-plane.jsonl.part"
mv "$out/texture-benchmark-plane.jsonl.part" "$out/texture-benchmark-plane.jsonl"
cat "$out/texture-benchmark-plane.jsonl"
echo "results: $out/texture-benchmark-plane.jsonl"
