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
import re
import shutil
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

# What every stub calls (exercises.STUB_TEMPLATE), found in a file's text.
STUB_CALL = "ExerciseNotImplemented("

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
            # A stub needs ExerciseNotImplemented's header: the teacher's file may not include it,
            # whether the stub is ours (a missing region) or the student's (an unfinished one,
            # as their student copy gave it to them; the include it came with lies outside the region).
            if STUB_CALL in text and not make_student_copy.includes_error_header(origin.resolve(), roots):
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
# The grading tests' build, for grade.py (a student's build, teacher mode) and prove_exercises.py
# (the stubbed copy): configured in Release with warnings not errors (a stub leaves parameters
# unused), only the exercise_tests target built, each log kept in the build folder.

# Cache entries of a build that another build of the same sources should share (the proof's
# stubbed copy takes them from the solution build).
SHARED_CACHE_ENTRIES = (
    "CMAKE_MAKE_PROGRAM", "CMAKE_CXX_COMPILER", "CMAKE_C_COMPILER",
    "CMAKE_CXX_COMPILER_LAUNCHER", "CMAKE_C_COMPILER_LAUNCHER", "CMAKE_CXX_FLAGS",
    "CMAKE_PREFIX_PATH", "CMAKE_TOOLCHAIN_FILE", "FREEZERAY_NATIVE",
)


@dataclass
class BuildResult:
    ok: bool
    seconds: float
    command: list[str]
    error: str = ""  # the first compiler error line, when it failed
    log: Path | None = None
    warnings: list[str] = field(default_factory=list)  # the compiler's warning lines


def read_cmake_cache(build_dir: Path) -> dict[str, str]:
    """The entries of build_dir/CMakeCache.txt, NAME -> value (types dropped)."""
    entries = {}
    cache = build_dir / "CMakeCache.txt"
    if not cache.is_file():
        return entries
    for line in cache.read_text(encoding="utf-8", errors="replace").splitlines():
        if not line or line.startswith(("#", "//")) or "=" not in line:
            continue
        key, value = line.split("=", 1)
        entries[key.split(":", 1)[0]] = value
    return entries


# A compiler's diagnostic: "path/file.cpp:12:5: error: ..." (GCC and Clang; "fatal error" too).
COMPILER_ERROR = re.compile(r"^(?P<file>\S[^:]*):\d+(?::\d+)?:\s+(?:fatal )?error:")
# A progress line of the build tool ("[ 5%] Building CXX object .../error.cpp.o"): never a reason.
PROGRESS_LINE = re.compile(r"^\s*\[\s*\d+%\]|^\s*(?:g?make|ninja)(?:\[\d+\])?:")


def first_error(log: str) -> str:
    """The error to fix first: the first compiler diagnostic, else CMake's error (with the line
    after it, which says what), else the linker's, else the first line that says "error:" and is
    not the build tool's progress (a source file may be called error.cpp)."""
    lines = log.splitlines()
    for line in lines:
        if COMPILER_ERROR.match(line.strip()):
            return line.strip()
    for index, line in enumerate(lines):
        if line.startswith("CMake Error"):
            following = next((l.strip() for l in lines[index + 1:index + 4] if l.strip()), "")
            return f"{line.strip()} {following}".strip()
    for line in lines:
        if "undefined reference" in line or "ld returned" in line or "cannot find -l" in line:
            return line.strip()
    for line in lines:
        if "error:" in line.lower() and not PROGRESS_LINE.match(line):
            return line.strip()
    return "the build failed (see the log)"


def run_logged(command: list[str], log: Path) -> BuildResult:
    """Run a cmake command, its output into `log`; what happened."""
    started = time.monotonic()
    result = subprocess.run(command, capture_output=True, text=True)
    output = result.stdout + result.stderr
    log.parent.mkdir(parents=True, exist_ok=True)
    log.write_text(output, encoding="utf-8")
    return BuildResult(result.returncode == 0, time.monotonic() - started, command,
                       first_error(output) if result.returncode else "", log,
                       [line for line in output.splitlines() if "warning:" in line])


def configure(source: Path, build: Path, like: dict[str, str] | None = None) -> BuildResult:
    """Configure build from source, with the generator and shared entries of the cache `like`
    (another build's) when given; a build folder configured from elsewhere, or with another
    generator, is removed first. The log goes to BUILD/grade-configure.log."""
    like = like or {}
    generator = like.get("CMAKE_GENERATOR")
    existing = read_cmake_cache(build)
    if existing and ((generator and existing.get("CMAKE_GENERATOR") != generator)
                     or Path(existing.get("CMAKE_HOME_DIRECTORY", "")) != source.resolve()):
        shutil.rmtree(build)
    command = ["cmake", "-S", str(source), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release", "-DFREEZERAY_WERROR=OFF"]
    if generator:
        command += ["-G", generator]
    command += [f"-D{entry}={like[entry]}" for entry in SHARED_CACHE_ENTRIES if like.get(entry)]
    return run_logged(command, build / "grade-configure.log")


def build_target(build: Path, target: str, jobs: int, log_name: str) -> BuildResult:
    """Build one target in Release; the log goes to BUILD/log_name."""
    command = ["cmake", "--build", str(build), "--target", target, "--config", "Release", "--parallel", str(jobs)]
    return run_logged(command, build / log_name)


def build_grading_tests(build: Path, jobs: int) -> BuildResult:
    """Build the exercise_tests target; the log goes to BUILD/grade-build.log."""
    return build_target(build, TEST_TARGET, jobs, "grade-build.log")


def find_grading_tests(build: Path) -> Path | None:
    """The exercise_tests executable of a build, if it has been built: where this project puts it,
    else the shallowest one below `build` (outside the proof's stubbed copy, which is built there)."""
    usual = build / "tests" / "exercises" / TEST_TARGET
    if usual.is_file() and os.access(usual, os.X_OK):
        return usual
    candidates = [path for path in build.rglob(TEST_TARGET) if path.is_file() and os.access(path, os.X_OK)
                  and "grading-student" not in path.relative_to(build).parts]
    return min(candidates, key=lambda path: len(path.parts)) if candidates else None


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
