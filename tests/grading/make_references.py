#!/usr/bin/env python3
"""Render the references the assignments are graded and shown against, with the solution's renderers.

    tests/grading/make_references.py --build-dir build [--only chNN/name] [--blocks] [--images DIR]

--blocks (what the grading tests read; small, committed): for every assignment made of several
regions (assignments.json, "reference"), each of its views is rendered in `batches` independent
renders of spp / batches samples, seeds seed, seed + 1, ... (the grading tests use other seeds),
at the view's small size, and the mean and standard error of each block of pixels (and channel)
over the batches are written to tests/data/references/chNN-name.json. The standard error comes
from the spread of the batches, so it holds for integrators that splat (bdpt) as for the others.

--images DIR (what grade.py --report shows; large, not committed): for every assignment with a
"report", a reference image at reference_spp from its own seed in DIR/chNN-name/reference.pfm,
and in DIR/chNN-name/solution.json what the solution's own render at the report's spp and seed
gives: its relMSE against the reference and its mean brightness (and the reference's), which the
report prints beside the student's.

The build must be of the solution (not a student copy): these are what correct code renders.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import shlex
import struct
import subprocess
import sys
import tempfile
from pathlib import Path

sys.dont_write_bytecode = True
sys.path.insert(0, str(Path(__file__).resolve().parent))
import exercises  # noqa: E402

REFERENCES_FOLDER = Path("tests") / "data" / "references"
REPORT_SEED = 7        # the seed of the report's renders (the student's, and the solution's for comparison)
REFERENCE_SEED = 1007  # the report's reference, independent of them


def reference_file(root: Path, name: str) -> Path:
    """tests/data/references/ch01-naive-path-tracer.json for ch01/naive-path-tracer."""
    return root / REFERENCES_FOLDER / (name.replace("/", "-") + ".json")


def renderer(build_dir: Path, name: str) -> Path:
    """The chapter's renderer in a build folder: chNN for chNN/..."""
    path = build_dir / "chapters" / exercises.chapter_of(name)
    if not path.is_file():
        raise RuntimeError(f"{path} does not exist: build it first (cmake --build {build_dir} --target {path.name})")
    return path


def read_pfm(path: Path) -> tuple[int, int, list[tuple[float, float, float]]]:
    """A colour PFM image: width, height and pixels row by row from the top."""
    data = path.read_bytes()
    header = []
    position = 0
    for _ in range(3):  # the lines "PF", "W H" and "scale"
        end = data.index(b"\n", position)
        header += data[position:end].split()
        position = end + 1
    if header[0] != b"PF":
        raise RuntimeError(f"{path}: not a colour PFM file")
    width, height, scale = int(header[1]), int(header[2]), float(header[3])
    order = "<" if scale < 0 else ">"
    values = struct.unpack(f"{order}{3 * width * height}f", data[position:position + 12 * width * height])
    rows = [[tuple(values[3 * (y * width + x):3 * (y * width + x) + 3]) for x in range(width)] for y in range(height)]
    rows.reverse()  # PFM stores the bottom row first
    return width, height, [pixel for row in rows for pixel in row]


def block_means(width: int, height: int, pixels: list, blocks: tuple[int, int]) -> list[list[float]]:
    """The mean of each block of pixels, per channel, blocks in row order from the top left."""
    bx, by = blocks
    if width % bx or height % by:
        raise RuntimeError(f"{width}x{height} pixels do not split into {bx}x{by} equal blocks")
    w, h = width // bx, height // by
    means = []
    for j in range(by):
        for i in range(bx):
            total = [0.0, 0.0, 0.0]
            for y in range(j * h, (j + 1) * h):
                for x in range(i * w, (i + 1) * w):
                    for c in range(3):
                        total[c] += pixels[y * width + x][c]
            means.append([t / (w * h) for t in total])
    return means


def run(command: list[str]) -> str:
    completed = subprocess.run(command, capture_output=True, text=True)
    if completed.returncode != 0:
        raise RuntimeError(f"{shlex.join(command)} failed:\n{completed.stderr.strip()}")
    return completed.stdout


