#!/usr/bin/env python3
"""End-to-end tests of grade.py on a tiny CMake project (configured and built for real, in a
temporary folder): teacher mode ignores a submission's weakened test and edited points; a
hang costs one exercise; a stale binary is refused with --no-build; the CSV and JSON carry the
gradebook's fields; --batch grades several submissions in one work folder.

    python3 tests/grading/test_teacher_mode.py      (needs cmake and a C++ compiler; ~30 s)
"""

from __future__ import annotations

import csv
import io
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

sys.dont_write_bytecode = True
HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import exercises  # noqa: E402
import grade  # noqa: E402
import make_student_copy  # noqa: E402
import submission  # noqa: E402
from test_grading_tools import ERROR_HPP, write_tree  # noqa: E402  (the synthetic trees' helpers)

WARPS_HPP = """\
#pragma once
#include "freezeray/error.hpp"
namespace freezeray {
int twice(int x);
int four_times(int x);
int settle(int x);
}
"""

WARPS_CPP = """\
#include "freezeray/ch01/warps.hpp"

namespace freezeray {

int twice(int x) {
    // EXERCISE(ch01/twice): return twice x
    return x + x;
    // END EXERCISE
}

int four_times(int x) {
    // EXERCISE(ch01/four-times): return four times x
    return 4 * x;
    // END EXERCISE
}

int settle(int x) {
    // EXERCISE(ch01/settle): return x
    return x;
    // END EXERCISE
}

}  // namespace freezeray
"""

# A stand-in for Catch2: runs the named check, prints a failure the way Catch2 does.
GRADING_TESTS = """\
#include "freezeray/ch01/warps.hpp"
#include <cstdio>
#include <exception>
#include <string>
using namespace freezeray;
static int check(const char* text, int got, int expected) {
    if (got == expected) return 0;
    std::printf("tests/exercises/exercises.cpp:9: FAILED:\\n  CHECK( %s )\\nwith expansion:\\n  %d == %d\\n", text, got, expected);
    return 1;
}
int main(int, char** argv) {
    const std::string name = argv[1];
    try {
        if (name == "ch01/twice") return check("twice(2) == 4", twice(2), 4);
        if (name == "ch01/four-times") return check("four_times(2) == 8", four_times(2), 8);
        if (name == "ch01/settle") return check("settle(3) == 3", settle(3), 3);
    } catch (const std::exception& e) {
        std::printf("due to unexpected exception with message:\\n  %s\\n", e.what());
        return 1;
    }
    return 2;
}
"""

CMAKE = """\
cmake_minimum_required(VERSION 3.16)
project(Tiny CXX)
option(FREEZERAY_WERROR "" OFF)
enable_testing()
add_library(course chapters/01-naive/src/warps.cpp)
target_include_directories(course PUBLIC common/core/include chapters/01-naive/include)
add_executable(exercise_tests tests/exercises/exercises.cpp)
target_link_libraries(exercise_tests course)
foreach(name twice four-times settle)
  add_test(NAME "exercise:ch01/${name}" COMMAND exercise_tests ch01/${name})
  set_tests_properties("exercise:ch01/${name}" PROPERTIES LABELS exercise TIMEOUT 3)
endforeach()
"""

POINTS = '{"default_points": 1, "points": {"ch01/four-times": 2}}\n'


def teacher_tree(root: Path) -> None:
    write_tree(root, {
        "CMakeLists.txt": CMAKE,
        "common/core/include/freezeray/error.hpp": ERROR_HPP,
        "chapters/01-naive/include/freezeray/ch01/warps.hpp": WARPS_HPP,
        "chapters/01-naive/src/warps.cpp": WARPS_CPP,
        "tests/exercises/exercises.cpp": GRADING_TESTS,
        "tests/grading/points.json": POINTS,
    })


def cheating_submission(root: Path) -> None:
    """Two planted mistakes (twice off by one, settle never returns), four-times' markers removed,
    and the grading tests and points edited in the student's favour."""
    teacher_tree(root)
    text = WARPS_CPP.replace("return x + x;", "return x + x + 1;")
    text = text.replace("    // EXERCISE(ch01/settle): return x\n    return x;",
                        "    // EXERCISE(ch01/settle): return x\n    for (volatile int i = 0;; i = i + 1) {}\n    return x;")
    text = text.replace("    // EXERCISE(ch01/four-times): return four times x\n", "")
    text = text.replace("    return 4 * x;\n    // END EXERCISE\n", "    return 4 * x;\n", 1)
    write_tree(root, {
        "chapters/01-naive/src/warps.cpp": text,
        "tests/exercises/exercises.cpp": "int main() { return 0; }\n",  # every test passes
        "tests/grading/points.json": '{"default_points": 100, "points": {}}\n',
    })


