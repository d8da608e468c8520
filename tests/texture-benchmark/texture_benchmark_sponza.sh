#!/usr/bin/env bash
# The texture benchmark on Crytek Sponza (scenes/sponza, its 36 textures from the shared scenes
# folder): every layout and filter, 8-bit texels where the files allow them, one run; checks that
# every line has its fields and that the scene's textures were all stored. JSON lines in
# OUT/texture-benchmark-sponza.jsonl, and on standard output. Timings are recorded, never
# asserted. Exit 77 (skipped) when the shared scenes are absent.
# Usage: texture_benchmark_sponza.sh TEXTURE_BENCHMARK REPOSITORY OUT
set -u
benchmark=$1
repository=$2
out=$3
scenes=${FREEZERAY_SHARED_SCENES:-$repository/../shared/scenes}
if [ ! -f "$scenes/crytek-sponza/sponza.obj" ]; then
    echo "skipped: $scenes/crytek-sponza/sponza.obj is not there (set FREEZERAY_SHARED_SCENES)"
    exit 77
fi
mkdir -p "$out"
results=$out/texture-benchmark-sponza.jsonl
configs=linear/bilinear,tiled/bilinear,linear/trilinear,tiled/trilinear
FREEZERAY_SHARED_SCENES=$scenes "$benchmark" "$repository/scenes/sponza/scene.json" --spp 4 --reps 5 \
    --configs "$configs" --json > "$results.part" || { echo "FAIL: texture-benchmark exit status $?"; exit 1; }
mv "$results.part" "$results"
cat "$results"
python3 - "$results" <<'PYTHON'
import json, sys
rows = [json.loads(line) for line in open(sys.argv[1]) if line.startswith("{")]
fields = ["configuration", "storage", "textures", "lookups", "memory_mib", "ns_per_lookup", "lines_per_lookup",
          "l1_misses_per_lookup", "l2_misses_per_lookup", "l3_misses_per_lookup"]
problems = [f"{len(rows)} lines, not 4"] if len(rows) != 4 else []
problems += [f"{r.get('configuration')}: no {f}" for r in rows for f in fields if f not in r]
problems += [f"{r['configuration']}: {r['textures']} textures" for r in rows if r.get("textures", 0) < 20]
for p in problems:
    print("FAIL: " + p)
sys.exit(1 if problems else 0)
PYTHON
status=$?
echo "results: $results"
exit $status
