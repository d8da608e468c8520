#!/usr/bin/env bash
# No render is lost with the splatting integrators of chapters 04 and 05 either: SIGINT during a
# bdpt or mlt render writes the image of the batches (rounds) done and exits 130; `--resume` of
# such a render is refused with the way to go on (another --sample-offset, then `merge`); and for
# mlt, --sample-offset gives a different, independent render (its offset enters the seed).
# Usage: splatting_interrupt.sh FREEZERAY SOURCE_DIR
set -u
renderer=$1
source_dir=$2
source "$(dirname "$0")/harness.sh"
scene="$source_dir/scenes/cornell-box/scene.json"
ok() { echo "ok   [$1]"; }
fail() { echo "FAIL [$1]"; failures=$((failures + 1)); }

for integrator in bdpt mlt; do
    out="$work/$integrator.exr"
    options=()  # mlt's own options (bdpt refuses them)
    if [ $integrator = mlt ]; then options=(--mlt-bootstrap 2000); fi
    "$renderer" render "$scene" --integrator $integrator --width 48 --height 48 --time 120 --quiet --threads 1 \
        "${options[@]}" --out "$out" 2>"$work/log" &
    pid=$!
    for _ in $(seq 1 100); do sleep 0.05; done  # 5 s: bootstrap done, rounds under way
    kill -INT $pid
    wait $pid; status=$?
    if [ $status -eq 130 ] && [ -s "$out" ] && grep -q -- "--sample-offset" "$work/log"; then
        ok "$integrator: SIGINT writes the image so far, exit 130, and says how to go on"
    else
        fail "$integrator: SIGINT gave exit $status; log: $(cat "$work/log")"
    fi
    if "$renderer" render "$scene" --integrator $integrator --width 48 --height 48 --spp 1 --quiet \
        --resume "$out.state" --out "$work/resumed.exr" 2>"$work/log2"; then
        fail "$integrator: --resume was accepted"
    elif grep -q -- "--resume" "$work/log2" && [ ! -e "$work/resumed.exr" ]; then
        ok "$integrator: --resume is refused: $(head -1 "$work/log2")"
    else
        fail "$integrator: --resume message: $(cat "$work/log2")"
    fi
done

"$renderer" render "$scene" --integrator mlt --width 16 --height 16 --spp 2 --quiet --mlt-bootstrap 2000 \
    --out "$work/a.pfm" >/dev/null 2>&1
"$renderer" render "$scene" --integrator mlt --width 16 --height 16 --spp 2 --quiet --mlt-bootstrap 2000 \
    --sample-offset 2 --out "$work/b.pfm" >/dev/null 2>&1
"$renderer" render "$scene" --integrator mlt --width 16 --height 16 --spp 2 --quiet --mlt-bootstrap 2000 \
    --out "$work/c.pfm" >/dev/null 2>&1
if cmp -s "$work/a.pfm" "$work/c.pfm" && ! cmp -s "$work/a.pfm" "$work/b.pfm"; then
    ok "mlt: the same seed repeats bit for bit; --sample-offset gives another render"
else
    fail "mlt: seed and --sample-offset"
fi
[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
