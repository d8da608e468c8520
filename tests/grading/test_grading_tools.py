#!/usr/bin/env python3
"""Unit tests of the grading scripts, on tiny synthetic trees in temporary folders.

    python3 tests/grading/test_grading_tools.py        (or: python3 -m unittest ...)
"""

from __future__ import annotations

import io
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import textwrap
import unittest
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

sys.dont_write_bytecode = True
HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import assignment_report  # noqa: E402
import exercises  # noqa: E402
import grade  # noqa: E402
import make_references  # noqa: E402
import make_student_copy  # noqa: E402
import prove_exercises  # noqa: E402
import submission  # noqa: E402

# A stand-in for common/core/include/freezeray/error.hpp, with its message (grade.py recognises
# "exercise NAME is not implemented"); test_teacher_mode.py compiles it.
ERROR_HPP = """\
#pragma once
#include <stdexcept>
#include <string>
namespace freezeray {
class ExerciseNotImplemented : public std::logic_error {
public:
    explicit ExerciseNotImplemented(const std::string& name)
        : std::logic_error("exercise " + name + " is not implemented yet") {}
};
}
"""

WARPS_HPP = """\
#pragma once
#include "freezeray/error.hpp"
namespace freezeray {
double twice(double x);
}
"""

# Includes error.hpp through warps.hpp: needs no extra include.
WARPS_CPP = """\
#include "freezeray/ch01/warps.hpp"

namespace freezeray {

double twice(double x) {
    // EXERCISE(ch01/twice): return twice x
    double result = x + x;
    return result;
    // END EXERCISE
}

}  // namespace freezeray
"""

# Includes nothing that brings error.hpp: gets the include after its last #include.
ESTIMATOR_CPP = """\
#include <cmath>
#include <vector>

namespace freezeray {

double four_times(double x) {
    // EXERCISE(ch01/four-times): return four times x
    return 4 * x;
    // END EXERCISE
}

}  // namespace freezeray
"""

CHAPTER_02_CPP = """\
#include "freezeray/ch01/warps.hpp"

namespace freezeray {

float mirror(float x) {
    float y = x;
    // EXERCISE(ch02/mirror): return minus y
    return -y;
    // END EXERCISE
}

}  // namespace freezeray
"""

GRADING_TESTS = """\
#include <catch2/catch.hpp>
TEST_CASE("ch01/twice", "[exercise]") {}
TEST_CASE("ch01/four-times", "[exercise]") {}
TEST_CASE( "ch02/mirror", "[exercise]") {}
"""


def write_tree(root: Path, files: dict[str, str]) -> None:
    """Create each file (path relative to root) with its text."""
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")


def synthetic_tree(root: Path) -> None:
    """A tiny FreezeRay-like tree with three exercises in two chapters."""
    write_tree(root, {
        "CMakeLists.txt": "project(Tiny)\n",
        "common/core/include/freezeray/error.hpp": ERROR_HPP,
        "chapters/01-naive/include/freezeray/ch01/warps.hpp": WARPS_HPP,
        "chapters/01-naive/src/warps.cpp": WARPS_CPP,
        "chapters/01-naive/src/estimator.cpp": ESTIMATOR_CPP,
        "chapters/02-importance/src/mirror.cpp": CHAPTER_02_CPP,
        "tests/exercises/exercises.cpp": GRADING_TESTS,
        "tests/grading/points.json": '{"default_points": 1, "points": {"ch02/mirror": 3}}\n',
        "build/CMakeCache.txt": "CMAKE_GENERATOR:INTERNAL=Ninja\n",
        "build/huge.o": "object code",
    })


class TreeTestCase(unittest.TestCase):
    """A test with a fresh synthetic tree in self.root."""

    def setUp(self):
        self.folder = tempfile.TemporaryDirectory(prefix="freezeray-grading-test-")
        self.root = Path(self.folder.name) / "repo"
        synthetic_tree(self.root)

    def tearDown(self):
        self.folder.cleanup()

    def copy(self, *options: str) -> Path:
        """Run make_student_copy.py's main on the tree; return the destination."""
        destination = Path(self.folder.name) / "student"
        with redirect_stdout(io.StringIO()):
            status = make_student_copy.main([str(self.root), str(destination), *options])
        self.assertEqual(status, 0)
        return destination


class FindingRegions(TreeTestCase):
    def test_finds_every_region_with_its_lines_and_description(self):
        regions = {region.name: region for region in exercises.find_regions(self.root)}
        self.assertEqual(sorted(regions), ["ch01/four-times", "ch01/twice", "ch02/mirror"])
        twice = regions["ch01/twice"]
        self.assertEqual(twice.path, Path("chapters/01-naive/src/warps.cpp"))
        self.assertEqual((twice.start, twice.end), (6, 9))
        self.assertEqual(twice.chapter, "ch01")
        self.assertEqual(twice.description, "return twice x")
        self.assertEqual(twice.indent, "    ")

    def test_the_synthetic_tree_passes_the_check(self):
        self.assertEqual(exercises.check_tree(self.root), [])
        with redirect_stdout(io.StringIO()) as output:
            self.assertEqual(exercises.main(["--root", str(self.root), "--check"]), 0)
        self.assertIn("3 exercise region(s) in 3 file(s)", output.getvalue())


