#!/usr/bin/env bash
# `render --bdpt-strategies DIR` (chapter 04): bdpt writes one image per strategy and the grids
# into DIR (made after the render); other integrators and a DIR that is a file are refused before
# rendering, with nothing written.
# Usage: strategy_images.sh FREEZERAY SOURCE_DIR
set -u
renderer=$1
source_dir=$2
source "$(dirname "$0")/harness.sh"
scene="$source_dir/scenes/cornell-box/scene.json"
fail() { echo "FAIL [$1]"; failures=$((failures + 1)); }

if "$renderer" render "$scene" --integrator bdpt --width 16 --height 16 --spp 2 --max-depth 3 --quiet \
    --out "$work/image.exr" --bdpt-strategies "$work/new/strategies" >/dev/null 2>&1; then
    for f in grid-weighted.png grid-unweighted.png s0-t2-weighted.exr s1-t1-unweighted.exr s3-t1-weighted.exr \
             longer-weighted.exr; do
        [ -s "$work/new/strategies/$f" ] || fail "bdpt wrote no $f"
    done
    [ -e "$work/new/strategies/s0-t5-weighted.exr" ] && fail "a strategy longer than --max-depth has an image"
    echo "ok   [bdpt writes its strategy images into a new folder]"
else
    fail "bdpt --bdpt-strategies did not render"
fi

message=$("$renderer" render "$scene" --integrator pt-mis --spp 1 --quiet --out "$work/out.png" \
    --bdpt-strategies "$work/other" 2>&1 >/dev/null)
if [ $? -eq 0 ] || ! grep -qF -- "--bdpt-strategies" <<<"$message" || [ -e "$work/out.png" ] || [ -e "$work/other" ]; then
    fail "pt-mis with --bdpt-strategies: $message"
else
    echo "ok   [an integrator without strategies is refused]: $message"
fi

touch "$work/a-file"
message=$("$renderer" render "$scene" --integrator bdpt --spp 1 --quiet --out "$work/out.png" \
    --bdpt-strategies "$work/a-file" 2>&1 >/dev/null)
if [ $? -eq 0 ] || ! grep -qF "is a file" <<<"$message" || [ -e "$work/out.png" ]; then
    fail "a file as the strategy folder: $message"
else
    echo "ok   [a file as the strategy folder is refused]: $message"
fi

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
