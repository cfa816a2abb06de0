#!/usr/bin/env python3
"""SPDX licence lines in corlab's source files (LICENSE: BSD-3-Clause).

Every tracked source file (C and C++, Python, CMake, shell, TOML, Gmsh .geo, the explorer's
HTML, CSS and JavaScript, the Makefile and the packaging scripts) carries the line
`SPDX-License-Identifier: BSD-3-Clause` in its own comment syntax. The line goes after the file's
opening description, which stays first:
- after a shebang and the leading comment block (the contiguous comment lines at the top);
- in Python, after the module docstring when there is one;
- in C with a leading /* ... */ block, in HTML with a leading <!-- ... --> block: after it.
A file with no leading comment gets the line first (after a shebang or <!DOCTYPE>).

    scripts/lint/spdx_headers.py --check   # lists the files without the line, exit 1 if any
    scripts/lint/spdx_headers.py --fix     # adds the line where it is missing (idempotent)

Data files (CSV, JSON, meshes, Markdown) are not source files: each data folder states its terms
in its README.md. Fuzz corpora, packaging/debian/copyright and the generated dataset specs are
left out (EXCLUDED).
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import ast
import pathlib
import re
import subprocess
import sys

LICENSE = "BSD-3-Clause"
ROOT = pathlib.Path(__file__).resolve().parents[2]
MARKER = re.compile(r"^\s*(#|//|/\*|\*|<!--)\s*SPDX-License-Identifier:\s*(\S+)")
# (glob patterns, comment syntax): "#", "//", "/*" (one-line /* ... */), "<!--".
KINDS = [
    (("*.cpp", "*.hpp"), "//"),
    (("*.c", "*.h", "*.css"), "/*"),
    (("*.js", "*.geo"), "//"),
    (("*.html",), "<!--"),
    (("*.py", "*.sh", "*.cmake", "*.cmake.in", "*.pc.in", "*.toml", "CMakeLists.txt", "Makefile",
      ".ci/run", "packaging/debian/*"), "#"),
]
# Left out: fuzz corpora (inputs kept byte for byte), the licence statement itself, and the
# dataset specs `corlab dataset design` writes (a unit test compares them with its output).
EXCLUDED = ("tests/fuzz/", "packaging/debian/copyright", "studies/dataset/fe_restitution.toml",
            "studies/dataset/fe_restitution_pairs.toml")


def comment_syntax(path):
    """The comment syntax of a tracked path, or None when it is not a source file."""
    rel = pathlib.PurePosixPath(path)
    if str(rel).startswith(EXCLUDED):
        return None
    for patterns, syntax in KINDS:
        if any(rel.match(p) or str(rel) == p for p in patterns):
            return syntax
    return None


def spdx_line(syntax):
    text = f"SPDX-License-Identifier: {LICENSE}"
    return {"#": f"# {text}", "//": f"// {text}", "/*": f"/* {text} */",
            "<!--": f"<!-- {text} -->"}[syntax]


def leading_block_end(lines, start, syntax):
    """Index after the file's leading comment block that begins at `start` (start if none)."""
    if start >= len(lines):
        return start
    if syntax in ("/*", "<!--"):
        opener, closer = ("/*", "*/") if syntax == "/*" else ("<!--", "-->")
        if not lines[start].lstrip().startswith(opener):
            return start
        for i in range(start, len(lines)):
            if closer in lines[i]:
                return i + 1
        return start
    i = start
    while i < len(lines) and lines[i].startswith(syntax):
        i += 1
    return i


def insertion_index(text, lines, syntax, is_python):
    """Where the SPDX line goes: after a shebang/doctype and the opening description."""
    start = 1 if lines and (lines[0].startswith("#!") or lines[0].startswith("<!DOCTYPE")) else 0
    if is_python:
        module = ast.parse(text)
        first = module.body[0] if module.body else None
        if (isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant)
                and isinstance(first.value.value, str)):
            return first.end_lineno
    return leading_block_end(lines, start, syntax)


def licence_of(lines):
    """The identifier of the file's SPDX line, or None."""
    for line in lines:
        match = MARKER.match(line)
        if match:
            return match.group(2).rstrip("*/-> ").strip()
    return None


def with_header(path, text):
    """The file's text with the SPDX line added (the same text when it has one)."""
    syntax = comment_syntax(path)
    lines = text.splitlines(keepends=True)
    if syntax is None or licence_of(lines) is not None:
        return text
    index = insertion_index(text, lines, syntax, path.endswith(".py"))
    if index > 0 and not lines[index - 1].endswith("\n"):
        lines[index - 1] += "\n"
    lines.insert(index, spdx_line(syntax) + "\n")
    return "".join(lines)


def tracked_files():
    out = subprocess.run(["git", "ls-files"], cwd=ROOT, check=True, capture_output=True,
                         text=True).stdout
    return [p for p in out.splitlines() if comment_syntax(p) and (ROOT / p).is_file()]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--check", action="store_true", help="list files without the SPDX line")
    mode.add_argument("--fix", action="store_true", help="add the SPDX line where it is missing")
    args = parser.parse_args(argv)
    missing, wrong = [], []
    for rel in tracked_files():
        path = ROOT / rel
        text = path.read_text(encoding="utf-8")
        found = licence_of(text.splitlines())
        if found is not None and found != LICENSE:
            wrong.append(f"{rel}: SPDX-License-Identifier {found}, expected {LICENSE}")
        elif found is None:
            missing.append(rel)
            if args.fix:
                path.write_text(with_header(rel, text), encoding="utf-8")
    for line in wrong:
        print(f"spdx_headers: {line}", file=sys.stderr)
    if args.fix:
        print(f"spdx_headers: added the SPDX line to {len(missing)} files")
        return 1 if wrong else 0
    for rel in missing:
        print(f"spdx_headers: no SPDX-License-Identifier line: {rel}", file=sys.stderr)
    if missing:
        print(f"spdx_headers: {len(missing)} files lack the line; run "
              "scripts/lint/spdx_headers.py --fix", file=sys.stderr)
    return 1 if missing or wrong else 0


if __name__ == "__main__":
    sys.exit(main())
