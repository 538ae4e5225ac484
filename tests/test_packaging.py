"""Packaging: the licence (SPDX expression, LICENSE file), the version, the changelog, and the
built artefacts: the wheel holds what the installed tool needs, the sdist what its tests need,
and the build itself says no warning (PEP 639 licence metadata)."""
from __future__ import annotations

import re
import subprocess
import sys
import tarfile
import tomllib
import zipfile
from importlib.metadata import version
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
#: What the sdist must carry besides the package: its tests, what they read, the benchmarks.
SDIST_TREES = ("tests", "docs", "tools", "benchmarks", ".ci")
SDIST_FILES = ("README.md", "LICENSE", "CHANGELOG.md", "pyproject.toml")


def test_version_is_2_0_0_everywhere():
    import dyncalc

    assert dyncalc.__version__ == "2.0.0"
    assert version("dyncalc") == "2.0.0", "reinstall: pip install -e '.[test]'"


def test_licence_is_an_spdx_expression_with_its_file():
    project = PYPROJECT["project"]
    assert project["license"] == "MIT"
    assert project["license-files"] == ["LICENSE"]
    text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("MIT License\n\nCopyright (c) ")
    assert "dyncalc developers" in text.splitlines()[2]
    assert "THE SOFTWARE IS PROVIDED \"AS IS\", WITHOUT WARRANTY OF ANY KIND" in text
    # PEP 639 (license as a string, license-files) needs setuptools 77
    (requirement,) = PYPROJECT["build-system"]["requires"]
    assert requirement == "setuptools>=77"


def test_changelog_has_unreleased_then_2_0_0():
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    headings = re.findall(r"^## (.+)$", text, flags=re.M)
    assert headings[0] == "[Unreleased]"
    assert re.fullmatch(r"\[2\.0\.0\] - \d{4}-\d{2}-\d{2}", headings[1]), headings[1]
    assert "keepachangelog.com" in text
    section = text.split("## [2.0.0]")[1]
    for kind in ("### Added", "### Changed"):
        assert kind in section


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    """The sdist and the wheel, built as CI builds them (``python -m build``)."""
    out = tmp_path_factory.mktemp("dist")
    run = subprocess.run([sys.executable, "-m", "build", "--outdir", str(out), str(ROOT)],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    (sdist,) = out.glob("dyncalc-2.0.0.tar.gz")
    (wheel,) = out.glob("dyncalc-2.0.0-py3-none-any.whl")
    return run.stdout + run.stderr, sdist, wheel


def test_build_says_no_warning(built):
    log, _sdist, _wheel = built
    # "byte-compiling is disabled" is the environment's choice (PYTHONDONTWRITEBYTECODE);
    # the lines that only list the files copied or added name test files such as
    # test_batch_warning_lines.py, so they are not read as warnings
    listing = re.compile(r"^(copying|adding|hard linking|creating|removing) ")
    noisy = [line for line in log.splitlines()
             if re.search(r"(?i)warn|deprecat", line)
             and not listing.match(line.strip())
             and "byte-compiling is disabled" not in line]
    assert noisy == []


def test_wheel_holds_what_the_installed_tool_needs(built):
    _log, _sdist, wheel = built
    with zipfile.ZipFile(wheel) as zf:
        names = set(zf.namelist())
        metadata = zf.read("dyncalc-2.0.0.dist-info/METADATA").decode()
        entry_points = zf.read("dyncalc-2.0.0.dist-info/entry_points.txt").decode()
    assert "dyncalc-2.0.0.dist-info/licenses/LICENSE" in names
    assert "dyncalc/py.typed" in names
    assert "dyncalc/result/schema/dyncalc-2.schema.json" in names
    # completions come from the installed program itself (click), no file to ship
    assert "dyncalc/cli/__init__.py" in names
    assert "License-Expression: MIT\n" in metadata
    assert "License-File: LICENSE\n" in metadata
    assert "dyncalc = dyncalc.quick:main" in entry_points
    assert not any(n.startswith(("tests/", "docs/", "tools/")) for n in names)
    package = {p.relative_to(ROOT).as_posix() for p in (ROOT / "dyncalc").rglob("*.py")
               if "__pycache__" not in p.parts}
    assert package <= names, sorted(package - names)


def test_sdist_holds_what_the_tests_need(built):
    _log, sdist, _wheel = built
    with tarfile.open(sdist) as tf:
        names = {n.partition("/")[2] for n in tf.getnames()}
    expected = set(SDIST_FILES)
    for tree in SDIST_TREES:
        expected |= {p.relative_to(ROOT).as_posix() for p in (ROOT / tree).rglob("*")
                     if p.is_file() and "__pycache__" not in p.parts and p.suffix != ".pyc"}
    expected |= {p.relative_to(ROOT).as_posix() for p in (ROOT / "dyncalc").rglob("*")
                 if p.is_file() and "__pycache__" not in p.parts and p.suffix != ".pyc"}
    assert expected <= names, sorted(expected - names)
    assert not any("__pycache__" in n or n.endswith(".pyc") for n in names)