class MalformedMarkers(unittest.TestCase):
    """Each mistake is reported with the file and line where it is."""

    def problems(self, body: str, path: str = "chapters/01-naive/src/bad.cpp") -> list[str]:
        return exercises.parse_file(textwrap.dedent(body), Path(path))[1]

    def assert_reported(self, problems: list[str], location: str, words: str):
        self.assertTrue(any(p.startswith(location) and words in p for p in problems),
                        f"expected '{location}: ...{words}...' in {problems}")

    def test_malformed_name(self):
        problems = self.problems("""\
            void f() {
                // EXERCISE(chapter1/Bad_Name): something
                // END EXERCISE
            }
            """)
        self.assert_reported(problems, "chapters/01-naive/src/bad.cpp:2:", "malformed exercise name 'chapter1/Bad_Name'")

    def test_missing_colon_or_description(self):
        self.assert_reported(self.problems("// EXERCISE(ch01/a) no colon\n// END EXERCISE\n"),
                             "chapters/01-naive/src/bad.cpp:1:", "malformed EXERCISE marker")
        self.assert_reported(self.problems("// EXERCISE(ch01/a):\nx;\n// END EXERCISE\n"),
                             "chapters/01-naive/src/bad.cpp:1:", "no description")

    def test_end_without_start(self):
        self.assert_reported(self.problems("int x;\n// END EXERCISE\n"),
                             "chapters/01-naive/src/bad.cpp:2:", "without a matching EXERCISE")

    def test_start_never_closed(self):
        self.assert_reported(self.problems("// EXERCISE(ch01/a): do it\nint x;\n"),
                             "chapters/01-naive/src/bad.cpp:1:", "never closed")

    def test_nested_regions(self):
        problems = self.problems("""\
            // EXERCISE(ch01/outer): outer
            // EXERCISE(ch01/inner): inner
            x;
            // END EXERCISE
            // END EXERCISE
            """)
        self.assert_reported(problems, "chapters/01-naive/src/bad.cpp:2:", "nested inside EXERCISE ch01/outer")

    def test_marker_after_code(self):
        self.assert_reported(self.problems("x = 1;  // EXERCISE(ch01/a): do it\n"),
                             "chapters/01-naive/src/bad.cpp:1:", "malformed EXERCISE marker")
        self.assert_reported(self.problems("// EXERCISE(ch01/a): do it\nx;\n}  // END EXERCISE\n"),
                             "chapters/01-naive/src/bad.cpp:3:", "malformed END EXERCISE marker")

    def test_empty_region(self):
        self.assert_reported(self.problems("// EXERCISE(ch01/a): do it\n// END EXERCISE\n"),
                             "chapters/01-naive/src/bad.cpp:1:", "is empty")

    def test_chapter_must_match_the_chapter_folder(self):
        problems = self.problems("// EXERCISE(ch02/a): do it\nx;\n// END EXERCISE\n",
                                 path="chapters/01-naive/src/a.cpp")
        self.assert_reported(problems, "chapters/01-naive/src/a.cpp:1:", "chapter 01's folder")


class CheckingTheTree(TreeTestCase):
    def test_duplicate_names_name_both_places(self):
        write_tree(self.root, {"chapters/01-naive/src/again.cpp":
                               "void g() {\n    // EXERCISE(ch01/twice): again\n    x;\n    // END EXERCISE\n}\n"})
        problems = exercises.check_tree(self.root)
        self.assertTrue(any("duplicate exercise name ch01/twice" in p and "chapters/01-naive/src/again.cpp:2" in p
                            and "chapters/01-naive/src/warps.cpp:6" in p for p in problems), problems)
        with self.assertRaises(exercises.MarkerError):
            exercises.find_regions(self.root)

    def test_region_without_test_and_test_without_region(self):
        write_tree(self.root, {"tests/exercises/more.cpp": 'TEST_CASE("ch01/ghost", "[exercise]") {}\n'})
        (self.root / "tests/exercises/exercises.cpp").write_text(
            GRADING_TESTS.replace('TEST_CASE("ch01/twice", "[exercise]") {}\n', ""))
        problems = exercises.check_tree(self.root)
        self.assertTrue(any(p.startswith("chapters/01-naive/src/warps.cpp:6:") and "no grading test" in p for p in problems))
        self.assertTrue(any(p.startswith("tests/exercises/more.cpp:1:") and "ch01/ghost" in p for p in problems))

    def test_points_for_an_unknown_exercise(self):
        (self.root / "tests/grading/points.json").write_text('{"points": {"ch09/nothing": 2}}')
        problems = exercises.check_tree(self.root)
        self.assertTrue(any("ch09/nothing" in p for p in problems), problems)

    def test_prerequisites_name_real_exercises_and_order_the_list(self):
        write_tree(self.root, {"tests/grading/prerequisites.json":
                               '{"prerequisites": {"ch01/four-times": ["ch01/twice"], "ch02/mirror": ["ch09/none"]}}'})
        problems = exercises.check_tree(self.root)
        self.assertEqual([p for p in problems if "prerequisites" in p],
                         ["tests/grading/prerequisites.json: ch09/none is not an exercise"])
        listing = grade.format_exercise_list(self.root, None, None)
        names = [line.split()[0] for line in listing.splitlines() if not line.startswith(" ")]
        self.assertEqual(names, ["ch01/twice", "ch01/four-times", "ch02/mirror"])  # twice moved before four-times
        self.assertIn("ch01/four-times  [1 point]  (first: ch01/twice)", listing)
        self.assertIn("ch02/mirror  [3 points]", listing)

    def test_a_region_outside_its_chapter_folder_is_reported(self):
        region = "// EXERCISE(ch01/elsewhere): return x\nreturn x;\n// END EXERCISE\n"
        write_tree(self.root, {"common/src/shared.cpp": region,
                               "chapters/02-importance/src/misplaced.cpp": region.replace("elsewhere", "misplaced")})
        problems = exercises.check_tree(self.root)
        self.assertTrue(any(p.startswith("common/src/shared.cpp:1:") and "outside chapters/" in p for p in problems),
                        problems)
        self.assertTrue(any(p.startswith("chapters/02-importance/src/misplaced.cpp:1:") and "chapter 02's folder" in p
                            for p in problems), problems)

    def test_check_exit_status_and_messages(self):
        write_tree(self.root, {"chapters/01-naive/src/broken.cpp": "// END EXERCISE\n"})
        with redirect_stderr(io.StringIO()) as errors:
            self.assertEqual(exercises.main(["--root", str(self.root)]), 1)
        self.assertIn("chapters/01-naive/src/broken.cpp:1:", errors.getvalue())


