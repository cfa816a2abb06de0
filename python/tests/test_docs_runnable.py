"""The documentation's runnable examples run (issue 31 item 10: the README's own `corlab dem`
example failed). Every fenced block opened with ```sh runnable in README.md and docs/user/*.md is
run line by line in a scratch directory (with data/, studies/ and tests/ of the source tree
beside it): each `corlab ...` command (a trailing backslash continues it) must exit 0, or N where
the line ends in `# exit N`. Other blocks are not run: mark a block runnable only when all its
commands finish in seconds."""
# SPDX-License-Identifier: BSD-3-Clause
import os
import pathlib
import re
import shlex
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
DOCS = [ROOT / "README.md"] + sorted((ROOT / "docs" / "user").glob("*.md"))
FENCE = re.compile(r"^\s*```(.*)$")


def runnable_blocks(path):
    """[(first line number, [(line number, command, expected exit)])] of the file's runnable
    blocks."""
    blocks, current, pending, start = [], None, "", 0
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        fence = FENCE.match(line)
        if fence and current is None:
            if fence.group(1).split()[:2] == ["sh", "runnable"]:
                current = (number, [])
            else:
                current = (number, None)  # a block that is not run
            continue
        if fence:
            if current[1] is not None:
                blocks.append(current)
            current = None
            continue
        if current is None or current[1] is None:
            continue
        text = line.strip()
        if not pending and (not text or text.startswith("#")):
            continue
        if not pending:
            start = number
        if text.endswith("\\"):
            pending += text[:-1] + " "
            continue
        command = pending + text
        pending = ""
        exit_code = re.search(r"#\s*exit (\d+)\s*$", command)
        current[1].append((start, command, int(exit_code.group(1)) if exit_code else 0))
    return blocks


ALL = [(path, block) for path in DOCS for block in runnable_blocks(path)]


def test_the_readme_has_runnable_examples():
    assert any(path.name == "README.md" for path, _ in ALL), \
        "README.md has no ```sh runnable block (its quick examples must stay tested)"


@pytest.mark.parametrize("path, block", ALL,
                         ids=[f"{p.relative_to(ROOT)}:{b[0]}" for p, b in ALL])
def test_runnable_block(path, block, tmp_path, corlab_bin):
    for name in ("data", "studies", "tests", "examples"):
        os.symlink(ROOT / name, tmp_path / name)
    for number, command, expected in block[1]:
        args = shlex.split(command, comments=True)
        where = f"{path.relative_to(ROOT)}:{number}: {command}"
        assert args[0] == "corlab", f"{where}: a runnable line runs corlab"
        done = subprocess.run([corlab_bin] + args[1:], cwd=tmp_path, capture_output=True,
                              text=True, timeout=300)
        assert done.returncode == expected, f"{where}: exit {done.returncode}\n{done.stderr}"
        if expected == 2:
            assert done.stderr.count("\n") == 1 and done.stderr.startswith("corlab: error: "), \
                f"{where}: not a one-line error: {done.stderr}"
