#!/usr/bin/env bash
# --integrator auto as a user runs it: it says what it chose and why, the EXR header keeps both,
# it cannot be resumed as auto, and compare takes it beside the others.
# Usage: auto_integrator.sh RENDERER SOURCE_DIR
set -u
renderer=$1
scene=$2/scenes/cornell-box/scene.json
source "$(dirname "$0")/harness.sh"

message=$("$renderer" render "$scene" --integrator auto --spp 8 --width 24 --height 24 --out "$work/auto.exr" 2>&1 >/dev/null)
status=$?
[ $status -eq 0 ] || fail "render --integrator auto exited $status: $message"
choice=$(grep "^auto chose " <<<"$message")
echo "$choice"
[ -n "$choice" ] || fail "no line says what auto chose: $message"
chosen=$(sed -n 's/^auto chose \([a-z-]*\): .*/\1/p' <<<"$choice")
case "$chosen" in
    pt-mis|bdpt|mlt) ;;
    *) fail "auto chose '$chosen', which is not one of its candidates" ;;
esac
grep -q "pilots of 4 spp each" <<<"$choice" || fail "the line does not say what the pilots were"
# The EXR header: the integrator that made the image, and why (attribute names and values are
# stored as plain text in the header).
grep -aq "freezeray:integrator_choice" "$work/auto.exr" || fail "the EXR header has no freezeray:integrator_choice"
grep -aq "$chosen: estimated efficiency" "$work/auto.exr" || fail "the EXR header does not give the reason for $chosen"

message=$("$renderer" render "$scene" --integrator auto --spp 8 --width 24 --height 24 --resume "$work/auto.exr.state" \
    --out "$work/again.exr" 2>&1 >/dev/null)
status=$?
[ $status -eq 1 ] || fail "resuming auto exited $status, not 1"
grep -q "cannot be resumed" <<<"$message" || fail "the refusal does not say why: $message"

"$renderer" compare "$scene" --integrators auto,pt-mis --spp 8 --width 16 --height 16 --out "$work/report" --quiet \
    >/dev/null 2>&1 || fail "compare with auto failed"
grep -q "| auto |" "$work/report/report.md" || fail "the report has no row for auto"

if [ $failures -ne 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo "all auto checks passed"
