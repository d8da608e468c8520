#!/usr/bin/env python3
"""Error against a reference as the sample count grows: renders a scene at doubling sample
counts with one renderer, compares each image with a reference (PFM) and prints a Markdown
table of spp, seconds, MSE, relMSE (epsilon 1e-2) and the estimated relMSE the renderer
reported from its own per-pixel variance.

Example (chapter 01's table in book/01-naive-path-tracing.md):
    build/chapters/ch01 render scenes/cornell-box/scene.json --width 64 --height 64 \\
        --spp 16384 --seed 100 --out out/cornell-64-reference.pfm
    tools/convergence_table.py --renderer build/chapters/ch01 --scene scenes/cornell-box/scene.json \\
        --reference out/cornell-64-reference.pfm --width 64 --height 64 --spp 16 64 256 1024 4096
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

from pfm_images import read_pfm, relative_mse


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--renderer", required=True)
    parser.add_argument("--scene", required=True)
    parser.add_argument("--reference", required=True, help="reference image (PFM)")
    parser.add_argument("--width", type=int, required=True)
    parser.add_argument("--height", type=int, required=True)
    parser.add_argument("--spp", type=int, nargs="+", required=True)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--integrator", default=None)
    args = parser.parse_args()

    rw, rh, reference = read_pfm(args.reference)
    if (rw, rh) != (args.width, args.height):
        sys.exit(f"{args.reference}: is {rw}x{rh}, the renders are {args.width}x{args.height}")
    print("| spp | seconds | MSE | relMSE | estimated relMSE |")
    print("|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as folder:
        for spp in args.spp:
            out = os.path.join(folder, f"{spp}.pfm")
            command = [args.renderer, "render", args.scene, "--width", str(args.width), "--height", str(args.height),
                       "--spp", str(spp), "--seed", str(args.seed), "--out", out]
            if args.integrator:
                command += ["--integrator", args.integrator]
            start = time.monotonic()
            run = subprocess.run(command, capture_output=True, text=True)
            seconds = time.monotonic() - start
            if run.returncode != 0:
                sys.exit(run.stderr)
            estimate = re.search(r"estimated relMSE ([0-9.e+-]+)\s*$", run.stderr.strip())
            _, _, image = read_pfm(out)
            squared = [(a - b) ** 2 for a, b in zip(image, reference)]
            mse = sum(squared) / len(squared)
            relmse = relative_mse(image, reference)
            print(f"| {spp} | {seconds:.2f} | {mse:.4g} | {relmse:.4g} | {estimate.group(1) if estimate else '?'} |")


if __name__ == "__main__":
    main()