def run_grade(arguments: list[str]) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        status = grade.main(arguments)
    return status, out.getvalue(), err.getvalue()


@unittest.skipUnless(shutil.which("cmake") and shutil.which("ctest"), "needs cmake and ctest")
class TeacherMode(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory(prefix="freezeray-teacher-test-")
        self.root = Path(self.folder.name)
        self.teacher = self.root / "teacher"
        teacher_tree(self.teacher)

    def tearDown(self):
        self.folder.cleanup()

    def results(self, json_file: Path) -> dict[str, dict]:
        return {row["exercise"]: row for row in json.loads(json_file.read_text())["exercises"]}

    def test_the_teachers_tests_grade_the_students_regions(self):
        cheat = self.root / "submissions" / "alice"
        cheating_submission(cheat)
        good = self.root / "submissions" / "bob"
        teacher_tree(good)
        work = self.root / "work"

        # Graded in its own build, the weakened tests pass everything: the weakening is real.
        own_build = self.root / "alice-build"
        self.assertEqual(os.system(f"cmake -S {cheat} -B {own_build} >/dev/null 2>&1"), 0)
        status, out, _ = run_grade(["--build-dir", str(own_build), "--quiet"])
        self.assertEqual(status, 0)
        self.assertIn("(3 of 3 exercises pass)", out)

        # Teacher mode: the teacher's tests and points; a hang costs one exercise.
        report = self.root / "alice.json"
        table = self.root / "alice.csv"
        status, out, err = run_grade(["--teacher-tests", str(self.teacher), "--submission", str(cheat),
                                      "--build-dir", str(work), "--student", "alice", "--json", str(report),
                                      "--csv", str(table), "--quiet"])
        self.assertEqual(status, 0, err)
        rows = self.results(report)
        self.assertEqual(rows["ch01/twice"]["result"], "FAIL (wrong result)")
        self.assertEqual(rows["ch01/twice"]["reason"], "5 == 4")
        self.assertEqual(rows["ch01/settle"]["result"], "FAIL (timed out)")
        self.assertEqual(rows["ch01/four-times"]["result"], "FAIL (not implemented)")
        self.assertEqual([rows[n]["points"] for n in sorted(rows)], [2, 1, 1])  # the teacher's points.json
        data = json.loads(report.read_text())
        self.assertEqual(data["student"], "alice")
        self.assertRegex(data["source_hash"], r"^[0-9a-f]{64}$")
        self.assertEqual(data["chapters"]["ch01"], {"earned": 0, "possible": 4})
        self.assertIn("ch01/four-times", " ".join(data["notes"]))
        self.assertIn("ch01/twice", out)
        self.assertIn("5 == 4", out)  # the reason is in the table too
        with table.open() as file:
            lines = list(csv.DictReader(file))
        self.assertEqual(list(lines[0]), grade.CSV_COLUMNS)
        self.assertEqual({line["student"] for line in lines}, {"alice"})
        self.assertEqual([line["kind"] for line in lines], ["exercise"] * 3 + ["chapter", "overall"])

        # A correct submission in the same work folder: everything passes, another hash.
        status, out, err = run_grade(["--teacher-tests", str(self.teacher), "--submission", str(good),
                                      "--build-dir", str(work), "--student", "bob", "--json", str(report), "--quiet"])
        self.assertEqual(status, 0, err)
        self.assertEqual({row["result"] for row in self.results(report).values()}, {"pass"})
        self.assertNotEqual(json.loads(report.read_text())["source_hash"], data["source_hash"])

        # --batch: the three of them (carol's code does not compile), one CSV, the gradebook to hand
        # back, a feedback file each and the class summary.
        carol = self.root / "submissions" / "carol"
        teacher_tree(carol)
        (carol / "chapters/01-naive/src/warps.cpp").write_text(WARPS_CPP.replace("return x + x;", "return x + ;"))
        table = self.root / "grades.csv"
        book = self.root / "gradebook.csv"
        feedback = self.root / "feedback"
        status, out, err = run_grade(["--teacher-tests", str(self.teacher), "--batch", str(self.root / "submissions"),
                                      "--build-dir", str(work), "--csv", str(table), "--gradebook", str(book),
                                      "--feedback", str(feedback), "--quiet"])
        self.assertEqual(status, 0, err)
        with table.open() as file:
            overall = {line["student"]: line["earned"] for line in csv.DictReader(file) if line["kind"] == "overall"}
        self.assertEqual(overall, {"alice": "0", "bob": "4", "carol": "0"})
        with book.open() as file:
            wide = {line["student"]: line for line in csv.DictReader(file)}
        self.assertEqual(sorted(wide), ["alice", "bob", "carol"])
        self.assertEqual([wide["bob"][n] for n in ("ch01/four-times", "ch01/settle", "ch01/twice")], ["2", "1", "1"])
        self.assertEqual((wide["bob"]["ch01 total"], wide["bob"]["total"], wide["bob"]["percent"]), ("4", "4", "100%"))
        self.assertEqual(wide["carol"]["build"], "does not compile")
        self.assertEqual(wide["alice"]["build"], "ok")
        self.assertEqual(sorted(p.name for p in feedback.iterdir()), ["alice.txt", "bob.txt", "carol.txt"])
        self.assertIn("5 == 4", (feedback / "alice.txt").read_text())
        self.assertIn("--verbose", (feedback / "alice.txt").read_text())
        self.assertIn("error:", (feedback / "carol.txt").read_text())  # the compiler's own words
        self.assertIn("class: 3 students", out)
        self.assertIn("1 did not compile: carol", out)
        self.assertIn("ch01/twice", out.split("pass rate per exercise")[1])

    def test_a_stale_binary_is_refused_and_a_normal_run_rebuilds(self):
        build = self.root / "build"
        self.assertEqual(os.system(f"cmake -S {self.teacher} -B {build} >/dev/null 2>&1"), 0)
        status, out, err = run_grade(["--build-dir", str(build), "--quiet"])
        self.assertEqual(status, 0, err)
        self.assertIn("(3 of 3 exercises pass)", out)
        # A mistake made after the build: --no-build refuses to grade the old binary.
        source = self.teacher / "chapters/01-naive/src/warps.cpp"
        time.sleep(1.1)  # a later modification time than the binary's, on any file system
        source.write_text(WARPS_CPP.replace("return 4 * x;", "return 3 * x;"))
        status, out, err = run_grade(["--build-dir", str(build), "--no-build", "--quiet"])
        self.assertEqual(status, 2)
        self.assertIn("older than its sources", err)
        self.assertIn("chapters/01-naive/src/warps.cpp", err)
        # Without --no-build it builds first and grades what the sources say.
        status, out, err = run_grade(["--build-dir", str(build), "--only", "ch01/four-times", "--quiet"])
        self.assertEqual(status, 0, err)
        self.assertIn("FAIL (wrong result): 6 == 8", out)
        self.assertNotIn("ch01/twice", out)
        # Code that does not compile is a grade of zero with the compiler's first error, not a crash.
        source.write_text(WARPS_CPP.replace("return x + x;", "return x + ;"))
        status, out, err = run_grade(["--build-dir", str(build), "--quiet"])
        self.assertEqual(status, 0, err)
        self.assertIn("FAIL (does not compile)", out)
        self.assertIn("error", out)


REPOSITORY = HERE.parent.parent


class OwnExercises(unittest.TestCase):
    """Teacher mode on this repository's own exercises, as a class hands them in: a student copy
    with some regions solved and the rest left as their stubs (which the student copy gave with an
    include outside the region, which teacher mode does not take)."""

    def test_every_stubbed_file_of_the_graded_tree_includes_what_its_stub_needs(self):
        regions = exercises.find_regions(REPOSITORY)
        self.assertGreater(len(regions), 20)
        with tempfile.TemporaryDirectory() as temporary:
            student = Path(temporary) / "student"
            make_student_copy.make_student_copy(REPOSITORY, student)
            # The student solves chapter 06's exercises (the teacher's bodies) and leaves the rest.
            solved = [r for r in regions if r.name.startswith("ch06/")]
            self.assertTrue(solved)
            for path in {r.path for r in solved}:
                (student / path).write_bytes((REPOSITORY / path).read_bytes())
            graded = submission.assemble_graded_tree(REPOSITORY, student, Path(temporary) / "graded")
            self.assertEqual(set(graded.taken), {r.name for r in regions})  # every region is there, stubbed or solved
            roots = make_student_copy.include_roots(graded.source)
            stubbed = sorted({r.path for r in regions if not r.name.startswith("ch06/")})
            lacking = [p.as_posix() for p in stubbed
                       if submission.STUB_CALL in (graded.source / p).read_text(encoding="utf-8")
                       and not make_student_copy.includes_error_header((graded.source / p).resolve(), roots)]
            self.assertEqual(lacking, [], "stubbed files that would not compile: ExerciseNotImplemented undeclared")
            # And they compile: the stubbed files whose own sources do not include the header.
            compiler = shutil.which("g++") or shutil.which("c++")
            if compiler is None:
                self.skipTest("no C++ compiler")
            needing = [p for p in stubbed if p.suffix == ".cpp" and not make_student_copy.includes_error_header(
                (REPOSITORY / p).resolve(), make_student_copy.include_roots(REPOSITORY))][:2]
            self.assertTrue(needing, "no exercise file lacks the header of its own: the check above proves nothing")
            includes = [f"-I{folder}" for folder in roots]
            for path in needing:
                result = subprocess.run([compiler, "-std=c++20", "-fsyntax-only", "-DGLM_ENABLE_EXPERIMENTAL", *includes,
                                         str(graded.source / path)], capture_output=True, text=True)
                self.assertEqual(result.returncode, 0, f"{path}: {submission.first_error(result.stderr)}")


@unittest.skipUnless(shutil.which("cmake") and shutil.which("ccache"), "needs cmake and ccache")
class StudentBuildThroughTheCache(unittest.TestCase):
    """The grading proof builds its student copy through the compiler cache at the same place
    within the copy as the solution's build (prove_exercises.student_build_dir): only the files
    the stubs change are compiled. An object is keyed by everything it was compiled from, so a
    stub cannot hide behind the solution's object; and if a stale object were ever used, the
    proof's own check (every stub reached) fails, as planting one here shows."""

    def test_only_stubbed_files_compile_and_a_stale_object_would_be_caught(self):
        import prove_exercises  # noqa: E402  (beside this script)
        with tempfile.TemporaryDirectory(prefix="freezeray-cache-test-") as temporary:
            root = Path(temporary)
            solution = root / "solution"
            teacher_tree(solution)
            cmake = CMAKE.replace("enable_testing()", f"include({REPOSITORY}/cmake/CompilerCache.cmake)\nenable_testing()")
            (solution / "CMakeLists.txt").write_text(cmake)
            environment = dict(os.environ, CCACHE_DIR=str(root / "cache"))

            def run(command: list[str]) -> str:
                result = subprocess.run(command, capture_output=True, text=True, env=environment)
                self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
                return result.stdout

            solution_build = solution / "build"
            run(["cmake", "-S", str(solution), "-B", str(solution_build)])
            run(["cmake", "--build", str(solution_build)])
            run(["ccache", "--zero-stats"])

            work = root / "work"
            copy = prove_exercises.refresh_copy(solution, work)
            student_build = prove_exercises.student_build_dir(solution, solution_build, work)
            self.assertEqual(student_build, work / "source" / "build")
            run(["cmake", "-S", str(copy), "-B", str(student_build)])
            run(["cmake", "--build", str(student_build)])
            stats = dict(line.split("\t") for line in run(["ccache", "--print-stats"]).splitlines() if "\t" in line)
            self.assertEqual(int(stats["direct_cache_hit"]), 1, stats)  # the grading tests' file: unchanged
            self.assertEqual(int(stats["cache_miss"]), 1, stats)        # warps.cpp, whose regions are stubs

            executable = student_build / "exercise_tests"
            def stub_reached(name: str) -> bool:
                result = subprocess.run([str(executable), name], capture_output=True, text=True)
                return result.returncode != 0 and name in prove_exercises.stubs_in(result.stdout + result.stderr)
            names = ["ch01/twice", "ch01/four-times", "ch01/settle"]
            self.assertTrue(all(stub_reached(name) for name in names))

            # Break it on purpose: the solution's object over the student's, newer than its source.
            objects = list(solution_build.rglob("warps.cpp.o"))
            self.assertEqual(len(objects), 1)
            stale = student_build / objects[0].relative_to(solution_build)
            shutil.copy2(objects[0], stale)
            later = time.time() + 5
            os.utime(stale, (later, later))
            run(["cmake", "--build", str(student_build)])
            self.assertFalse(any(stub_reached(name) for name in names),
                             "with the solution's object the stubs pass: the proof's check would fail")


class BuildFailureReason(unittest.TestCase):
    """The reason shown for a failed build is the compiler's first error, not a progress line."""

    def test_a_progress_line_naming_error_cpp_is_not_the_reason(self):
        log = ("[  5%] Building CXX object common/CMakeFiles/freezeray_core.dir/core/src/error.cpp.o\n"
               "[ 40%] Building CXX object chapters/06-kd-tree/CMakeFiles/x.dir/src/kdtree_build.cpp.o\n"
               "/work/chapters/06-kd-tree/src/kdtree_build.cpp:42:5: error: 'sah' was not declared in this scope\n"
               "gmake[2]: *** [x] Error 1\n")
        self.assertEqual(submission.first_error(log),
                         "/work/chapters/06-kd-tree/src/kdtree_build.cpp:42:5: error: 'sah' was not declared in this scope")

    def test_cmake_and_linker_errors_are_named(self):
        self.assertIn("does not exist", submission.first_error("CMake Error at CMakeLists.txt:3 (add_subdirectory):\n"
                                                               "  The source directory ... does not exist.\n"))
        self.assertIn("undefined reference", submission.first_error(
            "[ 90%] Linking CXX executable ch06\n/usr/bin/ld: a.o: undefined reference to `f()'\n"))
        self.assertEqual(submission.first_error("[  5%] Building CXX object error.cpp.o\n"), "the build failed (see the log)")


if __name__ == "__main__":
    unittest.main()
