#!/usr/bin/env bash
# FreezeRay's quick start (README.md):
#   ./run.sh render   install what is missing, build, render the Cornell box; prints the image path
#   ./run.sh test     install what is missing, build, run the whole test suite through ctest
# Run as root, or as a user who may use sudo (apt-get is called through sudo when not root).
set -euo pipefail
cd "$(dirname "$0")"

command=${1:-}
if [ "$command" != render ] && [ "$command" != test ]; then
    echo "usage: ./run.sh render | ./run.sh test" >&2
    exit 2
fi

# Debian 12 packages the build needs (README.md, "Dependencies").
packages=(g++ cmake make pkg-config python3 libglm-dev libstb-dev libtinyobjloader-dev catch2
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
    # Only what the render needs: the common library and chapter 01's renderer.
    cmake --build build --parallel "$jobs" --target ch01 >&2
    mkdir -p out
    # Prints the path of the image it wrote.
    build/chapters/ch01 render scenes/cornell-box/scene.json --out out/cornell-box.png
else
    cmake --build build --parallel "$jobs" >&2
    # Everything but the benchmarks (label `bench`).
    ctest --test-dir build --output-on-failure --parallel "$jobs" --label-exclude bench
fi
