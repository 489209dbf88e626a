"""The README's commands, outputs and numbers are the code's.

Facts checked:
- command (b) is exactly what CI runs (.ci/run), and command (a) installs the package
  and runs a `linecontact calc` command that succeeds;
- every `$ linecontact ...` example prints the lines the README shows (spaces
  collapsed; `...` stands for lines left out);
- every Python example prints exactly the text block that follows it;
- a number on a line, or in a sentence, that cites a benchmark record
  (tools/benchmarks/...) appears in that record, so a claimed figure cannot drift
  from the measurement; the same for every page of docs/ (and every record a page
  cites exists);
- every docs/ page the README names exists, and every page in docs/ is named (the map
  is complete);
- no figure that goes stale lives in the README (test counts, machine loads).
"""
from __future__ import annotations

import contextlib
import io
import re
import shlex
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text()
BLOCKS = re.findall(r"```(\w*)\n(.*?)```", README, re.S)


def _squash(text):
    return [" ".join(line.split()) for line in text.strip().splitlines()]


def _run_cli(command):
    from linecontact.calc.cli import main
    argv = shlex.split(command)
    assert argv[0] == "linecontact", command
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main(argv[1:])
    return status, out.getvalue(), err.getvalue()


def test_fresh_machine_commands():
    ci = (ROOT / ".ci" / "run").read_text().strip().splitlines()[-1]
    plain = [body.strip() for lang, body in BLOCKS if lang == ""]
    assert ci in plain, f"README's command (b) differs from .ci/run's: {ci}"
    main_job = next(b for b in plain if "pip install . &&" in b)
    status, out, err = _run_cli(main_job.split(" && ")[-1])
    assert status == 0, err
    assert "Universal curve (BEM)" in out


@pytest.mark.parametrize("block", [b for lang, b in BLOCKS if b.startswith("$ ")],
                         ids=lambda b: b.split("\n")[0][:60])
def test_cli_examples_print_what_the_readme_shows(block):
    lines = block.strip().splitlines()
    status, out, err = _run_cli(lines[0][2:])
    assert status == 0, err
    got = _squash(out)
    for shown in _squash("\n".join(lines[1:])):
        if shown == "...":
            continue
        assert shown in got, f"README shows a line the command does not print: {shown}"


def _python_examples():
    pairs = []
    for (lang, body), nxt in zip(BLOCKS, BLOCKS[1:] + [("", "")]):
        if lang == "python":
            pairs.append((body, nxt[1] if nxt[0] == "text" else None))
    return pairs


@pytest.mark.parametrize("code, shown", _python_examples(),
                         ids=lambda v: (v or "")[:40].replace("\n", " "))
def test_python_examples_print_what_the_readme_shows(code, shown):
    assert shown is not None, "every Python example is followed by its output"
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(code, "README.md", "exec"), {})
    assert out.getvalue().strip() == shown.strip()


RECORD = re.compile(r"tools/benchmarks/results/[\w.-]+\.txt")
FIGURE = re.compile(r"(?<![\w.])\d+\.\d+(?![\d.]*\d)")


def _sentences(text):
    """The sentences of a Markdown text: its paragraphs, list items and table rows, each
    split at full stops (code blocks left out)."""
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    for paragraph in re.split(r"\n\s*\n|\n(?=\s*(?:[-*|]|\d+\.) )", text):
        yield from re.split(r"(?<=[.!?])\s+(?=[A-Z(`])", " ".join(paragraph.split()))


def _unrecorded_figures(text):
    """(record, figure) for every decimal figure of a sentence that cites a benchmark
    record (tools/benchmarks/results/NAME.txt) and appears in none of the records it
    cites."""
    for sentence in _sentences(text):
        records = RECORD.findall(sentence)
        if not records:
            continue
        texts = [(ROOT / r.rstrip(".")).read_text() for r in records]
        for number in FIGURE.findall(sentence):
            if not any(number in t for t in texts):
                yield records, number


def test_benchmark_figures_are_the_records():
    """A figure quoted in the README in a sentence that cites a benchmark record is in
    that record (the record is the measurement; the README may not drift from it)."""
    for line in README.splitlines():
        for rec in re.findall(r"tools/benchmarks/[\w./-]+\.(?:txt|md)", line):
            text = (ROOT / rec).read_text()
            for number in re.findall(r"\d+\.\d+", line):
                assert number in text, f"README's {number} is not in {rec}"
    bad = list(_unrecorded_figures(README))
    assert not bad, f"README quotes figures its cited records do not hold: {bad}"


@pytest.mark.parametrize("page", sorted(p.name for p in (ROOT / "docs").glob("*.md")))
def test_docs_figures_are_the_records(page):
    """The same for every docs page: a figure in a sentence that cites a benchmark
    record appears in that record, and every cited record exists."""
    text = (ROOT / "docs" / page).read_text()
    for rec in RECORD.findall(text):
        assert (ROOT / rec.rstrip(".")).is_file(), f"docs/{page} cites a missing {rec}"
    bad = list(_unrecorded_figures(text))
    assert not bad, f"docs/{page} quotes figures its cited records do not hold: {bad}"


def test_docs_map_is_complete():
    named = set(re.findall(r"docs/([\w-]+\.md)", README))
    present = {p.name for p in (ROOT / "docs").glob("*.md")}
    assert named - present == set(), f"README names missing pages {named - present}"
    assert present - named == set(), f"pages missing from the README's map: {present - named}"


def test_no_stale_figures():
    for pattern in (r"\d+ tests", r"load average", r"\d+ s (CPU|wall)", r"passed"):
        assert not re.search(pattern, README), f"a figure that goes stale: {pattern}"
