#!/usr/bin/env bash
# FreezeRay's quick start (README.md):
#   ./run.sh render   install what is missing, build, render the Cornell box; prints the image path
#   ./run.sh test     install what is missing, build, run the whole test suite through ctest
#   ./run.sh compare  (optional) install, build, compare three integrators on the Cornell box at
#                     equal time; prints the report's path and opens it when a desktop is there
# Run as root, or as a user who may use sudo (apt-get is called through sudo when not root).
set -euo pipefail
cd "$(dirname "$0")"

command=${1:-}
if [ "$command" != render ] && [ "$command" != test ] && [ "$command" != compare ]; then
    echo "usage: ./run.sh render | ./run.sh test | ./run.sh compare" >&2
    exit 2
fi

# Debian 12 packages the build needs (README.md, "Dependencies").
packages=(g++ cmake make ccache pkg-config python3 libglm-dev libstb-dev libtinyobjloader-dev catch2
          nlohmann-json3-dev libcli11-dev libopenexr-dev)
missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "installing: ${missing[*]}" >&2
    if [ "$(id -u)" -eq 0 ]; then apt_get=(apt-get); else apt_get=(sudo apt-get); fi
    export DEBIAN_FRONTEND=noninteractive
    "${apt_get[@]}" update -q >&2
    "${apt_get[@]}" install -y -q --no-install-recommends "${missing[@]}" >&2
fi

jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >&2

if [ "$command" = render ]; then
    # Only what the render needs: the complete renderer, not the tests.
    cmake --build build --parallel "$jobs" --target freezeray >&2
    mkdir -p out
    # auto renders short pilots with the integrators the scene allows and finishes with the most
    # efficient (it says which on stderr); prints the path of the image it wrote.
    build/chapters/freezeray render scenes/cornell-box/scene.json --integrator auto --spp 256 \
        --out out/cornell-box.png
elif [ "$command" = compare ]; then
    cmake --build build --parallel "$jobs" --target freezeray >&2
    mkdir -p out
    # 10 s each. Without a reference the report estimates each image's error from its own
    # per-pixel variance, which is honest only for independent samples: hence that sampler here
    # (book/00-measuring.md, book/09-quasi-monte-carlo.md).
    build/chapters/freezeray compare scenes/cornell-box/scene.json --integrators pt-naive,pt-mis,bdpt \
        --sampler independent --time 10 --out out/compare-cornell-box --quiet >&2
    report=out/compare-cornell-box/report.html
    echo "$report"
    if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && command -v xdg-open > /dev/null; then
        xdg-open "$report" > /dev/null 2>&1 || true
    fi
else
    started=$(date +%s)
    cmake --build build --parallel "$jobs" >&2
    built=$(date +%s)
    # Everything but the benchmarks (label `bench`).
    status=0
    ctest --test-dir build --output-on-failure --parallel "$jobs" --label-exclude bench || status=$?
    finished=$(date +%s)
    echo "run.sh test: build $((built - started)) s, tests $((finished - built)) s, total $((finished - started)) s" >&2
    exit $status
fi
