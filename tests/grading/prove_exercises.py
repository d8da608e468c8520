#!/usr/bin/env python3
"""Prove that every exercise's grading test fails on its stub and passes on its solution.

    tests/grading/prove_exercises.py --source . --build-dir build [--work DIR] [--isolate]

1. Every exercise region has a grading test of the same name in `exercise_tests`, and every
   grading test has a region (`exercise_tests --list-test-names-only`).
2. In the solution build (--build-dir, already built), every grading test passes.
3. A student copy with every region stubbed is made in WORK/source, configured (Release,
   same generator as the solution build) in the folder that lies within the copy where the
   solution's build folder lies within the solution (WORK/source/build for a build folder
   `build`; WORK/build when the solution's build is elsewhere), and only the `exercise_tests`
   target is built: through the compiler cache, only what the stubs change is compiled; there every grading test must fail, and its output
   must show its own stub's ExerciseNotImplemented message.

A test that fails on the student copy only through another exercise's stub (it calls that
exercise first) has not shown that it catches its own stub. With --isolate, such an
exercise is checked again on a copy where it alone is stubbed (an incremental rebuild);
without it, that is reported as a violation.

Each test runs in its own process, from its build folder, with a time limit. WORK is kept
between runs (default: BUILD_DIR/grading-student), so a second run rebuilds only what
changed. Exit status 0 when everything is proven, 1 on any violation, 2 on bad arguments.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

sys.dont_write_bytecode = True  # keep __pycache__ out of the source tree
sys.path.insert(0, str(Path(__file__).resolve().parent))
import exercises  # noqa: E402  (the shared parsing modules beside this script)
import make_student_copy  # noqa: E402
import submission  # noqa: E402

TEST_TARGET = submission.TEST_TARGET


@dataclass
class Run:
    """One run of one grading test."""

    passed: bool
    stubs: list[str] = field(default_factory=list)  # exercises whose stub message appeared
    timed_out: bool = False
    output: str = ""

    def describe(self) -> str:
        """'pass', 'FAIL', 'FAIL (timeout)'..., for the table."""
        if self.timed_out:
            return "FAIL (timeout)"
        return "pass" if self.passed else "FAIL"


@dataclass
class Proof:
    """Everything learned about one exercise (or one grading test without a region)."""

    name: str
    has_region: bool
    has_test: bool
    parts: tuple[str, ...] = ()  # an assignment made of these regions (assignments.json)
    solution: Run | None = None
    stubbed: Run | None = None
    isolated: Run | None = None
    violations: list[str] = field(default_factory=list)

    def stub_column(self) -> str:
        """What happened on the student copy, in a few words."""
        run = self.isolated or self.stubbed
        if run is None:
            return "-"
        if run.passed:
            return "pass"
        where = " alone" if self.isolated else ""
        if self.name in run.stubs:
            return f"FAIL (its stub{where})"
        if self.parts and any(part in run.stubs for part in self.parts):
            where = " (its chapter stubbed)" if self.isolated else ""
            return f"FAIL (its part {next(p for p in run.stubs if p in self.parts)}{where})"
        if self.isolated is not None:
            return "FAIL (stubbed alone)"
        if run.stubs:
            return f"FAIL (via {run.stubs[0]})"
        return run.describe() + " (no stub message)"


# --- Small helpers ----------------------------------------------------------------------------

def catch_test_spec(name: str) -> str:
    """A Catch2 test spec that matches exactly this test name (escapes , [ ] and backslash)."""
    for character in "\\,[]":
        name = name.replace(character, "\\" + character)
    return name


def print_step(message: str) -> None:
    """A progress line, flushed so it interleaves well with the build's output."""
    print(f"-- {message}", flush=True)


def tail(text: str, lines: int = 30) -> str:
    """The last lines of a long output."""
    return "\n".join(text.splitlines()[-lines:])


