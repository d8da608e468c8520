#!/usr/bin/env python3
"""Keep FreezeRay's book in step with the code: listings and figures.

    tools/book.py check                      a listing differs from its source region: exit 1
    tools/book.py update                     rewrite every listing from its source region
    tools/book.py figures --build-dir build  render the figures listed in book/figures.json

Listings. A C++ source tags a region with two comment lines, `// BOOK(name)` and
`// END BOOK` (names unique across the repository). A book page (book/*.md) embeds it as

    <!-- BOOK(name) -->
    *From `path/to/file.cpp`*
    ```cpp
    ...the region's lines, dedented...
    ```
    <!-- END BOOK -->

and everything between the two HTML comments is generated: write the two comments, run
`update`, and the caption and code appear. Inside a listing an exercise region (from
`// EXERCISE(chNN/name): ...` to `// END EXERCISE`) shows as one comment,
`// (exercise chNN/name: see the exercises at the end of this chapter)`, so the book never
gives the answer away. Nested BOOK regions are allowed; their marker lines are left out.

Figures. book/figures.json lists {"output": ..., "command": [...]} entries. Each command
runs from the repository root; its first word is an executable of the build
(BUILD_DIR/NAME or BUILD_DIR/chapters/NAME) or a Python script of the repository (a path
ending in .py, run with this Python), "{output}" stands for the output path and
"{build_dir}" for BUILD_DIR.
An entry may add "copy_from": a file the command writes (under out/, say, beside files
too large to commit) that is then copied to the output, and "needs": the build targets a
script runs (the book-figures target builds them first).
"""

from __future__ import annotations

import argparse
import difflib
import json
import os
import re
import shutil
import subprocess
import sys
import textwrap
import time
from dataclasses import dataclass
from pathlib import Path

# Where tagged sources live, and which files are C++.
SOURCE_FOLDERS = ("common", "chapters", "tests")
CPP_SUFFIXES = {".cpp", ".cc", ".cxx", ".hpp", ".hh", ".h", ".hxx", ".inl", ".ipp"}
BOOK_FOLDER = "book"
FIGURES_FILE = Path("book") / "figures.json"

# Markers in the C++ sources.
NAME_PATTERN = r"[a-z0-9]+(?:[-_/.][a-z0-9]+)*"
SOURCE_HINT = re.compile(r"//\s*(END\s+)?BOOK\b")
SOURCE_START = re.compile(rf"^\s*// BOOK\((?P<name>{NAME_PATTERN})\)\s*$")
SOURCE_END = re.compile(r"^\s*// END BOOK\s*$")
EXERCISE_START = re.compile(r"^(?P<indent>\s*)// EXERCISE\((?P<name>[^)]*)\):")
EXERCISE_END = re.compile(r"^\s*// END EXERCISE\s*$")
HIDDEN_EXERCISE = "// (exercise {name}: see the exercises at the end of this chapter)"

# Markers in the book pages.
PAGE_START = re.compile(r"^<!--\s*BOOK\((?P<name>[^)]*)\)\s*-->\s*$")
PAGE_END = re.compile(r"^<!--\s*END BOOK\s*-->\s*$")

# A committed figure bigger than this earns a warning: keep the repository light.
FIGURE_SIZE_WARNING = 400 * 1024


class BookError(Exception):
    """Something the user must fix; `problems` lists 'file:line: what'."""

    def __init__(self, problems: list[str]):
        super().__init__("\n".join(problems))
        self.problems = problems


@dataclass
class Region:
    """A `// BOOK(name)` region: marker lines start and end (1-based), the lines between."""

    name: str
    path: Path  # relative to the repository root
    start: int
    end: int
    lines: list[str]

    @property
    def location(self) -> str:
        return f"{self.path.as_posix()}:{self.start}"


@dataclass
class Embed:
    """A listing in a book page: the marker lines are start and end (0-based indices)."""

    name: str
    page: Path
    start: int
    end: int

    @property
    def location(self) -> str:
        return f"{self.page.as_posix()}:{self.start + 1}"


