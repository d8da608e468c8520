#!/usr/bin/env bash
# light-sampler-benchmark's command line: on the Cornell box at 32 x 32 it prints one JSON object
# per light sampler, each with a positive time per choice and a light chosen at (nearly) every
# point; bad input is refused with a message and exit status 1.
# Usage: light_sampler_benchmark_cli.sh LIGHT_SAMPLER_BENCHMARK REPOSITORY
set -u
benchmark=$1
repository=$2
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

output=$("$benchmark" "$repository/scenes/cornell-box/scene.json" --width 32 --height 32 --reps 1 --json 2>&1) ||
    fail "exit status $? ($output)"
python3 - "$output" <<'PYTHON' || failures=$((failures + 1))
import json, sys
rows = [json.loads(l) for l in sys.argv[1].splitlines() if l.startswith("{")]
problems = []
if [r["sampler"] for r in rows] != ["power", "uniform", "bvh-tree", "bvh"]:
    problems.append("expected power, uniform, bvh-tree, bvh, got %s" % [r["sampler"] for r in rows])
for r in rows:
    if not r["ns_per_choice"] > 0: problems.append("%s: no time per choice" % r["sampler"])
    if r["points"] < 900: problems.append("%s: only %d shading points of 1024 pixels" % (r["sampler"], r["points"]))
    # Power and uniform always choose; the tree leaves out the light where it cannot shine (the
    # ceiling around it), which the camera sees in a few rows of pixels only; bvh leaves it out
    # in the tree's share of the choices only.
    wanted = {"bvh-tree": 0.8, "bvh": 0.84}.get(r["sampler"], 1.0)
    if r["chosen_fraction"] < wanted: problems.append("%s: a light chosen in %.4f of the walks" % (r["sampler"], r["chosen_fraction"]))
for p in problems: print("FAIL:", p)
sys.exit(1 if problems else 0)
PYTHON

expect_failure() {
    local name=$1 expected=$2; shift 2
    local message status
    message=$("$benchmark" "$@" 2>&1)
    status=$?
    [ $status -eq 1 ] || fail "[$name] exit status $status, not 1"
    grep -qF -- "$expected" <<< "$message" || fail "[$name] message lacks '$expected': $message"
}
expect_failure "unknown light sampler" "--samplers" "$repository/scenes/cornell-box/scene.json" --samplers power,tree
expect_failure "missing scene" "nowhere.json" "$repository/scenes/nowhere.json"
expect_failure "no passes" "--reps" "$repository/scenes/cornell-box/scene.json" --reps 0

[ $failures -eq 0 ] && echo "light-sampler-benchmark: all checks passed"
exit $((failures > 0))
