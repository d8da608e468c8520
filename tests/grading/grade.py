#!/usr/bin/env python3
"""Grade the exercises of a FreezeRay build: build the grading tests, run them, print a score table.

A student, on their own copy:

    tests/grading/grade.py --build-dir build [--chapter ch01 | --only ch01/name] [--quiet]

A teacher, on one submission or a folder of them, against the teacher's own tree:

    tests/grading/grade.py --teacher-tests TEACHER --submission DIR --build-dir WORK --student ID --csv grades.csv
    tests/grading/grade.py --teacher-tests TEACHER --batch SUBMISSIONS --build-dir WORK --csv grades.csv

First the grading tests are built (`cmake --build DIR --target exercise_tests`, its log in
DIR/grade-build.log): what is graded is what the sources say now. With --no-build nothing is
built, and a test binary older than any of its sources is refused, naming them.

Then `ctest -L exercise` runs every grading test in its own process with its time limit (the
TIMEOUT of tests/exercises/CMakeLists.txt), so a crash or a hang costs that exercise only; its
output goes to DIR/grade-ctest.log (printed with --verbose). The report gives, per exercise, its
points and result, and for a failure the first line of the reason (a Catch2 message, or the
failed check's expansion); then the total per chapter and overall. Points come from
tests/grading/points.json (the teacher's, in teacher mode).

Teacher mode (--teacher-tests with --submission or --batch): the graded tree is the teacher's,
with only the bodies of the exercise regions taken from the submission (submission.py), so a
submission that edits a test or points.json gains nothing. --batch grades every folder of
SUBMISSIONS in turn in the same WORK folder (the build reused: only files whose regions differ
recompile), its name the student id, into one CSV.

Assignment reports: --report DIR renders, for each assignment (assignments.json), its scene with
the graded code and writes a page with the student's image beside the solution's reference (a
slider), the error image and the two relMSEs (assignment_report.py); the references come from
make_references.py --images on the solution's tree (--references DIR).

Gradebook output: --json FILE and --csv FILE hold the student id (--student), the time, the
hash of the graded regions, per exercise its points, earned, result and reason, and per chapter
the subtotals (long format, for scripts). --gradebook FILE is the one to hand back: one row per
student, a column per exercise and per chapter, the total. --feedback DIR writes each student's
report to DIR/STUDENT.txt. --batch ends with a class summary: totals, who did not compile, and
each exercise's pass rate. When the build fails, only the exercises in the file the compiler
stopped at are "does not compile"; the others are "not graded: FILE does not compile".

Exit status: 0 whenever the report could be produced (a low grade, or code that does not
compile, is a grade, not an error); 2 when it could not (no build folder, stale binary with
--no-build, no grading tests).
"""

from __future__ import annotations

import argparse
import csv
import datetime
import json
import re
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass, field
from pathlib import Path

sys.dont_write_bytecode = True  # keep __pycache__ out of the source tree
sys.path.insert(0, str(Path(__file__).resolve().parent))
import assignment_report  # noqa: E402  (the shared modules beside this script)
import exercises  # noqa: E402
import submission  # noqa: E402

# ctest names a grading test "exercise: ch01/name" (Catch2 v2's catch_discover_tests may
# drop the space after the colon, so accept both).
CTEST_PREFIX = re.compile(r"^exercise:\s*")
CTEST_LABEL = "exercise"
POINTS = Path("tests") / "grading" / "points.json"


class GradingError(Exception):
    """The report cannot be produced (no build folder, no grading tests, a stale binary...)."""


@dataclass
class Outcome:
    """What happened to one grading test: status is 'pass', 'fail' or 'not run'."""

    status: str
    detail: str = ""   # not implemented, needs chNN/x, timed out, wrong result...
    reason: str = ""   # the first line of why, from the test's output
    evidence: str = ""  # the folder where the test wrote its evidence (images, tables), if it did


@dataclass
class Row:
    """One line of the report."""

    exercise: str
    chapter: str
    points: int
    earned: int
    result: str
    reason: str = ""
    evidence: str = ""


@dataclass
class Report:
    """A graded build: its rows and what identifies it in a gradebook."""

    rows: list[Row]
    student: str = ""
    time: str = ""
    source_hash: str = ""
    notes: list[str] = field(default_factory=list)


