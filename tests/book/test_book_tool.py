#!/usr/bin/env python3
"""Unit tests of tools/book.py, on a tiny synthetic repository in a temporary folder.

    python3 tests/book/test_book_tool.py        (or: python3 -m unittest ...)
"""

from __future__ import annotations

import importlib.util
import io
import json
import sys
import tempfile
import textwrap
import unittest
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

sys.dont_write_bytecode = True
TOOL = Path(__file__).resolve().parents[2] / "tools" / "book.py"
spec = importlib.util.spec_from_file_location("book", TOOL)
book = importlib.util.module_from_spec(spec)
sys.modules["book"] = book  # dataclasses look their module up by name
spec.loader.exec_module(book)

WARPS_CPP = """\
#include "freezeray/ch01/warps.hpp"

namespace freezeray {

// BOOK(uniform-hemisphere)
// Inverting the CDF (PBR eq. 13.6).
Vec3 sample_uniform_hemisphere(const Vec2& u) {
    // EXERCISE(ch01/uniform-hemisphere): map u to the hemisphere
    const float z = u.x;
    return spherical_direction(z, u.y);
    // END EXERCISE
}
// END BOOK

    // BOOK(indented)
    int indented() {
        // BOOK(inner)
        return 1;   
        // END BOOK
    }
    // END BOOK

}  // namespace freezeray
"""

PAGE = """\
# Chapter 01

The warp:

<!-- BOOK(uniform-hemisphere) -->
<!-- END BOOK -->

An indented one:

<!-- BOOK(indented) -->
stale text
<!-- END BOOK -->

The end.
"""

# A stand-in renderer: writes "image" to the path after --out.
FAKE_RENDERER = """\
#!/usr/bin/env python3
import sys
from pathlib import Path
Path(sys.argv[sys.argv.index("--out") + 1]).write_text("image " + " ".join(sys.argv[1:]))
"""