# --- Reading the sources ----------------------------------------------------------------------

def source_files(root: Path) -> list[Path]:
    """The C++ files that may hold BOOK regions, relative to root (build trees skipped)."""
    files = []
    for folder in SOURCE_FOLDERS:
        for directory, subfolders, names in os.walk(root / folder):
            if (Path(directory) / "CMakeCache.txt").exists():
                subfolders[:] = []
                continue
            subfolders[:] = sorted(name for name in subfolders if name != "__pycache__")
            files.extend((Path(directory) / name).relative_to(root)
                         for name in names if Path(name).suffix in CPP_SUFFIXES)
    return sorted(files)


def parse_source(text: str, path: Path) -> tuple[list[Region], list[str]]:
    """The BOOK regions of one file (they may nest), and its marker problems."""
    regions, problems = [], []
    lines = text.splitlines()
    open_regions: list[tuple[str, int]] = []  # (name, 1-based line) of each region still open
    exercise: str | None = None  # the exercise region we are inside, if any
    for number, line in enumerate(lines, start=1):
        if EXERCISE_START.match(line):
            exercise = EXERCISE_START.match(line)["name"]
        elif EXERCISE_END.match(line):
            exercise = None
        if not SOURCE_HINT.search(line):
            continue
        start = SOURCE_START.match(line)
        if start and exercise is not None:
            problems.append(f"{path.as_posix()}:{number}: BOOK({start['name']}) opens inside exercise "
                            f"{exercise} and would show its solution; tag a region around the whole exercise")
            open_regions.append((start["name"], number))
        elif start:
            open_regions.append((start["name"], number))
        elif SOURCE_END.match(line):
            if not open_regions:
                problems.append(f"{path.as_posix()}:{number}: END BOOK without a matching BOOK marker")
                continue
            name, first = open_regions.pop()
            regions.append(Region(name, path, first, number, lines[first:number - 1]))
        else:
            problems.append(f"{path.as_posix()}:{number}: malformed BOOK marker: expected "
                            "`// BOOK(kebab-name)` or `// END BOOK` alone on its line")
    for name, first in open_regions:
        problems.append(f"{path.as_posix()}:{first}: BOOK({name}) is never closed with `// END BOOK`")
    return regions, problems


def find_regions(root: Path) -> dict[str, Region]:
    """Every BOOK region of the repository by name; raises BookError on bad or duplicate markers."""
    regions: dict[str, Region] = {}
    problems: list[str] = []
    for path in source_files(root):
        found, file_problems = parse_source((root / path).read_text(encoding="utf-8", errors="replace"), path)
        problems.extend(file_problems)
        for region in found:
            if region.name in regions:
                problems.append(f"{region.location}: BOOK({region.name}) is a duplicate; "
                                f"the name is already used at {regions[region.name].location}")
            else:
                regions[region.name] = region
    if problems:
        raise BookError(problems)
    return regions


# --- Turning a region into a listing ----------------------------------------------------------

def hide_exercises(region: Region) -> list[str]:
    """The region's lines with each exercise region replaced by one comment (and BOOK markers dropped)."""
    shown: list[str] = []
    exercise: tuple[str, int] | None = None  # (name, line) of the exercise we are inside
    for offset, line in enumerate(region.lines):
        number = region.start + 1 + offset
        start = EXERCISE_START.match(line)
        if start:
            exercise = (start["name"], number)
            shown.append(start["indent"] + HIDDEN_EXERCISE.format(name=start["name"]))
        elif EXERCISE_END.match(line):
            if exercise is None:
                raise BookError([f"{region.location}: BOOK({region.name}) starts inside an exercise region "
                                 f"(which ends at line {number}) and would show its solution"])
            exercise = None
        elif exercise is None and not (SOURCE_START.match(line) or SOURCE_END.match(line)):
            shown.append(line)
    if exercise is not None:
        raise BookError([f"{region.location}: BOOK({region.name}) ends inside exercise {exercise[0]} "
                         f"(line {exercise[1]}) and would show its solution; "
                         "a listing must hold whole exercise regions"])
    return shown