def build_errors(log: str) -> str:
    """The compiler's error lines of a build log (or its end when there are none)."""
    errors = [line for line in log.splitlines() if "error" in line.lower()]
    return "\n".join(errors[:20]) if errors else tail(log, 40)


def regions_named_in(log: str, copy: Path, regions: list[exercises.Region]) -> str:
    """A hint listing the exercise regions in the files a build log's errors point at."""
    prefix = str(copy.resolve()) + os.sep
    suspects = []
    for region in regions:
        # An absolute path, or one relative to the compiling folder (the compiler cache's: ../../x).
        if prefix + str(region.path) in log or f"../{region.path.as_posix()}:" in log:
            suspects.append(f"{region.name} ({region.location})")
    return ("\nexercise regions in the files with errors: " + ", ".join(suspects)) if suspects else ""


# --- Running grading tests --------------------------------------------------------------------

def list_tests(executable: Path, cwd: Path) -> list[str]:
    """The test names in a Catch2 executable (--list-test-names-only)."""
    result = subprocess.run([str(executable), "--list-test-names-only"], cwd=cwd,
                            capture_output=True, text=True)
    # Catch2 v2 exits with the number of tests listed; only a signal means it failed.
    if result.returncode < 0:
        raise RuntimeError(f"{executable} --list-test-names-only crashed:\n{tail(result.stderr)}")
    return [line.strip() for line in result.stdout.splitlines() if line.strip()]


def run_test(executable: Path, name: str, cwd: Path, timeout: float) -> Run:
    """Run one grading test in its own process; note which stubs' messages it printed."""
    command = [str(executable), catch_test_spec(name), "--reporter", "xml"]
    try:
        result = subprocess.run(command, cwd=cwd, capture_output=True, text=True,
                                errors="replace", timeout=timeout)
    except subprocess.TimeoutExpired as expired:
        output = (expired.stdout or b"").decode(errors="replace") if isinstance(expired.stdout, bytes) \
            else (expired.stdout or "")
        return Run(passed=False, stubs=stubs_in(output), timed_out=True, output=output)
    output = result.stdout + result.stderr
    return Run(passed=result.returncode == 0, stubs=stubs_in(output), output=output)


def stubs_in(output: str) -> list[str]:
    """The exercises whose ExerciseNotImplemented message appears in output, in order."""
    names = []
    for match in exercises.NOT_IMPLEMENTED.finditer(output):
        if match["name"] not in names:
            names.append(match["name"])
    return names


# --- The student build ------------------------------------------------------------------------

def configure_student_build(source: Path, build: Path, solution_cache: dict[str, str]) -> None:
    """Configure the student copy like the solution build (same generator, Release, no -Werror)."""
    print_step(f"configuring the student copy in {build}")
    result = submission.configure(source, build, like=solution_cache)
    print_step("  " + " ".join(result.command))
    if not result.ok:
        raise RuntimeError("configuring the student copy failed:\n" + tail(result.log.read_text(encoding="utf-8")))


def build_student_tests(build: Path, jobs: int) -> list[str]:
    """Build only the exercise_tests target of the student copy; return the compiler's warnings."""
    print_step(f"building the student copy in {build}")
    result = submission.build_grading_tests(build, jobs)
    if not result.ok:
        raise RuntimeError(
            "building the student copy failed: a stub must compile wherever its region is "
            "(does a region declare a name used after `// END EXERCISE`, or sit in a constexpr "
            "or consteval function?)\n" + build_errors(result.log.read_text(encoding="utf-8")))
    print_step(f"built in {result.seconds:.0f} s")
    return result.warnings


def student_executable(solution_build: Path, solution_executable: Path, student_build: Path) -> Path:
    """exercise_tests in the student build: same place as in the solution build, or searched for."""
    try:
        relative = solution_executable.resolve().relative_to(solution_build.resolve())
        if (student_build / relative).is_file():
            return student_build / relative
    except ValueError:
        pass
    found = submission.find_grading_tests(student_build)
    if found is None:
        raise RuntimeError(f"the student build in {student_build} has no {TEST_TARGET} executable")
    return found