class Assignments(TreeTestCase):
    """assignments.json: composite assignments (a test of their own, parts of their chapter) and
    whole-feature regions."""

    def write_assignments(self, table: str) -> None:
        write_tree(self.root, {"tests/grading/assignments.json": '{"assignments": ' + table + '}'})

    def test_a_composite_assignment_needs_its_test_and_real_parts(self):
        self.write_assignments('{"ch01/tiny-renderer": {"title": "t", "parts": ["ch01/twice", "ch01/four-times"]}}')
        problems = exercises.check_tree(self.root)
        self.assertEqual(len(problems), 1, problems)
        self.assertIn('assignment ch01/tiny-renderer has no grading test', problems[0])
        write_tree(self.root, {"tests/exercises/more.cpp": 'TEST_CASE("ch01/tiny-renderer", "[exercise]") {}\n',
                               "tests/grading/points.json": '{"points": {"ch01/tiny-renderer": 2}}'})
        self.assertEqual(exercises.check_tree(self.root), [])
        self.write_assignments('{"ch01/tiny-renderer": {"parts": ["ch01/twice", "ch02/mirror", "ch01/none"]}}')
        problems = "\n".join(exercises.check_tree(self.root))
        self.assertIn("part ch02/mirror belongs to another chapter", problems)
        self.assertIn("part ch01/none is not an exercise", problems)

    def test_a_region_assignment_must_be_a_region_and_a_composite_must_not(self):
        self.write_assignments('{"ch02/mirror": {"parts": ["ch02/mirror"]}, "ch01/ghost": {"parts": ["ch01/ghost"]},'
                               ' "ch01/twice": {"parts": ["ch01/twice", "ch01/four-times"]}}')
        problems = "\n".join(exercises.check_tree(self.root))
        self.assertIn("ch01/ghost is neither an exercise region nor made of parts", problems)
        self.assertIn("ch01/twice is both an exercise region and an assignment made of other regions", problems)
        self.assertNotIn("ch02/mirror", problems)

    def test_malformed_assignments_are_reported(self):
        self.write_assignments('{"ch01/x": {"parts": []}}')
        self.assertTrue(any("non-empty list 'parts'" in p for p in exercises.check_tree(self.root)))

    def test_the_list_puts_a_composite_after_its_parts(self):
        self.write_assignments('{"ch01/tiny-renderer": {"title": "A tiny renderer", "parts": ["ch01/four-times", '
                               '"ch01/twice"], "book": "book/01.md"}, "ch02/mirror": {"title": "Mirrors", '
                               '"parts": ["ch02/mirror"]}}')
        write_tree(self.root, {"tests/exercises/more.cpp": 'TEST_CASE("ch01/tiny-renderer", "[exercise]") {}\n'})
        listing = grade.format_exercise_list(self.root, None, None)
        names = [line.split()[0] for line in listing.splitlines() if not line.startswith(" ")]
        self.assertEqual(names, ["ch01/four-times", "ch01/twice", "ch01/tiny-renderer", "ch02/mirror"])
        self.assertIn("ch01/tiny-renderer  [1 point]  (first: ch01/four-times, ch01/twice)", listing)
        self.assertIn("assignment, made of the exercises above: A tiny renderer (book/01.md)", listing)
        self.assertIn("assignment, a whole feature in one region: Mirrors", listing)
        self.assertNotIn("tiny-renderer", grade.format_exercise_list(self.root, "ch02", None))
        self.assertEqual(exercises.all_prerequisites(self.root)["ch01/tiny-renderer"], ["ch01/four-times", "ch01/twice"])


