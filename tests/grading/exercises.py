#!/usr/bin/env python3
"""Find and check the exercise regions marked in FreezeRay's C++ sources.

An exercise is a region of a function body, between two comment lines:

    // EXERCISE(ch01/uniform-hemisphere): return a direction uniformly distributed ...
    ...solution lines...
    // END EXERCISE

The name is `chNN/kebab-name`; its chapter `chNN` is the chapter that teaches it.
Regions live only under chapters/, in the folder of the chapter that teaches them
(chapters/NN-name/ for chNN/...): common/ holds what no chapter is about, so it has none.
This module is shared by
make_student_copy.py, grade.py and prove_exercises.py; run on its own it checks the
markers (`--check`) or lists the exercises (`--list`).
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from dataclasses import dataclass
from pathlib import Path

# The folder, relative to the repository root, that holds exercise regions, one subfolder per
# chapter (NN-name); and the folders that must hold none.
REGION_FOLDERS = ("chapters",)
FORBIDDEN_FOLDERS = ("common",)

# The C++ files scanned for markers.
CPP_SUFFIXES = {".cpp", ".cc", ".cxx", ".hpp", ".hh", ".h", ".hxx", ".inl", ".ipp"}

# Where the grading tests live, and the points table.
TESTS_FOLDER = Path("tests") / "exercises"
POINTS_FILE = Path("tests") / "grading" / "points.json"
PREREQUISITES_FILE = Path("tests") / "grading" / "prerequisites.json"
ASSIGNMENTS_FILE = Path("tests") / "grading" / "assignments.json"

# The stub that replaces a region; it compiles in any function whatever its return type.
STUB_TEMPLATE = 'throw ::freezeray::ExerciseNotImplemented("{name}");'
ERROR_HEADER = "freezeray/error.hpp"

# A name is chNN/kebab-name: two-digit chapter, lowercase words joined by hyphens.
NAME_PATTERN = r"ch(?P<chapter>\d{2})/[a-z0-9]+(?:-[a-z0-9]+)*"
CHAPTER_PATTERN = re.compile(r"ch\d{2}")

# Any line that mentions a marker, well formed or not.
START_HINT = re.compile(r"//\s*EXERCISE\b")
END_HINT = re.compile(r"//\s*END\s+EXERCISE\b")

# The exact forms: the marker alone on its line, at statement level.
START_MARKER = re.compile(r"^(?P<indent>\s*)// EXERCISE\((?P<name>[^)]*)\):\s*(?P<description>.*?)\s*$")
END_MARKER = re.compile(r"^\s*// END EXERCISE\s*$")
NAME = re.compile(rf"^{NAME_PATTERN}$")

# The grading tests: TEST_CASE("ch01/uniform-hemisphere", "[exercise]").
TEST_CASE = re.compile(r'TEST_CASE\s*\(\s*"(?P<name>[^"]*)"')

# A chapter folder is chapters/NN-name; its regions belong to chapter NN.
CHAPTER_FOLDER = re.compile(r"^chapters/(?P<number>\d{2})-[^/]+/")

# The message ExerciseNotImplemented carries (common/core/include/freezeray/error.hpp).
NOT_IMPLEMENTED = re.compile(r"exercise\s+(?P<name>ch\d{2}/[a-z0-9-]+)\s+is\s+not\s+implemented")


@dataclass(frozen=True)
class Region:
    """One exercise region: the marker lines are `start` and `end` (1-based, inclusive)."""

    name: str
    description: str
    path: Path  # relative to the repository root
    start: int
    end: int
    indent: str

    @property
    def chapter(self) -> str:
        """The chapter the exercise belongs to, e.g. 'ch01'."""
        return chapter_of(self.name)

    @property
    def location(self) -> str:
        """'file:line' of the opening marker, for messages."""
        return f"{self.path.as_posix()}:{self.start}"


class MarkerError(Exception):
    """The markers in the sources are not well formed; `problems` lists 'file:line: what'."""

    def __init__(self, problems: list[str]):
        super().__init__("\n".join(problems))
        self.problems = problems


def chapter_of(name: str) -> str:
    """The chapter of an exercise or assignment name: 'ch01' for 'ch01/uniform-hemisphere'."""
    return name.split("/", 1)[0]


def is_chapter_name(text: str) -> bool:
    """True for a chapter name such as 'ch01'."""
    return CHAPTER_PATTERN.fullmatch(text) is not None


def source_files(root: Path, folders: tuple[str, ...] = REGION_FOLDERS) -> list[Path]:
    """The C++ files under chapters/ (or `folders`), relative to root, in a stable order."""
    files = []
    for folder in folders:
        base = root / folder
        if not base.is_dir():
            continue
        for path in base.rglob("*"):
            if path.suffix in CPP_SUFFIXES and path.is_file():
                files.append(path.relative_to(root))
    return sorted(files)


def parse_file(text: str, path: Path) -> tuple[list[Region], list[str]]:
    """Find the regions in one file's text. Returns (regions, problems as 'file:line: what')."""
    regions: list[Region] = []
    problems: list[str] = []
    where = path.as_posix()
    open_match = None  # the START marker of the region we are inside, if any
    open_line = 0
    for number, line in enumerate(text.splitlines(), start=1):
        if END_HINT.search(line):
            if not END_MARKER.match(line):
                problems.append(f"{where}:{number}: malformed END EXERCISE marker: "
                                "it must be the comment `// END EXERCISE` alone on its line")
            elif open_match is None:
                problems.append(f"{where}:{number}: END EXERCISE without a matching EXERCISE marker")
            else:
                if number == open_line + 1:
                    problems.append(f"{where}:{open_line}: exercise region "
                                    f"{open_match['name']} is empty")
                regions.append(Region(name=open_match["name"], description=open_match["description"],
                                      path=path, start=open_line, end=number,
                                      indent=open_match["indent"]))
                open_match = None
            continue
        if not START_HINT.search(line):
            continue
        match = START_MARKER.match(line)
        if match is None:
            problems.append(f"{where}:{number}: malformed EXERCISE marker: expected "
                            "`// EXERCISE(chNN/kebab-name): what to implement` alone on its line")
            continue
        name_problem = check_name(match["name"], match["description"], path)
        if name_problem:
            problems.append(f"{where}:{number}: {name_problem}")
            continue
        if open_match is not None:
            problems.append(f"{where}:{number}: EXERCISE {match['name']} is nested inside "
                            f"EXERCISE {open_match['name']} (opened at line {open_line}); "
                            "close the first region with `// END EXERCISE` before opening another")
            continue
        open_match, open_line = match, number
    if open_match is not None:
        problems.append(f"{where}:{open_line}: EXERCISE {open_match['name']} is never closed "
                        "with `// END EXERCISE`")
    return regions, problems


