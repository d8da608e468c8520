#!/usr/bin/env python3
"""Grade the exercises of a FreezeRay build: run the grading tests and print a score table.

    tests/grading/grade.py --build-dir build [--chapter ch01] [--quiet] [--json grade.json]

Runs `ctest --test-dir DIR -L exercise --output-on-failure` (every grading test in its own
process, so a crash or a hang costs one exercise, not the whole run), reads ctest's JUnit
output and prints, per exercise, its points and whether it passed; then the total per
chapter and overall. Points come from tests/grading/points.json (default 1 per exercise).

An exercise whose region is in the sources but whose test did not run is listed as
"no test" and counts for its points in the total possible.

Exit status: 0 whenever the report could be produced (a low grade is not an error);
2 when the build folder or its grading tests are missing.
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass
from pathlib import Path

sys.dont_write_bytecode = True  # keep __pycache__ out of the source tree
sys.path.insert(0, str(Path(__file__).resolve().parent))
import exercises  # noqa: E402  (the shared parsing module beside this script)

# ctest names a grading test "exercise: ch01/name" (Catch2 v2's catch_discover_tests may
# drop the space after the colon, so accept both).
CTEST_PREFIX = re.compile(r"^exercise:\s*")
CTEST_LABEL = "exercise"


class GradingError(Exception):
    """The report cannot be produced (no build folder, no grading tests...)."""


@dataclass
class Outcome:
    """What happened to one grading test: status is 'pass', 'fail' or 'not run'."""

    status: str
    detail: str = ""


@dataclass
class Row:
    """One line of the report."""

    exercise: str
    chapter: str
    points: int
    earned: int
    result: str


# --- Running the tests ------------------------------------------------------------------------

def check_build_dir(build_dir: Path) -> None:
    """Raise GradingError unless build_dir is a configured CMake build with tests."""
    if not build_dir.is_dir():
        raise GradingError(f"build folder {build_dir} does not exist; configure and build first:\n"
                           f"  cmake -S . -B {build_dir} && cmake --build {build_dir} --target exercise_tests")
    if not (build_dir / "CTestTestfile.cmake").is_file():
        raise GradingError(f"{build_dir} has no CTestTestfile.cmake: is it a configured FreezeRay build "
                           "folder with FREEZERAY_BUILD_TESTS=ON?")


def ctest_command(build_dir: Path, junit: Path, chapter: str | None, jobs: int) -> list[str]:
    """The ctest command line that runs the grading tests (of one chapter, if given)."""
    command = ["ctest", "--test-dir", str(build_dir), "-L", CTEST_LABEL, "--output-on-failure",
               "--output-junit", str(junit.resolve())]
    if chapter is not None:
        command += ["-R", f"^exercise: ?{chapter}/"]
    if jobs > 1:
        command += ["--parallel", str(jobs)]
    return command


def run_grading_tests(build_dir: Path, chapter: str | None, quiet: bool, jobs: int) -> dict[str, Outcome]:
    """Run the grading tests with ctest; return the outcome per exercise name."""
    with tempfile.TemporaryDirectory(prefix="freezeray-grade-") as scratch:
        junit = Path(scratch) / "grading.xml"
        command = ctest_command(build_dir, junit, chapter, jobs)
        try:
            completed = subprocess.run(command, capture_output=quiet, text=True)
        except FileNotFoundError as error:
            raise GradingError("ctest was not found: install CMake (Debian: apt install cmake)") from error
        if not junit.is_file():
            raise GradingError(f"ctest wrote no results (exit status {completed.returncode}); "
                               f"command: {' '.join(command)}")
        outcomes = parse_ctest_junit(junit.read_text(encoding="utf-8", errors="replace"))
    if not outcomes:
        which = f"for {chapter} " if chapter else ""
        raise GradingError(f"no grading tests {which}(label '{CTEST_LABEL}') are registered in {build_dir}; "
                           f"build them first: cmake --build {build_dir} --target exercise_tests")
    return outcomes


def exercise_of(test_name: str) -> str:
    """The exercise name of a ctest test name: 'exercise: ch01/x' -> 'ch01/x'."""
    return CTEST_PREFIX.sub("", test_name, count=1)


def parse_ctest_junit(text: str) -> dict[str, Outcome]:
    """Read ctest's --output-junit file: the outcome of each test, keyed by exercise name."""
    root = ElementTree.fromstring(text)
    outcomes: dict[str, Outcome] = {}
    for case in root.iter("testcase"):
        name = exercise_of(case.get("name", ""))
        status = case.get("status", "")
        output = case.findtext("system-out") or ""
        failure = case.find("failure")
        if status == "run" and failure is None:
            outcomes[name] = Outcome("pass")
        elif status == "fail" or failure is not None:
            message = failure.get("message", "") if failure is not None else ""
            outcomes[name] = Outcome("fail", failure_detail(name, message, output))
        else:
            outcomes[name] = Outcome("not run", status or "not run")
    return outcomes


