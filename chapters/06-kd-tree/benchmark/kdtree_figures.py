#!/usr/bin/env python3
"""Chapter 06's measured figures, made with ray-benchmark (its --json lines).

    kdtree_figures.py build-scaling --build-dir build --out book/figures/ch06-build-scaling/plot.svg
    kdtree_figures.py cost-sweep    --build-dir build --out book/figures/ch06-cost-sweep/plot.svg
    kdtree_figures.py depth-sweep   --build-dir build --out book/figures/ch06-depth-sweep/plot.svg
    kdtree_figures.py equal-time    --build-dir build --out book/figures/ch06-equal-time.md

build-scaling: the KD-tree's build time (one thread) against the triangle count N, on spheres
subdivided 3 to 8 times (1,280 to 1,310,720 triangles, written to a temporary folder) and on the
shared scenes' bunny, dragon and Sponza, beside Embree's high-quality build of the same meshes
in the same runs. The slope of log(time) against log(N) over the spheres is fitted: O(N log N)
gives a little more than 1.

cost-sweep: Mrays/s of the shared Sponza batches (one thread) against the intersection cost
C_I with the traversal cost C_T = 1, with the build time and memory of each tree, beside Embree
on the same rays in the same run.

depth-sweep: the same against the maximum depth, with pbrt-v3's costs (the automatic depth for
Sponza is 31).

equal-time: pt-mis on scenes/sponza/scene.json for the same seconds with brute force and with
the KD-tree, each image's relMSE against a reference rendered with the KD-tree and another seed
(kept in out/, made once), as a Markdown table at --out.

Each writes the SVG plot at --out and a Markdown table beside it (table.md), with the machine's
figures as measured; the shared scenes come from ../shared/scenes or $FREEZERAY_SHARED_SCENES.
Without them, the figure is not made (exit status 0, a message says why).
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "scenes" / "tools"))
import meshes  # noqa: E402  (the scene tools' mesh generators)
sys.path.insert(0, str(ROOT / "tools"))
from shared_scenes import shared_scenes  # noqa: E402  (where Sponza and the ray batches are)
from svg_plot import svg_plot  # noqa: E402  (the figures' line plots)


def ray_benchmark(build_dir: Path) -> Path:
    path = build_dir / "chapters" / "06-kd-tree" / "benchmark" / "ray-benchmark"
    if not path.is_file():
        sys.exit(f"kdtree_figures: {path} is not built (cmake --build {build_dir} --target ray-benchmark)")
    return path


def run_json(command: list[str]) -> tuple[list[dict], int]:
    """ray-benchmark's JSON lines, and the mesh's triangle count from its notes."""
    print("  " + " ".join(command), flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"kdtree_figures: the command failed ({result.returncode}):\n{result.stderr}")
    triangles = 0
    for line in result.stderr.splitlines():
        if line.startswith("mesh:"):  # "mesh: PATH, N triangles, M vertices"
            triangles = int(line.rsplit(" triangles", 1)[0].rsplit(" ", 1)[1])
    return [json.loads(line) for line in result.stdout.splitlines() if line.startswith("{")], triangles


# --- meshes -------------------------------------------------------------------------------


def write_icosphere(path: Path, subdivisions: int) -> int:
    """The unit icosphere of scenes/tools/meshes.py, subdivided `subdivisions` times, as OBJ."""
    vertices, faces = meshes.icosphere(subdivisions)
    with path.open("w") as out:
        meshes.write_obj_vertices(out, vertices)
        for a, b, c in faces:
            out.write(f"f {a + 1} {b + 1} {c + 1}\n")
    return len(faces)


def obj_bounds(path: Path) -> tuple[list[float], list[float]]:
    low, high = [math.inf] * 3, [-math.inf] * 3
    with path.open() as obj:
        for line in obj:
            if line.startswith("v "):
                p = [float(x) for x in line.split()[1:4]]
                low = [min(a, b) for a, b in zip(low, p)]
                high = [max(a, b) for a, b in zip(high, p)]
    return low, high


def camera_for(path: Path) -> str:
    """A camera outside the mesh's bounds, looking at their centre (ray-benchmark --camera)."""
    low, high = obj_bounds(path)
    centre = [(a + b) / 2.0 for a, b in zip(low, high)]
    radius = math.sqrt(sum((b - a) ** 2 for a, b in zip(low, high))) / 2.0
    direction = (0.3, 0.4, 1.0)
    norm = math.sqrt(sum(d * d for d in direction))
    eye = [c + 2.5 * radius * d / norm for c, d in zip(centre, direction)]
    return ",".join("%.6g" % x for x in eye + centre + [40.0])


