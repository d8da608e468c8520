#!/usr/bin/env python3
"""Chapter 08's measured figures, on scenes/texture-plane (its 8192 x 8192 texture is made first by
the scene's make_scene.py when it is missing).

    texture_figures.py lookups --build-dir build --out book/figures/ch08-lookups/table.md
    texture_figures.py plane   --build-dir build --filter bilinear --spp 4 --out book/figures/ch08-plane-bilinear-4spp.png

lookups: texture-benchmark's lookups of every layout and filter, in both texel formats, three
rounds (each round measures every configuration side by side in one process): nanoseconds per
lookup (median over the rounds, the range in brackets), speed relative to linear/bilinear in the
same round, and the cache model's texels, lines and misses per lookup (the same in every round:
the model is deterministic).

plane: the scene rendered by the complete renderer with one texture filter, as PNG.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
SCENE = ROOT / "scenes" / "texture-plane" / "scene.json"
TEXTURE = ROOT / "scenes" / "texture-plane" / "ground.png"
CONFIGURATIONS = ["linear/bilinear", "tiled/bilinear", "linear/trilinear", "tiled/trilinear",
                  "tiled/trilinear/8", "tiled/trilinear/16"]


def ensure_texture() -> None:
    if not TEXTURE.is_file():
        print(f"texture_figures: making {TEXTURE.relative_to(ROOT)}", flush=True)
        subprocess.run([sys.executable, "make_scene.py"], cwd=TEXTURE.parent, check=True)


def executable(build_dir: Path, relative: str) -> Path:
    path = build_dir / relative
    if not path.is_file():
        sys.exit(f"texture_figures: {path} is not built")
    return path


def lookups_figure(args: argparse.Namespace) -> int:
    ensure_texture()
    benchmark = executable(args.build_dir, "chapters/08-texture-tiling/benchmark/texture-benchmark")
    rows: dict = {}  # (format, configuration) -> list of rows, one per round
    for round_ in range(args.rounds):
        for texel_format in ("auto", "float"):
            command = [str(benchmark), str(SCENE), str(TEXTURE), "--spp", str(args.spp), "--reps", str(args.repetitions),
                       "--texel-format", texel_format, "--configs", ",".join(CONFIGURATIONS), "--json"]
            print("  " + " ".join(command), flush=True)
            result = subprocess.run(command, capture_output=True, text=True)
            if result.returncode != 0:
                sys.exit(f"texture_figures: texture-benchmark failed ({result.returncode}):\n{result.stderr}")
            for line in result.stdout.splitlines():
                if line.startswith("{"):
                    row = json.loads(line)
                    rows.setdefault((texel_format, row["configuration"]), []).append(row)
    table = ["| storage | configuration | MiB | ns/lookup | speed × linear/bilinear | texels read | lines | L1 misses | "
             "L2 misses | L3 misses |",
             "| --- | --- | --: | --: | --: | --: | --: | --: | --: | --: |"]
    for (texel_format, configuration), measured in rows.items():
        ns = [r["ns_per_lookup"] for r in measured]
        ratio = [r["speed_ratio"] for r in measured]
        r = measured[0]
        table.append(f"| {r['storage']} | {configuration} | {r['memory_mib']:.0f} | {statistics.median(ns):.1f} "
                     f"[{min(ns):.1f}–{max(ns):.1f}] | {statistics.median(ratio):.2f} [{min(ratio):.2f}–{max(ratio):.2f}] | "
                     f"{r['texels_per_lookup']:.2f} | {r['lines_per_lookup']:.2f} | {r['l1_misses_per_lookup']:.3f} | "
                     f"{r['l2_misses_per_lookup']:.3f} | {r['l3_misses_per_lookup']:.3f} |")
    first = next(iter(rows.values()))[0]
    table.append("")
    table.append(f"{first['lookups']} lookups ({args.spp} camera rays per pixel of texture-plane), "
                 f"{args.rounds} rounds of {args.repetitions} timed passes each (the fastest pass of a round counts).")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text("\n".join(table) + "\n")
    print("\n".join(table))
    return 0


def plane_figure(args: argparse.Namespace) -> int:
    ensure_texture()
    renderer = executable(args.build_dir, "chapters/freezeray")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    command = [str(renderer), "render", str(SCENE), "--spp", str(args.spp), "--texture-filter", args.filter,
               "--quiet", "--out", str(args.out)]
    print("  " + " ".join(command), flush=True)
    return subprocess.run(command).returncode


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    lookups = commands.add_parser("lookups")
    lookups.add_argument("--rounds", type=int, default=3)
    lookups.add_argument("--repetitions", type=int, default=10)
    lookups.add_argument("--spp", type=int, default=4)
    lookups.set_defaults(run=lookups_figure)
    plane = commands.add_parser("plane")
    plane.add_argument("--filter", choices=["bilinear", "trilinear"], required=True)
    plane.add_argument("--spp", type=int, required=True)
    plane.set_defaults(run=plane_figure)
    for command in (lookups, plane):
        command.add_argument("--build-dir", type=Path, required=True)
        command.add_argument("--out", type=Path, required=True)
    args = parser.parse_args()
    return args.run(args)


if __name__ == "__main__":
    sys.exit(main())