def student_build_dir(source: Path, solution_build: Path, work: Path) -> Path:
    """Where the student copy is built: at the same place within the copy as the solution's build
    folder within the solution, so that the compiler cache (cmake/CompilerCache.cmake) gives the
    student build every object whose sources are unchanged and only the files that differ are
    compiled; WORK/build (everything compiled) when the solution's build lies outside its source."""
    try:
        within = solution_build.resolve().relative_to(source.resolve())
    except ValueError:
        return work / "build"
    return work / "source" / within


def refresh_copy(source: Path, work: Path, only: str | None = None, stub: bool = True,
                 chapter: str | None = None) -> Path:
    """Make (or bring up to date) the student copy in work/source; return its path."""
    copy = work / "source"
    counts = make_student_copy.make_student_copy(source, copy, only=only, chapter=chapter, update=True, stub=stub)
    print_step(f"student copy in {copy}: {counts['stubbed']} exercise(s) stubbed, "
               f"{counts['written']} file(s) rewritten")
    return copy


# --- Planted mistakes -------------------------------------------------------------------------
# A grading test's bias detector names a classic mistake when the test fails (tests/support/
# bias_detectors.hpp). planted_mistakes.json lists, per exercise, mistakes to plant in the
# solution: each must make the test fail with its own detector's words, and no other's.

PLANTS_FILE = Path(__file__).resolve().parent / "planted_mistakes.json"


@dataclass
class Plant:
    exercise: str
    mistake: str   # a few words for the table
    replace: str   # text of the solution's region...
    with_: str     # ...and what the mistake writes instead
    expect: str    # words the test's output must show


def load_plants(path: Path = PLANTS_FILE) -> list[Plant]:
    if not path.is_file():
        return []
    data = json.loads(path.read_text(encoding="utf-8"))
    return [Plant(p["exercise"], p["mistake"], p["replace"], p["with"], p["expect"]) for p in data["planted"]]


def plant_mistake(copy: Path, plant: Plant, regions: list[exercises.Region]) -> None:
    """Write plant's mistake into its exercise's region in the copy (of the solution)."""
    region = next((r for r in regions if r.name == plant.exercise), None)
    if region is None:
        raise RuntimeError(f"planted mistake '{plant.mistake}': no exercise {plant.exercise}")
    path = copy / region.path
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    body = "".join(lines[region.start:region.end - 1])
    if body.count(plant.replace) != 1:
        raise RuntimeError(f"planted mistake '{plant.mistake}': '{plant.replace}' is not in {plant.exercise}'s "
                           f"region exactly once ({region.path}:{region.start})")
    lines[region.start:region.end - 1] = [body.replace(plant.replace, plant.with_)]
    path.write_text("".join(lines), encoding="utf-8")