class References(unittest.TestCase):
    def test_reads_a_pfm_top_row_first_and_averages_blocks(self):
        with tempfile.TemporaryDirectory() as folder:
            path = Path(folder) / "a.pfm"
            # 2 x 2, little-endian (negative scale), bottom row first: bottom (1, 2), top (3, 4)
            pixels = [1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4]
            path.write_bytes(b"PF\n2 2\n-1.0\n" + b"".join(struct.pack("<f", v) for v in pixels))
            width, height, read = make_references.read_pfm(path)
        self.assertEqual((width, height), (2, 2))
        self.assertEqual([p[0] for p in read], [3, 4, 1, 2])
        self.assertEqual(make_references.block_means(2, 2, read, (2, 1)), [[2.0] * 3, [3.0] * 3])
        self.assertEqual(make_references.block_means(2, 2, read, (1, 1)), [[2.5] * 3])
        with self.assertRaises(RuntimeError):
            make_references.block_means(2, 2, read, (3, 1))

    def test_reference_file_names(self):
        self.assertEqual(make_references.reference_file(Path("/r"), "ch01/naive-path-tracer"),
                         Path("/r/tests/data/references/ch01-naive-path-tracer.json"))

    def test_last_relative_mse_of_a_comparison(self):
        with tempfile.TemporaryDirectory() as folder:
            (Path(folder) / "convergence.csv").write_text(
                "integrator,checkpoint,relative_mse\npt-naive,1,0.5\npt-naive,2,0.25\nbdpt,1,0.1\n")
            self.assertEqual(make_references.last_relative_mse(Path(folder), "pt-naive"), 0.25)
            with self.assertRaises(RuntimeError):
                make_references.last_relative_mse(Path(folder), "mlt")


class AssignmentReports(unittest.TestCase):
    def test_verdicts(self):
        self.assertIn("is about the solution's", assignment_report.verdict_of(0.02, 0.02, ""))
        self.assertIn("3.0 times the solution's", assignment_report.verdict_of(0.06, 0.02, ""))
        # a bias shows in the mean brightness even when noise hides it pixel by pixel
        reference = [0.5, 0.5, 0.5]
        self.assertIn("as the solution's is", assignment_report.brightness_sentence([0.505] * 3, [0.498] * 3, reference))
        dark = assignment_report.brightness_sentence([0.45] * 3, [0.498] * 3, reference)
        self.assertIn("90.0 % of the reference's", dark)
        self.assertIn("darker than it should be", dark)
        self.assertIn("brighter", assignment_report.brightness_sentence([0.6] * 3, [0.49] * 3, reference))
        self.assertIn("as the solution's is", assignment_report.brightness_sentence([0.6] * 3, [0.45] * 3, reference))
        self.assertEqual(assignment_report.verdict_of(None, None, "the renderer stopped: x"),
                         "No image: the renderer stopped: x")

    def test_the_template_has_every_placeholder_filled(self):
        values = {key: "X" for key in ("title", "name", "grade", "verdict", "reference", "mine", "error",
                                       "has_images", "width", "height", "settings", "command", "book", "comparison")}
        page = assignment_report.fill(assignment_report.TEMPLATE.read_text(encoding="utf-8"), values)
        self.assertNotIn("{{", page)
        self.assertIn('type="range"', page)  # the slider

    def test_a_missing_reference_makes_a_page_that_says_how_to_make_it(self):
        with tempfile.TemporaryDirectory() as folder:
            root = Path(folder)
            assignment = exercises.Assignment("ch01/tiny", "Tiny", ("ch01/a", "ch01/b"), "book/01.md",
                                              {"scene": "s.json", "integrator": "pt-naive", "width": 8, "height": 8,
                                               "spp": 4}, {})
            made = assignment_report.make_one(assignment, root / "build", root, root / "refs", root / "report",
                                              "0/2 FAIL (wrong result)", 1)
            self.assertIn("make_references.py", made.verdict)
            assignment_report.write_index(root / "report", [made], "alice")
            self.assertIn("ch01/tiny", (root / "report" / "index.html").read_text())
            self.assertIn("0/2 FAIL (wrong result)", (root / "report" / "report.md").read_text())
            self.assertIn("hidden", (root / "report" / "ch01-tiny" / "index.html").read_text())


