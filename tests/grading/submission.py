#!/usr/bin/env python3
"""A submission graded against the teacher's tree: only the student's exercise regions count.

grade.py --teacher-tests TEACHER --submission DIR assembles, in WORK/source, the teacher's tree
(tests, grading helpers, points.json, CMake files: everything) with the body of each exercise
region taken from the submission's copy of the same file. Whatever else the submission changed
(a weakened grading test, an edited points.json, a helper outside a region) is not there. A
region the submission lacks (its file missing, or its markers removed) gets the stub, and is
graded as not implemented.

Files are written only when their content changes, so grading the next submission in the same
WORK folder rebuilds only the files whose regions differ (`--batch`).

The graded sources' hash (SHA-256 over each region's name and body, in name order) identifies
what was graded, for the gradebook.
"""

from __future__ import annotations

import hashlib
import os
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

sys.dont_write_bytecode = True  # keep __pycache__ out of the source tree
sys.path.insert(0, str(Path(__file__).resolve().parent))
import exercises  # noqa: E402  (the shared modules beside this script)
import make_student_copy  # noqa: E402

TEST_TARGET = "exercise_tests"

# What a build of the grading tests reads: a binary older than any of these is stale.
BUILD_INPUTS = ("common", "chapters", "tests/exercises", "tests/support", "CMakeLists.txt", "cmake")
SOURCE_SUFFIXES = {".cpp", ".cc", ".hpp", ".h", ".inl", ".txt", ".cmake"}


@dataclass
class GradedTree:
    """What assemble_graded_tree made: where, from which regions, and their hash."""

    source: Path
    taken: list[str] = field(default_factory=list)    # regions whose body came from the submission
    missing: list[str] = field(default_factory=list)  # regions the submission lacks (stubbed)
    written: int = 0                                   # files rewritten in this pass
    source_hash: str = ""


def region_bodies(text: str, path: Path) -> dict[str, list[str]]:
    """The lines inside each region of a file (markers excluded), by exercise name."""
    regions, _ = exercises.parse_file(text, path)
    lines = text.splitlines(keepends=True)
    return {region.name: lines[region.start:region.end - 1] for region in regions}


def spliced_text(teacher_text: str, regions: list[exercises.Region], bodies: dict[str, list[str]]) -> str:
    """The teacher's file with each region's body replaced by the submission's (or the stub)."""
    lines = teacher_text.splitlines(keepends=True)
    for region in sorted(regions, key=lambda r: r.start, reverse=True):
        if region.name in bodies:
            body = bodies[region.name]
        else:
            marker = lines[region.start - 1]
            newline = marker[len(marker.rstrip("\r\n")):] or "\n"
            body = [region.indent + exercises.STUB_TEMPLATE.format(name=region.name) + newline]
        if body and not body[-1].endswith("\n"):
            body = body[:-1] + [body[-1] + "\n"]
        lines[region.start:region.end - 1] = body
    return "".join(lines)


def hash_regions(bodies: dict[str, list[str] | None]) -> str:
    """SHA-256 of every region's name and body (None: missing), in name order."""
    digest = hashlib.sha256()
    for name in sorted(bodies):
        digest.update(name.encode("utf-8") + b"\0")
        body = bodies[name]
        digest.update(b"<missing>" if body is None else "".join(body).encode("utf-8"))
        digest.update(b"\0")
    return digest.hexdigest()


