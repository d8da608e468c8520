#!/usr/bin/env python3
"""Make a student copy of FreezeRay: the same tree with every exercise region stubbed out.

    tests/grading/make_student_copy.py SRC DEST [--only ch01/name | --chapter ch01] [--update]

The lines between `// EXERCISE(name): ...` and `// END EXERCISE` are replaced by

    throw ::freezeray::ExerciseNotImplemented("name");

which compiles in any function whatever its return type and fails loudly, naming the
exercise. The marker lines stay, so students see where to work. A file that does not
already include freezeray/error.hpp (directly or through another project header) gets
`#include "freezeray/error.hpp"` after its last #include line.

Which files are copied: in a git checkout, the tracked files plus the untracked files git
does not ignore (`git ls-files --cached --others --exclude-standard`); otherwise every
file except .git, top-level build*/ folders and any CMake build tree.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

sys.dont_write_bytecode = True  # keep __pycache__ out of the source tree
sys.path.insert(0, str(Path(__file__).resolve().parent))
import exercises  # noqa: E402  (the shared parsing module beside this script)

# Written at the top of DEST so that --update knows it may rewrite and prune the folder.
COPY_MARKER = ".freezeray-student-copy"

INCLUDE_LINE = re.compile(r'^\s*#\s*include\s*[<"](?P<header>[^>"]+)[>"]')
QUOTED_INCLUDE = re.compile(r'^\s*#\s*include\s*"(?P<header>[^"]+)"', re.MULTILINE)
PRAGMA_ONCE = re.compile(r"^\s*#\s*pragma\s+once\b")


# --- Which files make up the tree -------------------------------------------------------------

def list_files(source: Path, exclude: Path | None = None) -> list[Path]:
    """The files of the tree at source, relative to it, without `exclude` (e.g. DEST) or build trees."""
    files = git_files(source)
    if files is None:
        files = walked_files(source)
    build_trees = {path.parent for path in files if path.name == "CMakeCache.txt"}
    kept = []
    for path in files:
        if any(tree != Path(".") and tree in path.parents for tree in build_trees):
            continue
        if exclude is not None and is_inside(source / path, exclude):
            continue
        if (source / path).is_file() or (source / path).is_symlink():
            kept.append(path)
    return sorted(kept)


def git_files(source: Path) -> list[Path] | None:
    """Tracked plus untracked-but-not-ignored files, or None when source is not a git checkout."""
    if not (source / ".git").exists():
        return None
    try:
        result = subprocess.run(
            ["git", "-C", str(source), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
            capture_output=True, check=True)
    except (OSError, subprocess.CalledProcessError):
        return None
    names = [name for name in result.stdout.decode("utf-8").split("\0") if name]
    return [Path(name) for name in names] or None


def walked_files(source: Path) -> list[Path]:
    """Every file under source except .git, __pycache__, top-level build*/ folders and build trees."""
    files = []
    for folder, subfolders, filenames in os.walk(source):
        here = Path(folder)
        relative = here.relative_to(source)
        if here != source and (here / "CMakeCache.txt").exists():
            subfolders[:] = []
            continue
        subfolders[:] = sorted(name for name in subfolders
                               if name not in (".git", "__pycache__")
                               and not (relative == Path(".") and name.startswith("build")))
        files.extend(relative / name for name in filenames)
    return files


def is_inside(path: Path, folder: Path) -> bool:
    """True when path is folder or lies below it."""
    try:
        path.resolve().relative_to(folder.resolve())
        return True
    except ValueError:
        return False


# --- Stubbing ---------------------------------------------------------------------------------

def stub_regions(text: str, regions: list[exercises.Region]) -> str:
    """Replace the lines inside each region (all in this file) by the stub; keep the markers."""
    lines = text.splitlines(keepends=True)
    for region in sorted(regions, key=lambda r: r.start, reverse=True):
        marker = lines[region.start - 1]
        newline = marker[len(marker.rstrip("\r\n")):] or "\n"
        stub = region.indent + exercises.STUB_TEMPLATE.format(name=region.name) + newline
        lines[region.start:region.end - 1] = [stub]
    return "".join(lines)


def add_error_include(text: str) -> str:
    """Insert `#include "freezeray/error.hpp"` after the last #include (or #pragma once, or at the top)."""
    lines = text.splitlines(keepends=True)
    newline = "\r\n" if lines and lines[0].endswith("\r\n") else "\n"
    include = f'#include "{exercises.ERROR_HEADER}"{newline}'
    position = 0
    for index, line in enumerate(lines):
        if INCLUDE_LINE.match(line) or (position == 0 and PRAGMA_ONCE.match(line)):
            position = index + 1
    if position > 0 and not lines[position - 1].endswith("\n"):
        lines[position - 1] += newline
    lines.insert(position, include)
    return "".join(lines)