class StudentCopy(TreeTestCase):
    def test_every_region_is_stubbed_and_markers_kept(self):
        copy = self.copy()
        text = (copy / "chapters/01-naive/src/warps.cpp").read_text()
        self.assertIn("    // EXERCISE(ch01/twice): return twice x\n"
                      '    throw ::freezeray::ExerciseNotImplemented("ch01/twice");\n'
                      "    // END EXERCISE\n", text)
        self.assertNotIn("x + x", text)
        self.assertNotIn("4 * x", (copy / "chapters/01-naive/src/estimator.cpp").read_text())
        self.assertNotIn("return -y", (copy / "chapters/02-importance/src/mirror.cpp").read_text())
        # Lines outside the regions are untouched.
        self.assertIn("    float y = x;\n", (copy / "chapters/02-importance/src/mirror.cpp").read_text())

    def test_error_header_included_only_where_missing(self):
        copy = self.copy()
        warps = (copy / "chapters/01-naive/src/warps.cpp").read_text()
        self.assertEqual(warps.count("#include"), 1, "warps.hpp already brings error.hpp")
        estimator = [line for line in (copy / "chapters/01-naive/src/estimator.cpp").read_text().splitlines()
                     if not line.startswith(("#pragma GCC diagnostic", "// The exercise stubs"))]
        self.assertEqual(estimator[:3], ["#include <cmath>", "#include <vector>",
                                         '#include "freezeray/error.hpp"'])

    def test_a_stubbed_file_alone_silences_what_its_stubs_leave_unused(self):
        copy = self.copy("--only", "ch01/four-times")
        stubbed = (copy / "chapters/01-naive/src/estimator.cpp").read_text().splitlines()
        self.assertIn("#pragma GCC diagnostic push", stubbed)
        self.assertIn('#pragma GCC diagnostic ignored "-Wunused-parameter"', stubbed)
        self.assertEqual(stubbed[-1], "#pragma GCC diagnostic pop")
        # A file without a stub is the solution's, byte for byte (its object comes from the cache).
        self.assertNotIn("#pragma GCC diagnostic", (copy / "chapters/01-naive/src/warps.cpp").read_text())
        header = make_student_copy.quiet_unused_warnings("#pragma once\nint f(int x);\n").splitlines()
        self.assertEqual(header[0], "#pragma once")
        self.assertEqual(header[2], "#pragma GCC diagnostic push")

    def test_include_added_to_a_file_without_includes(self):
        text = make_student_copy.add_error_include("#pragma once\nint f();\n")
        self.assertEqual(text, '#pragma once\n#include "freezeray/error.hpp"\nint f();\n')
        self.assertEqual(make_student_copy.add_error_include("int f();\n"),
                         '#include "freezeray/error.hpp"\nint f();\n')

    def test_only_one_exercise(self):
        copy = self.copy("--only", "ch01/four-times")
        self.assertIn("ExerciseNotImplemented", (copy / "chapters/01-naive/src/estimator.cpp").read_text())
        self.assertIn("x + x", (copy / "chapters/01-naive/src/warps.cpp").read_text())
        self.assertIn("return -y", (copy / "chapters/02-importance/src/mirror.cpp").read_text())

    def test_one_chapter(self):
        copy = self.copy("--chapter", "ch02")
        self.assertIn("ExerciseNotImplemented", (copy / "chapters/02-importance/src/mirror.cpp").read_text())
        self.assertIn("x + x", (copy / "chapters/01-naive/src/warps.cpp").read_text())

    def test_unknown_exercise_is_an_error(self):
        with redirect_stderr(io.StringIO()) as errors:
            status = make_student_copy.main([str(self.root), str(Path(self.folder.name) / "s"),
                                             "--only", "ch01/nope"])
        self.assertEqual(status, 1)
        self.assertIn("no exercise named ch01/nope", errors.getvalue())

    def test_build_folders_are_not_copied(self):
        copy = self.copy()
        self.assertFalse((copy / "build").exists())
        self.assertTrue((copy / "tests/exercises/exercises.cpp").is_file())

    def test_refuses_a_non_empty_destination_and_updates_a_copy(self):
        copy = self.copy()
        with self.assertRaises(SystemExit):
            make_student_copy.make_student_copy(self.root, copy)
        untouched = (copy / "chapters/01-naive/src/warps.cpp").stat().st_mtime_ns
        (self.root / "CMakeLists.txt").unlink()
        write_tree(copy, {"build/CMakeCache.txt": "", "out/CMakeCache.txt": "", "stale/old.txt": ""})
        counts = make_student_copy.make_student_copy(self.root, copy, update=True)
        self.assertEqual(counts["written"], 0)
        self.assertEqual(counts["removed"], 2)
        self.assertFalse((copy / "CMakeLists.txt").exists())
        self.assertFalse((copy / "stale").exists())
        self.assertTrue((copy / "build/CMakeCache.txt").exists(), "a build folder in the copy is kept")
        self.assertTrue((copy / "out/CMakeCache.txt").exists(), "a build tree in the copy is kept")
        self.assertEqual((copy / "chapters/01-naive/src/warps.cpp").stat().st_mtime_ns, untouched)

    @unittest.skipUnless(shutil.which("git"), "git is not installed")
    def test_git_checkout_copies_tracked_and_unignored_files(self):
        write_tree(self.root, {".gitignore": "/build*/\n*.log\n", "notes.log": "ignored", "new.txt": "untracked"})
        subprocess.run(["git", "init", "-q", str(self.root)], check=True)
        subprocess.run(["git", "-C", str(self.root), "add", "CMakeLists.txt", "common", "chapters"], check=True)
        copy = self.copy()
        self.assertTrue((copy / "new.txt").is_file())
        self.assertTrue((copy / "tests/exercises/exercises.cpp").is_file())
        self.assertFalse((copy / "notes.log").exists())
        self.assertFalse((copy / "build").exists())
        self.assertIn("ExerciseNotImplemented", (copy / "chapters/01-naive/src/warps.cpp").read_text())


