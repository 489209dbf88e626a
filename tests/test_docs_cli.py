"""The examples of docs/cli.md print what the page shows (the page is read as a user
reads it: each `$ linecontact ...` command and the lines below it, `...` eliding
columns or rows)."""

from __future__ import annotations

import contextlib
import io
import re
import shlex
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
CLI_MD = (ROOT / "docs" / "cli.md").read_text()


def _examples():
    """(command, shown lines) of each indented `$ linecontact` block."""
    out = []
    for block in re.findall(r"((?:^ {4,}.*\n?)+)", CLI_MD, re.M):
        lines = [line.strip() for line in block.splitlines() if line.strip()]
        if lines and lines[0].startswith("$ linecontact "):
            out.append((lines[0][2:], lines[1:]))
    return out


def _run(command):
    from linecontact.calc.cli import main
    argv = shlex.split(command)
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main(argv[1:])
        except SystemExit as exc:
            status = exc.code
    return status, out.getvalue() + err.getvalue()


@pytest.mark.parametrize("command,shown", _examples(), ids=lambda x: str(x)[:70])
def test_cli_page_examples_print_what_the_page_shows(command, shown):
    """Each shown line (its pieces between `...`, whitespace squashed) is printed, in
    the same line of the output: the page's tables are the program's."""
    status, text = _run(command)
    got = [" ".join(line.split()) for line in text.splitlines()]
    for line in shown:
        if line == "...":
            continue
        pieces = [" ".join(p.split()) for p in line.split("...") if p.strip()]
        assert any(all(p in g for p in pieces) for g in got), (
            f"docs/cli.md shows a line the command does not print: {line}\n{text}")
