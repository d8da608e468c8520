#!/usr/bin/env bash
# ray-benchmark as a user runs it, on the Cornell box's mesh: JSON lines with every field, ray
# and hit files that read back, and bad input refused with exit status 1, a message naming what
# and where, and no output file left behind.
# Usage: ray_benchmark_cli.sh RAY_BENCHMARK SOURCE_DIR
set -u
benchmark=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
mesh="$source_dir/scenes/cornell-box/cornell-box.obj"
camera=(--camera 278,273,-800,278,273,0,39.3 --resolution 40)

fail() { echo "FAIL [$1]: $2"; failures=$((failures + 1)); }

# --- JSON lines: one per measurement, every field, rays within the limit ---------------------
if ! "$benchmark" "$mesh" "${camera[@]}" --accel bruteforce --json --limit 1000 --reps 2 --threads 1,2 \
        --write-rays "$work/cornell.rays" --hits-out "$work/cornell.hits" >"$work/out.jsonl" 2>"$work/err.txt"; then
    fail "json run" "exit status $?: $(cat "$work/err.txt")"
else
    if python3 - "$work/out.jsonl" <<'PY'
import json, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
fields = ["accel", "kind", "threads", "rays", "mrays_per_s", "median_ms", "reps", "build_ms", "memory_mb",
          "differ_from_embree", "ties"]
problems = []
for row in rows:
    for field in fields:
        if field not in row:
            problems.append(f"row {row} lacks {field}")
brute = [r for r in rows if r.get("accel") == "bruteforce"]
embree = [r for r in rows if r.get("accel") == "embree"]
# 3 kinds x 2 thread counts per accelerator.
if len(brute) != 6:
    problems.append(f"{len(brute)} bruteforce rows, expected 6")
if embree and len(embree) != 6:
    problems.append(f"{len(embree)} embree rows, expected 0 or 6")
for r in brute + embree:
    if r["kind"] not in ("primary", "diffuse", "shadow"):
        problems.append(f"unknown kind {r['kind']}")
    if r["threads"] not in (1, 2):
        problems.append(f"threads {r['threads']}")
    if not (0 < r["rays"] <= 1000):
        problems.append(f"{r['rays']} rays, expected 1..1000")
    if not (isinstance(r["mrays_per_s"], (int, float)) and r["mrays_per_s"] > 0):
        problems.append(f"mrays_per_s {r['mrays_per_s']}")
    if r["reps"] != 2:
        problems.append(f"reps {r['reps']}")
for r in brute:
    # With Embree the differences are counted (ties only for closest-hit rays); without, null.
    if embree:
        if not isinstance(r["differ_from_embree"], int):
            problems.append(f"differ_from_embree {r['differ_from_embree']} with Embree present")
        if (r["ties"] is None) != (r["kind"] == "shadow"):
            problems.append(f"ties {r['ties']} for {r['kind']}")
    elif r["differ_from_embree"] is not None or r["ties"] is not None:
        problems.append("differ/ties not null without Embree")