def include_roots(root: Path) -> list[Path]:
    """The folders quoted #includes are resolved against: common/include or each room's include
    folder in common/ (common/*/include), and chapters/*/include."""
    roots = [root / "common" / "include", *sorted((root / "common").glob("*/include"))]
    roots.extend(sorted((root / "chapters").glob("*/include")))
    return [folder for folder in roots if folder.is_dir()]


def includes_matching(path: Path, roots: list[Path], matches, seen: set[Path] | None = None) -> bool:
    """True when the file includes, directly or through project headers, a header for which
    matches(name as the #include writes it, the resolved file or None) holds. Quoted includes are
    resolved against the file's folder, then `roots`."""
    seen = set() if seen is None else seen
    if path in seen or not path.is_file():
        return False
    seen.add(path)
    text = path.read_text(encoding="utf-8", errors="replace")
    for match in QUOTED_INCLUDE.finditer(text):
        header = match["header"]
        found = next((folder / header for folder in [path.parent, *roots] if (folder / header).is_file()), None)
        resolved = found.resolve() if found is not None else None
        if matches(header, resolved):
            return True
        if resolved is not None and includes_matching(resolved, roots, matches, seen):
            return True
    return False


def includes_error_header(path: Path, roots: list[Path]) -> bool:
    """True when the file includes freezeray/error.hpp, directly or through project headers."""
    return includes_matching(path, roots, lambda header, _: header == exercises.ERROR_HEADER)


def includes_any(path: Path, targets: set[Path], roots: list[Path]) -> bool:
    """True when the file includes one of `targets` (resolved paths), directly or through project headers."""
    return includes_matching(path, roots, lambda _, resolved: resolved in targets)


# What a stub leaves unused (the parameters, locals and helpers its region used) would show as
# warnings the student takes for their own mistakes. They are turned off in the stubbed files
# alone, by pragmas around the file, so that every other file of the copy compiles with exactly
# the solution's command line and the compiler cache gives the student build the solution's
# objects for them (cmake/CompilerCache.cmake).
QUIET_UNUSED = ("-Wunused-parameter", "-Wunused-variable", "-Wunused-but-set-variable", "-Wunused-function")


def quiet_unused_warnings(text: str) -> str:
    """Wrap a stubbed file in `#pragma GCC diagnostic` push/ignored/pop for QUIET_UNUSED (after
    `#pragma once` in a header)."""
    lines = text.splitlines(keepends=True)
    newline = "\r\n" if lines and lines[0].endswith("\r\n") else "\n"
    opening = [f"// The exercise stubs below leave names unused until you write them: no warning for that.{newline}",
               f"#pragma GCC diagnostic push{newline}",
               *(f'#pragma GCC diagnostic ignored "{flag}"{newline}' for flag in QUIET_UNUSED)]
    position = next((i + 1 for i, line in enumerate(lines) if PRAGMA_ONCE.match(line)), 0)
    if lines and not lines[-1].endswith("\n"):
        lines[-1] += newline
    return "".join(lines[:position] + opening + lines[position:] + [f"#pragma GCC diagnostic pop{newline}"])


SOURCE_SUFFIXES = (".cpp", ".cc", ".hpp", ".h", ".inl")


def student_text(source: Path, path: Path, regions: list[exercises.Region], roots: list[Path]) -> str:
    """The student version of one source file: its regions stubbed, error.hpp included, the
    warnings of what the stubs leave unused turned off in it."""
    text = (source / path).read_text(encoding="utf-8")
    stubbed = stub_regions(text, regions)
    if not includes_error_header((source / path).resolve(), roots):
        stubbed = add_error_include(stubbed)
    return quiet_unused_warnings(stubbed)


# --- Writing the copy -------------------------------------------------------------------------

def prepare_destination(destination: Path, update: bool) -> None:
    """Create DEST; refuse to write into a non-empty folder we did not make unless it is a copy."""
    if destination.exists():
        if not destination.is_dir():
            raise SystemExit(f"error: {destination} exists and is not a folder")
        is_copy = (destination / COPY_MARKER).is_file()
        if any(destination.iterdir()) and not (update and is_copy):
            hint = ("pass --update to refresh it" if is_copy
                    else "choose a new or empty folder")
            raise SystemExit(f"error: {destination} is not empty; {hint}")
    destination.mkdir(parents=True, exist_ok=True)


def write_if_changed(target: Path, content: bytes, mode: int) -> bool:
    """Write content unless the file already holds it (so incremental builds stay incremental)."""
    if target.is_file() and not target.is_symlink() and target.read_bytes() == content:
        return False
    if target.is_symlink():
        target.unlink()
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_bytes(content)
    os.chmod(target, mode & 0o7777)
    return True