# --- Building ---------------------------------------------------------------------------------

def check_build_dir(build_dir: Path) -> None:
    """Raise GradingError unless build_dir is a configured CMake build with tests."""
    if not build_dir.is_dir():
        raise GradingError(f"build folder {build_dir} does not exist; configure and build first:\n"
                           f"  cmake -S . -B {build_dir} && cmake --build {build_dir} --target exercise_tests")
    if not (build_dir / "CTestTestfile.cmake").is_file():
        raise GradingError(f"{build_dir} has no CTestTestfile.cmake: is it a configured FreezeRay build "
                           "folder with FREEZERAY_BUILD_TESTS=ON?")


def check_fresh(build_dir: Path, source: Path | None) -> None:
    """With --no-build: refuse a grading-test binary older than any of its sources."""
    binary = submission.find_grading_tests(build_dir)
    if binary is None:
        raise GradingError(f"{build_dir} has no {submission.TEST_TARGET}: build it, or leave out --no-build")
    if source is None or not source.is_dir():
        return
    newer = submission.newer_sources(source, binary)
    if newer:
        names = ", ".join(path.as_posix() for path in newer)
        raise GradingError(f"{binary} is older than its sources ({names}{', ...' if len(newer) == 5 else ''}): "
                           "it would grade old code. Leave out --no-build to build first.")


# --- Running the tests ------------------------------------------------------------------------

def ctest_command(build_dir: Path, junit: Path, chapter: str | None, jobs: int, only: str | None = None) -> list[str]:
    """The ctest command line that runs the grading tests (of one chapter or exercise, if given)."""
    command = ["ctest", "--test-dir", str(build_dir), "-L", CTEST_LABEL, "--output-on-failure",
               "--output-junit", str(junit.resolve())]
    if only is not None:
        command += ["-R", f"^exercise: ?{re.escape(only)}$"]
    elif chapter is not None:
        command += ["-R", f"^exercise: ?{chapter}/"]
    if jobs > 1:
        command += ["--parallel", str(jobs)]
    return command


def run_grading_tests(build_dir: Path, chapter: str | None, verbose: bool, jobs: int,
                      only: str | None = None) -> dict[str, Outcome]:
    """Run the grading tests with ctest (output to BUILD/grade-ctest.log); the outcome per exercise."""
    with tempfile.TemporaryDirectory(prefix="freezeray-grade-") as scratch:
        junit = Path(scratch) / "grading.xml"
        command = ctest_command(build_dir, junit, chapter, jobs, only)
        try:
            completed = subprocess.run(command, capture_output=True, text=True)
        except FileNotFoundError as error:
            raise GradingError("ctest was not found: install CMake (Debian: apt install cmake)") from error
        (build_dir / "grade-ctest.log").write_text(completed.stdout + completed.stderr, encoding="utf-8")
        if verbose:
            print(completed.stdout + completed.stderr)
        if not junit.is_file():
            raise GradingError(f"ctest wrote no results (exit status {completed.returncode}); "
                               f"command: {' '.join(command)}")
        outcomes = parse_ctest_junit(junit.read_text(encoding="utf-8", errors="replace"),
                                     ctest_verdicts(completed.stdout))
    if not outcomes:
        which = f"for {only or chapter} " if (only or chapter) else ""
        raise GradingError(f"no grading tests {which}(label '{CTEST_LABEL}') are registered in {build_dir}; "
                           f"build them first: cmake --build {build_dir} --target exercise_tests")
    return outcomes


def exercise_of(test_name: str) -> str:
    """The exercise name of a ctest test name: 'exercise: ch01/x' -> 'ch01/x'."""
    return CTEST_PREFIX.sub("", test_name, count=1)


# ctest's own line for a test it stopped or that crashed:
#   "3/3 Test #3: exercise:ch01/settle .............***Timeout   3.00 sec"
#   "1/3 Test #1: exercise:ch01/twice ..............***Exception: SegFault  0.01 sec"
CTEST_VERDICT = re.compile(r"Test\s+#\d+:\s+(?P<name>.+?)\s+\.+\s*\*\*\*(?P<verdict>Timeout|Exception: \S+)")