class BookTool(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory(prefix="freezeray-book-test-")
        self.root = Path(self.folder.name)
        self.write("common/src/warps.cpp", WARPS_CPP)
        self.write("book/01-naive.md", PAGE)
        self.write("book/README.md", "<!-- BOOK(not-a-page) -->\n")  # README is not a page

    def tearDown(self):
        self.folder.cleanup()

    def write(self, name: str, text: str) -> Path:
        path = self.root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
        return path

    def run_tool(self, *arguments: str) -> tuple[int, str, str]:
        """Run book.py's main on the synthetic root: (exit status, stdout, stderr)."""
        out, err = io.StringIO(), io.StringIO()
        with redirect_stdout(out), redirect_stderr(err):
            status = book.main(["--root", str(self.root), *arguments])
        return status, out.getvalue(), err.getvalue()

    def page(self) -> str:
        return (self.root / "book/01-naive.md").read_text()

    def test_update_writes_the_listings_and_check_then_passes(self):
        status, output, _ = self.run_tool("update")
        self.assertEqual(status, 0)
        self.assertIn("updated book/01-naive.md:5: BOOK(uniform-hemisphere)", output)
        self.assertIn(textwrap.dedent("""\
            <!-- BOOK(indented) -->
            *From `common/src/warps.cpp`*
            ```cpp
            int indented() {
                return 1;
            }
            ```
            <!-- END BOOK -->
            """), self.page())
        self.assertTrue(self.page().endswith("The end.\n"))
        self.assertEqual(self.run_tool("check")[0], 0)

    def test_exercise_solution_lines_are_hidden(self):
        self.run_tool("update")
        page = self.page()
        self.assertNotIn("const float z = u.x", page)
        self.assertNotIn("EXERCISE", page)
        self.assertIn("Vec3 sample_uniform_hemisphere(const Vec2& u) {\n"
                      "    // (exercise ch01/uniform-hemisphere: see the exercises at the end of this chapter)\n"
                      "}\n", page)

    def test_a_mutated_listing_fails_check_naming_it_and_update_repairs_it(self):
        self.run_tool("update")
        good = self.page()
        (self.root / "book/01-naive.md").write_text(good.replace("int indented() {", "int indented(int) {"))
        status, _, errors = self.run_tool("check")
        self.assertEqual(status, 1)
        self.assertIn("book/01-naive.md:", errors)
        self.assertIn("listing BOOK(indented) differs from its source common/src/warps.cpp:15", errors)
        self.assertIn("-int indented(int) {", errors)
        self.assertIn("+int indented() {", errors)
        self.assertEqual(self.run_tool("update")[0], 0)
        self.assertEqual(self.page(), good)
        self.assertEqual(self.run_tool("check")[0], 0)

    def test_a_changed_source_fails_check(self):
        self.run_tool("update")
        self.write("common/src/warps.cpp", WARPS_CPP.replace("return 1;", "return 2;"))
        status, _, errors = self.run_tool("check")
        self.assertEqual(status, 1)
        self.assertIn("BOOK(inner)", WARPS_CPP)  # the nested region's markers are not shown...
        self.assertIn("+    return 2;", errors)  # ...but its code is

    def test_a_listing_naming_no_region(self):
        self.write("book/02-more.md", "<!-- BOOK(missing) -->\n<!-- END BOOK -->\n")
        status, _, errors = self.run_tool("check")
        self.assertEqual(status, 1)
        self.assertIn("book/02-more.md:1: listing BOOK(missing) names no region", errors)

    def test_a_duplicated_region_tag(self):
        self.write("chapters/01-naive/src/other.cpp", "// BOOK(inner)\nint x;\n// END BOOK\n")
        status, _, errors = self.run_tool("check")
        self.assertEqual(status, 1)
        self.assertIn("BOOK(inner) is a duplicate", errors)
        self.assertIn("common/src/warps.cpp:17", errors)

    def test_unclosed_markers(self):
        self.write("common/src/open.cpp", "// BOOK(open)\nint x;\n")
        self.write("book/03.md", "<!-- BOOK(inner) -->\n")
        status, _, errors = self.run_tool("update")
        self.assertEqual(status, 1)
        self.assertIn("common/src/open.cpp:1: BOOK(open) is never closed", errors)

    def test_a_listing_that_cuts_an_exercise_is_refused(self):
        self.write("common/src/cut.cpp", textwrap.dedent("""\
            // BOOK(cut)
            void f() {
                // EXERCISE(ch01/f): do it
                secret();
            // END BOOK
                // END EXERCISE
            }
            """))
        self.write("book/02-cut.md", "<!-- BOOK(cut) -->\n<!-- END BOOK -->\n")
        status, _, errors = self.run_tool("check")
        self.assertEqual(status, 1)
        self.assertIn("BOOK(cut) ends inside exercise ch01/f", errors)

    def test_figures_run_from_the_build_folder(self):
        renderer = self.write("build/chapters/ch01", FAKE_RENDERER)
        renderer.chmod(0o755)
        self.write("book/figures.json", json.dumps([
            {"output": "book/figures/a.png", "command": ["ch01", "render", "s.json", "--out", "{output}"]},
        ]))
        status, output, _ = self.run_tool("figures", "--build-dir", str(self.root / "build"))
        self.assertEqual(status, 0)
        self.assertIn("regenerated book/figures/a.png", output)
        self.assertEqual((self.root / "book/figures/a.png").read_text(),
                         "image render s.json --out book/figures/a.png")

    def test_a_figure_copied_from_a_file_its_command_writes(self):
        renderer = self.write("build/chapters/ch01", FAKE_RENDERER)
        renderer.chmod(0o755)
        self.write("book/figures.json", json.dumps([
            {"output": "book/figures/b.png", "command": ["ch01", "render", "--out", "out/big/b.png"],
             "copy_from": "out/big/b.png"},
        ]))
        (self.root / "out/big").mkdir(parents=True)
        status, output, _ = self.run_tool("figures", "--build-dir", str(self.root / "build"))
        self.assertEqual(status, 0, output)
        self.assertEqual((self.root / "book/figures/b.png").read_text(), "image render --out out/big/b.png")

    def test_a_figure_made_by_a_script_of_the_repository(self):
        (self.root / "build").mkdir()
        self.write("tools/plot.py", textwrap.dedent("""\
            import sys
            from pathlib import Path
            out = Path(sys.argv[sys.argv.index("--out") + 1])
            out.parent.mkdir(parents=True, exist_ok=True)
            out.write_text("plot " + " ".join(sys.argv[1:]))
            """))
        self.write("book/figures.json", json.dumps([
            {"output": "book/figures/p.svg", "command": ["tools/plot.py", "--build-dir", "{build_dir}", "--out", "{output}"],
             "needs": ["ray-benchmark"]},
        ]))
        status, output, errors = self.run_tool("figures", "--build-dir", str(self.root / "build"))
        self.assertEqual(status, 0, errors)
        self.assertEqual((self.root / "book/figures/p.svg").read_text(),
                         f"plot --build-dir {self.root / 'build'} --out book/figures/p.svg")

    def test_figures_with_a_missing_renderer(self):
        (self.root / "build").mkdir()
        self.write("book/figures.json", json.dumps([{"output": "book/figures/a.png", "command": ["ch09"]}]))
        status, _, errors = self.run_tool("figures", "--build-dir", str(self.root / "build"))
        self.assertEqual(status, 1)
        self.assertIn("ch09 is not built", errors)

    def test_the_repository_figures_file_is_valid(self):
        figures = book.load_figures(TOOL.parents[1])
        # Figures go to book/figures/; intermediate files a later figure needs (references) go
        # to out/, which git ignores.
        self.assertTrue(all(figure.output.startswith(("book/figures/", "out/")) for figure in figures))


if __name__ == "__main__":
    unittest.main()