def check_plants(plants: list[Plant], regions: list[exercises.Region], source: Path, work: Path,
                 solution_build: Path, solution_executable: Path, jobs: int, timeout: float) -> list[str]:
    """Plant each mistake in turn (incremental rebuilds); return the violations."""
    violations = []
    rows = []
    for plant in plants:
        print_step(f"planting '{plant.mistake}' in {plant.exercise}")
        copy = refresh_copy(source, work, stub=False)
        plant_mistake(copy, plant, regions)
        student_build = student_build_dir(source, solution_build, work)
        build_student_tests(student_build, jobs)
        executable = student_executable(solution_build, solution_executable, student_build)
        run = run_test(executable, plant.exercise, student_build, timeout)
        others = [p.expect for p in plants if p.exercise == plant.exercise and p is not plant and p.expect in run.output]
        if run.passed:
            verdict = "VIOLATION: the test passes"
            violations.append(f"{plant.exercise}: the planted mistake '{plant.mistake}' passes its grading test")
        elif plant.expect not in run.output:
            verdict = "VIOLATION: not named"
            violations.append(f"{plant.exercise}: the planted mistake '{plant.mistake}' fails, but the output does not "
                              f"name it ('{plant.expect}')")
        elif others:
            verdict = "VIOLATION: named wrongly too"
            violations.append(f"{plant.exercise}: the planted mistake '{plant.mistake}' is also named as {others}")
        else:
            verdict = "named"
        rows.append((plant.exercise, plant.mistake, verdict))
    if rows:
        width = max(len(r[0]) for r in rows) + 2
        mistake_width = max(len(r[1]) for r in rows) + 2
        print()
        print(f"{'exercise':{width}}{'planted mistake':{mistake_width}}detector")
        for exercise, mistake, verdict in rows:
            print(f"{exercise:{width}}{mistake:{mistake_width}}{verdict}")
    return violations


# --- The proof --------------------------------------------------------------------------------

def match_tests_to_regions(regions: list[exercises.Region], tests: list[str],
                           composites: dict[str, tuple[str, ...]] | None = None) -> dict[str, Proof]:
    """Step 1: one Proof per exercise or test; a region without test or test without region is a
    violation. An assignment made of regions (`composites`: its parts) has its regions in them."""
    proofs: dict[str, Proof] = {}
    composites = composites or {}
    region_at = {region.name: region for region in regions}
    for name in sorted(set(region_at) | set(tests) | set(composites)):
        proof = Proof(name, has_region=name in region_at or name in composites, has_test=name in tests,
                      parts=composites.get(name, ()))
        if not proof.has_test and proof.parts:
            proof.violations.append(f"assignment {name} has no grading test "
                                    f'(TEST_CASE("{name}", "[exercise]") in tests/exercises/)')
        elif not proof.has_test:
            proof.violations.append(f"{region_at[name].location}: exercise {name} has no grading test "
                                    f'(TEST_CASE("{name}", "[exercise]") in tests/exercises/)')
        if not proof.has_region:
            proof.violations.append(f"grading test \"{name}\" has no region "
                                    f"(`// EXERCISE({name}): ...` under chapters/)")
        proofs[name] = proof
    return proofs


def check_solution(proofs: dict[str, Proof], executable: Path, build_dir: Path, timeout: float) -> None:
    """Step 2: every grading test passes in the solution build."""
    for proof in proofs.values():
        if not proof.has_test:
            continue
        proof.solution = run_test(executable, proof.name, build_dir, timeout)
        if not proof.solution.passed:
            proof.violations.append(f"{proof.name}: fails on the solution "
                                    f"({proof.solution.describe()}):\n{tail(proof.solution.output, 15)}")


def check_stubbed(proofs: dict[str, Proof], executable: Path, build_dir: Path, timeout: float) -> list[str]:
    """Step 3: every grading test fails on the all-stubbed copy. Returns the exercises to isolate."""
    to_isolate = []
    for proof in proofs.values():
        if not (proof.has_test and proof.has_region):
            continue
        proof.stubbed = run_test(executable, proof.name, build_dir, timeout)
        if proof.stubbed.passed:
            proof.violations.append(f"{proof.name}: passes on the stub, so the test does not check the exercise")
        elif proof.parts:  # an assignment made of regions: it must reach one of its parts' stubs
            if proof.stubbed.stubs and proof.stubbed.stubs[0] not in proof.parts:
                to_isolate.append(proof.name)  # it stopped at an earlier chapter's exercise first
            elif not any(part in proof.stubbed.stubs for part in proof.parts):
                proof.violations.append(f"{proof.name}: fails on the student copy without reaching the stub of any "
                                        f"of its parts ({', '.join(proof.parts)})")
        elif proof.name not in proof.stubbed.stubs:
            to_isolate.append(proof.name)
    return to_isolate


