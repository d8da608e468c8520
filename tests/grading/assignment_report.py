#!/usr/bin/env python3
"""The assignment reports of grade.py --report: the student's render beside the solution's reference.

For every assignment of assignments.json with a "report" block, the chapter's renderer of the
graded build renders the assignment's scene (`chNN compare ... --reference REFERENCES/NAME/reference.exr`:
the image, its error image and its relMSE against the reference), and the report template
(report_template.html) is filled in REPORT/NAME/index.html: a slider between the reference and
the student's image, the error image, the student's relMSE beside the one the solution reaches
with the same samples and seed (REFERENCES/NAME/solution.json), the assignment's grade, and the
commands that made it. REPORT/index.html lists the assignments; REPORT/report.md says the same in
Markdown.

The references are made once, on the solution's tree, by make_references.py --images
REFERENCES; a teacher hands that folder out with the assignment.
"""

from __future__ import annotations

import html
import json
import shlex
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

sys.dont_write_bytecode = True
sys.path.insert(0, str(Path(__file__).resolve().parent))
import exercises  # noqa: E402
import make_references  # noqa: E402
import submission  # noqa: E402

TEMPLATE = Path(__file__).resolve().parent / "report_template.html"

# Above this ratio of relMSEs the student's render is called different from the solution's: at the
# same samples and seed a correct solution renders the solution's very image (ratio 1), and a
# different but unbiased estimator rarely doubles the error.
SAME_AS_SOLUTION_RATIO = 1.5


@dataclass
class AssignmentReport:
    """What one assignment's report says."""

    name: str
    title: str
    grade: str              # "2/2 pass", "0/3 FAIL (wrong result): ..." or "not graded"
    verdict: str            # one sentence on the image
    folder: str             # relative to the report's root


def build_renderer(build_dir: Path, target: str, jobs: int) -> str:
    """Builds the chapter's renderer; '' when it built, else the first error."""
    built = submission.build_target(build_dir, target, jobs, f"grade-build-{target}.log")
    return "" if built.ok else f"{built.error} (log: {built.log})"


def brightness_sentence(mine: list[float], solution: list[float], reference: list[float]) -> str:
    """What the image's mean brightness says: a bias shows there even when noise hides it pixel by
    pixel. Judged against the solution's own deviation at the same samples (its noise), with a
    floor of 2 %."""
    def luminance(c: list[float]) -> float:
        return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
    if luminance(reference) <= 0.0:
        return ""
    ratio = luminance(mine) / luminance(reference)
    allowed = max(3.0 * abs(luminance(solution) / luminance(reference) - 1.0), 0.02)
    if abs(ratio - 1.0) <= allowed:
        return f" Its mean brightness is {100 * ratio:.1f} % of the reference's, as the solution's is."
    side = "darker" if ratio < 1.0 else "brighter"
    return (f" But its mean brightness is {100 * ratio:.1f} % of the reference's (the solution's is within "
            f"{100 * allowed:.0f} %): your image is {side} than it should be, a bias rather than noise.")


def verdict_of(relmse: float | None, solution: float | None, failure: str, brightness: str = "") -> str:
    """A few sentences on the student's image against the solution's."""
    if failure:
        return f"No image: {failure}"
    if relmse is None or solution is None:
        return "No error could be measured."
    ratio = relmse / solution if solution > 0 else float("inf")
    if ratio <= SAME_AS_SOLUTION_RATIO:
        text = (f"Your render's error against the reference, relMSE {relmse:.4g}, is about the solution's at the same "
                f"samples and seed ({solution:.4g}; ratio {ratio:.2f}).")
    else:
        text = (f"Your render's error against the reference, relMSE {relmse:.4g}, is {ratio:.1f} times the solution's "
                f"at the same samples and seed ({solution:.4g}): compare the images, and see in the error image where "
                "they differ.")
    return text + brightness


def fill(template: str, values: dict[str, str]) -> str:
    """The template with each {{key}} replaced (values are HTML already)."""
    for key, value in values.items():
        template = template.replace("{{" + key + "}}", value)
    return template