def check_name(name: str, description: str, path: Path) -> str | None:
    """What is wrong with an exercise's name or description, or None if nothing is."""
    match = NAME.match(name)
    if match is None:
        return (f"malformed exercise name '{name}': expected chNN/kebab-name, "
                "e.g. ch01/uniform-hemisphere")
    if not description:
        return f"EXERCISE {name} has no description after the colon: say what to implement"
    folder = CHAPTER_FOLDER.match(path.as_posix())
    if folder and folder["number"] != match["chapter"]:
        return (f"exercise {name} is in chapter {folder['number']}'s folder; "
                f"name it ch{folder['number']}/... or move it")
    return None


def find_regions_with_problems(root: Path) -> tuple[list[Region], list[str]]:
    """All regions under root, and every marker problem (including duplicate names)."""
    regions: list[Region] = []
    problems: list[str] = []
    for path in source_files(root):
        text = (root / path).read_text(encoding="utf-8", errors="replace")
        file_regions, file_problems = parse_file(text, path)
        regions.extend(file_regions)
        problems.extend(file_problems)
    # A region outside chapters/ is misplaced (parse_file reports one in another chapter's folder).
    for path in source_files(root, FORBIDDEN_FOLDERS):
        text = (root / path).read_text(encoding="utf-8", errors="replace")
        for region in parse_file(text, path)[0]:
            problems.append(f"{region.location}: exercise {region.name} is outside chapters/: an exercise "
                            f"lives in the folder of the chapter that teaches it")
    first_seen: dict[str, Region] = {}
    for region in regions:
        if region.name in first_seen:
            problems.append(f"{region.location}: duplicate exercise name {region.name} "
                            f"(first used at {first_seen[region.name].location})")
        else:
            first_seen[region.name] = region
    return regions, problems


def find_regions(root: Path) -> list[Region]:
    """All regions under root; raises MarkerError when any marker is not well formed."""
    regions, problems = find_regions_with_problems(root)
    if problems:
        raise MarkerError(problems)
    return regions


def select_regions(regions: list[Region], only: str | None = None,
                   chapter: str | None = None) -> list[Region]:
    """The regions named by --only NAME or --chapter chNN (all of them when neither is given)."""
    if only is not None:
        chosen = [region for region in regions if region.name == only]
        if not chosen:
            known = ", ".join(sorted(region.name for region in regions)) or "none"
            raise ValueError(f"no exercise named {only} (exercises: {known})")
        return chosen
    if chapter is not None:
        if not is_chapter_name(chapter):
            raise ValueError(f"'{chapter}' is not a chapter name: expected chNN, e.g. ch01")
        return [region for region in regions if region.chapter == chapter]
    return list(regions)