def isolate(proofs: dict[str, Proof], names: list[str], source: Path, work: Path, solution_build: Path,
            solution_executable: Path, jobs: int, timeout: float) -> None:
    """Check each named exercise on a copy where it alone is stubbed (incremental rebuilds)."""
    student_build = student_build_dir(source, solution_build, work)
    for name in names:
        proof = proofs[name]
        if proof.parts:  # an assignment made of regions: its chapter's regions, its parts among them, stubbed
            chapter = exercises.chapter_of(name)
            print_step(f"isolating {name}: stubbing chapter {chapter}'s exercises alone")
            refresh_copy(source, work, chapter=chapter)
        else:
            print_step(f"isolating {name}: stubbing it alone")
            refresh_copy(source, work, only=name)
        build_student_tests(student_build, jobs)
        executable = student_executable(solution_build, solution_executable, student_build)
        proof.isolated = run_test(executable, name, student_build, timeout)
        if proof.isolated.passed:
            proof.violations.append(f"{name}: passes when it alone is stubbed, so the test "
                                    "does not check the exercise")
        elif proof.parts and not any(part in proof.isolated.stubs for part in proof.parts):
            proof.violations.append(f"{name}: fails with its chapter's exercises stubbed without reaching the stub "
                                    f"of any of its parts ({', '.join(proof.parts)})")


def check_prerequisites(proofs: dict[str, Proof], prerequisites: dict[str, list[str]]) -> list[str]:
    """A test that stops at another exercise's stub on the all-stubbed copy needs that exercise
    first: prerequisites.json must say so, so that students learn it before they fail."""
    violations = []
    for proof in proofs.values():
        run = proof.stubbed
        if run is None or run.passed or not run.stubs or run.stubs[0] == proof.name:
            continue
        if run.stubs[0] not in prerequisites.get(proof.name, []):
            violations.append(f"{proof.name}: its test runs {run.stubs[0]} first, which "
                              f"{exercises.PREREQUISITES_FILE.as_posix()} does not list as its prerequisite")
    return violations


def report_unisolated(proofs: dict[str, Proof], names: list[str]) -> None:
    """Without --isolate, a test that never reached its own stub is not proven."""
    for name in names:
        run = proofs[name].stubbed
        cause = f"through {run.stubs[0]}'s stub" if run.stubs else "without any stub message"
        proofs[name].violations.append(
            f"{name}: fails on the student copy only {cause}; its own stub was never reached. "
            "Make the test call its exercise first, or run with --isolate")


def format_table(proofs: dict[str, Proof]) -> str:
    """The proof as a table: exercise, solution, stub, verdict."""
    width = max([len("exercise"), *(len(name) for name in proofs)]) + 2
    stub_width = max([34, *(len(proof.stub_column()) + 2 for proof in proofs.values())])
    lines = [f"{'exercise':{width}}{'solution':10}{'stub':{stub_width}}verdict", "-" * (width + stub_width + 18)]
    for proof in proofs.values():
        solution = proof.solution.describe() if proof.solution else "-"
        checked = proof.stubbed is not None or not (proof.has_test and proof.has_region)
        verdict = "VIOLATION" if proof.violations else ("ok" if checked else "not checked")
        if not proof.has_test:
            verdict += " (no test)"
        elif not proof.has_region:
            verdict += " (no region)"
        lines.append(f"{proof.name:{width}}{solution:10}{proof.stub_column():{stub_width}}{verdict}")
    return "\n".join(lines)