CANNED_JUNIT = """\
<?xml version="1.0" encoding="UTF-8"?>
<testsuite name="(empty)" tests="4" failures="2" disabled="0" skipped="0" hostname="" time="0">
  <testcase name="exercise:ch01/twice" classname="exercise:ch01/twice" time="0.002" status="run">
    <system-out>All tests passed (1 assertion in 1 test case)</system-out>
  </testcase>
  <testcase name="exercise: ch01/four-times" classname="exercise: ch01/four-times" time="0.002" status="fail">
    <failure message=""/>
    <system-out>due to unexpected exception with message:
  exercise ch01/four-times is not implemented yet (see the chapter&apos;s book page)</system-out>
  </testcase>
  <testcase name="exercise:ch02/mirror" classname="exercise:ch02/mirror" time="0.002" status="fail">
    <failure message=""/>
    <system-out>  exercise ch01/twice is not implemented yet</system-out>
  </testcase>
  <testcase name="exercise:ch02/other" classname="exercise:ch02/other" time="0.002" status="fail">
    <failure message="Timeout"/>
    <system-out></system-out>
  </testcase>
</testsuite>
"""


class BuildFailureRows(unittest.TestCase):
    def test_only_the_exercises_in_the_failing_file_are_said_not_to_compile(self):
        error = "/work/source/chapters/06-kd-tree/src/sah.cpp:12:5: error: expected expression"
        files = {"ch06/sah-cost": Path("chapters/06-kd-tree/src/sah.cpp"),
                 "ch01/lambertian": Path("chapters/01-naive-path-tracing/src/lambertian.cpp")}
        rows = {row.exercise: row for row in grade.rows_for_build_failure(
            sorted(files), 1, {}, None, None, error, files, Path("/work/source"))}
        self.assertEqual(rows["ch06/sah-cost"].result, "FAIL (does not compile)")
        self.assertEqual(rows["ch01/lambertian"].result,
                         "FAIL (not graded: chapters/06-kd-tree/src/sah.cpp does not compile)")
        self.assertEqual(rows["ch01/lambertian"].reason, error)  # the error to fix, on every row
        # The compiler cache writes paths relative to the compiling folder.
        relative = "../../chapters/06-kd-tree/src/sah.cpp:12:5: error: expected expression"
        rows = {row.exercise: row for row in grade.rows_for_build_failure(sorted(files), 1, {}, None, None, relative, files)}
        self.assertEqual(rows["ch06/sah-cost"].result, "FAIL (does not compile)")
        self.assertEqual(rows["ch01/lambertian"].result,
                         "FAIL (not graded: chapters/06-kd-tree/src/sah.cpp does not compile)")
        # Without a file in the error (a linker's), every exercise is said not to compile.
        rows = grade.rows_for_build_failure(sorted(files), 1, {}, None, None, "undefined reference to `f()'", files)
        self.assertEqual({row.result for row in rows}, {"FAIL (does not compile)"})


