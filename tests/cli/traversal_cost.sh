#!/usr/bin/env bash
# The traversal-cost integrator of chapter 06 on the Cornell box: a false-colour PNG and a note
# giving its scale; a clear error with brute force (it counts the KD-tree's work) and for an
# unknown quantity, nothing written then.
# Usage: traversal_cost.sh SOURCE_DIR CH06
set -u
source_dir=$1 ch06=$2
source "$(dirname "$0")/harness.sh"
scene=$source_dir/scenes/cornell-box/scene.json

check() {  # check NAME CONDITION...
    local name=$1; shift
    if "$@"; then echo "ok   [$name]"; else echo "FAIL [$name]"; failures=$((failures + 1)); fi
}

for show in nodes leaves tests; do
    notes=$("$ch06" render "$scene" --integrator traversal-cost --traversal-cost-show "$show" --width 32 --height 32 \
        --spp 1 --out "$work/$show.png" 2>&1 >/dev/null)
    status=$?
    check "traversal-cost --traversal-cost-show $show renders (status $status)" test $status -eq 0
    check "the $show image is written" test -s "$work/$show.png"
    check "the note gives the $show scale: $notes" grep -q "traversal-cost: .* per camera ray, viridis from 0" <<<"$notes"
    check "the summary says there is no error estimate (a count is not an estimate of light): $notes" \
        grep -q "1 spp, .*, no error estimate$" <<<"$notes"
    check "the summary prints no negative relMSE" bash -c '! grep -q "relMSE -" <<<"$1"' _ "$notes"
done
# The Cornell box's tree: a camera ray visits some interior nodes and tests a few triangles.
notes=$("$ch06" render "$scene" --integrator traversal-cost --width 16 --height 16 --spp 1 --out "$work/n.pfm" 2>&1)
check "a camera ray visits interior nodes (mean above 1): $notes" \
    python3 -c "import re,sys; m=re.search(r'mean ([0-9.]+)', sys.argv[1]); sys.exit(0 if m and float(m.group(1)) > 1 else 1)" "$notes"

errors=$("$ch06" render "$scene" --integrator traversal-cost --accel bruteforce --width 16 --height 16 --spp 1 \
    --out "$work/brute.png" 2>&1)
status=$?
check "with brute force: a non-zero exit ($status)" test $status -ne 0
check "with brute force: the error names --accel kdtree: $errors" grep -q "use --accel kdtree" <<<"$errors"
check "with brute force: no image left" test ! -e "$work/brute.png"

errors=$("$ch06" render "$scene" --integrator traversal-cost --traversal-cost-show depth --width 16 --height 16 \
    --spp 1 --out "$work/bad.png" 2>&1)
status=$?
check "an unknown quantity: a non-zero exit ($status)" test $status -ne 0
check "an unknown quantity: the error names the flag: $errors" grep -q -- "--traversal-cost-show.*'depth' is not nodes, leaves or tests" <<<"$errors"
check "an unknown quantity: no image left" test ! -e "$work/bad.png"

if [ $failures -ne 0 ]; then echo "$failures failures"; exit 1; fi
echo "traversal-cost renders its images and refuses what it cannot count"