def make_one(assignment: exercises.Assignment, build_dir: Path, source: Path, references: Path, report_root: Path,
             grade: str, jobs: int) -> AssignmentReport:
    """Renders one assignment's scene with the graded build and writes its page."""
    spec = assignment.render
    key = assignment.name.replace("/", "-")
    folder = report_root / key
    folder.mkdir(parents=True, exist_ok=True)
    reference = references / key / "reference.pfm"
    solution_file = references / key / "solution.json"
    renderer = assignment.chapter
    failure = ""
    relmse = solution = None
    brightness = ""
    command: list[str] = []
    if not reference.is_file() or not solution_file.is_file():
        failure = (f"no reference in {references / key}: make the references on the solution's tree with "
                   f"tests/grading/make_references.py --build-dir BUILD --images {references}")
    else:
        failure = build_renderer(build_dir, renderer, jobs)
    if not failure:
        known = json.loads(solution_file.read_text(encoding="utf-8"))
        solution = float(known["solution_relative_mse"])
        program = str(build_dir / "chapters" / renderer)
        settings = [*make_references.report_arguments(source, spec), "--spp", str(spec["spp"]),
                    "--seed", str(make_references.REPORT_SEED)]
        command = [program, "compare", *settings, "--integrators", spec["integrator"],
                   "--reference", str(reference.resolve()), "--out", str((folder / "compare").resolve()), "--quiet"]
        image = folder / "mine.pfm"
        for run in (command, [program, "render", *settings, "--integrator", spec["integrator"],
                              "--out", str(image.resolve()), "--quiet"]):
            rendered = subprocess.run(run, capture_output=True, text=True)
            if rendered.returncode != 0:
                lines = [line for line in rendered.stderr.splitlines() if line.strip()]
                failure = f"the renderer stopped: {lines[-1] if lines else 'exit status ' + str(rendered.returncode)}"
                break
        if not failure:
            relmse = make_references.last_relative_mse(folder / "compare", spec["integrator"])
            brightness = brightness_sentence(make_references.image_mean(image), known["solution_mean"],
                                             known["reference_mean"])
    verdict = verdict_of(relmse, solution, failure, brightness)
    images = "compare/images"
    mine = f"{images}/{spec['integrator']}.png"
    values = {
        "title": html.escape(assignment.title),
        "name": html.escape(assignment.name),
        "grade": html.escape(grade),
        "verdict": html.escape(verdict),
        "reference": f"{images}/reference.png",
        "mine": mine,
        "error": f"{images}/{spec['integrator']}-error.png",
        "has_images": "" if not failure else "hidden",
        "width": str(spec["width"]),
        "height": str(spec["height"]),
        "settings": html.escape(f"{spec['scene']}, {spec['integrator']}, {spec['spp']} samples per pixel, "
                                f"{spec['width']}x{spec['height']}, seed {make_references.REPORT_SEED}"),
        "command": html.escape(shlex.join(command)) if command else "(not run)",
        "book": html.escape(assignment.book),
        "comparison": "compare/report.html",
    }
    (folder / "index.html").write_text(fill(TEMPLATE.read_text(encoding="utf-8"), values), encoding="utf-8")
    return AssignmentReport(assignment.name, assignment.title, grade, verdict, key)


def write_index(report_root: Path, reports: list[AssignmentReport], student: str) -> None:
    """REPORT/index.html and REPORT/report.md: one entry per assignment."""
    who = f" of {student}" if student else ""
    items = "\n".join(f'<li><a href="{r.folder}/index.html">{html.escape(r.name)}</a>: {html.escape(r.title)}<br>'
                      f"<b>{html.escape(r.grade)}</b>. {html.escape(r.verdict)}</li>" for r in reports)
    (report_root / "index.html").write_text(
        f"<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Assignments{html.escape(who)}</title></head>\n"
        f"<body style=\"font-family: sans-serif; max-width: 60em\">\n<h1>Assignments{html.escape(who)}</h1>\n"
        f"<ul>\n{items}\n</ul>\n</body></html>\n", encoding="utf-8")
    lines = [f"# Assignments{who}", ""]
    for r in reports:
        lines += [f"## {r.name}: {r.title}", "", f"- Grade: {r.grade}", f"- {r.verdict}",
                  f"- Images and slider: [{r.folder}/index.html]({r.folder}/index.html)", ""]
    (report_root / "report.md").write_text("\n".join(lines), encoding="utf-8")


def make_reports(build_dir: Path, source: Path, references: Path, report_root: Path, grades: dict[str, str],
                 chapter: str | None, only: str | None, student: str, jobs: int) -> list[AssignmentReport]:
    """Every selected assignment's page, and the index. `grades` maps an exercise to its line."""
    assignments = exercises.load_assignments(source / exercises.ASSIGNMENTS_FILE)
    reports = []
    report_root.mkdir(parents=True, exist_ok=True)
    for assignment in assignments.values():
        if not assignment.render or (only is not None and only != assignment.name) \
                or (chapter is not None and chapter != assignment.chapter):
            continue
        reports.append(make_one(assignment, build_dir, source, references, report_root,
                                grades.get(assignment.name, "not graded"), jobs))
    write_index(report_root, reports, student)
    return reports
