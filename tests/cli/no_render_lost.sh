#!/usr/bin/env bash
# No render is lost: a signal writes what was done, a second one exits at once, checkpoints
# survive a kill -9, a resumed render equals the uninterrupted one bit for bit, and merging two
# halves of a render equals the whole within floating-point rounding.
# Usage: no_render_lost.sh RENDERER SOURCE_DIR
set -u
renderer=$1
scene=$2/scenes/cornell-box/scene.json
source "$(dirname "$0")/harness.sh"

# The render every case uses: long enough to be interrupted, small enough to finish in seconds.
render() { "$renderer" render "$scene" --width 48 --height 48 --quiet "$@"; }

# The uninterrupted render.
render --seed 5 --spp 3000 --out "$work/whole.pfm" >/dev/null 2>&1 || fail "the uninterrupted render failed"

# start_render ARGS...: starts a render in the background; its pid in $pid.
# (exec: $pid is the renderer itself, not a shell around it, so signals reach it.)
start_render() { ( exec "$renderer" render "$scene" --width 48 --height 48 --quiet "$@" >"$work/log" 2>&1 ) & pid=$!; }

# wait_for FILE SECONDS: waits until FILE exists.
wait_for() { for _ in $(seq 1 $(( $2 * 20 ))); do [ -e "$1" ] && return 0; sleep 0.05; done; return 1; }

# 1. SIGINT: exit 130, the image so far and the state are written.
start_render --seed 5 --spp 3000 --out "$work/a.pfm"
sleep 0.5
kill -INT $pid
wait $pid; status=$?
if [ $status -eq 130 ] && [ -s "$work/a.pfm" ] && [ -s "$work/a.pfm.state" ] && grep -q "spp in every pixel" "$work/log"; then
    ok "SIGINT: exit 130, wrote the image and the state: $(grep -o '[0-9]* spp in every pixel' "$work/log")"
else
    fail "SIGINT: exit $status, log: $(cat "$work/log")"
fi

# 2. Resuming gives the uninterrupted image, bit for bit.
render --seed 5 --spp 3000 --out "$work/a.pfm" --resume "$work/a.pfm.state" >/dev/null 2>&1
if cmp -s "$work/a.pfm" "$work/whole.pfm"; then ok "interrupted then resumed equals uninterrupted, bit for bit"; else fail "the resumed render differs from the uninterrupted one"; fi

# 3. SIGTERM: exit 143.
start_render --seed 5 --spp 3000 --out "$work/b.pfm"
sleep 0.5
kill -TERM $pid
wait $pid; status=$?
if [ $status -eq 143 ] && [ -s "$work/b.pfm.state" ]; then ok "SIGTERM: exit 143, state written"; else fail "SIGTERM: exit $status"; fi

# 4. A second signal exits at once: the first one's writing is not waited for.
start_render --seed 5 --spp 100000 --out "$work/c.pfm"
sleep 1
kill -INT $pid; kill -INT $pid
wait $pid; status=$?
if [ $status -eq 130 ]; then ok "a second SIGINT exits at once with 130"; else fail "second SIGINT: exit $status"; fi
if ls "$work"/c.pfm* >/dev/null 2>&1 && [ -e "$work/c.pfm" ] && ! cmp -s <(head -c 2 "$work/c.pfm") <(printf 'PF'); then
    fail "a torn output file was left"
fi

# 5. Checkpoints survive kill -9, and resuming from one equals the uninterrupted render.
start_render --seed 5 --spp 3000 --out "$work/d.pfm" --checkpoint 0.3
wait_for "$work/d.pfm.state" 20 || fail "no checkpoint was written"
sleep 0.5
kill -KILL $pid; wait $pid 2>/dev/null
if render --seed 5 --spp 3000 --out "$work/d.pfm" --resume "$work/d.pfm.state" >/dev/null 2>&1 && cmp -s "$work/d.pfm" "$work/whole.pfm"; then
    ok "after kill -9, the last checkpoint resumes to the uninterrupted image, bit for bit"
else
    fail "resuming from a checkpoint after kill -9 failed or differs"
fi

# 6. Resuming with other settings is refused.
if render --spp 3000 --seed 6 --out "$work/e.pfm" --resume "$work/d.pfm.state" >/dev/null 2>"$work/log"; then
    fail "resuming with another seed was accepted"
elif grep -q -- "--resume" "$work/log" && grep -q "seed" "$work/log" && [ ! -e "$work/e.pfm" ]; then
    ok "resuming with another seed is refused: $(cat "$work/log")"
else
    fail "resuming with another seed: unclear refusal: $(cat "$work/log")"
fi

# 6b. Resuming with no more samples than the saved render has is refused, and writes nothing.
if render --seed 5 --spp 1 --out "$work/f.pfm" --resume "$work/d.pfm.state" >/dev/null 2>"$work/log"; then
    fail "resuming with fewer samples than saved was accepted"
elif grep -q -- "--spp" "$work/log" && grep -q "already has" "$work/log" && [ ! -e "$work/f.pfm" ]; then
    ok "resuming with fewer samples than saved is refused: $(cat "$work/log")"
else
    fail "resuming with fewer samples: unclear refusal: $(cat "$work/log")"
fi

# 7. Merging two halves of one seed's samples equals the whole within rounding.
render --seed 5 --spp 64 --out "$work/half1.exr" >/dev/null 2>&1
render --seed 5 --spp 64 --sample-offset 64 --out "$work/half2.exr" >/dev/null 2>&1
render --seed 5 --spp 128 --out "$work/whole128.pfm" >/dev/null 2>&1
"$renderer" merge "$work/merged.pfm" "$work/half1.exr" "$work/half2.exr" --quiet >/dev/null 2>&1 || fail "merge failed"
if python3 - "$work/merged.pfm" "$work/whole128.pfm" <<'PY'
import struct, sys
def read(path):
    with open(path, "rb") as f:
        f.readline(); w, h = map(int, f.readline().split()); scale = float(f.readline()); data = f.read()
    return struct.unpack(("<" if scale < 0 else ">") + "%df" % (w * h * 3), data)
a, b = read(sys.argv[1]), read(sys.argv[2])
# Float storage of the halves (24-bit mantissas) and a different order of additions: a few
# units in the last place, relative to the larger value.
worst = max(abs(x - y) / max(abs(x), abs(y), 1e-30) for x, y in zip(a, b))
print("largest relative difference: %.3g" % worst)
sys.exit(0 if worst < 1e-5 else 1)
PY
then ok "merging two halves equals the whole within rounding"; else fail "the merged image differs from the whole"; fi

if [ $failures -ne 0 ]; then echo "$failures case(s) failed"; exit 1; fi
echo "no render is lost"
