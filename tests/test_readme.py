"""The README's examples are real: every ``$ dyncalc ...`` line in a ``console`` block is run
and its output compared with the lines shown under it."""
import re
import shlex
from pathlib import Path

import pytest
from click.testing import CliRunner

from dyncalc.cli import cli

README = Path(__file__).resolve().parents[1] / "README.md"


def _examples():
    text = README.read_text(encoding="utf-8")
    examples = []
    for block in re.findall(r"```console\n(.*?)```", text, re.S):
        command, output = None, []
        for line in block.splitlines():
            if line.startswith("$ "):
                if command is not None:
                    examples.append((command, output))
                command, output = line[2:], []
            else:
                output.append(line)
        if command is not None:
            examples.append((command, output))
    return examples


EXAMPLES = _examples()


def test_readme_has_examples():
    assert len(EXAMPLES) >= 10


@pytest.mark.parametrize("command, expected", EXAMPLES, ids=[c for c, _ in EXAMPLES])
def test_readme_example(command, expected, monkeypatch):
    monkeypatch.chdir(README.parent)  # examples read files such as docs/examples/*.csv
    words = shlex.split(command)
    assert words[0] == "dyncalc"
    result = CliRunner().invoke(cli, words[1:])
    shown = result.output.splitlines()  # stdout and stderr interleaved, as on a terminal
    assert shown == expected
