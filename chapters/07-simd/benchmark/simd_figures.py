#!/usr/bin/env python3
"""Chapter 07's measured figures, made with chapter 06's ray-benchmark (its --json lines).

    simd_figures.py widths      --build-dir build --out book/figures/ch07-widths/plot.svg
    simd_figures.py depth-sweep --build-dir build --out book/figures/ch07-depth-sweep/plot.svg

widths: Mrays/s of the shared Sponza batches (one thread) with kdtree-simd at every packet width
this processor runs, each run with kdtree and Embree beside it, so that each width's ratios are
measured side by side; the plot shows kdtree-simd's rate divided by kdtree's in the same run.

depth-sweep: diffuse rays per second of kdtree and kdtree-simd (the widest width) in the same
runs, against the KD-tree's maximum depth: with packets, a shallower tree with fuller leaves costs
less than it does with one triangle per test.

Each writes the SVG plot at --out and a Markdown table beside it (table.md), with the machine's
figures as measured; the shared scenes come from ../shared/scenes or $FREEZERAY_SHARED_SCENES.
Without them, the figure is not made (exit status 0, a message says why).
"""

from __future__ import annotations

import argparse
import re
import statistics
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "chapters" / "06-kd-tree" / "benchmark"))
sys.path.insert(0, str(ROOT / "tools"))
# Chapter 06's figure helpers: finding the benchmark and running it; the book's SVG plots.
from kdtree_figures import ray_benchmark, run_json, shared_scenes  # noqa: E402
from svg_plot import svg_plot  # noqa: E402

KINDS = {"primary": "#2980b9", "diffuse": "#c0392b", "shadow": "#27ae60"}


def sponza_batches() -> tuple[Path, Path] | None:
    scenes = shared_scenes()
    mesh = scenes / "crytek-sponza" / "sponza.obj"
    rays = scenes.parent / "rays" / "sponza.rays"
    if not mesh.is_file() or not rays.is_file():
        print(f"simd_figures: {mesh} or {rays} not found; the figure is not made")
        return None
    return mesh, rays


def measure(args: argparse.Namespace, mesh: Path, rays: Path, extra: list[str]) -> dict:
    """One run of kdtree and kdtree-simd (and Embree, when the benchmark has it): accel -> kind -> row."""
    lines, _ = run_json([str(ray_benchmark(args.build_dir)), str(mesh), "--rays", str(rays), "--accel",
                         "kdtree,kdtree-simd", "--threads", "1", "--reps", str(args.repetitions), "--json", *extra])
    rows: dict = {}
    for line in lines:
        rows.setdefault(line["accel"], {})[line["kind"]] = line
    return rows


def runnable_widths(args: argparse.Namespace) -> list[int]:
    """The widths this processor runs, as ray-benchmark's --help states them for --simd-width
    ("... (this processor runs 1, 4, 8 and 16; ...")."""
    result = subprocess.run([str(ray_benchmark(args.build_dir)), "--help"], capture_output=True, text=True)
    match = re.search(r"this processor runs ([0-9, and]+);", " ".join(result.stdout.split()))
    if not match:
        sys.exit("simd_figures: ray-benchmark --help does not list the widths this processor runs")
    return [int(w) for w in re.findall(r"[0-9]+", match.group(1))]


def write_figure(out: Path, svg: str, table: list[str]) -> None:
    """The plot at `out`, its table as table.md beside it (and on standard output)."""
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(svg)
    (out.parent / "table.md").write_text("\n".join(table) + "\n")
    print("\n".join(table))


