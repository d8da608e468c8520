#!/usr/bin/env bash
# The ray-throughput benchmark on Crytek Sponza with the shared batches (../shared/rays/README.md):
# the accelerators named in FULL_BATCH_ACCELERATORS (Embree among them when ray-benchmark has it)
# on every ray, then bruteforce on the first 2000 rays of each kind. Writes the JSON lines to OUT_DIR and prints
# them; checks that the mesh has the 262,267 triangles the batches were made for and that every
# line has its fields. Timings are recorded, never asserted. Exit 77 (skipped) when the shared
# files are absent.
# Usage: ray_benchmark_sponza.sh RAY_BENCHMARK SOURCE_DIR OUT_DIR [FULL_BATCH_ACCELERATORS]
set -u
benchmark=$1
source_dir=$2
out_dir=$3
accelerators=${4:-}

scenes=${FREEZERAY_SHARED_SCENES:-$source_dir/../shared/scenes}
rays=${FREEZERAY_SHARED_RAYS:-$scenes/../rays/sponza.rays}
mesh=$scenes/crytek-sponza/sponza.obj
for file in "$mesh" "$rays"; do
    if [ ! -f "$file" ]; then
        echo "skipped: $file is not there (set FREEZERAY_SHARED_SCENES, or FREEZERAY_SHARED_RAYS)"
        exit 77
    fi
done
mkdir -p "$out_dir"
results=$out_dir/ray-benchmark-sponza.jsonl
notes=$out_dir/ray-benchmark-sponza.notes.txt
: >"$results"
: >"$notes"

run() {
    echo "+ ray-benchmark $*" | tee -a "$notes"
    if ! "$benchmark" "$mesh" --rays "$rays" --json "$@" >>"$results" 2>>"$notes"; then
        echo "FAIL: ray-benchmark $* exited with status $?"; cat "$notes"; exit 1
    fi
}

# The full batches, for the accelerators fast enough to trace them (Embree always measures
# itself when present, so naming it is only needed when it is alone).
if [ -n "$accelerators" ]; then run --accel "$accelerators" --threads 1,2 --reps 5; fi
# Brute force is O(n) per ray: its first 2000 rays of each kind take minutes already. (Embree
# measures itself again on those rays, the reference for bruteforce's disagreement counts.)
run --accel bruteforce --limit 2000 --threads 1 --reps 1
cat "$notes"
cat "$results"

python3 - "$results" "$notes" <<'PY'
import json, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
notes = open(sys.argv[2]).read()
problems = []
if "262267 triangles" not in notes:
    problems.append("the mesh does not have the 262267 triangles the shared batches were made for")
fields = ["accel", "kind", "threads", "rays", "mrays_per_s", "median_ms", "reps", "build_ms", "memory_mb",
          "differ_from_embree", "ties"]
for row in rows:
    missing = [f for f in fields if f not in row]
    if missing:
        problems.append(f"{row} lacks {missing}")
if not any(r["accel"] == "bruteforce" for r in rows):
    problems.append("no bruteforce rows")
# A summary for the notes: Mrays/s per accelerator, kind and thread count.
for r in rows:
    differ = "" if r["differ_from_embree"] is None else f", differ {r['differ_from_embree']}, ties {r['ties']}"
    print(f"{r['accel']:>12} {r['kind']:>8} {r['threads']} threads: {r['rays']:>7} rays, "
          f"{r['mrays_per_s']:.4g} Mrays/s, build {r['build_ms']:.1f} ms{differ}")
print("\n".join(problems))
sys.exit(1 if problems else 0)
PY
