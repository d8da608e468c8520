#!/usr/bin/env python3
"""Chapter 08's measured figures, on scenes/texture-plane (its 8192 x 8192 texture is made first by
the scene's make_scene.py when it is missing) and on scenes/sponza (Crytek Sponza's 36 textures,
from the shared scenes folder; without it that figure is not made, exit status 0).

    texture_figures.py lookups    --build-dir build --out book/figures/ch08-lookups/table.md
    texture_figures.py lookups    --build-dir build --scene sponza --out book/figures/ch08-lookups-sponza/table.md
    texture_figures.py misses     --build-dir build --out book/figures/ch08-misses/plot.svg
    texture_figures.py access-map --build-dir build --tile 16,11 --out book/figures/ch08-access-map/middle.png
    texture_figures.py plane      --build-dir build --filter bilinear --spp 4 --out book/figures/ch08-plane-bilinear-4spp.png

lookups: texture-benchmark's lookups of every layout and filter, in both texel formats, three
rounds (each round measures every configuration side by side in one process): nanoseconds per
lookup (median over the rounds, the range in brackets), speed relative to linear/bilinear in the
same round, and the cache model's texels, lines and misses per lookup (the same in every round:
the model is deterministic).

misses: the cache model's L1 and L3 misses per lookup on texture-plane against the tile's side
(2 to 32 texels), without MIP levels (bilinear) and with them (trilinear), rows as dashed lines;
a table beside the plot (table.md). The model is deterministic: one pass, no timing.

access-map: one 16 x 16 pixel tile of texture-plane, the texels its lookups read and the cache
lines they bring in, with rows, with 4 x 4 tiles, and with tiles and MIP levels, side by side; the
benchmark's account of each panel in a table beside the image (the image's name with .md).

plane: the scene rendered by the complete renderer with one texture filter, as PNG.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import statistics
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "tools"))
from shared_scenes import shared_scenes  # noqa: E402  (where Sponza is)
from svg_plot import svg_plot  # noqa: E402  (the book's line plots)

SCENE = ROOT / "scenes" / "texture-plane" / "scene.json"
SPONZA = ROOT / "scenes" / "sponza" / "scene.json"
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


def run_benchmark(args: argparse.Namespace, scene: Path, options: list[str]) -> tuple[list[dict], str]:
    """texture-benchmark's JSON lines (with --json) or nothing, and its standard error."""
    benchmark = executable(args.build_dir, "chapters/08-texture-tiling/benchmark/texture-benchmark")
    command = [str(benchmark), str(scene)] + options
    print("  " + " ".join(command), flush=True)
    environment = dict(os.environ, FREEZERAY_SHARED_SCENES=str(shared_scenes()))
    result = subprocess.run(command, capture_output=True, text=True, env=environment)
    if result.returncode != 0:
        sys.exit(f"texture_figures: texture-benchmark failed ({result.returncode}):\n{result.stderr}")
    return [json.loads(line) for line in result.stdout.splitlines() if line.startswith("{")], result.stderr


def lookups_figure(args: argparse.Namespace) -> int:
    if args.scene == "sponza":
        scene = SPONZA
        if not (shared_scenes() / "crytek-sponza" / "sponza.obj").is_file():
            print(f"texture_figures: {shared_scenes()}/crytek-sponza is not there; the figure is not made")
            return 0
    else:
        ensure_texture()
        scene = SCENE
    rows: dict = {}  # (format, configuration) -> list of rows, one per round
    for round_ in range(args.rounds):
        for texel_format in ("auto", "float"):
            measured, _ = run_benchmark(args, scene, ["--spp", str(args.spp), "--reps", str(args.repetitions),
                                                      "--texel-format", texel_format, "--configs",
                                                      ",".join(CONFIGURATIONS), "--json"])
            for row in measured:
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
    table.append(f"{first['lookups']} lookups of {first['textures']} "
                 f"{'texture' if first['textures'] == 1 else 'textures'} ({args.spp} camera rays per pixel of "
                 f"{'Crytek Sponza' if args.scene == 'sponza' else 'texture-plane'}), "
                 f"{args.rounds} rounds of {args.repetitions} timed passes each (the fastest pass of a round counts).")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text("\n".join(table) + "\n")
    print("\n".join(table))
    return 0