def ctest_verdicts(stdout: str) -> dict[str, str]:
    """What ctest's output says of tests that timed out or crashed (its JUnit file does not say)."""
    verdicts = {}
    for match in CTEST_VERDICT.finditer(stdout):
        verdict = match["verdict"]
        verdicts[exercise_of(match["name"])] = \
            "timed out" if verdict == "Timeout" else f"crashed ({verdict.split(': ', 1)[1]})"
    return verdicts


def parse_ctest_junit(text: str, verdicts: dict[str, str] | None = None) -> dict[str, Outcome]:
    """Read ctest's --output-junit file (and its verdicts on timeouts and crashes, from its
    output): the outcome of each test, keyed by exercise name."""
    verdicts = verdicts or {}
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
            detail = failure_detail(name, message, output)
            if detail == "wrong result" and name in verdicts:
                detail = verdicts[name]
            reason = "" if detail == "not implemented" or detail.startswith("needs ") else first_reason(output)
            if detail == "timed out":
                seconds = float(case.get("time", "0") or 0)
                reason = f"no result within {seconds:.0f} s: an endless loop, or far too slow"
            evidence = EVIDENCE.search(output)
            outcomes[name] = Outcome("fail", detail, reason, evidence["path"] if evidence else "")
        else:
            outcomes[name] = Outcome("not run", status or "not run")
    return outcomes


# A grading test that wrote evidence of its failure (tests/support/evidence.hpp) says where:
#   "... with message: 'evidence: /path/build/test-evidence/ch01_uniform-hemisphere'"
EVIDENCE = re.compile(r"evidence: (?P<path>[^'\s]+)")


def failure_detail(name: str, message: str, output: str) -> str:
    """A few words on why a grading test failed, for the report."""
    stubs = [match["name"] for match in exercises.NOT_IMPLEMENTED.finditer(output)]
    if name in stubs:
        return "not implemented"
    if stubs:
        return f"needs {stubs[0]}"
    if message.lower() == "timeout":
        return "timed out"
    if message and message.lower() not in ("failed", ""):
        return message.lower()
    return "wrong result"


# Catch2's account of a failure: "file:line: FAILED:", the check, then "with expansion:" and
# "with message:" blocks, each followed by indented lines.
FAILED_LINE = re.compile(r":\d+: FAILED:\s*$")
BLOCK_TITLES = ("with expansion:", "with message:", "with messages:", "due to unexpected exception with message:")


# Catch2's compact reporter (the grading tests'): one line per failure,
#   "file.cpp:95: failed: test.passed for: false with 2 messages: 'a' and 'likely mistake: ...'"
COMPACT_FAILURE = re.compile(r":\d+: failed: (?P<check>.*?)(?: for: (?P<expansion>.*?))?"
                             r"(?: with (?:\d+ messages?|message): (?P<messages>'.*'))?$")


def best_message(messages: list[str], fallback: str) -> str:
    """A bias detector's "likely mistake", else the message that says FAILED, else the first."""
    messages = [m for m in messages if not m.startswith("evidence: ")]  # a path, not a reason
    for wanted in ("likely mistake:", "FAILED"):
        for message in messages:
            if wanted in message:
                return message
    return next((m for m in messages if m), fallback)


def first_reason(output: str) -> str:
    """Why a Catch2 test failed, in one line: best_message of its first failure's messages, else
    the check's expansion, else the check (compact reporter, or the console's)."""
    for line in output.splitlines():
        match = COMPACT_FAILURE.search(line)
        if match:
            messages = match["messages"][1:-1].split("' and '") if match["messages"] else []
            return best_message(messages, match["expansion"] or match["check"])
    lines = output.splitlines()
    for index, line in enumerate(lines):
        if not FAILED_LINE.search(line):
            continue
        check, expansion, messages = "", "", []
        current, paragraph = None, []
        for following in lines[index + 1:index + 60] + [""]:
            stripped = following.strip()
            if FAILED_LINE.search(following) or stripped.startswith("----") or stripped.startswith("===="):
                break
            if stripped in BLOCK_TITLES or not stripped:
                if paragraph:  # Catch2 wraps a long message over several lines: join them
                    text = " ".join(paragraph)
                    if current == "with expansion:" and not expansion:
                        expansion = text
                    elif current is not None and current != "with expansion:":
                        messages.append(text)
                    elif current is None and not check:
                        check = text
                    paragraph = []
                if stripped:
                    current = stripped
                continue
            paragraph.append(stripped)
        return best_message(messages, expansion or check)
    for line in lines:  # not Catch2's format: the first line that speaks of an error or a failure
        if "error" in line.lower() or "fail" in line.lower():
            return line.strip()
    return ""