def find_grading_tests(root: Path) -> dict[str, str]:
    """The TEST_CASE names in tests/exercises/*.cpp, each with its 'file:line'."""
    tests: dict[str, str] = {}
    folder = root / TESTS_FOLDER
    if not folder.is_dir():
        return tests
    for path in sorted(folder.glob("*.cpp")):
        text = path.read_text(encoding="utf-8", errors="replace")
        for match in TEST_CASE.finditer(text):
            line = text.count("\n", 0, match.start()) + 1
            tests.setdefault(match["name"], f"{path.relative_to(root).as_posix()}:{line}")
    return tests


def load_points(path: Path) -> tuple[int, dict[str, int]]:
    """Read points.json: (default points, points per exercise name)."""
    if not path.is_file():
        return 1, {}
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except json.JSONDecodeError as error:
        raise ValueError(f"{path}:{error.lineno}: not valid JSON: {error.msg}") from error
    default = data.get("default_points", 1)
    points = data.get("points", {})
    if not isinstance(default, int) or not isinstance(points, dict):
        raise ValueError(f"{path}: expected {{\"default_points\": int, \"points\": {{name: int}}}}")
    for name, value in points.items():
        if not isinstance(value, int) or value < 0:
            raise ValueError(f"{path}: points for {name} must be a whole number >= 0, not {value!r}")
    return default, points


def load_prerequisites(path: Path) -> dict[str, list[str]]:
    """tests/grading/prerequisites.json: for an exercise, those to do first (empty when absent)."""
    if not path.is_file():
        return {}
    data = json.loads(path.read_text(encoding="utf-8"))
    table = data.get("prerequisites", {})
    if not isinstance(table, dict) or not all(isinstance(v, list) for v in table.values()):
        raise ValueError(f"{path}: 'prerequisites' must map exercise names to lists of names")
    return {name: list(before) for name, before in table.items()}


@dataclass(frozen=True)
class Assignment:
    """A larger piece of work (assignments.json): one region that is a whole feature, or
    several regions (its parts) that together make one, graded by a test of its own named after
    it. `render_reference` says what its grading test renders (the views compared with the
    solution's, make_references.py --blocks); `render` what grade.py --report shows."""

    name: str
    title: str
    parts: tuple[str, ...]
    book: str
    render: dict
    render_reference: dict

    @property
    def chapter(self) -> str:
        return chapter_of(self.name)

    @property
    def is_composite(self) -> bool:
        """True when it is made of other regions and has a grading test of its own."""
        return self.parts != (self.name,)


def load_assignments(path: Path) -> dict[str, Assignment]:
    """tests/grading/assignments.json: the assignments by name (empty when absent)."""
    if not path.is_file():
        return {}
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except json.JSONDecodeError as error:
        raise ValueError(f"{path}:{error.lineno}: not valid JSON: {error.msg}") from error
    table = data.get("assignments", {})
    if not isinstance(table, dict):
        raise ValueError(f"{path}: 'assignments' must map names to objects")
    assignments = {}
    for name, entry in table.items():
        where = f"{path}: assignments.{name}"
        if not isinstance(entry, dict) or not isinstance(entry.get("parts"), list) or not entry["parts"]:
            raise ValueError(f"{where}: expected an object with a non-empty list 'parts'")
        if not isinstance(entry.get("title", ""), str) or not isinstance(entry.get("report", {}), dict) \
                or not isinstance(entry.get("reference", {}), dict):
            raise ValueError(f"{where}: 'title' must be a string, 'report' and 'reference' objects")
        assignments[name] = Assignment(name, entry.get("title", name), tuple(entry["parts"]),
                                       entry.get("book", ""), entry.get("report", {}), entry.get("reference", {}))
    return assignments


def all_prerequisites(root: Path) -> dict[str, list[str]]:
    """prerequisites.json, with each composite assignment's parts added to its own list."""
    before = load_prerequisites(root / PREREQUISITES_FILE)
    for assignment in load_assignments(root / ASSIGNMENTS_FILE).values():
        if assignment.is_composite:
            listed = before.setdefault(assignment.name, [])
            listed += [part for part in assignment.parts if part not in listed]
    return before