def prove(args: argparse.Namespace) -> int:
    """Run the three steps; print the table and the violations. Returns the exit status."""
    source = args.source.resolve()
    build_dir = args.build_dir.resolve()
    work = (args.work or build_dir / "grading-student").resolve()
    regions = exercises.find_regions(source)
    executable = args.exercise_tests or submission.find_grading_tests(build_dir)
    if executable is None or not Path(executable).is_file():
        print(f"prove: error: no {TEST_TARGET} in {build_dir}; build it first: "
              f"cmake --build {args.build_dir} --target {TEST_TARGET}", file=sys.stderr)
        return 2
    executable = Path(executable).resolve()

    print_step(f"{len(regions)} exercise region(s) in {source}; tests from {executable}")
    composites = {a.name: a.parts for a in exercises.load_assignments(source / exercises.ASSIGNMENTS_FILE).values()
                  if a.is_composite}
    proofs = match_tests_to_regions(regions, list_tests(executable, build_dir), composites)
    print_step("running the grading tests on the solution")
    check_solution(proofs, executable, build_dir, args.test_timeout)

    problems = []
    if any(proof.has_test and proof.has_region for proof in proofs.values()):
        try:
            copy = refresh_copy(source, work)
            student_build = student_build_dir(source, build_dir, work)
            configure_student_build(copy, student_build, submission.read_cmake_cache(build_dir))
            warnings = build_student_tests(student_build, args.jobs)
            if warnings:
                # A student reads every warning as theirs: the stubs must not cause any
                # (cmake/Warnings.cmake turns off the unused-name warnings in a student copy).
                problems.append(f"the student copy compiles with {len(warnings)} warning(s), which the "
                                "student would take for their own:\n" + "\n".join(warnings[:10]))
            stubbed_executable = student_executable(build_dir, executable, student_build)
            print_step("running the grading tests on the stubs")
            to_isolate = check_stubbed(proofs, stubbed_executable, student_build, args.test_timeout)
            if to_isolate and args.isolate:
                isolate(proofs, to_isolate, source, work, build_dir, executable, args.jobs, args.test_timeout)
            else:
                report_unisolated(proofs, to_isolate)
            problems += check_prerequisites(proofs, exercises.all_prerequisites(source))
            problems += check_plants(load_plants(), regions, source, work, build_dir, executable, args.jobs,
                                     args.test_timeout)
        except RuntimeError as error:
            problems.append(str(error) + regions_named_in(str(error), work / "source", regions))

    print()
    print(format_table(proofs))
    violations = problems + [violation for proof in proofs.values() for violation in proof.violations]
    print()
    if violations:
        for violation in violations:
            print(f"violation: {violation}")
        print(f"\n{len(violations)} violation(s): the grading scheme is not proven")
        return 1
    print(f"proven: all {len(proofs)} grading test(s) pass on their solution and fail on their stub")
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description="Prove that every grading test fails on its stub and passes on its solution.")
    parser.add_argument("--source", type=Path, default=exercises.repository_root(),
                        help="the repository with the solutions (default: the one holding this script)")
    parser.add_argument("--build-dir", type=Path, required=True,
                        help="the solution build folder, with exercise_tests built")
    parser.add_argument("--exercise-tests", type=Path, metavar="PATH",
                        help="the exercise_tests executable (default: found in --build-dir)")
    parser.add_argument("--work", type=Path, metavar="DIR",
                        help="where the student copy and its build go (default: BUILD_DIR/grading-student)")
    parser.add_argument("--jobs", type=int, default=2, help="parallel build jobs (default 2)")
    parser.add_argument("--test-timeout", type=float, default=300, metavar="SECONDS",
                        help="time limit for one grading test (default 300)")
    parser.add_argument("--isolate", action="store_true",
                        help="re-check, with it alone stubbed, an exercise whose test failed only "
                             "through another exercise's stub")
    args = parser.parse_args(argv)
    if not args.build_dir.is_dir():
        parser.error(f"build folder {args.build_dir} does not exist")
    try:
        return prove(args)
    except exercises.MarkerError as error:
        print(error, file=sys.stderr)
        print("prove: error: the exercise markers are not well formed", file=sys.stderr)
        return 1
    except RuntimeError as error:
        print(f"prove: error: {error}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