# --- The report -------------------------------------------------------------------------------

def source_dir_of(build_dir: Path) -> Path | None:
    """The source tree a build folder was configured from (CMakeCache.txt), if known."""
    home = submission.read_cmake_cache(build_dir).get("CMAKE_HOME_DIRECTORY")
    return Path(home) if home else None


def build_rows(outcomes: dict[str, Outcome], region_names: list[str], default_points: int,
               points: dict[str, int], chapter: str | None, only: str | None = None) -> list[Row]:
    """One row per exercise (tested or marked in the sources), sorted by name."""
    names = set(outcomes) | set(region_names)
    if only is not None:
        names = {name for name in names if name == only}
    elif chapter is not None:
        names = {name for name in names if name.startswith(chapter + "/")}
    rows = []
    for name in sorted(names):
        worth = points.get(name, default_points)
        outcome = outcomes.get(name, Outcome("not run", "no test"))
        chapter_name = exercises.chapter_of(name)
        if outcome.status == "pass":
            rows.append(Row(name, chapter_name, worth, worth, "pass"))
        elif outcome.status == "fail":
            rows.append(Row(name, chapter_name, worth, 0, f"FAIL ({outcome.detail})", outcome.reason,
                            outcome.evidence))
        else:
            rows.append(Row(name, chapter_name, worth, 0, outcome.detail))
    return rows


def failing_file(error: str, source: Path | None) -> Path | None:
    """The file the build's first error is in, relative to the graded tree where that can be told:
    an absolute path inside it, or a path relative to the compiling folder (as the compiler cache
    writes them: ../../chapters/...), whose leading ../ are dropped."""
    match = submission.COMPILER_ERROR.match(error.strip())  # its file: "path/file.cpp:12:5: error: ..."
    if match is None:
        return None
    path = Path(match["file"])
    if path.is_absolute():
        if source is not None:
            try:
                return path.resolve().relative_to(source.resolve())
            except ValueError:
                pass
        return path
    parts = list(path.parts)
    while parts and parts[0] in ("..", "."):
        parts.pop(0)
    return Path(*parts) if parts else path


def same_file(region_file: Path, broken: Path) -> bool:
    """Whether the error's file is the region's (the error's may carry a leading folder)."""
    own, theirs = region_file.as_posix(), broken.as_posix()
    return theirs == own or theirs.endswith("/" + own)


def rows_for_build_failure(region_names: list[str], default_points: int, points: dict[str, int],
                           chapter: str | None, only: str | None, error: str,
                           region_files: dict[str, Path] | None = None, source: Path | None = None) -> list[Row]:
    """Every exercise at zero when the grading tests do not compile: the error is the reason. An
    exercise whose own file is not the one that fails is marked as blocked by it, so that a student
    sees which of their files to fix first and that the others were not judged."""
    broken = failing_file(error, source)
    outcomes = {}
    for name in region_names:
        own = (region_files or {}).get(name)
        if broken is not None and own is not None and not same_file(own, broken):
            outcomes[name] = Outcome("fail", f"not graded: {broken.as_posix()} does not compile", error)
        else:
            outcomes[name] = Outcome("fail", "does not compile", error)
    return build_rows(outcomes, region_names, default_points, points, chapter, only)


def percent(earned: int, possible: int) -> str:
    """'75%' (or '-' when nothing is possible)."""
    return f"{100 * earned / possible:.0f}%" if possible else "-"


def chapter_totals(rows: list[Row]) -> dict[str, tuple[int, int]]:
    """(earned, possible) per chapter, in the rows' order."""
    totals: dict[str, tuple[int, int]] = {}
    for row in rows:
        earned, possible = totals.get(row.chapter, (0, 0))
        totals[row.chapter] = (earned + row.earned, possible + row.points)
    return totals


