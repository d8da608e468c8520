#!/usr/bin/env python3
"""Chapter 09's figure of point sets, drawn from the samplers themselves (sampler-points).

    qmc_figures.py point-sets --build-dir build --out book/figures/ch09-point-sets.svg

point-sets: the first 256 positions in pixel (0, 0) that each sampler gives (seed 0): independent,
stratified, Sobol's dimensions 0 and 1 unscrambled, Sobol Owen-scrambled (the `sobol` sampler)
and `zsobol`. The first 64 points are drawn dark, the other 192 light, over a grid of 8 x 8
cells: where each dark point sits alone in its cell, the first 64 samples already stratify the
pixel, as a net's do; the whole 256 then fill the 16 x 16 cells that halve those.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
from pathlib import Path

SAMPLERS = [("independent", "independent"), ("stratified", "stratified"),
            ("sobol-unscrambled", "Sobol, unscrambled"), ("sobol", "sobol (Owen-scrambled)"), ("zsobol", "zsobol")]
COUNT, FIRST = 256, 64


def sampler_points(build_dir: Path) -> Path:
    path = build_dir / "chapters" / "09-quasi-monte-carlo" / "benchmark" / "sampler-points"
    if not path.is_file():
        sys.exit(f"qmc_figures: {path} is not built (cmake --build {build_dir} --target sampler-points)")
    return path


def points_of(program: Path, sampler: str) -> list[tuple[float, float]]:
    command = [str(program), "--sampler", sampler, "--count", str(COUNT)]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"qmc_figures: {' '.join(command)} failed: {result.stderr.strip()}")
    points = []
    for line in result.stdout.split():
        x, y = line.split(",")
        points.append((float(x), float(y)))
    if len(points) != COUNT:
        sys.exit(f"qmc_figures: {sampler} gave {len(points)} points, expected {COUNT}")
    return points


def cells_holding_one(points: list[tuple[float, float]], n: int) -> int:
    """How many of the n x n cells hold exactly one of the points."""
    counts: dict[tuple[int, int], int] = {}
    for x, y in points:
        cell = (min(int(x * n), n - 1), min(int(y * n), n - 1))
        counts[cell] = counts.get(cell, 0) + 1
    return sum(1 for c in counts.values() if c == 1)


def point_sets_svg(sets: list[tuple[str, list[tuple[float, float]]]]) -> str:
    size, gap, top = 190, 20, 58
    width = len(sets) * size + (len(sets) + 1) * gap
    height = top + size + 40
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="sans-serif" '
           f'font-size="12">', f'<rect width="{width}" height="{height}" fill="white"/>']
    for i, (label, points) in enumerate(sets):
        left = gap + i * (size + gap)
        out.append(f'<text x="{left + size / 2}" y="20" text-anchor="middle" font-size="13">{label}</text>')
        out.append(f'<text x="{left + size / 2}" y="38" text-anchor="middle" fill="#555">first {FIRST}: '
                   f'{cells_holding_one(points[:FIRST], 8)} of 64 cells</text>')
        out.append(f'<text x="{left + size / 2}" y="{top + size + 20}" text-anchor="middle" fill="#555">all {COUNT}: '
                   f'{cells_holding_one(points, 16)} of 256 cells</text>')
        for k in range(9):
            t = left + k * size / 8
            u = top + k * size / 8
            out.append(f'<line x1="{t:.1f}" y1="{top}" x2="{t:.1f}" y2="{top + size}" stroke="#ccc"/>')
            out.append(f'<line x1="{left}" y1="{u:.1f}" x2="{left + size}" y2="{u:.1f}" stroke="#ccc"/>')
        # The light ones first, so that the first 64 are drawn over them.
        for order, (x, y) in sorted(enumerate(points), key=lambda p: -p[0]):
            colour, radius = ("#1f3a93", 2.6) if order < FIRST else ("#9db4e8", 1.8)
            out.append(f'<circle cx="{left + x * size:.1f}" cy="{top + (1 - y) * size:.1f}" r="{radius}" fill="{colour}"/>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("figure", choices=["point-sets"])
    parser.add_argument("--build-dir", type=Path, required=True)
    parser.add_argument("--out", type=Path, required=True)
    args = parser.parse_args()
    program = sampler_points(args.build_dir)
    sets = [(label, points_of(program, name)) for name, label in SAMPLERS]
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(point_sets_svg(sets))
    for label, points in sets:
        print(f"  {label}: first {FIRST} alone in {cells_holding_one(points[:FIRST], 8)} of 64 cells, "
              f"all {COUNT} in {cells_holding_one(points, 16)} of 256")
    return 0


if __name__ == "__main__":
    sys.exit(main())