def make_blocks(root: Path, build_dir: Path, assignment: exercises.Assignment, threads: int) -> Path:
    """The block references of one composite assignment, written to tests/data/references/."""
    spec = assignment.render_reference
    batches, spp, seed = int(spec["batches"]), int(spec["spp"]), int(spec["seed"])
    if spp % batches:
        raise RuntimeError(f"{assignment.name}: spp {spp} is not a multiple of batches {batches}")
    program = renderer(build_dir, assignment.name)
    views = []
    with tempfile.TemporaryDirectory() as folder:
        for view in spec["views"]:
            per_batch = []
            for batch in range(batches):
                out = Path(folder) / "batch.pfm"
                command = [str(program), "render", str(root / view["scene"]), "--integrator", view["integrator"],
                           "--width", str(view["width"]), "--height", str(view["height"]),
                           *(["--max-depth", str(view["max_depth"])] if "max_depth" in view else []),
                           "--spp", str(spp // batches),
                           "--seed", str(seed + batch), "--threads", str(threads), "--out", str(out), "--quiet"]
                run(command)
                width, height, pixels = read_pfm(out)
                per_batch.append(block_means(width, height, pixels, tuple(view["blocks"])))
            mean, error = [], []
            for b in range(len(per_batch[0])):
                mean.append([sum(batch[b][c] for batch in per_batch) / batches for c in range(3)])
                error.append([math.sqrt(sum((batch[b][c] - mean[b][c]) ** 2 for batch in per_batch)
                                        / (batches - 1) / batches) for c in range(3)])
            # The whole image, tested too: a small bias everywhere (a roulette without reweighting)
            # hides in the noise of each block but not in the image's mean. Its standard error
            # comes from the batches as well, since pixels need not be independent (mlt's chains).
            whole = [[sum(block[c] for block in batch) / len(batch) for c in range(3)] for batch in per_batch]
            image_mean = [sum(w[c] for w in whole) / batches for c in range(3)]
            image_error = [math.sqrt(sum((w[c] - image_mean[c]) ** 2 for w in whole) / (batches - 1) / batches)
                           for c in range(3)]
            views.append({**view, "mean": mean, "standard_error": error,
                          "image_mean": image_mean, "image_standard_error": image_error})
            print(f"{assignment.name}: {view['scene']} {view['integrator']}: {len(mean)} blocks, "
                  f"largest relative standard error {max(e[c] / max(m[c], 1e-9) for m, e in zip(mean, error) for c in range(3)):.4f}")
    document = {
        "description": f"The solution's render of assignment {assignment.name}'s views, in blocks of pixels: per "
                       "block (row order from the top left) and channel, the mean over the batches and its "
                       "standard error. Written by tests/grading/make_references.py --blocks; read by the "
                       "assignment's grading test.",
        "assignment": assignment.name,
        "spp": spp, "batches": batches, "seed": seed,
        "views": views,
    }
    path = reference_file(root, assignment.name)
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_suffix(".json.partial")
    temporary.write_text(json.dumps(document, indent=1) + "\n", encoding="utf-8")
    temporary.replace(path)
    return path


def last_relative_mse(compare_folder: Path, integrator: str) -> float:
    """The relMSE of the comparison's final image of `integrator` (its convergence.csv)."""
    with (compare_folder / "convergence.csv").open(newline="", encoding="utf-8") as file:
        rows = [row for row in csv.DictReader(file) if row["integrator"] == integrator]
    if not rows or not rows[-1]["relative_mse"]:
        raise RuntimeError(f"{compare_folder}/convergence.csv has no relMSE for {integrator}")
    return float(rows[-1]["relative_mse"])


def report_arguments(root: Path, report: dict) -> list[str]:
    """The scene and the settings every render of a report shares."""
    return [str(root / report["scene"]), "--width", str(report["width"]), "--height", str(report["height"])]


def image_mean(path: Path) -> list[float]:
    """The mean of a PFM image, per channel."""
    width, height, pixels = read_pfm(path)
    return block_means(width, height, pixels, (1, 1))[0]


def make_image(root: Path, build_dir: Path, assignment: exercises.Assignment, images: Path, threads: int) -> Path:
    """The report's reference image of one assignment, and the solution's relMSE and mean
    brightness at the report's samples and seed."""
    report = assignment.render
    folder = images / assignment.name.replace("/", "-")
    folder.mkdir(parents=True, exist_ok=True)
    program = renderer(build_dir, assignment.name)
    reference = folder / "reference.pfm"
    run([str(program), "render", *report_arguments(root, report), "--integrator", report["integrator"],
         "--spp", str(report["reference_spp"]), "--seed", str(REFERENCE_SEED), "--threads", str(threads),
         "--out", str(reference), "--quiet"])
    with tempfile.TemporaryDirectory() as scratch:
        solution = Path(scratch) / "solution"
        run([str(program), "compare", *report_arguments(root, report), "--integrators", report["integrator"],
             "--spp", str(report["spp"]), "--seed", str(REPORT_SEED), "--threads", str(threads),
             "--reference", str(reference), "--out", str(solution), "--quiet"])
        relmse = last_relative_mse(solution, report["integrator"])
        image = Path(scratch) / "solution.pfm"
        run([str(program), "render", *report_arguments(root, report), "--integrator", report["integrator"],
             "--spp", str(report["spp"]), "--seed", str(REPORT_SEED), "--threads", str(threads),
             "--out", str(image), "--quiet"])
        solution_mean = image_mean(image)
    (folder / "solution.json").write_text(json.dumps({
        "assignment": assignment.name, "report": report, "seed": REPORT_SEED, "reference_seed": REFERENCE_SEED,
        "solution_relative_mse": relmse, "solution_mean": solution_mean, "reference_mean": image_mean(reference),
    }, indent=1) + "\n", encoding="utf-8")
    print(f"{assignment.name}: reference {reference}; the solution's relMSE at {report['spp']} spp: {relmse:.4g}")
    return folder


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Render the assignments' references with the solution's renderers.")
    parser.add_argument("--build-dir", type=Path, required=True, help="a build folder of the solution")
    parser.add_argument("--root", type=Path, default=exercises.repository_root(), help="the repository")
    parser.add_argument("--only", metavar="chNN/name", help="only this assignment")
    parser.add_argument("--blocks", action="store_true", help="write the grading tests' block references")
    parser.add_argument("--images", type=Path, metavar="DIR", help="write the report's reference images to DIR")
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args(argv)
    if not args.blocks and args.images is None:
        parser.error("say what to make: --blocks, --images DIR, or both")
    assignments = exercises.load_assignments(args.root / exercises.ASSIGNMENTS_FILE)
    if args.only is not None and args.only not in assignments:
        parser.error(f"no assignment {args.only} in {exercises.ASSIGNMENTS_FILE}")
    try:
        for assignment in assignments.values():
            if args.only not in (None, assignment.name):
                continue
            if args.blocks and assignment.render_reference:
                make_blocks(args.root, args.build_dir, assignment, args.threads)
            if args.images is not None and assignment.render:
                make_image(args.root, args.build_dir, assignment, args.images, args.threads)
    except RuntimeError as error:
        print(f"make_references: error: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