class GradeReport(unittest.TestCase):
    def test_parses_ctest_junit_output(self):
        outcomes = grade.parse_ctest_junit(CANNED_JUNIT)
        self.assertEqual(outcomes["ch01/twice"].status, "pass")
        self.assertEqual((outcomes["ch01/four-times"].status, outcomes["ch01/four-times"].detail),
                         ("fail", "not implemented"))
        self.assertEqual(outcomes["ch02/mirror"].detail, "needs ch01/twice")
        self.assertEqual(outcomes["ch02/other"].detail, "timed out")

    def test_catch_counts_one_message_in_the_singular(self):
        line = ("t.cpp:9: failed: a == Approx( 0.9 ) for: 0.75f == Approx( 0.9 ) with 1 message: "
                "'likely mistake: the balance heuristic'")
        self.assertEqual(grade.first_reason(line), "likely mistake: the balance heuristic")

    def test_evidence_is_kept_apart_from_the_reason(self):
        junit = CANNED_JUNIT.replace(
            "<system-out>  exercise ch01/twice is not implemented yet</system-out>",
            "<system-out>t.cpp:37: failed: result.passed for: false with 2 messages: "
            "&apos;evidence: /b/test-evidence/ch02_mirror&apos; and &apos;chi^2 = 3, p = 0&apos;</system-out>")
        outcome = grade.parse_ctest_junit(junit)["ch02/mirror"]
        self.assertEqual((outcome.detail, outcome.reason, outcome.evidence),
                         ("wrong result", "chi^2 = 3, p = 0", "/b/test-evidence/ch02_mirror"))
        rows = grade.build_rows({"ch02/mirror": outcome}, ["ch02/mirror"], 1, {}, None)
        self.assertIn("evidence (images, tables): /b/test-evidence/ch02_mirror", grade.format_report(rows))

    def test_timeouts_and_crashes_come_from_ctests_output(self):
        verdicts = grade.ctest_verdicts(
            "3/4 Test #3: exercise:ch02/other .............***Timeout   3.00 sec\n"
            "1/4 Test  #1: exercise: ch01/twice ..............***Exception: SegFault  0.01 sec\n"
            "2/4 Test #2: exercise:ch02/mirror .............***Failed    0.01 sec\n")
        self.assertEqual(verdicts, {"ch02/other": "timed out", "ch01/twice": "crashed (SegFault)"})
        outcomes = grade.parse_ctest_junit(CANNED_JUNIT.replace('message="Timeout"', 'message=""'), verdicts)
        self.assertEqual(outcomes["ch02/other"].detail, "timed out")
        self.assertIn("no result within", outcomes["ch02/other"].reason)

    def test_the_reason_is_the_first_line_of_catchs_account(self):
        output = ("tests/exercises/test_ch01.cpp:40: FAILED:\n  CHECK( mean == Approx(1.0) )\nwith expansion:\n"
                  "  0.543 == Approx( 1.0 )\nwith message:\n  mean 0.543 vs known 1\n\n"
                  "tests/exercises/test_ch01.cpp:41: FAILED:\n  CHECK( x )\n")
        self.assertEqual(grade.first_reason(output), "mean 0.543 vs known 1")
        self.assertEqual(grade.first_reason(output.replace("with message:\n  mean 0.543 vs known 1\n", "")),
                         "0.543 == Approx( 1.0 )")
        self.assertEqual(grade.first_reason("x.cpp:3: FAILED:\n  REQUIRE( ok )\n"), "REQUIRE( ok )")
        # Several messages, the passing one first, a bias detector's wrapped over two lines.
        detected = ("x.cpp:9: FAILED:\n  CHECK( test.passed )\nwith expansion:\n  false\nwith messages:\n"
                    "  one-sample t-test, mean 1.005 vs known 1: passed\n\n"
                    "  one-sample t-test, mean 0.99 vs known 0.75: FAILED\n\n"
                    "  likely mistake: the cosine |cos theta_i| is missing from the weight (f /\n"
                    "  pdf) (that would give 1, and this gives 0.99)\n\n")
        self.assertEqual(grade.first_reason(detected), "likely mistake: the cosine |cos theta_i| is missing from "
                                                       "the weight (f / pdf) (that would give 1, and this gives 0.99)")
        self.assertEqual(grade.first_reason(detected.split("\n\n  likely")[0] + "\n\n"),
                         "one-sample t-test, mean 0.99 vs known 0.75: FAILED")
        # The compact reporter, which the grading tests use.
        compact = ("t.cpp:95: failed: test.passed for: false with 3 messages: 'mean 0.5 vs known 1: FAILED' and "
                   "'likely mistake: no 1/pdf (that would give 0.54)' and ''\n"
                   "t.cpp:16: failed: p(1.0f, 4.0f) == 1.0f for: 4.0f == 1.0f\n")
        self.assertEqual(grade.first_reason(compact), "likely mistake: no 1/pdf (that would give 0.54)")
        self.assertEqual(grade.first_reason(compact.split("\n", 1)[1]), "4.0f == 1.0f")
        self.assertEqual(grade.first_reason("t.cpp:3: failed: ok\n"), "ok")

    def test_table_totals_per_chapter_and_overall(self):
        outcomes = grade.parse_ctest_junit(CANNED_JUNIT)
        rows = grade.build_rows(outcomes, ["ch01/twice", "ch01/four-times", "ch02/mirror", "ch03/untested"],
                                default_points=1, points={"ch02/mirror": 3}, chapter=None)
        report = grade.format_report(rows)
        lines = {line.split()[0] + (" " + line.split()[1] if line.split()[1] == "total" else ""): line
                 for line in report.splitlines() if line.strip() and not line.startswith("-")}
        self.assertIn("1/1", lines["ch01/twice"])
        self.assertIn("FAIL (not implemented)", lines["ch01/four-times"])
        self.assertIn("0/3", lines["ch02/mirror"])
        self.assertIn("no test", lines["ch03/untested"])
        self.assertIn("1/2", lines["ch01 total"])
        self.assertIn("0/4", lines["ch02 total"])
        self.assertIn("1/7", lines["overall"])
        self.assertIn("(1 of 5 exercises pass)", lines["overall"])

    def test_chapter_filter(self):
        rows = grade.build_rows(grade.parse_ctest_junit(CANNED_JUNIT), [], 1, {}, chapter="ch02")
        self.assertEqual([row.exercise for row in rows], ["ch02/mirror", "ch02/other"])

    def test_ctest_command_selects_the_chapter(self):
        command = grade.ctest_command(Path("build"), Path("/tmp/x.xml"), "ch01", jobs=1)
        self.assertEqual(command[:5], ["ctest", "--test-dir", "build", "-L", "exercise"])
        self.assertIn("^exercise: ?ch01/", command)

    def test_missing_build_folder_is_an_error(self):
        with redirect_stderr(io.StringIO()) as errors:
            self.assertEqual(grade.main(["--build-dir", "/nonexistent/build"]), 2)
        self.assertIn("does not exist", errors.getvalue())


FAKE_TESTS = """\
#!/usr/bin/env python3
# A stand-in for exercise_tests: lists two tests; 'ch01/a' fails through its stub.
import sys
if "--list-test-names-only" in sys.argv:
    print("ch01/a\\nch01/b")
    sys.exit(2)
if sys.argv[1] == "ch01/a":
    print("<Exception>exercise ch01/a is not implemented yet</Exception>")
    sys.exit(1)
if sys.argv[1] == "ch01/b":
    print("<Exception>exercise ch01/a is not implemented yet</Exception>", file=sys.stderr)
    sys.exit(1)
sys.exit(3)
"""