print("\n".join(problems))
sys.exit(1 if problems else 0)
PY
    then
        echo "ok   [json run] $(wc -l <"$work/out.jsonl") JSON lines with every field"
    else
        fail "json run" "JSON lines wrong; output was: $(cat "$work/out.jsonl")"
    fi
    # The ray file: 20 header bytes, 29 per ray; 1000 primary rays (1600 pixels, all hit the box).
    rays_size=$(stat -c %s "$work/cornell.rays" 2>/dev/null || echo 0)
    if [ "$rays_size" -ne $((20 + 29 * 3000)) ]; then fail "write-rays" "$rays_size bytes, expected $((20 + 29 * 3000))"; else echo "ok   [write-rays] $rays_size bytes"; fi
    hits_size=$(stat -c %s "$work/cornell.hits" 2>/dev/null || echo 0)
    if [ "$hits_size" -ne $((20 + 8 * 2000)) ]; then fail "hits-out" "$hits_size bytes, expected $((20 + 8 * 2000))"; else echo "ok   [hits-out] $hits_size bytes"; fi
    if ls "$work"/*.tmp-* >/dev/null 2>&1; then fail "atomic writes" "a temporary file was left"; fi
fi

# --- The written rays read back, and give the same hits --------------------------------------
if "$benchmark" "$mesh" --rays "$work/cornell.rays" --accel bruteforce --reps 1 --hits-out "$work/again.hits" \
        >"$work/table.txt" 2>&1; then
    if cmp -s "$work/cornell.hits" "$work/again.hits"; then echo "ok   [rays read back] same hits"; else fail "rays read back" "the hits differ"; fi
    if grep -q "^bruteforce *primary" "$work/table.txt"; then echo "ok   [table] has a bruteforce primary row"; else fail "table" "$(cat "$work/table.txt")"; fi
else
    fail "rays read back" "exit status $?: $(cat "$work/table.txt")"
fi

# --- --order coherent: the same rays sorted, every kind measured, answers as Embree's ---------
if "$benchmark" "$mesh" --rays "$work/cornell.rays" --accel kdtree --order coherent --json --reps 1 \
        >"$work/coherent.jsonl" 2>"$work/err.txt"; then
    if ! python3 - "$work/coherent.jsonl" <<'PY'
import json, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
kd = [r for r in rows if r["accel"] == "kdtree"]
problems = [] if len(kd) == 3 else [f"{len(kd)} kdtree rows, expected 3"]
problems += [f"{r['kind']}: {r['differ_from_embree']} differ" for r in kd if r["differ_from_embree"] not in (None, 0)]
print("\n".join(problems))
sys.exit(1 if problems else 0)
PY
    then fail "coherent order" "rows wrong"; fi
else
    fail "coherent order" "exit status $?: $(cat "$work/err.txt")"
fi

# --- Bad input: exit status 1, a message naming what and where, no output file ---------------
# expect_failure NAME EXPECTED_TEXT... -- ARGS
expect_failure() {
    local name=$1; shift
    local expected=()
    while [ "$1" != "--" ]; do expected+=("$1"); shift; done
    shift
    rm -f "$work/out.hits" "$work/out.rays"
    local message status
    message=$("$benchmark" "$@" 2>&1 >/dev/null)
    status=$?
    local ok=1
    if [ $status -ne 1 ]; then echo "FAIL [$name]: exit status $status, expected 1"; ok=0; fi
    for text in "${expected[@]}"; do
        if ! grep -qF -- "$text" <<<"$message"; then echo "FAIL [$name]: message lacks '$text'"; ok=0; fi
    done
    if ls "$work"/out.* "$work"/*.tmp-* >/dev/null 2>&1; then echo "FAIL [$name]: an output file was left"; ok=0; fi
    if [ $ok -eq 1 ]; then echo "ok   [$name] (exit $status): $message"; else echo "     message was: $message"; failures=$((failures + 1)); fi
}

out=(--hits-out "$work/out.hits")
expect_failure "missing mesh" "nothing.obj" "does not exist" -- "$work/nothing.obj" "${camera[@]}" "${out[@]}"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 5\n' >"$work/range.obj"
expect_failure "face index out of range" "range.obj:4" -- "$work/range.obj" "${camera[@]}" "${out[@]}"
expect_failure "missing ray file" "none.rays" -- "$mesh" --rays "$work/none.rays" "${out[@]}"
printf 'FRRAYS02\0\0\0\0\0\0\0\0\0\0\0\0' >"$work/magic.rays"
expect_failure "wrong magic" "magic.rays" "FRRAYS01" -- "$mesh" --rays "$work/magic.rays" "${out[@]}"
head -c 1000 "$work/cornell.rays" >"$work/short.rays"
expect_failure "truncated ray file" "short.rays" "truncated at record 33" -- "$mesh" --rays "$work/short.rays" "${out[@]}"
python3 - "$work/cornell.rays" "$work/tag.rays" <<'PY'
import sys
data = bytearray(open(sys.argv[1], "rb").read())
data[20 + 29 * 7 + 28] = 9  # record 7's tag
open(sys.argv[2], "wb").write(data)
PY
expect_failure "bad tag" "tag.rays: record 7" "tag 9" -- "$mesh" --rays "$work/tag.rays" "${out[@]}"
expect_failure "unknown accelerator" "--accel" "octree" "bruteforce" -- "$mesh" "${camera[@]}" --accel octree "${out[@]}"
expect_failure "camera that sees nothing" "--camera" "none of the primary rays" -- "$mesh" --camera 278,273,-800,278,273,-1600,39.3 --resolution 8 "${out[@]}"
expect_failure "malformed camera" "--camera" "seven numbers" -- "$mesh" --camera 1,2,3 "${out[@]}"
expect_failure "bad resolution" "--resolution" -- "$mesh" "${camera[@]:0:2}" --resolution 0x5 "${out[@]}"
expect_failure "zero threads" "--threads" -- "$mesh" "${camera[@]}" --threads 1,0 "${out[@]}"
expect_failure "zero repetitions" "--reps" -- "$mesh" "${camera[@]}" --reps 0 "${out[@]}"
expect_failure "not a number" "--reps" -- "$mesh" "${camera[@]}" --reps many "${out[@]}"
expect_failure "hits into a missing folder" "no/such" "does not exist" -- "$mesh" "${camera[@]}" --hits-out "$work/no/such/out.hits"
expect_failure "unknown order" "--order" "random" -- "$mesh" "${camera[@]}" --order random "${out[@]}"
expect_failure "camera with a ray file" "--camera" -- "$mesh" --rays "$work/cornell.rays" --camera 0,0,0,0,0,1,40

if [ $failures -ne 0 ]; then echo "$failures failures"; exit 1; fi
echo "all ray-benchmark command-line checks passed"
