#!/usr/bin/env bash
# sampler-points as the book's figure script runs it: 256 points per sampler in [0, 1)^2, Sobol's
# first 64 and all 256 one per cell of 8 x 8 and 16 x 16 (a net's property, which independent
# points lack; vertex 4's BSDF direction, the first pair of its own joint set), the same points on every run; bad input refused with exit status 1 and a message.
# Usage: sampler_points_cli.sh SAMPLER_POINTS
set -u
program=$1
failures=0
fail() { echo "FAIL [$1]: $2"; failures=$((failures + 1)); }

for sampler in independent stratified sobol zsobol sobol-unscrambled; do
    for draw in pixel bsdf; do
        if ! out=$("$program" --sampler "$sampler" --count 256 --draw "$draw" --vertex 4 --pixel-x 5 --pixel-y 7 2>&1); then
            fail "$sampler $draw" "exit status $?: $out"; continue
        fi
        if ! python3 - "$sampler" "$draw" <<PY
import sys
sampler, draw = sys.argv[1], sys.argv[2]
points = [tuple(map(float, line.split(","))) for line in """$out""".split()]
problems = []
if len(points) != 256:
    problems.append(f"{len(points)} points")
if any(not (0.0 <= v < 1.0) for p in points for v in p):
    problems.append("a coordinate outside [0, 1)")
def alone(ps, n):
    cells = {}
    for x, y in ps:
        c = (int(x * n), int(y * n))
        cells[c] = cells.get(c, 0) + 1
    return sum(1 for v in cells.values() if v == 1)
if sampler.startswith("sobol") or sampler == "zsobol":
    if alone(points[:64], 8) != 64 or alone(points, 16) != 256:
        problems.append(f"not nets: {alone(points[:64], 8)} of 64, {alone(points, 16)} of 256 cells")
elif sampler == "independent" and alone(points, 16) == 256:
    # 256 independent points one per cell of 16 x 16 has probability 256!/256^256, about 1e-110.
    problems.append("independent points stratified")
if problems:
    print(f"{sampler} {draw}: " + "; ".join(problems))
    sys.exit(1)
PY
        then failures=$((failures + 1)); fi
    done
done

first=$("$program" --sampler sobol --count 16 --seed 9)
second=$("$program" --sampler sobol --count 16 --seed 9)
other=$("$program" --sampler sobol --count 16 --seed 10)
[ "$first" = "$second" ] || fail "determinism" "two runs with seed 9 differ"
[ "$first" != "$other" ] || fail "seeds" "seeds 9 and 10 give the same points"

expect_failure() {
    local name=$1 text=$2; shift 2
    local message status
    message=$("$program" "$@" 2>&1 >/dev/null); status=$?
    if [ $status -ne 1 ]; then fail "$name" "exit status $status, expected 1"; return; fi
    grep -qF -- "$text" <<<"$message" || fail "$name" "message lacks '$text': $message"
}
expect_failure "unknown sampler" "--sampler" --sampler halton
expect_failure "no samples" "--count" --count 0
expect_failure "pixel outside" "--pixel-x" --pixel-x 64
expect_failure "vertex 0" "--vertex" --draw bsdf --vertex 0

if [ $failures -ne 0 ]; then echo "$failures failures"; exit 1; fi
echo "sampler-points: all checks passed"