def format_report(rows: list[Row]) -> str:
    """The grade report: one line per exercise (with a failure's reason), a total per chapter, the overall total."""
    width = max([len("exercise"), *(len(row.exercise) for row in rows)]) + 2
    lines = [f"{'exercise':{width}}{'points':>8}  result", "-" * (width + 30)]
    totals = chapter_totals(rows)
    for chapter, (earned, possible) in totals.items():
        for row in (r for r in rows if r.chapter == chapter):
            reason = f": {row.reason}" if row.reason else ""
            lines.append(f"{row.exercise:{width}}{f'{row.earned}/{row.points}':>8}  {row.result}{reason}")
            if row.evidence:
                lines.append(f"{'':{width}}{'':>8}  evidence (images, tables): {row.evidence}")
        lines.append(f"{chapter + ' total':{width}}{f'{earned}/{possible}':>8}  {percent(earned, possible)}")
        lines.append("")
    earned = sum(row.earned for row in rows)
    possible = sum(row.points for row in rows)
    passed = sum(1 for row in rows if row.result == "pass")
    lines.append(f"{'overall':{width}}{f'{earned}/{possible}':>8}  {percent(earned, possible)}"
                 f"  ({passed} of {len(rows)} exercises pass)")
    return "\n".join(lines)


def report_json(report: Report) -> dict:
    """The report as plain data, for --json."""
    return {
        "student": report.student,
        "time": report.time,
        "source_hash": report.source_hash,
        "exercises": [row.__dict__ for row in report.rows],
        "chapters": {chapter: {"earned": e, "possible": p} for chapter, (e, p) in chapter_totals(report.rows).items()},
        "earned": sum(row.earned for row in report.rows),
        "possible": sum(row.points for row in report.rows),
        "notes": report.notes,
    }


CSV_COLUMNS = ["student", "time", "source_hash", "kind", "name", "points", "earned", "result", "reason"]


def csv_rows(report: Report) -> list[list[str]]:
    """The gradebook's rows of one report: one per exercise, one per chapter, one overall."""
    head = [report.student, report.time, report.source_hash]
    rows = [head + ["exercise", r.exercise, str(r.points), str(r.earned), r.result, r.reason] for r in report.rows]
    for chapter, (earned, possible) in chapter_totals(report.rows).items():
        rows.append(head + ["chapter", chapter, str(possible), str(earned), percent(earned, possible), ""])
    earned = sum(r.earned for r in report.rows)
    possible = sum(r.points for r in report.rows)
    rows.append(head + ["overall", "", str(possible), str(earned), percent(earned, possible), "; ".join(report.notes)])
    return rows


def write_csv(path: Path, reports: list[Report]) -> None:
    """All reports into one CSV, written atomically."""
    partial = path.with_name(path.name + ".part")
    with partial.open("w", newline="", encoding="utf-8") as file:
        writer = csv.writer(file)
        writer.writerow(CSV_COLUMNS)
        for report in reports:
            writer.writerows(csv_rows(report))
    partial.replace(path)


def write_gradebook(path: Path, reports: list[Report]) -> None:
    """The gradebook a teacher hands back: one row per student, a column per exercise and per
    chapter (points earned), the total and its percentage, and the notes; written atomically."""
    exercises_seen: list[str] = []
    chapters_seen: list[str] = []
    for report in reports:
        for row in report.rows:
            if row.exercise not in exercises_seen:
                exercises_seen.append(row.exercise)
            if row.chapter not in chapters_seen:
                chapters_seen.append(row.chapter)
    exercises_seen.sort()
    chapters_seen.sort()
    header = ["student", *exercises_seen, *(f"{c} total" for c in chapters_seen), "total", "possible", "percent",
              "build", "time", "source_hash", "notes"]
    partial = path.with_name(path.name + ".part")
    with partial.open("w", newline="", encoding="utf-8") as file:
        writer = csv.writer(file)
        writer.writerow(header)
        for report in reports:
            earned = {row.exercise: str(row.earned) for row in report.rows}
            totals = chapter_totals(report.rows)
            total = sum(row.earned for row in report.rows)
            possible = sum(row.points for row in report.rows)
            compiles = not any("does not compile" in row.result for row in report.rows)
            writer.writerow([report.student, *(earned.get(name, "") for name in exercises_seen),
                             *(str(totals[c][0]) if c in totals else "" for c in chapters_seen),
                             str(total), str(possible), percent(total, possible),
                             "ok" if compiles else "does not compile", report.time, report.source_hash,
                             "; ".join(report.notes)])
    partial.replace(path)