def failure_detail(name: str, message: str, output: str) -> str:
    """A few words on why a grading test failed, for the report."""
    stubs = [match["name"] for match in exercises.NOT_IMPLEMENTED.finditer(output)]
    if name in stubs:
        return "not implemented"
    if stubs:
        return f"needs {stubs[0]}"
    if message and message.lower() not in ("failed", ""):
        return message.lower()
    return "wrong result"


# --- The report -------------------------------------------------------------------------------

def source_dir_of(build_dir: Path) -> Path | None:
    """The source tree a build folder was configured from (CMakeCache.txt), if known."""
    cache = build_dir / "CMakeCache.txt"
    if not cache.is_file():
        return None
    for line in cache.read_text(encoding="utf-8", errors="replace").splitlines():
        if line.startswith("CMAKE_HOME_DIRECTORY:"):
            return Path(line.split("=", 1)[1])
    return None


def build_rows(outcomes: dict[str, Outcome], region_names: list[str], default_points: int,
               points: dict[str, int], chapter: str | None) -> list[Row]:
    """One row per exercise (tested or marked in the sources), sorted by name."""
    names = set(outcomes) | set(region_names)
    if chapter is not None:
        names = {name for name in names if name.startswith(chapter + "/")}
    rows = []
    for name in sorted(names):
        worth = points.get(name, default_points)
        outcome = outcomes.get(name, Outcome("not run", "no test"))
        if outcome.status == "pass":
            rows.append(Row(name, name.split("/", 1)[0], worth, worth, "pass"))
        elif outcome.status == "fail":
            rows.append(Row(name, name.split("/", 1)[0], worth, 0, f"FAIL ({outcome.detail})"))
        else:
            rows.append(Row(name, name.split("/", 1)[0], worth, 0, outcome.detail))
    return rows


def percent(earned: int, possible: int) -> str:
    """'75%' (or '-' when nothing is possible)."""
    return f"{100 * earned / possible:.0f}%" if possible else "-"


def format_report(rows: list[Row]) -> str:
    """The grade report: one line per exercise, a total per chapter, the overall total."""
    width = max([len("exercise"), *(len(row.exercise) for row in rows)]) + 2
    lines = [f"{'exercise':{width}}{'points':>8}  result", "-" * (width + 30)]
    chapters: dict[str, list[Row]] = {}
    for row in rows:
        chapters.setdefault(row.chapter, []).append(row)
    for chapter, chapter_rows in chapters.items():
        for row in chapter_rows:
            lines.append(f"{row.exercise:{width}}{f'{row.earned}/{row.points}':>8}  {row.result}")
        earned = sum(row.earned for row in chapter_rows)
        possible = sum(row.points for row in chapter_rows)
        lines.append(f"{chapter + ' total':{width}}{f'{earned}/{possible}':>8}  {percent(earned, possible)}")
        lines.append("")
    earned = sum(row.earned for row in rows)
    possible = sum(row.points for row in rows)
    passed = sum(1 for row in rows if row.result == "pass")
    lines.append(f"{'overall':{width}}{f'{earned}/{possible}':>8}  {percent(earned, possible)}"
                 f"  ({passed} of {len(rows)} exercises pass)")
    return "\n".join(lines)


def report_json(rows: list[Row]) -> dict:
    """The report as plain data, for --json."""
    return {
        "exercises": [row.__dict__ for row in rows],
        "earned": sum(row.earned for row in rows),
        "possible": sum(row.points for row in rows),
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Run the grading tests of a build and print the grade.")
    parser.add_argument("--build-dir", type=Path, required=True, help="the CMake build folder")
    parser.add_argument("--chapter", metavar="chNN", help="grade only this chapter, e.g. ch01")
    parser.add_argument("--quiet", action="store_true", help="print only the report, not ctest's output")
    parser.add_argument("--jobs", type=int, default=1, help="grading tests run at once (default 1)")
    parser.add_argument("--json", type=Path, metavar="FILE", help="also write the report as JSON to FILE")
    args = parser.parse_args(argv)
    if args.chapter is not None and not exercises.is_chapter_name(args.chapter):
        parser.error(f"'{args.chapter}' is not a chapter name: expected chNN, e.g. ch01")

    try:
        check_build_dir(args.build_dir)
        default_points, points = exercises.load_points(Path(__file__).resolve().parent / "points.json")
        source = source_dir_of(args.build_dir)
        region_names = []
        if source is not None and source.is_dir():
            region_names = [region.name for region in exercises.find_regions_with_problems(source)[0]]
        outcomes = run_grading_tests(args.build_dir, args.chapter, args.quiet, args.jobs)
    except (GradingError, ValueError) as error:
        print(f"grade: error: {error}", file=sys.stderr)
        return 2

    rows = build_rows(outcomes, region_names, default_points, points, args.chapter)
    print()
    print(format_report(rows))
    if args.json is not None:
        args.json.write_text(json.dumps(report_json(rows), indent=2) + "\n", encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