class ProofParts(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory(prefix="freezeray-prove-test-")
        self.executable = Path(self.folder.name) / "exercise_tests"
        self.executable.write_text(FAKE_TESTS)
        self.executable.chmod(0o755)

    def tearDown(self):
        self.folder.cleanup()

    def region(self, name: str) -> exercises.Region:
        return exercises.Region(name, "do it", Path("common/src/a.cpp"), 1, 3, "")

    def test_lists_and_runs_tests_one_per_process(self):
        folder = Path(self.folder.name)
        self.assertEqual(prove_exercises.list_tests(self.executable, folder), ["ch01/a", "ch01/b"])
        run = prove_exercises.run_test(self.executable, "ch01/a", folder, timeout=30)
        self.assertFalse(run.passed)
        self.assertEqual(run.stubs, ["ch01/a"])

    def test_missing_tests_and_regions_are_violations(self):
        proofs = prove_exercises.match_tests_to_regions([self.region("ch01/a"), self.region("ch01/c")],
                                                        ["ch01/a", "ch01/b"])
        self.assertEqual(proofs["ch01/a"].violations, [])
        self.assertIn("no grading test", proofs["ch01/c"].violations[0])
        self.assertIn("has no region", proofs["ch01/b"].violations[0])

    def test_a_test_failing_only_through_another_stub_needs_isolation(self):
        folder = Path(self.folder.name)
        proofs = prove_exercises.match_tests_to_regions([self.region("ch01/a"), self.region("ch01/b")],
                                                        ["ch01/a", "ch01/b"])
        to_isolate = prove_exercises.check_stubbed(proofs, self.executable, folder, timeout=30)
        self.assertEqual(to_isolate, ["ch01/b"])
        self.assertEqual(proofs["ch01/a"].stub_column(), "FAIL (its stub)")
        self.assertEqual(proofs["ch01/b"].stub_column(), "FAIL (via ch01/a)")
        prove_exercises.report_unisolated(proofs, to_isolate)
        self.assertIn("only through ch01/a's stub", proofs["ch01/b"].violations[0])
        table = prove_exercises.format_table(proofs)
        self.assertRegex(table, r"ch01/b .*VIOLATION")

    def test_a_test_stopping_at_an_unlisted_stub_is_a_violation(self):
        folder = Path(self.folder.name)
        proofs = prove_exercises.match_tests_to_regions([self.region("ch01/a"), self.region("ch01/b")],
                                                        ["ch01/a", "ch01/b"])
        prove_exercises.check_stubbed(proofs, self.executable, folder, timeout=30)
        violations = prove_exercises.check_prerequisites(proofs, {})
        self.assertEqual(len(violations), 1)
        self.assertIn("ch01/b: its test runs ch01/a first", violations[0])
        self.assertEqual(prove_exercises.check_prerequisites(proofs, {"ch01/b": ["ch01/a"]}), [])

    def test_a_composite_assignment_is_proven_through_its_parts_stubs(self):
        folder = Path(self.folder.name)
        proofs = prove_exercises.match_tests_to_regions([self.region("ch01/a")], ["ch01/a", "ch01/b"],
                                                        {"ch01/b": ("ch01/a", "ch01/c")})
        self.assertEqual(proofs["ch01/b"].violations, [])
        to_isolate = prove_exercises.check_stubbed(proofs, self.executable, folder, timeout=30)
        self.assertEqual(to_isolate, [])
        self.assertEqual(proofs["ch01/b"].violations, [])
        self.assertEqual(proofs["ch01/b"].stub_column(), "FAIL (its part ch01/a)")
        # stopping first at an exercise that is not a part (an earlier chapter's): checked again
        # with its chapter's regions stubbed alone
        proofs = prove_exercises.match_tests_to_regions([self.region("ch01/a")], ["ch01/a", "ch01/b"],
                                                        {"ch01/b": ("ch01/c", "ch01/d")})
        self.assertEqual(prove_exercises.check_stubbed(proofs, self.executable, folder, timeout=30), ["ch01/b"])
        self.assertEqual(proofs["ch01/b"].violations, [])

    def test_catch_test_spec_escapes_special_characters(self):
        self.assertEqual(prove_exercises.catch_test_spec("ch01/a"), "ch01/a")
        self.assertEqual(prove_exercises.catch_test_spec("a,b[c]"), "a\\,b\\[c\\]")

    def test_reads_the_cmake_cache(self):
        build = Path(self.folder.name)
        (build / "CMakeCache.txt").write_text("// comment\nCMAKE_GENERATOR:INTERNAL=Unix Makefiles\n"
                                              "CMAKE_CXX_COMPILER:FILEPATH=/usr/bin/c++\n")
        cache = submission.read_cmake_cache(build)
        self.assertEqual(cache["CMAKE_GENERATOR"], "Unix Makefiles")
        self.assertEqual(cache["CMAKE_CXX_COMPILER"], "/usr/bin/c++")


if __name__ == "__main__":
    unittest.main()
