#!/usr/bin/env python3
"""What a scene pays for effects it does not contain: the complete renderer (`freezeray`, every
chapter) against the earliest chapter's renderer that can render the scene, on scenes without the
later chapters' effects (no environment, textures, alpha masks, delta lights, glossy or specular
surfaces), with the same integrator, accelerator, sampler and light sampler, in alternating pairs.

Each pair renders the same image twice, first with the chapter's renderer, then with freezeray
(the order alternates from pair to pair, so that a slow drift of the machine's load falls on both
alike); the ratio of their render times (as each reports it, loading excluded) is freezeray's
over the chapter's. The images must be identical, pixel for pixel: the same work is done, and
anything freezeray did beyond it would show in the time. The table gives the median ratio over
the pairs and its spread (lowest and highest).

    tools/effect_cost_benchmark.py --build-dir build [--pairs 7] [--scale 1] [--only TEXT] [--json]

Exit status 1 when a pair of images differs, 2 on bad input.
"""
import argparse
import json
import re
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

# Every case: the scene, what it lacks of the later chapters, the integrator, the earliest renderer
# that has it, its samples per pixel (about 2 s on two cores at --scale 1), and what freezeray is
# told so that it does the earliest renderer's work (its own defaults are chapter 06's tree,
# chapter 09's Sobol sampler and chapter 10's light BVH).
CASES = [
    {"name": "cornell pt-naive", "scene": "scenes/cornell-box/scene.json", "integrator": "pt-naive",
     "chapter": "ch01", "spp": 48, "size": 256,
     "absent": "environment, textures, alpha masks, delta lights, glossy, specular"},
    {"name": "cornell pt-is", "scene": "scenes/cornell-box/scene.json", "integrator": "pt-is",
     "chapter": "ch02", "spp": 40, "size": 256,
     "absent": "environment, textures, alpha masks, delta lights, glossy, specular"},
    {"name": "cornell pt-mis", "scene": "scenes/cornell-box/scene.json", "integrator": "pt-mis",
     "chapter": "ch03", "spp": 24, "size": 256, "light_sampler": "power",
     "absent": "environment, textures, alpha masks, delta lights, glossy, specular, splatting"},
    {"name": "furnace-environment pt-mis", "scene": "scenes/furnace/scene-environment.json",
     "integrator": "pt-mis", "chapter": "ch03", "spp": 16, "size": 256, "light_sampler": "power",
     "absent": "area emitters, textures, alpha masks, delta lights, glossy, specular, splatting"},
    {"name": "cornell bdpt", "scene": "scenes/cornell-box/scene.json", "integrator": "bdpt",
     "chapter": "ch04", "spp": 8, "size": 256,
     "absent": "environment, textures, alpha masks, delta lights, glossy, specular"},
]

# The render's progress line on stderr, "pt-mis: 100% of its samples, 6.94e+05 samples/s, elapsed
# 0.8 s, ...": its rate has three digits, its time only one decimal, so the time is the samples
# divided by the rate.
RATE_PATTERN = re.compile(r"([0-9.]+e[+-]?[0-9]+|[0-9.]+) samples/s")


def render(renderer: Path, case: dict, scale: float, out: Path) -> float:
    """Renders one case and returns its render time in seconds (loading excluded)."""
    spp = max(1, round(case["spp"] * scale))
    command = [str(renderer), "render", str(ROOT / case["scene"]), "--integrator", case["integrator"],
               "--spp", str(spp), "--width", str(case["size"]), "--height", str(case["size"]),
               "--seed", "1", "--out", str(out)]
    if renderer.name == "freezeray":
        command += ["--accel", "bruteforce", "--sampler", "independent"]
        if "light_sampler" in case:
            command += ["--light-sampler", case["light_sampler"]]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed:\n{result.stderr}")
    rates = RATE_PATTERN.findall(result.stderr)
    if not rates:
        raise RuntimeError(f"{' '.join(command)}: no samples/s in its output:\n{result.stderr}")
    return spp * case["size"] * case["size"] / float(rates[-1])


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build-dir", type=Path, required=True, help="the CMake build folder")
    parser.add_argument("--pairs", type=int, default=7, help="alternating pairs per case (default 7)")
    parser.add_argument("--scale", type=float, default=1.0,
                        help="multiplies every case's samples per pixel (default 1: about 2 s a render)")
    parser.add_argument("--only", metavar="TEXT", help="only the cases whose name contains TEXT")
    parser.add_argument("--json", action="store_true", help="one JSON object per line and case")
    args = parser.parse_args(argv)
    if args.pairs < 1 or args.scale <= 0:
        print("effect_cost_benchmark: --pairs must be at least 1 and --scale positive", file=sys.stderr)
        return 2
    cases = [c for c in CASES if args.only is None or args.only in c["name"]]
    if not cases:
        print(f"effect_cost_benchmark: no case's name contains '{args.only}'", file=sys.stderr)
        return 2
    chapters = args.build_dir / "chapters"
    complete = chapters / "freezeray"
    missing = [p for p in [complete] + [chapters / c["chapter"] for c in cases] if not p.is_file()]
    if missing:
        print(f"effect_cost_benchmark: not built: {', '.join(map(str, missing))}", file=sys.stderr)
        return 2

    all_identical = True
    if not args.json:
        print(f"{'case':<28} {'earliest':>8} {'pairs':>5} {'earliest s':>10} {'freezeray s':>11} "
              f"{'ratio':>6} {'lowest':>6} {'highest':>7}  images")
    with tempfile.TemporaryDirectory() as folder:
        for case in cases:
            earliest = chapters / case["chapter"]
            a_image, b_image = Path(folder) / "a.pfm", Path(folder) / "b.pfm"
            a_times, b_times, identical = [], [], True
            for pair in range(args.pairs):
                order = [(earliest, a_image, a_times), (complete, b_image, b_times)]
                if pair % 2 == 1:
                    order.reverse()
                for renderer, image, times in order:
                    times.append(render(renderer, case, args.scale, image))
                identical = identical and a_image.read_bytes() == b_image.read_bytes()
            all_identical = all_identical and identical
            ratios = [b / a for a, b in zip(a_times, b_times)]
            row = {"case": case["name"], "absent": case["absent"], "earliest": case["chapter"],
                   "pairs": args.pairs, "earliest_s": statistics.median(a_times),
                   "freezeray_s": statistics.median(b_times), "ratio": statistics.median(ratios),
                   "lowest": min(ratios), "highest": max(ratios), "identical_images": identical}
            if args.json:
                print(json.dumps(row), flush=True)
            else:
                print(f"{row['case']:<28} {row['earliest']:>8} {row['pairs']:>5} {row['earliest_s']:>10.3f} "
                      f"{row['freezeray_s']:>11.3f} {row['ratio']:>6.3f} {row['lowest']:>6.3f} "
                      f"{row['highest']:>7.3f}  {'identical' if identical else 'DIFFER'}", flush=True)
    if not all_identical:
        print("effect_cost_benchmark: freezeray's image differs from the earliest renderer's: "
              "they did not do the same work", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
