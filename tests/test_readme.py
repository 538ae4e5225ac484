"""The examples of README.md and of every page under docs/ are real: every ``$ dyncalc ...``
line in a ``console`` block is run from the repository root and its output compared, line for
line, with the lines shown under it (stdout and stderr interleaved, as on a terminal); its exit
status must be the one the lines shown imply (2 after an ``Error:`` line, 1 after a failed
``--check``, else 0)."""
from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest
from click.testing import CliRunner

from dyncalc.cli import cli

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
PAGES = [README, *sorted((ROOT / "docs").rglob("*.md"))]
BLOCK = re.compile(r"^```console\n(.*?)^```", re.S | re.M)


def examples_of(text: str) -> list[tuple[str, list[str]]]:
    """The ``(command, lines shown)`` pairs of the ``console`` blocks of a Markdown text."""
    examples = []
    for block in BLOCK.findall(text):
        command, output = None, []
        for line in block.splitlines():
            if line.startswith("$ "):
                if command is not None:
                    examples.append((command, output))
                command, output = line[2:], []
            elif command is None:
                raise ValueError(f"a console block must start with '$ ': {line!r}")
            else:
                output.append(line)
        if command is not None:
            examples.append((command, output))
    return examples


def expected_status(lines: list[str]) -> int:
    """The exit status the lines shown imply (the contract's codes, SPEC "Exit status")."""
    if any(line.startswith("Error: ") for line in lines):
        return 2
    if any(re.match(r"check \S+: .*: FAIL\b", line) for line in lines):
        return 1
    return 0


def _collect():
    params = []
    for page in PAGES:
        name = page.relative_to(ROOT).as_posix()
        for command, output in examples_of(page.read_text(encoding="utf-8")):
            params.append(pytest.param(command, output, id=f"{name}: {command[:70]}"))
    return params


EXAMPLES = _collect()


def _count(page: Path) -> int:
    return len(examples_of(page.read_text(encoding="utf-8")))


def test_readme_has_a_tour():
    assert 5 <= _count(README) <= 14  # one line a command (rigid-body the 14th)


def test_every_guide_page_has_examples():
    for page in sorted((ROOT / "docs" / "guide").glob("*.md")):
        if page.name != "completion.md":  # completion is typed into a shell, not dyncalc
            assert _count(page) >= 1, page.name


def test_the_parser_reads_blocks_and_sees_a_changed_output():
    text = ("intro\n\n```console\n$ dyncalc a\none\n$ dyncalc b\n```\n\n```sh\n$ x\n```\n"
            "```console\n$ dyncalc c\nError: no\n```\n")
    assert examples_of(text) == [("dyncalc a", ["one"]), ("dyncalc b", []),
                                 ("dyncalc c", ["Error: no"])]
    with pytest.raises(ValueError, match="must start with"):
        examples_of("```console\nstray\n```\n")
    assert expected_status(["Error: no"]) == 2
    assert expected_status(["check f: expected 1 Hz, given 2 Hz, ...: FAIL; likely slip"]) == 1
    assert expected_status(["check f: expected 1 Hz, given 1 Hz, ...: pass"]) == 0
    # a wrong line shown is caught: the real output of a README example, one digit changed
    command, shown = examples_of(README.read_text(encoding="utf-8"))[0]
    result = CliRunner().invoke(cli, shlex.split(command)[1:])
    assert result.output.splitlines() == shown
    changed = [re.sub(r"\d", lambda m: str((int(m.group()) + 1) % 10), line, count=1)
               for line in shown]
    assert result.output.splitlines() != changed


@pytest.mark.parametrize("command, expected", EXAMPLES)
def test_example(command, expected, monkeypatch):
    monkeypatch.chdir(ROOT)  # examples read files such as docs/examples/*.csv
    words = shlex.split(command)
    assert words[0] == "dyncalc"
    result = CliRunner().invoke(cli, words[1:])
    shown = result.output.splitlines()  # stdout and stderr interleaved, as on a terminal
    assert shown == expected
    assert result.exit_code == expected_status(expected), result.output