def listing_code(region: Region) -> list[str]:
    """The code of a listing: exercises hidden, dedented, no trailing spaces or blank edges."""
    code = textwrap.dedent("\n".join(hide_exercises(region))).splitlines()
    code = [line.rstrip() for line in code]
    while code and not code[0]:
        code.pop(0)
    while code and not code[-1]:
        code.pop()
    return code


def listing_block(region: Region) -> list[str]:
    """The lines a page shows between `<!-- BOOK(name) -->` and `<!-- END BOOK -->`."""
    code = listing_code(region)
    longest_backticks = max((len(run) for line in code for run in re.findall(r"`+", line)), default=0)
    fence = "`" * max(3, longest_backticks + 1)
    return [f"*From `{region.path.as_posix()}`*", fence + "cpp", *code, fence]


# --- Reading and writing the pages ------------------------------------------------------------

def book_pages(root: Path) -> list[Path]:
    """The book's pages (book/**/*.md except README.md), relative to root."""
    folder = root / BOOK_FOLDER
    if not folder.is_dir():
        return []
    return sorted(path.relative_to(root) for path in folder.rglob("*.md") if path.name != "README.md")


def parse_page(lines: list[str], page: Path) -> tuple[list[Embed], list[str]]:
    """The listings embedded in a page, and its marker problems."""
    embeds, problems = [], []
    current: tuple[str, int] | None = None
    for index, line in enumerate(lines):
        start, end = PAGE_START.match(line), PAGE_END.match(line)
        if start and current is not None:
            problems.append(f"{page.as_posix()}:{index + 1}: BOOK({start['name']}) opens inside "
                            f"BOOK({current[0]}) (line {current[1] + 1}), which has no `<!-- END BOOK -->`")
            current = (start["name"], index)
        elif start:
            current = (start["name"], index)
        elif end and current is None:
            problems.append(f"{page.as_posix()}:{index + 1}: `<!-- END BOOK -->` without a BOOK marker")
        elif end:
            embeds.append(Embed(current[0], page, current[1], index))
            current = None
    if current is not None:
        problems.append(f"{page.as_posix()}:{current[1] + 1}: BOOK({current[0]}) is never closed "
                        "with `<!-- END BOOK -->`")
    return embeds, problems


@dataclass
class PageResult:
    """What regenerating one page found: its new text, what changed, what was wrong."""

    text: str
    changed: list[tuple[Embed, Region, list[str], list[str]]]  # embed, region, old block, new block
    problems: list[str]
    names: list[str]  # the listings the page embeds


def regenerate_page(root: Path, page: Path, regions: dict[str, Region]) -> PageResult:
    """The page with every listing rebuilt from its region (unknown listings are left as they are)."""
    text = (root / page).read_text(encoding="utf-8")
    lines = text.splitlines()
    embeds, problems = parse_page(lines, page)
    changed, listing_problems = [], []
    for embed in reversed(embeds):  # from the bottom, so earlier line numbers stay valid
        region = regions.get(embed.name)
        if region is None:
            listing_problems.append(f"{embed.location}: listing BOOK({embed.name}) names no region: "
                            f"no `// BOOK({embed.name})` in {', '.join(SOURCE_FOLDERS)}/")
            continue
        try:
            new_block = listing_block(region)
        except BookError as error:
            listing_problems.extend(error.problems)
            continue
        old_block = lines[embed.start + 1:embed.end]
        if old_block != new_block:
            changed.append((embed, region, old_block, new_block))
            lines[embed.start + 1:embed.end] = new_block
    new_text = "\n".join(lines) + ("\n" if text.endswith("\n") or not text else "")
    problems.extend(reversed(listing_problems))
    return PageResult(new_text, list(reversed(changed)), problems, [embed.name for embed in embeds])