def write_feedback(folder: Path, reports: list[Report]) -> list[Path]:
    """One text file per student with their report, as the terminal shows it; the paths written."""
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for index, report in enumerate(reports):
        name = re.sub(r"[^A-Za-z0-9._-]", "_", report.student) or f"student-{index + 1}"
        text = f"{report.student or 'this build'}  ({report.time}, sources {report.source_hash[:12]})\n\n"
        text += format_report(report.rows) + "\n"
        text += "".join(f"note: {note}\n" for note in report.notes)
        if any(row.result.startswith("FAIL") and row.reason for row in report.rows):
            text += ("\nA failing test says what it expected and what came; run the grader with --verbose, or the "
                     "test alone with --only NAME --verbose, for its whole output.\n")
        path = folder / f"{name}.txt"
        partial = path.with_name(path.name + ".part")
        partial.write_text(text, encoding="utf-8")
        partial.replace(path)
        written.append(path)
    return written


def class_summary(reports: list[Report]) -> str:
    """The class at a glance: totals (mean, median, range), how many did not compile, and each
    exercise's pass rate, hardest first."""
    if not reports:
        return ""
    totals = sorted(sum(r.earned for r in report.rows) for report in reports)
    possible = max((sum(r.points for r in report.rows) for report in reports), default=0)
    n = len(totals)
    median = totals[n // 2] if n % 2 else (totals[n // 2 - 1] + totals[n // 2]) / 2
    broken = [r.student for r in reports if any("does not compile" in row.result for row in r.rows)]
    lines = [f"class: {n} student{'s' if n != 1 else ''}, total out of {possible}: mean {sum(totals) / n:.1f}, "
             f"median {median:g}, lowest {totals[0]}, highest {totals[-1]}"]
    if broken:
        lines.append(f"  {len(broken)} did not compile: {', '.join(broken)}")
    passes: dict[str, int] = {}
    for report in reports:
        for row in report.rows:
            passes[row.exercise] = passes.get(row.exercise, 0) + (row.result == "pass")
    lines.append("  pass rate per exercise, hardest first:")
    for name, count in sorted(passes.items(), key=lambda item: (item[1], item[0])):
        lines.append(f"    {name:40} {count}/{n}")
    return "\n".join(lines)


# --- Grading one build ------------------------------------------------------------------------

def now() -> str:
    return datetime.datetime.now(datetime.timezone.utc).replace(microsecond=0).isoformat()


def say(args: argparse.Namespace, message: str) -> None:
    if not args.quiet:
        print(message, flush=True)


def grade_build(args: argparse.Namespace, build_dir: Path, source: Path | None, points_file: Path,
                student: str, source_hash: str, notes: list[str]) -> Report:
    """Build (unless --no-build), run the grading tests, and make the report of one build."""
    default_points, points = exercises.load_points(points_file)
    region_names = []
    region_files: dict[str, Path] = {}
    if source is not None and source.is_dir():
        regions = exercises.find_regions_with_problems(source)[0]
        region_files = {region.name: region.path for region in regions}
        try:
            region_names = exercises.graded_names(source, regions)  # and the assignments made of regions
        except ValueError:
            region_names = [region.name for region in regions]
    report = Report([], student, now(), source_hash, notes)
    if args.no_build:
        check_fresh(build_dir, source)
    else:
        say(args, f"building {submission.TEST_TARGET} in {build_dir} ...")
        built = submission.build_grading_tests(build_dir, args.jobs_build)
        say(args, f"  {'built' if built.ok else 'FAILED'} in {built.seconds:.0f} s (log: {built.log})")
        if not built.ok:
            report.rows = rows_for_build_failure(region_names, default_points, points, args.chapter, args.only,
                                                 built.error, region_files, source)
            report.notes.append(f"the grading tests do not compile: {built.error}")
            return report
    say(args, "running the grading tests ...")
    outcomes = run_grading_tests(build_dir, args.chapter, args.verbose, args.jobs, args.only)
    report.rows = build_rows(outcomes, region_names, default_points, points, args.chapter, args.only)
    if args.report is not None and source is not None:
        folder = args.report / student if args.batch is not None else args.report
        say(args, f"rendering the assignments' reports into {folder} ...")
        grades = {row.exercise: f"{row.earned}/{row.points} {row.result}" + (f": {row.reason}" if row.reason else "")
                  for row in report.rows}
        references = args.references or build_dir / "assignment-references"
        made = assignment_report.make_reports(build_dir, source, references, folder, grades, args.chapter, args.only,
                                              student, args.jobs_build)
        report.notes.append(f"assignment reports ({len(made)}): {folder / 'index.html'}")
    return report


def grade_submission(args: argparse.Namespace, folder: Path, student: str) -> Report:
    """Teacher mode: the teacher's tree with this submission's regions, built in WORK and graded."""
    started = time.monotonic()
    work = args.build_dir
    tree = submission.assemble_graded_tree(args.teacher_tests, folder, work / "source")
    build = work / "build"
    notes = [f"regions missing from the submission (graded as not implemented): {', '.join(tree.missing)}"] \
        if tree.missing else []
    if not (build / "CMakeCache.txt").is_file():
        say(args, f"configuring {build} ...")
        configured = submission.configure(tree.source, build)
        if not configured.ok:
            raise GradingError(f"configuring the teacher's tree failed: {configured.error} (log: {configured.log})")
    report = grade_build(args, build, tree.source, args.teacher_tests / POINTS, student, tree.source_hash, notes)
    report.notes.append(f"graded in {time.monotonic() - started:.0f} s ({tree.written} files rewritten)")
    return report


def format_exercise_list(root: Path, chapter: str | None, only: str | None) -> str:
    """The exercises in the order to do them (chapter by chapter, each after its prerequisites),
    with points, prerequisites, where and what; an assignment made of several exercises comes
    after its parts, and every assignment says what it makes."""
    regions = exercises.select_regions(exercises.find_regions(root), only=only, chapter=chapter)
    assignments = exercises.load_assignments(root / exercises.ASSIGNMENTS_FILE)
    default_points, points = exercises.load_points(root / POINTS)
    before = exercises.all_prerequisites(root)
    by_name: dict[str, exercises.Region | None] = {region.name: region for region in regions}
    for assignment in assignments.values():
        wanted = only == assignment.name or (only is None and chapter in (None, assignment.chapter))
        if assignment.is_composite and wanted:
            by_name[assignment.name] = None
    ordered: list[str] = []

    def place(name: str, seen: tuple[str, ...] = ()) -> None:  # after its prerequisites
        if name not in by_name or name in ordered or name in seen:
            return
        for first in sorted(before.get(name, [])):
            place(first, seen + (name,))
        ordered.append(name)

    for name in sorted(by_name):
        place(name)
    lines = []
    for name in ordered:
        worth = points.get(name, default_points)
        needs = f"  (first: {', '.join(before[name])})" if before.get(name) else ""
        lines.append(f"{name}  [{worth} point{'s' if worth != 1 else ''}]{needs}")
        region = by_name[name]
        if region is not None:
            lines.append(f"    {region.location}: {region.description}")
        if name in assignments:
            kind = "made of the exercises above" if region is None else "a whole feature in one region"
            book = f" ({assignments[name].book})" if assignments[name].book else ""
            lines.append(f"    assignment, {kind}: {assignments[name].title}{book}")
    return "\n".join(lines)


def print_report(args: argparse.Namespace, report: Report) -> None:
    if report.student:
        print(f"\n{report.student}  ({report.time}, sources {report.source_hash[:12]})")
    print()
    print(format_report(report.rows))
    for note in report.notes:
        print(f"note: {note}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Build and run the grading tests of a build and print the grade.")
    parser.add_argument("--build-dir", type=Path,
                        help="the CMake build folder (teacher mode: the work folder, WORK/source and WORK/build)")
    parser.add_argument("--list", action="store_true",
                        help="list the exercises in order, with their points and what to do before each, and stop")
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--chapter", metavar="chNN", help="grade only this chapter, e.g. ch01")
    which.add_argument("--only", metavar="chNN/name", help="grade only this exercise")
    parser.add_argument("--no-build", action="store_true",
                        help="do not build first; refuse a test binary older than its sources")
    parser.add_argument("--quiet", action="store_true", help="print only the report")
    parser.add_argument("--verbose", action="store_true", help="also print ctest's output")
    parser.add_argument("--jobs", type=int, default=1, help="grading tests run at once (default 1)")
    parser.add_argument("--jobs-build", type=int, default=2, help="compiler processes when building (default 2)")
    parser.add_argument("--student", default="", help="the student id written into --json and --csv")
    parser.add_argument("--json", type=Path, metavar="FILE", help="also write the report as JSON to FILE")
    parser.add_argument("--csv", type=Path, metavar="FILE", help="also write the report as CSV to FILE")
    parser.add_argument("--gradebook", type=Path, metavar="FILE",
                        help="also write the gradebook: one row per student, a column per exercise and chapter, the "
                             "total (CSV)")
    parser.add_argument("--feedback", type=Path, metavar="DIR",
                        help="also write each student's report to DIR/STUDENT.txt, to hand back")
    parser.add_argument("--teacher-tests", type=Path, metavar="TEACHER",
                        help="teacher mode: the teacher's FreezeRay tree, whose tests and points.json grade")
    parser.add_argument("--report", type=Path, metavar="DIR",
                        help="also render each assignment's scene with the graded code and write pages comparing it "
                             "with the solution's reference to DIR (a folder per student with --batch)")
    parser.add_argument("--references", type=Path, metavar="DIR",
                        help="the references made by make_references.py --images on the solution's tree "
                             "(default: BUILD_DIR/assignment-references)")
    graded = parser.add_mutually_exclusive_group()
    graded.add_argument("--submission", type=Path, metavar="DIR", help="teacher mode: one submission's tree")
    graded.add_argument("--batch", type=Path, metavar="SUBMISSIONS",
                        help="teacher mode: a folder of submissions, one folder each, named by student id")
    args = parser.parse_args(argv)
    if args.list:
        root = args.teacher_tests or exercises.repository_root()
        print(format_exercise_list(root, args.chapter, args.only))
        return 0
    if args.build_dir is None:
        parser.error("--build-dir is required (except with --list)")
    if args.chapter is not None and not exercises.is_chapter_name(args.chapter):
        parser.error(f"'{args.chapter}' is not a chapter name: expected chNN, e.g. ch01")
    if args.only is not None and not re.fullmatch(exercises.NAME_PATTERN, args.only):
        parser.error(f"'{args.only}' is not an exercise name: expected chNN/kebab-name")
    teacher_mode = args.submission is not None or args.batch is not None
    if teacher_mode != (args.teacher_tests is not None):
        parser.error("--teacher-tests goes with --submission or --batch, and they with it")
    if args.batch is not None and args.no_build:
        parser.error("--batch builds each submission; --no-build does not apply")

    reports: list[Report] = []
    try:
        if args.batch is not None:
            folders = sorted(p for p in args.batch.iterdir() if p.is_dir()) if args.batch.is_dir() else []
            if not folders:
                raise GradingError(f"{args.batch} holds no submission folders")
            for folder in folders:
                say(args, f"== {folder.name}")
                report = grade_submission(args, folder, folder.name)
                reports.append(report)
                print_report(args, report)
        elif args.submission is not None:
            if not args.submission.is_dir():
                raise GradingError(f"submission {args.submission} is not a folder")
            reports.append(grade_submission(args, args.submission, args.student))
            print_report(args, reports[-1])
        else:
            check_build_dir(args.build_dir)
            source = source_dir_of(args.build_dir)
            points_file = (source / POINTS) if source is not None and (source / POINTS).is_file() \
                else Path(__file__).resolve().parent / "points.json"
            source_hash = submission.hash_of_tree(source) if source is not None and source.is_dir() else ""
            reports.append(grade_build(args, args.build_dir, source, points_file, args.student, source_hash, []))
            print_report(args, reports[-1])
    except (GradingError, ValueError) as error:
        print(f"grade: error: {error}", file=sys.stderr)
        return 2

    if args.json is not None:
        data = [report_json(r) for r in reports] if args.batch is not None else report_json(reports[0])
        args.json.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    if args.csv is not None:
        write_csv(args.csv, reports)
    if args.gradebook is not None:
        write_gradebook(args.gradebook, reports)
    if args.feedback is not None:
        write_feedback(args.feedback, reports)
    if args.batch is not None:
        print()
        print(class_summary(reports))
    return 0


if __name__ == "__main__":
    sys.exit(main())
