#!/usr/bin/env bash
# compare --make-reference: the reference gets a seed other than the comparison's, says what it
# can measure, stops at a target error, and is refused by a comparison that uses its seed.
# Usage: make_reference.sh RENDERER SOURCE_DIR
set -u
renderer=$1
scene=$2/scenes/cornell-box/scene.json
source "$(dirname "$0")/harness.sh"

# A reference by samples: it exists, and its summary names its seed and the errors it can measure.
message=$("$renderer" compare "$scene" --integrators pt-mis --spp 64 --width 16 --height 16 --make-reference "$work/ref.exr" 2>&1 >/dev/null)
status=$?
echo "$message" | tail -n 1
[ $status -eq 0 ] || fail "make-reference exited $status"
[ -s "$work/ref.exr" ] || fail "no reference written"
grep -q "measures errors down to" <<<"$message" || fail "the summary does not say which errors the reference can measure"
seed=$(sed -n 's/^reference: .*, seed \([0-9]*\) (the comparison.s is 0).*/\1/p' <<<"$message")
[ -n "$seed" ] || fail "the summary does not name the reference's seed"
[ "$seed" != "0" ] || fail "the reference has the comparison's seed 0"

# The comparison it was made for accepts it; one with the reference's own seed refuses it.
"$renderer" compare "$scene" --integrators pt-mis --spp 4 --width 16 --height 16 --reference "$work/ref.exr" \
    --out "$work/report" --quiet >/dev/null 2>&1 || fail "compare refused the reference made for it"
grep -q "ref.exr (64 spp, pt-mis)" "$work/report/report.md" || fail "the report does not describe the reference"
if [ -n "$seed" ]; then
    message=$("$renderer" compare "$scene" --integrators pt-mis --spp 4 --width 16 --height 16 --reference "$work/ref.exr" \
        --seed "$seed" --out "$work/same-seed" --quiet 2>&1 >/dev/null)
    status=$?
    [ $status -eq 1 ] || fail "a comparison with the reference's own seed exited $status, not 1"
    grep -q "this comparison's" <<<"$message" || fail "the refusal does not say why: $message"
    [ -e "$work/same-seed" ] && fail "the refused comparison left its folder"
fi

# A reference by target error stops once its estimated relMSE is below the target (the sample
# count is only a cap here, far above what the target needs).
message=$("$renderer" compare "$scene" --integrators pt-mis --spp 65536 --target-error 0.005 --width 16 --height 16 \
    --make-reference "$work/target.exr" 2>&1 >/dev/null)
status=$?
[ $status -eq 0 ] || fail "make-reference with --target-error exited $status"
reached=$(sed -n 's/^pt-mis: 16x16, \([0-9]*\) spp, .*estimated relMSE \([0-9.e+-]*\)$/\1 \2/p' <<<"$message")
echo "target 0.005: reached $reached (spp, estimated relMSE)"
read -r spp estimate <<<"$reached"
if [ -z "${estimate:-}" ]; then
    fail "no summary line: $message"
else
    awk -v e="$estimate" 'BEGIN { exit !(e <= 0.005) }' || fail "stopped at estimated relMSE $estimate, above the target 0.005"
    [ "$spp" -lt 65536 ] || fail "ran to the cap ($spp spp) instead of stopping at the target"
fi

if [ $failures -ne 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo "all make-reference checks passed"