def widths_figure(args: argparse.Namespace) -> int:
    batches = sponza_batches()
    if batches is None:
        return 0
    mesh, rays = batches
    widths = runnable_widths(args)
    ratios = {w: {k: [] for k in KINDS} for w in widths}       # kdtree-simd / kdtree, per round
    to_embree = {w: {k: [] for k in KINDS} for w in widths}    # kdtree-simd / Embree
    rates = {w: {k: [] for k in KINDS} for w in widths}
    for _ in range(args.rounds):
        for w in widths:
            rows = measure(args, mesh, rays, ["--simd-width", str(w)])
            for k in KINDS:
                simd = rows["kdtree-simd"][k]["mrays_per_s"]
                ratios[w][k].append(simd / rows["kdtree"][k]["mrays_per_s"])
                rates[w][k].append(simd)
                if "embree" in rows:
                    to_embree[w][k].append(simd / rows["embree"][k]["mrays_per_s"])
    series = [{"name": f"{k} rays", "colour": colour,
               "points": [(w, statistics.median(ratios[w][k])) for w in widths]} for k, colour in KINDS.items()]
    svg = svg_plot(series, "packet width W (lanes)", "Mrays/s of kdtree-simd / kdtree (same run)",
                   "Sponza: the packet test's speed-up per width, one thread", False, False)
    table = ["| W | primary × kdtree | diffuse × kdtree | shadow × kdtree | diffuse Mrays/s | diffuse × Embree |",
             "| --: | --: | --: | --: | --: | --: |"]
    for w in widths:
        def cell(k: str) -> str:
            values = ratios[w][k]
            return f"{statistics.median(values):.2f} [{min(values):.2f}–{max(values):.2f}]"
        embree = f"{statistics.median(to_embree[w]['diffuse']):.2f}" if to_embree[w]["diffuse"] else "–"
        table.append(f"| {w} | {cell('primary')} | {cell('diffuse')} | {cell('shadow')} | "
                     f"{statistics.median(rates[w]['diffuse']):.3g} | {embree} |")
    table += ["", f"Medians over {args.rounds} rounds (widths in turn in each round), the range in brackets; each "
              f"figure the median of {args.repetitions} timed runs after a warm-up, one thread."]
    write_figure(Path(args.out), svg, table)
    return 0


def depth_sweep_figure(args: argparse.Namespace) -> int:
    batches = sponza_batches()
    if batches is None:
        return 0
    mesh, rays = batches
    depths = [18, 22, 26, 31, 34]
    measured = {d: measure(args, mesh, rays, ["--kdtree-max-depth", str(d)]) for d in depths}
    series = [{"name": f"{accel} diffuse", "colour": colour,
               "points": [(d, measured[d][accel]["diffuse"]["mrays_per_s"]) for d in depths]}
              for accel, colour in (("kdtree", "#7f8c8d"), ("kdtree-simd", "#c0392b"))]
    svg = svg_plot(series, "maximum depth (automatic: 31)", "diffuse Mrays/s (one thread)",
                   "Sponza: diffuse rays per second against the depth limit", False, False)
    table = ["| max depth | kdtree diffuse Mrays/s | kdtree-simd diffuse Mrays/s | kdtree-simd / kdtree | "
             "kdtree-simd build ms | kdtree-simd memory MB | kdtree memory MB |",
             "| --: | --: | --: | --: | --: | --: | --: |"]
    for d in depths:
        tree, simd = measured[d]["kdtree"]["diffuse"], measured[d]["kdtree-simd"]["diffuse"]
        table.append(f"| {d} | {tree['mrays_per_s']:.3g} | {simd['mrays_per_s']:.3g} | "
                     f"{simd['mrays_per_s'] / tree['mrays_per_s']:.2f} | {simd['build_ms']:.0f} | "
                     f"{simd.get('memory_mb') or 0:.1f} | {tree.get('memory_mb') or 0:.1f} |")
    table += ["", f"Each row one run of both accelerators (the widest packet width), each figure the median of "
              f"{args.repetitions} timed runs after a warm-up, one thread."]
    write_figure(Path(args.out), svg, table)
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    commands = parser.add_subparsers(dest="figure", required=True)
    for name in ("widths", "depth-sweep"):
        command = commands.add_parser(name)
        command.add_argument("--build-dir", type=Path, default=ROOT / "build")
        command.add_argument("--out", required=True, help="the SVG to write; table.md goes beside it")
        command.add_argument("--repetitions", type=int, default=3)
        if name == "widths":
            command.add_argument("--rounds", type=int, default=3, help="times each width is measured, in turn")
    args = parser.parse_args()
    return widths_figure(args) if args.figure == "widths" else depth_sweep_figure(args)


if __name__ == "__main__":
    sys.exit(main())