def remove_stale_files(destination: Path, keep: set[Path]) -> int:
    """Delete the files of an earlier copy that are no longer part of the tree; return how many.

    Build trees, top-level build*/ folders and .git inside the copy are left alone."""
    removed = 0
    emptied: set[Path] = set()
    for folder, subfolders, filenames in os.walk(destination):
        here = Path(folder)
        relative = here.relative_to(destination)
        subfolders[:] = [name for name in subfolders
                         if name != ".git"
                         and not (relative == Path(".") and name.startswith("build"))
                         and not (here / name / "CMakeCache.txt").exists()]
        for name in filenames:
            path = relative / name
            if path not in keep and path != Path(COPY_MARKER):
                (here / name).unlink()
                removed += 1
                emptied.add(here)
    for folder in sorted(emptied, key=lambda path: len(path.parts), reverse=True):
        while folder != destination and folder.is_dir() and not any(folder.iterdir()):
            folder.rmdir()
            folder = folder.parent
    return removed


def make_student_copy(source: Path, destination: Path, only: str | None = None,
                      chapter: str | None = None, update: bool = False, stub: bool = True) -> dict[str, int]:
    """Copy source to destination with the chosen regions stubbed (none with stub=False: a copy of
    the solution). Returns counts for the summary."""
    source = source.resolve()
    regions = exercises.select_regions(exercises.find_regions(source), only=only, chapter=chapter) if stub else []
    prepare_destination(destination, update)
    by_file: dict[Path, list[exercises.Region]] = {}
    for region in regions:
        by_file.setdefault(region.path, []).append(region)

    files = list_files(source, exclude=destination)
    roots = include_roots(source)
    stubbed_headers = {(source / p).resolve() for p in by_file if p.suffix in (".hpp", ".h", ".inl")}
    written = 0
    for path in files:
        origin = source / path
        target = destination / path
        if origin.is_symlink():
            if target.is_symlink() and os.readlink(target) == os.readlink(origin):
                continue
            if target.exists() or target.is_symlink():
                target.unlink()
            target.parent.mkdir(parents=True, exist_ok=True)
            target.symlink_to(os.readlink(origin))
            written += 1
            continue
        if path in by_file:
            content = student_text(source, path, by_file[path], roots).encode("utf-8")
        elif path.suffix in SOURCE_SUFFIXES and stubbed_headers and includes_any(origin.resolve(), stubbed_headers, roots):
            # It includes a stubbed header, so it compiles anew anyway; what the stub there leaves
            # unused may be defined here (a helper only the solution called).
            content = quiet_unused_warnings(origin.read_text(encoding="utf-8")).encode("utf-8")
        else:
            content = origin.read_bytes()
        written += write_if_changed(target, content, origin.stat().st_mode)
    missing = set(by_file) - set(files)
    if missing:
        names = ", ".join(sorted(p.as_posix() for p in missing))
        raise SystemExit(f"error: regions in files that are not part of the copy (ignored by git?): {names}")

    (destination / COPY_MARKER).write_text(
        f"This tree is a FreezeRay student copy made by tests/grading/make_student_copy.py.\n"
        f"Stubbed exercises: {', '.join(sorted(r.name for r in regions)) or 'none'}\n",
        encoding="utf-8")
    removed = remove_stale_files(destination, set(files)) if update else 0
    return {"files": len(files), "written": written, "removed": removed,
            "stubbed": len(regions), "stubbed_files": len(by_file)}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description="Copy the FreezeRay tree with every exercise region replaced by a failing stub.")
    parser.add_argument("source", type=Path, help="the repository (with solutions)")
    parser.add_argument("destination", type=Path, help="the folder to create (new or empty)")
    choice = parser.add_mutually_exclusive_group()
    choice.add_argument("--only", metavar="NAME", help="stub only this exercise, e.g. ch01/uniform-hemisphere")
    choice.add_argument("--chapter", metavar="chNN", help="stub only this chapter's exercises")
    parser.add_argument("--update", action="store_true",
                        help="refresh an earlier student copy in place: rewrite only changed files and "
                             "delete files no longer in the source (build folders are kept)")
    args = parser.parse_args(argv)

    if not args.source.is_dir():
        parser.error(f"{args.source} is not a folder")
    if is_inside(args.source, args.destination):
        parser.error("the destination must not contain the source")
    try:
        counts = make_student_copy(args.source, args.destination, only=args.only,
                                   chapter=args.chapter, update=args.update)
    except exercises.MarkerError as error:
        print(error, file=sys.stderr)
        print("error: fix the exercise markers first", file=sys.stderr)
        return 1
    except ValueError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    print(f"student copy in {args.destination}: {counts['files']} files "
          f"({counts['written']} written, {counts['removed']} removed), "
          f"{counts['stubbed']} exercise(s) stubbed in {counts['stubbed_files']} file(s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