def listing_diff(embed: Embed, region: Region, old: list[str], new: list[str]) -> str:
    """A unified diff from the page's listing to what its source region says."""
    return "\n".join(difflib.unified_diff(
        old, new, lineterm="",
        fromfile=f"{embed.location} listing BOOK({embed.name}) in the book",
        tofile=f"{region.location} region BOOK({region.name}) in the source"))


# --- Commands ---------------------------------------------------------------------------------

def command_check(root: Path) -> int:
    """Exit status 1 when a listing differs from its region, names no region, or a tag is duplicated."""
    regions = find_regions(root)
    problems, used, pages = [], [], book_pages(root)
    for page in pages:
        result = regenerate_page(root, page, regions)
        used.extend(result.names)
        problems.extend(result.problems)
        for embed, region, old, new in result.changed:
            problems.append(f"{embed.location}: listing BOOK({embed.name}) differs from its source "
                            f"{region.location}; run tools/book.py update\n"
                            + listing_diff(embed, region, old, new))
    if problems:
        raise BookError(problems)
    print(f"book: {len(used)} listing(s) in {len(pages)} page(s) match their sources")
    unused = sorted(set(regions) - set(used))
    if unused:
        print(f"book: note: {len(unused)} region(s) shown in no page: {', '.join(unused)}")
    return 0


def command_update(root: Path) -> int:
    """Rewrite every listing from its region; exit status 1 if some listing could not be."""
    regions = find_regions(root)
    problems = []
    for page in book_pages(root):
        result = regenerate_page(root, page, regions)
        problems.extend(result.problems)
        if result.changed:
            (root / page).write_text(result.text, encoding="utf-8")
            for embed, region, _, _ in result.changed:
                print(f"updated {embed.location}: BOOK({embed.name}) from {region.location}")
    if problems:
        raise BookError(problems)
    return 0


@dataclass
class Figure:
    """One entry of book/figures.json."""

    output: str
    command: list[str]
    description: str = ""
    copy_from: str = ""
    needs: tuple[str, ...] = ()


def load_figures(root: Path) -> list[Figure]:
    """Read and check book/figures.json."""
    path = root / FIGURES_FILE
    try:
        entries = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError as error:
        raise BookError([f"{FIGURES_FILE}: not found"]) from error
    except json.JSONDecodeError as error:
        raise BookError([f"{FIGURES_FILE}:{error.lineno}: not valid JSON: {error.msg}"]) from error
    if not isinstance(entries, list):
        raise BookError([f"{FIGURES_FILE}: expected a list of {{\"output\", \"command\"}} entries"])
    figures, problems = [], []
    for index, entry in enumerate(entries):
        where = f"{FIGURES_FILE}: entry {index}"
        if not isinstance(entry, dict) or set(entry) - {"output", "command", "description", "copy_from", "needs"}:
            problems.append(f"{where}: expected only the keys output, command, description, copy_from and needs")
            continue
        needs = entry.get("needs", [])
        if not (isinstance(needs, list) and all(isinstance(word, str) and word for word in needs)):
            problems.append(f"{where}: needs must be a list of build target names")
            continue
        copy_from = entry.get("copy_from", "")
        if not isinstance(copy_from, str) or Path(copy_from).is_absolute():
            problems.append(f"{where}: copy_from must be a path relative to the repository root")
            continue
        output, command = entry.get("output"), entry.get("command")
        if not isinstance(output, str) or not output or Path(output).is_absolute():
            problems.append(f"{where}: output must be a path relative to the repository root")
        elif not (isinstance(command, list) and command and all(isinstance(word, str) for word in command)):
            problems.append(f"{where} ({output}): command must be a non-empty list of strings")
        else:
            figures.append(Figure(output, command, entry.get("description", ""), copy_from, tuple(needs)))
    if problems:
        raise BookError(problems)
    return figures