def assemble_graded_tree(teacher: Path, submission: Path, destination: Path) -> GradedTree:
    """Write the teacher's tree with the submission's region bodies into destination."""
    teacher = teacher.resolve()
    regions = exercises.find_regions(teacher)
    by_file: dict[Path, list[exercises.Region]] = {}
    for region in regions:
        by_file.setdefault(region.path, []).append(region)
    tree = GradedTree(destination)
    graded: dict[str, list[str] | None] = {}
    files = make_student_copy.list_files(teacher, exclude=destination)
    roots = make_student_copy.include_roots(teacher)
    for path in files:
        origin = teacher / path
        if origin.is_symlink():
            continue  # the project has none; a link would point into the teacher's tree anyway
        content = origin.read_bytes()
        if path in by_file:
            theirs = submission / path
            bodies = region_bodies(theirs.read_text(encoding="utf-8", errors="replace"), path) if theirs.is_file() else {}
            text = spliced_text(content.decode("utf-8"), by_file[path], bodies)
            for region in by_file[path]:
                graded[region.name] = bodies.get(region.name)
                (tree.taken if region.name in bodies else tree.missing).append(region.name)
            if any(region.name not in bodies for region in by_file[path]) and \
                    not make_student_copy.includes_error_header(origin.resolve(), roots):
                text = make_student_copy.add_error_include(text)
            content = text.encode("utf-8")
        tree.written += make_student_copy.write_if_changed(destination / path, content, origin.stat().st_mode)
    make_student_copy.remove_stale_files(destination, set(files))
    tree.taken.sort()
    tree.missing.sort()
    tree.source_hash = hash_regions(graded)
    return tree


def hash_of_tree(root: Path) -> str:
    """The hash of the regions as they are in a tree (a student grading their own build)."""
    bodies: dict[str, list[str] | None] = {}
    for path in exercises.source_files(root):
        text = (root / path).read_text(encoding="utf-8", errors="replace")
        if "EXERCISE" in text:
            bodies.update(region_bodies(text, path))
    return hash_regions(bodies)


# --- Building ---------------------------------------------------------------------------------

@dataclass
class BuildResult:
    ok: bool
    seconds: float
    error: str = ""  # the first compiler error line, when it failed
    log: Path | None = None


def first_error(log: str) -> str:
    """The first line of a build log that says error (the one to fix first)."""
    for line in log.splitlines():
        if "error" in line.lower() and not line.lstrip().startswith(("make", "gmake", "ninja")):
            return line.strip()
    return "the build failed (see the log)"


def configure(source: Path, build: Path) -> BuildResult:
    """Configure build from source (Release, warnings not errors: stubs leave parameters unused)."""
    started = time.monotonic()
    command = ["cmake", "-S", str(source), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release", "-DFREEZERAY_WERROR=OFF"]
    result = subprocess.run(command, capture_output=True, text=True)
    build.mkdir(parents=True, exist_ok=True)
    log = build / "grade-configure.log"
    log.write_text(result.stdout + result.stderr, encoding="utf-8")
    return BuildResult(result.returncode == 0, time.monotonic() - started,
                       first_error(result.stdout + result.stderr) if result.returncode else "", log)


def build_grading_tests(build: Path, jobs: int) -> BuildResult:
    """Build the exercise_tests target; the log goes to BUILD/grade-build.log."""
    started = time.monotonic()
    command = ["cmake", "--build", str(build), "--target", TEST_TARGET, "--parallel", str(jobs)]
    result = subprocess.run(command, capture_output=True, text=True)
    log = build / "grade-build.log"
    log.write_text(result.stdout + result.stderr, encoding="utf-8")
    return BuildResult(result.returncode == 0, time.monotonic() - started,
                       first_error(result.stdout + result.stderr) if result.returncode else "", log)


def find_grading_tests(build: Path) -> Path | None:
    """The exercise_tests executable of a build, if it has been built."""
    for candidate in [build / "tests" / "exercises" / TEST_TARGET, *build.rglob(TEST_TARGET)]:
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return candidate
    return None


def newer_sources(source: Path, binary: Path, limit: int = 5) -> list[Path]:
    """The build inputs changed after binary was built (at most `limit`, newest first)."""
    built = binary.stat().st_mtime
    newer = []
    for name in BUILD_INPUTS:
        base = source / name
        candidates = [base] if base.is_file() else base.rglob("*") if base.is_dir() else []
        for path in candidates:
            if path.is_file() and (path.suffix in SOURCE_SUFFIXES or path.name == "CMakeLists.txt") \
                    and path.stat().st_mtime > built:
                newer.append(path)
    newer.sort(key=lambda p: p.stat().st_mtime, reverse=True)
    return [p.relative_to(source) for p in newer[:limit]]