def check_assignments(root: Path, names: set[str], tests: dict[str, str]) -> list[str]:
    """assignments.json names real exercises; a composite one has a test and no region."""
    problems = []
    try:
        assignments = load_assignments(root / ASSIGNMENTS_FILE)
    except ValueError as error:
        return [str(error)]
    where = ASSIGNMENTS_FILE.as_posix()
    for assignment in assignments.values():
        if not NAME.match(assignment.name):
            problems.append(f"{where}: {assignment.name!r} is not a name like ch01/kebab-name")
            continue
        if assignment.is_composite:
            if assignment.name in names:
                problems.append(f"{where}: {assignment.name} is both an exercise region and an assignment "
                                "made of other regions")
            if len(assignment.parts) < 2:
                problems.append(f"{where}: {assignment.name} names one part: make the region itself the assignment")
            if (root / TESTS_FOLDER).is_dir() and assignment.name not in tests:
                problems.append(f"{where}: assignment {assignment.name} has no grading test: add "
                                f'TEST_CASE("{assignment.name}", "[exercise]") to {TESTS_FOLDER.as_posix()}/')
        elif assignment.name not in names:
            problems.append(f"{where}: {assignment.name} is neither an exercise region nor made of parts")
        for part in assignment.parts if assignment.is_composite else ():
            if part not in names:
                problems.append(f"{where}: {assignment.name}'s part {part} is not an exercise")
            elif chapter_of(part) != assignment.chapter:
                problems.append(f"{where}: {assignment.name}'s part {part} belongs to another chapter")
    return problems


def graded_names(root: Path, regions: list[Region]) -> list[str]:
    """What the grading tests grade: every exercise region and every composite assignment."""
    composites = [a.name for a in load_assignments(root / ASSIGNMENTS_FILE).values() if a.is_composite]
    return sorted({region.name for region in regions} | set(composites))


def check_tree(root: Path) -> list[str]:
    """Every problem with the markers, the grading tests' names, points.json and assignments.json."""
    regions, problems = find_regions_with_problems(root)
    region_names = {region.name for region in regions}
    tests = find_grading_tests(root)
    problems += check_assignments(root, region_names, tests)
    try:
        names = set(graded_names(root, regions))
    except ValueError:
        names = set(region_names)
    if (root / TESTS_FOLDER).is_dir():
        for region in regions:
            if region.name not in tests:
                problems.append(f"{region.location}: exercise {region.name} has no grading test: add "
                                f'TEST_CASE("{region.name}", "[exercise]") to {TESTS_FOLDER.as_posix()}/')
        for name, location in tests.items():
            if name not in names:
                problems.append(f"{location}: grading test \"{name}\" names no exercise region "
                                f"(expected `// EXERCISE({name}): ...` under chapters/, or an assignment "
                                f"made of regions in {ASSIGNMENTS_FILE.as_posix()})")
    try:
        _, points = load_points(root / POINTS_FILE)
    except ValueError as error:
        problems.append(str(error))
        points = {}
    for name in points:
        if name not in names:
            problems.append(f"{POINTS_FILE.as_posix()}: points given for {name}, which is not an exercise")
    try:
        prerequisites = load_prerequisites(root / PREREQUISITES_FILE)
    except ValueError as error:
        problems.append(str(error))
        prerequisites = {}
    for name, before in prerequisites.items():
        for other in [name, *before]:
            if other not in names:
                problems.append(f"{PREREQUISITES_FILE.as_posix()}: {other} is not an exercise")
    return problems


def repository_root() -> Path:
    """The repository this script belongs to (tests/grading/ is two levels down)."""
    return Path(__file__).resolve().parents[2]


def print_regions(regions: list[Region]) -> None:
    """One line per exercise: name, location, description."""
    for region in sorted(regions, key=lambda r: r.name):
        print(f"{region.name:40} {region.location:60} {region.description}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Check or list the exercise regions in the sources.")
    parser.add_argument("--root", type=Path, default=repository_root(),
                        help="repository root (default: the one holding this script)")
    action = parser.add_mutually_exclusive_group()
    action.add_argument("--check", action="store_true",
                        help="check the markers, the grading tests' names and points.json (the default)")
    action.add_argument("--list", action="store_true", help="list the exercises")
    args = parser.parse_args(argv)

    if args.list:
        try:
            print_regions(find_regions(args.root))
        except MarkerError as error:
            print(error, file=sys.stderr)
            return 1
        return 0

    problems = check_tree(args.root)
    if problems:
        for problem in problems:
            print(problem, file=sys.stderr)
        print(f"{len(problems)} problem(s) with the exercise markers", file=sys.stderr)
        return 1
    regions = find_regions(args.root)
    files = {region.path for region in regions}
    print(f"{len(regions)} exercise region(s) in {len(files)} file(s), all well formed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