def find_executable(build_dir: Path, name: str) -> Path | None:
    """BUILD_DIR/NAME or BUILD_DIR/chapters/NAME, if built."""
    for candidate in (build_dir / name, build_dir / "chapters" / name):
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return candidate
    return None


def render_figure(root: Path, build_dir: Path, figure: Figure, dry_run: bool) -> str | None:
    """Run one figure's command; returns a problem, or None when the figure was made."""
    if figure.command[0].endswith(".py"):
        if not (root / figure.command[0]).is_file():
            return f"{figure.output}: the script {figure.command[0]} does not exist"
        program = [sys.executable, figure.command[0]]
    else:
        executable = find_executable(build_dir, figure.command[0])
        if executable is None:
            return (f"{figure.output}: {figure.command[0]} is not built in {build_dir} or {build_dir}/chapters "
                    f"(cmake --build {build_dir} --target {figure.command[0]})")
        program = [str(executable)]
    command = program + [word.replace("{output}", figure.output).replace("{build_dir}", str(build_dir))
                         for word in figure.command[1:]]
    print(f"{figure.output}: {' '.join(command)}", flush=True)
    if dry_run:
        return None
    (root / figure.output).parent.mkdir(parents=True, exist_ok=True)
    started = time.monotonic()
    result = subprocess.run(command, cwd=root)
    if result.returncode != 0:
        return f"{figure.output}: the command failed with exit status {result.returncode}"
    if figure.copy_from:
        if not (root / figure.copy_from).is_file():
            return f"{figure.output}: the command succeeded but wrote no {figure.copy_from} to copy"
        shutil.copyfile(root / figure.copy_from, root / figure.output)
    if not (root / figure.output).is_file():
        return f"{figure.output}: the command succeeded but wrote no {figure.output}"
    size = (root / figure.output).stat().st_size
    print(f"regenerated {figure.output} ({size / 1024:.0f} kB, {time.monotonic() - started:.1f} s)")
    if size > FIGURE_SIZE_WARNING:
        print(f"book: warning: {figure.output} is {size / 1024:.0f} kB; keep committed figures small")
    return None


def command_figures(root: Path, build_dir: Path, only: str | None, dry_run: bool) -> int:
    """Regenerate the figures of book/figures.json (those whose output contains `only`)."""
    if not build_dir.is_dir():
        raise BookError([f"build folder {build_dir} does not exist; build first (cmake --build {build_dir})"])
    figures = [figure for figure in load_figures(root) if only is None or only in figure.output]
    if not figures:
        raise BookError([f"no figure in {FIGURES_FILE} matches '{only}'"])
    problems = [problem for figure in figures
                if (problem := render_figure(root, build_dir.resolve(), figure, dry_run)) is not None]
    if problems:
        raise BookError(problems)
    print(f"book: {len(figures)} figure(s) {'would be ' if dry_run else ''}regenerated")
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Keep the book's listings and figures in step with the code.")
    parser.add_argument("--root", type=Path, default=Path(__file__).resolve().parents[1],
                        help="repository root (default: the one holding this script)")
    commands = parser.add_subparsers(dest="command", required=True)
    commands.add_parser("check", help="fail when a listing differs from its source region")
    commands.add_parser("update", help="rewrite the listings from their source regions")
    figures = commands.add_parser("figures", help="regenerate the figures of book/figures.json")
    figures.add_argument("--build-dir", type=Path, required=True, help="the CMake build folder")
    figures.add_argument("--only", metavar="TEXT", help="only the figures whose output path contains TEXT")
    figures.add_argument("--dry-run", action="store_true", help="print the commands without running them")
    args = parser.parse_args(argv)

    root = args.root.resolve()
    try:
        if args.command == "check":
            return command_check(root)
        if args.command == "update":
            return command_update(root)
        return command_figures(root, args.build_dir, args.only, args.dry_run)
    except BookError as error:
        for problem in error.problems:
            print(f"book: {problem}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