def least_squares_slope(points: list[tuple[float, float]]) -> float:
    lx = [math.log(x) for x, _ in points]
    ly = [math.log(y) for _, y in points]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


# --- the figures --------------------------------------------------------------------------


def build_scaling(args: argparse.Namespace) -> int:
    scenes = shared_scenes()
    benchmark = ray_benchmark(args.build_dir)
    # (name, triangles, kdtree ms, embree ms or None, a sphere?, the tree's bytes per triangle)
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        inputs = []
        for level in range(3, 9):
            path = Path(folder) / f"sphere-{level}.obj"
            write_icosphere(path, level)
            inputs.append((f"sphere, {level} subdivisions", path, True))
        for name, relative in (("dragon", "stanford-dragon/dragon.obj"), ("bunny", "stanford-bunny/bunny.obj"),
                               ("Sponza", "crytek-sponza/sponza.obj")):
            if (scenes / relative).is_file():
                inputs.append((name, scenes / relative, False))
            else:
                print(f"kdtree_figures: {scenes / relative} not found; {name} is left out")
        for name, path, is_sphere in inputs:
            command = [str(benchmark), str(path), "--accel", "kdtree", "--kdtree-build-threads", "1", "--limit", "1",
                       "--reps", "1", "--json", "--resolution", "8", "--camera", camera_for(path)]
            kdtree_ms, embree_ms, triangles, memory = [], [], 0, 0.0
            for _ in range(args.repetitions):
                lines, triangles = run_json(command)
                kd = [l for l in lines if l["accel"] == "kdtree"]
                em = [l for l in lines if l["accel"] == "embree"]
                kdtree_ms.append(kd[0]["build_ms"])
                memory = kd[0]["memory_mb"] or 0.0
                if em:
                    embree_ms.append(em[0]["build_ms"])
            rows.append((name, triangles, sorted(kdtree_ms)[len(kdtree_ms) // 2],
                         sorted(embree_ms)[len(embree_ms) // 2] if embree_ms else None, is_sphere,
                         memory * 1024 * 1024 / triangles))
    spheres = [(n, k) for name, n, k, e, s, _ in rows if s]
    slope = least_squares_slope(spheres)
    large_slope = least_squares_slope(spheres[-3:])
    series = [{"name": "kdtree, spheres", "colour": "#c0392b", "points": spheres},
              {"name": "kdtree, scenes", "colour": "#e67e22", "line": False,
               "points": [(n, k) for name, n, k, e, s, _ in rows if not s]}]
    if all(e is not None for _, _, _, e, _, _ in rows):
        series.append({"name": "Embree, spheres", "colour": "#2c3e50", "dashed": True,
                       "points": [(n, e) for name, n, k, e, s, _ in rows if s]})
        series.append({"name": "Embree, scenes", "colour": "#7f8c8d", "line": False,
                       "points": [(n, e) for name, n, k, e, s, _ in rows if not s]})
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(svg_plot(series, "triangles N", "build time (ms, one thread)",
                            f"Build time against N (kdtree slope {slope:.2f} on the spheres)", True, True))
    table = ["| mesh | triangles | kdtree build ms | Embree build ms | ratio | kdtree bytes per triangle |",
             "| :-- | --: | --: | --: | --: | --: |"]
    for name, n, k, e, _, tree_bytes in rows:
        table.append(f"| {name} | {n:,} | {k:.0f} | {'' if e is None else f'{e:.0f}'} | "
                     f"{'' if e is None else f'{k / e:.2f}'} | {tree_bytes:.0f} |")
    table.append("")
    table.append(f"Least-squares slope of log(kdtree build ms) against log(N): {slope:.3f} over all the spheres, "
                 f"{large_slope:.3f} over the three largest (medians of {args.repetitions} runs each; one build "
                 "thread for both).")
    (out.parent / "table.md").write_text("\n".join(table) + "\n")
    print("\n".join(table))
    return 0


def sweep(args: argparse.Namespace, flag: str, values: list[int], x_label: str, title: str, log_x: bool,
          first_column: str) -> int:
    """Sponza's shared batches traced by trees built with `flag` set to each of `values`."""
    scenes = shared_scenes()
    mesh = scenes / "crytek-sponza" / "sponza.obj"
    rays = scenes.parent / "rays" / "sponza.rays"
    if not mesh.is_file() or not rays.is_file():
        print(f"kdtree_figures: {mesh} or {rays} not found; the sweep is not made")
        return 0
    benchmark = ray_benchmark(args.build_dir)
    measured = {}  # value -> {kind: the kdtree row}
    embree = {}    # value -> {kind: Embree's Mrays/s in the same run}
    for value in values:
        lines, _ = run_json([str(benchmark), str(mesh), "--rays", str(rays), "--accel", "kdtree", "--threads", "1",
                             "--reps", str(args.repetitions), "--json", flag, str(value)])
        measured[value] = {l["kind"]: l for l in lines if l["accel"] == "kdtree"}
        embree[value] = {l["kind"]: l["mrays_per_s"] for l in lines if l["accel"] == "embree"}
    colours = {"primary": "#2980b9", "diffuse": "#c0392b", "shadow": "#27ae60"}
    series = [{"name": f"kdtree {kind}", "colour": colours[kind],
               "points": [(v, measured[v][kind]["mrays_per_s"]) for v in values]} for kind in colours]
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(svg_plot(series, x_label, "Mrays/s (one thread)", title, log_x, False))
    table = [f"| {first_column} | primary Mrays/s | diffuse Mrays/s | shadow Mrays/s | build ms | memory MB | "
             "diffuse / Embree's |", "| --: | --: | --: | --: | --: | --: | --: |"]
    for v in values:
        row = measured[v]
        ratio = row["diffuse"]["mrays_per_s"] / embree[v]["diffuse"] if embree[v] else float("nan")
        table.append(f"| {v} | {row['primary']['mrays_per_s']:.3g} | {row['diffuse']['mrays_per_s']:.3g} | "
                     f"{row['shadow']['mrays_per_s']:.3g} | {row['primary']['build_ms']:.0f} | "
                     f"{row['primary'].get('memory_mb') or 0:.1f} | {ratio:.2f} |")
    if any(embree.values()):
        table.append("")
        medians = {kind: sorted(e[kind] for e in embree.values())[len(values) // 2] for kind in colours}
        table.append("Embree in the same runs, the median over them: " +
                     ", ".join(f"{kind} {m:.3g}" for kind, m in medians.items()) +
                     f" Mrays/s. Each row is the median of {args.repetitions} timed runs after a warm-up; the "
                     "last column divides by Embree's diffuse rate measured in the same run.")
    (out.parent / "table.md").write_text("\n".join(table) + "\n")
    print("\n".join(table))
    return 0


def equal_time(args: argparse.Namespace) -> int:
    """pt-mis on Sponza for the same seconds with brute force and with the KD-tree, each image's
    error measured by `freezeray compare` against one reference rendered with another seed."""
    scenes = shared_scenes()
    if not (scenes / "crytek-sponza" / "sponza.obj").is_file():
        print(f"kdtree_figures: {scenes / 'crytek-sponza'} not found; the comparison is not made")
        return 0
    freezeray = args.build_dir / "chapters" / "freezeray"
    if not freezeray.is_file():
        sys.exit(f"kdtree_figures: {freezeray} is not built (cmake --build {args.build_dir} --target freezeray)")
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    size = ["--width", str(args.size), "--height", str(args.size)]
    scene = ROOT / "scenes" / "sponza" / "scene.json"
    reference = ROOT / "out" / f"sponza-{args.size}-reference.pfm"
    if not reference.is_file():
        reference.parent.mkdir(parents=True, exist_ok=True)
        command = [str(freezeray), "render", str(scene), "--integrator", "pt-mis", "--time", str(args.reference_seconds),
                   "--seed", "777", "--quiet", "--out", str(reference)] + size
        print("  " + " ".join(command), flush=True)
        subprocess.run(command, check=True)
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for accelerator in ("bruteforce", "kdtree"):
            # The scene with an accelerator block: compare has no --accel of its own.
            description = json.loads(scene.read_text())
            description["accelerator"] = {"type": accelerator}
            variant = Path(folder) / f"sponza-{accelerator}.json"
            variant.write_text(json.dumps(description))
            report = Path(folder) / accelerator
            command = [str(freezeray), "compare", str(variant), "--integrators", "pt-mis", "--time", str(args.seconds),
                       "--reference", str(reference), "--seed", "1", "--out", str(report), "--quiet"] + size
            print("  " + " ".join(command), flush=True)
            result = subprocess.run(command, capture_output=True, text=True)
            if result.returncode != 0:
                sys.exit(f"kdtree_figures: compare failed:\n{result.stderr}")
            # "pt-mis  <spp> spp  <seconds> s  relMSE <value>  slope <s>"
            line = next(l for l in result.stderr.splitlines() if l.startswith("pt-mis"))
            words = line.split()
            rows.append((accelerator, int(words[1]), float(words[3]), float(words[6])))
    brute, tree = rows
    table = ["| accelerator | samples per pixel | seconds | samples per second | relMSE against the reference |",
             "| :-- | --: | --: | --: | --: |"]
    for name, spp, seconds, error in rows:
        table.append(f"| {name} | {spp:,} | {seconds:.1f} | {spp * args.size * args.size / seconds:,.0f} | {error:.4g} |")
    table.append("")
    table.append(f"pt-mis on scenes/sponza/scene.json at {args.size}x{args.size}, {args.seconds:g} s each, seed 1; the "
                 f"reference: pt-mis with the KD-tree for {args.reference_seconds:g} s, seed 777. The KD-tree's image "
                 f"has {tree[3] / brute[3]:.3g} times brute force's error after the same time "
                 f"({brute[3] / tree[3]:.3g} times lower), with {tree[1] / brute[1]:.3g} times the samples.")
    out.write_text("\n".join(table) + "\n")
    print("\n".join(table))
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    commands = parser.add_subparsers(dest="figure", required=True)
    for name in ("build-scaling", "cost-sweep", "depth-sweep", "equal-time"):
        command = commands.add_parser(name)
        command.add_argument("--build-dir", type=Path, default=ROOT / "build")
        command.add_argument("--out", required=True, help="the SVG to write; table.md goes beside it "
                             "(equal-time: the Markdown table)")
        command.add_argument("--repetitions", type=int, default=3)
        if name == "equal-time":
            command.add_argument("--seconds", type=float, default=30.0, help="render time of each image")
            command.add_argument("--reference-seconds", type=float, default=480.0)
            command.add_argument("--size", type=int, default=64, help="image width and height")
    args = parser.parse_args()
    if args.figure == "build-scaling":
        return build_scaling(args)
    if args.figure == "equal-time":
        return equal_time(args)
    if args.figure == "cost-sweep":
        return sweep(args, "--kdtree-intersection-cost", [5, 10, 20, 40, 80, 160, 320],
                     "C_I / C_T (C_T = 1, empty bonus 0.5)", "Sponza: rays per second against the cost ratio", True,
                     "C_I / C_T")
    return sweep(args, "--kdtree-max-depth", [18, 22, 26, 29, 31, 34, 38], "maximum depth (automatic: 31)",
                 "Sponza: rays per second against the depth limit", False, "max depth")


if __name__ == "__main__":
    sys.exit(main())