def misses_figure(args: argparse.Namespace) -> int:
    ensure_texture()
    sizes = [2, 4, 8, 16, 32]
    configurations = []
    for filter_ in ("bilinear", "trilinear"):
        configurations.append(f"linear/{filter_}")
        configurations += [f"tiled/{filter_}/{size}" for size in sizes]
    rows, _ = run_benchmark(args, SCENE, ["--spp", str(args.spp), "--reps", "1", "--configs", ",".join(configurations),
                                          "--json"])
    by_name = {r["configuration"]: r for r in rows}
    def tiled(filter_: str, size: int) -> dict:
        return by_name[f"tiled/{filter_}" + ("" if size == 4 else f"/{size}")]
    series = []
    colours = {("bilinear", "l1"): "#2980b9", ("bilinear", "l3"): "#c0392b",
               ("trilinear", "l1"): "#27ae60", ("trilinear", "l3"): "#8e44ad"}
    for filter_, mip in (("bilinear", "no MIP"), ("trilinear", "MIP")):
        for level, key in (("l1", "l1_misses_per_lookup"), ("l3", "l3_misses_per_lookup")):
            colour = colours[(filter_, level)]
            series.append({"name": f"tiles, {level.upper()}, {mip}", "colour": colour,
                           "points": [(size, tiled(filter_, size)[key]) for size in sizes]})
            flat = by_name[f"linear/{filter_}"][key]
            series.append({"name": f"rows, {level.upper()}, {mip}", "colour": colour, "dashed": True, "line": True,
                           "points": [(sizes[0], flat), (sizes[-1], flat)]})
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(svg_plot(series, "texels on a tile's side", "misses per lookup (cache model)",
                                 "texture-plane, 8-bit texels: misses per lookup", True, True))
    table = ["| configuration | storage | lines per lookup | L1 misses | L2 misses | L3 misses |",
             "| --- | --- | --: | --: | --: | --: |"]
    for r in rows:
        table.append(f"| {r['configuration']} | {r['storage']} | {r['lines_per_lookup']:.3f} | "
                     f"{r['l1_misses_per_lookup']:.4f} | {r['l2_misses_per_lookup']:.4f} | {r['l3_misses_per_lookup']:.4f} |")
    table += ["", f"{rows[0]['lookups']} lookups ({args.spp} camera rays per pixel of texture-plane); the model: "
              "L1 32 KiB 8-way, L2 1 MiB 8-way, L3 32 MiB 16-way, LRU, fed with the texture's reads alone."]
    (args.out.parent / "table.md").write_text("\n".join(table) + "\n")
    print("\n".join(table))
    return 0


def access_map_figure(args: argparse.Namespace) -> int:
    ensure_texture()
    args.out.parent.mkdir(parents=True, exist_ok=True)
    configurations = ["linear/bilinear", "tiled/bilinear", "tiled/trilinear"]
    _, log = run_benchmark(args, SCENE, ["--spp", str(args.spp), "--reps", "1", "--configs", ",".join(configurations),
                                         "--access-map", str(args.out), "--map-tile", args.tile])
    table = ["| panel | configuration | level | texels shown | texels read | cache lines read |",
             "| --- | --- | --: | --- | --: | --: |"]
    pattern = re.compile(r"access map, (\S+): tile \S+, texture \d+ \((\d+) of the tile's (\d+) lookups\), level (\d+), "
                         r"texels (\[\d+, \d+\] x \[\d+, \d+\]): (\d+) texels read, (\d+) cache lines")
    lookups = None
    for panel, match in zip(("left", "middle", "right"), pattern.finditer(log)):
        name, _, lookups, level, shown, texels, lines = match.groups()
        table.append(f"| {panel} | {name} | {level} | {shown} | {texels} | {lines} |")
    if lookups is None:
        sys.exit(f"texture_figures: texture-benchmark printed no access map:\n{log}")
    table += ["", f"Tile {args.tile} of 16 x 16 pixels of texture-plane, {args.spp} camera rays per pixel, {lookups} "
              "lookups; lines counted over all levels a panel's lookups read."]
    args.out.with_suffix(".md").write_text("\n".join(table) + "\n")
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
    lookups.add_argument("--scene", choices=["plane", "sponza"], default="plane")
    lookups.set_defaults(run=lookups_figure)
    misses = commands.add_parser("misses")
    misses.add_argument("--spp", type=int, default=4)
    misses.set_defaults(run=misses_figure)
    access = commands.add_parser("access-map")
    access.add_argument("--spp", type=int, default=4)
    access.add_argument("--tile", default="16,11", help="column,row of the 16 x 16 pixel tile")
    access.set_defaults(run=access_map_figure)
    plane = commands.add_parser("plane")
    plane.add_argument("--filter", choices=["bilinear", "trilinear"], required=True)
    plane.add_argument("--spp", type=int, required=True)
    plane.set_defaults(run=plane_figure)
    for command in (lookups, misses, access, plane):
        command.add_argument("--build-dir", type=Path, required=True)
        command.add_argument("--out", type=Path, required=True)
    args = parser.parse_args()
    return args.run(args)


if __name__ == "__main__":
    sys.exit(main())
