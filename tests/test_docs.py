"""The generated scene catalog: the committed ``docs/scenes.md`` is what ``tools/gen_docs.py``
makes from the scene data now, the generator is deterministic and sees a change in the data,
and the page says what the CLI really gives (result names, canonical units, example values)."""
from __future__ import annotations

import importlib.util
import json
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from dyncalc.cli import cli
from dyncalc.scenes.runner import scene_kind
from dyncalc.scenes import catalog

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
SCENES = list(catalog().values())
IDS = [s.name for s in SCENES]
#: The scenes natural-frequency computes (the others' cards show the refusal and eom).
COMPUTED = [s for s in SCENES if not s.no_frequency]
COMPUTED_IDS = [s.name for s in COMPUTED]


@pytest.fixture(scope="module")
def gen():
    spec = importlib.util.spec_from_file_location("gen_docs", ROOT / "tools" / "gen_docs.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def page(gen):
    return gen.generate()["scenes.md"]


def _section(page: str, name: str) -> str:
    """The part of the page under ``## name``, up to the next ``## `` heading."""
    match = re.search(rf"^## {re.escape(name)}\n(.*?)(?=^## |\Z)", page, re.S | re.M)
    assert match, f"docs/scenes.md has no section for {name}"
    return match.group(1)


def _table_after(section: str, title: str) -> list[list[str]]:
    """The rows (cells stripped, header and rule left out) of the table after ``title``."""
    rows = []
    for line in section[section.index(title):].splitlines():
        if not line.startswith("|"):
            break
        rows.append([c.strip() for c in re.split(r"(?<!\\)\|", line)[1:-1]])
    return rows[2:]


def _cli_json(example: str) -> dict:
    words = shlex.split(example)
    result = CliRunner().invoke(cli, [*words[1:], "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


# --- the committed file --------------------------------------------------------------------------

def test_committed_page_matches_the_generator(page):
    path = DOCS / "scenes.md"
    assert path.is_file(), "docs/scenes.md is missing; run `python tools/gen_docs.py`"
    assert path.read_bytes() == page.encode("utf-8"), (
        "docs/scenes.md differs from what the scene catalog generates; run "
        "`python tools/gen_docs.py` and commit the result")


def test_generation_is_deterministic(gen, page):
    assert gen.generate()["scenes.md"] == page
    assert str(ROOT) not in page
    assert "\r" not in page
    assert page.endswith("\n") and not page.endswith("\n\n")


def test_generated_files(gen):
    assert sorted(gen.generate()) == ["commands.md", "scenes.md"]


# --- the commands page, from the Command records -------------------------------------------

def test_committed_commands_page_matches_the_records(gen):
    path = DOCS / "commands.md"
    assert path.is_file(), "docs/commands.md is missing; run `python tools/gen_docs.py`"
    assert path.read_bytes() == gen.generate()["commands.md"].encode("utf-8"), (
        "docs/commands.md differs from what the Command records generate; run "
        "`python tools/gen_docs.py` and commit the result")


def test_commands_page_lists_every_parameter_and_result(gen):
    from dyncalc.cli import cli

    text = gen.generate()["commands.md"]
    for name, command in cli.commands.items():
        if name == "scenes":
            continue
        assert f"\n## {name}\n" in text
        section = text.split(f"\n## {name}\n", 1)[1].split("\n## ", 1)[0]
        for p in command.record.parameters:
            assert f"| `{p.flag} {p.metavar}` |" in section, (name, p.name)
        for r in command.record.results:
            assert f"| `{r.name}` |" in section, (name, r.name)


def test_a_changed_record_changes_the_commands_page(gen):
    from dyncalc.commands.rolling_onset import COMMAND
    from dyncalc.commands.record import Command

    values = {slot: getattr(COMMAND, slot) for slot in Command.__slots__}
    values["parameters"] = values["parameters"][:-1]
    changed = Command(**values)
    records = gen.command_records()
    page = gen.render_commands(records)
    other = gen.render_commands([changed if r.name == "rolling-onset" else r for r in records])
    assert "`--method METHOD`" in page.split("## rolling-onset", 1)[1]
    assert "`--method METHOD`" not in other.split("## rolling-onset", 1)[1]


# --- the generator sees the data ---------------------------------------------------------------

def test_a_changed_summary_changes_the_page(gen, page):
    scenes = dict(catalog())
    scenes["drum-block-spring"] = scenes["drum-block-spring"].replace(
        summary="a drum that is not the textbook's")
    changed = gen.render_catalog(scenes)
    assert changed != page
    assert "a drum that is not the textbook's" in changed
    assert "A drum that is not the textbook's." in _section(changed, "drum-block-spring")
    assert "a drum that is not the textbook's" not in page


def test_a_changed_parameter_changes_the_page(gen, page):
    scenes = dict(catalog())
    scene = scenes["pendulum"]
    params = tuple(p if p.name != "g" else type(p)("g", p.dim, p.description, default="9.81 m/s^2")
                   for p in scene.params)
    scenes["pendulum"] = scene.replace(params=params)
    changed = gen.render_catalog(scenes)
    assert "default `9.81 m/s^2`" in _section(changed, "pendulum")
    assert "default `9.81 m/s^2`" not in _section(page, "pendulum")


def test_a_dropped_scene_leaves_the_page(gen, page):
    scenes = {n: s for n, s in catalog().items() if n != "quarter-car"}
    changed = gen.render_catalog(scenes)
    assert "## quarter-car" in page
    assert "## quarter-car" not in changed and "(#quarter-car)" not in changed


def test_check_flags_a_stale_or_missing_page(gen, page, tmp_path):
    assert gen.check(tmp_path) == ["commands.md", "scenes.md"]  # missing
    (tmp_path / "scenes.md").write_bytes(page.encode("utf-8"))
    assert gen.check(tmp_path) == ["commands.md"]
    (tmp_path / "commands.md").write_bytes(gen.generate()["commands.md"].encode("utf-8"))
    assert gen.check(tmp_path) == []
    (tmp_path / "scenes.md").write_bytes(page.replace("E5.12", "E5.13", 1).encode("utf-8"))
    assert gen.check(tmp_path) == ["scenes.md"]


def test_check_option_exit_status(gen, page, tmp_path, capsys):
    (tmp_path / "scenes.md").write_text("# stale\n")
    assert gen.main(["--check", "--out-dir", str(tmp_path)]) == 1
    assert "scenes.md differs from the generated page" in capsys.readouterr().err
    assert gen.main(["--out-dir", str(tmp_path)]) == 0
    assert (tmp_path / "scenes.md").read_bytes() == page.encode("utf-8")
    assert gen.main(["--check", "--out-dir", str(tmp_path)]) == 0


def test_check_option_on_the_checkout():
    run = subprocess.run([sys.executable, "tools/gen_docs.py", "--check"], cwd=ROOT,
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert "docs/ is up to date" in run.stdout


# --- what the page says ------------------------------------------------------------------------

def test_index_lists_every_scene_in_catalog_order(page):
    index = _section(page, "Index")
    rows = _table_after(index, "| scene |")
    assert [re.match(r"\[([^\]]+)\]\(#\1\)", r[0]).group(1) for r in rows] == IDS
    for row, scene in zip(rows, SCENES):
        assert row[1] == scene.summary
        ids = re.findall(r"\bE\d+\.\d+\b", scene.reference)
        assert row[2] == (", ".join(ids) or "-")


@pytest.mark.parametrize("scene", SCENES, ids=IDS)
def test_section_carries_the_scene(page, scene):
    section = _section(page, scene.name)
    assert f"`{scene.equation}`" in section
    assert f"`{scene.formula}`" in section
    assert f"```sh\n{scene.example}\n```" in section
    assert scene.reference in section
    params = _table_after(section, "| parameter |")
    assert [r[0] for r in params] == [f"`{p.name}`" for p in scene.params]
    for row, p in zip(params, scene.params):
        if p.dim is not None:
            assert row[1] == f"`{p.dim.display}`"
            assert row[2] == (f"`{p.dim.si}`" if p.dim.si else "-")
        status = (f"default `{p.default}`" if p.default is not None
                  else "optional" if p.optional else "required")
        assert row[3] == status
    for group in scene.one_of:
        assert ", ".join(f"`{n}`" for n in group) in section
    for constraint in scene.constraints:
        assert constraint.text in section
    for method in scene.methods:
        assert f"`{method}`" in section


@pytest.mark.parametrize("scene", COMPUTED, ids=COMPUTED_IDS)
def test_results_are_what_the_cli_gives(page, scene):
    """The result names listed are those of the example's --json, in its order, each with
    the canonical unit of its kind; the example values are the JSON's, to 6 digits."""
    section = _section(page, scene.name)
    rows = _table_after(section, "| result |")
    listed = [r[0].strip("`") for r in rows if r[4] == "the example"]
    data = _cli_json(scene.example)
    assert listed == list(data["results"])
    for row in rows:
        name = row[0].strip("`")
        unit = scene_kind(scene, name).dim.si
        assert row[2] == (f"`{unit}`" if unit else "-"), name
    gives = section[section.index("gives ("):].split("\n", 1)[0]
    for name, got in data["results"].items():
        unit = scene_kind(scene, name).dim.si
        if got["unit"] != unit:  # shown in another unit by the CLI (an angle in deg)
            continue
        values = got["value"] if isinstance(got["value"], list) else [got["value"]]
        text = ", ".join(f"{v:.6g}" for v in values)
        text = f"({text})" if isinstance(got["value"], list) else text
        assert "`" + f"{name} = {text} {unit}".rstrip() + "`" in gives, name


@pytest.mark.parametrize("scene", COMPUTED, ids=COMPUTED_IDS)
def test_damped_rows_only_where_zeta_is_taken(page, scene):
    rows = _table_after(_section(page, scene.name), "| result |")
    damped = {r[0].strip("`") for r in rows if r[4] == "`zeta=`"}
    if scene.accepts_zeta:
        assert damped == {"zeta", "omega_d", "f_d", "T_d"}
    else:
        assert damped == set()
        assert scene.no_zeta_because in _section(page, scene.name)


# --- docs/architecture.md and the README's pointer to it ---------------------------------------

def _layout_entries() -> list[str]:
    """The names the tree of docs/architecture.md lists directly under ``dyncalc/``."""
    text = (DOCS / "architecture.md").read_text(encoding="utf-8")
    tree = re.search(r"```\ndyncalc/\n(.*?)```", text, re.S)
    assert tree, "docs/architecture.md has no dyncalc/ tree"
    return re.findall(r"^  (\S+)", tree.group(1), re.M)


def test_architecture_tree_is_the_package():
    """Every part the page names exists, and every part of the package is named."""
    package = ROOT / "dyncalc"
    parts = {p.name + ("/" if p.is_dir() else "") for p in package.iterdir()
             if not p.name.startswith("_") and p.name != "__pycache__"
             and (p.is_dir() or p.suffix == ".py")}
    parts.add("__init__.py")
    assert set(_layout_entries()) == parts


def test_architecture_names_the_layers_contract():
    text = (DOCS / "architecture.md").read_text(encoding="utf-8")
    pyproject = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    assert "[tool.importlinter]" in pyproject and "[tool.importlinter]" in text
    assert "tests/test_architecture.py" in text
    assert len(text.splitlines()) <= 60


def test_readme_points_to_the_docs():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    section = readme[readme.index("\n## Where things live\n"):]
    for target in ("docs/architecture.md", "docs/scenes.md"):
        assert f"]({target})" in section
        assert (ROOT / target).is_file()


def test_readme_links_are_relative_and_resolve():
    """Every link of the README is a web address or a relative path to a file of this
    repository (no absolute path, nothing outside it, no anchor-less dead link); it links
    every page of the docs site (docs/*.md, docs/guide/*.md) and the man page."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    targets = re.findall(r"\]\(([^)\s]+)\)", readme)
    local = [t for t in targets if not t.startswith(("https://", "http://"))]
    assert local, "the README links nothing of its own"
    for target in local:
        path = target.split("#", 1)[0]
        assert not path.startswith("/") and ".." not in Path(path).parts, target
        assert (ROOT / path).is_file(), target
    pages = {p.relative_to(ROOT).as_posix() for p in DOCS.glob("*.md")}
    pages |= {p.relative_to(ROOT).as_posix() for p in (DOCS / "guide").glob("*.md")}
    assert pages <= set(local), sorted(pages - set(local))
    assert "docs/man/dyncalc.1" in local
    assert len(readme.splitlines()) <= 190  # short: a tour line a command, the rest in docs/


def test_the_docs_picture_is_the_benchmarks():
    """docs/img/speed_accuracy.png is a copy (the site cannot reach benchmarks/) of the picture
    benchmarks/speed_accuracy.py draws: copy it again when the benchmark is re-run."""
    assert (DOCS / "img" / "speed_accuracy.png").read_bytes() == (
        ROOT / "benchmarks" / "results" / "speed_accuracy.png").read_bytes()


def test_the_code_cites_the_projects_own_docs():
    """The package's docstrings cite the reference in this repository (docs/, README.md), not
    the contract documents outside it; every docs/ page they cite exists. (Two scene modules
    name ../shared/SCENES.md as the source of their mpmath reference values, on purpose.)"""
    import re

    cited = set()
    for path in (ROOT / "dyncalc").rglob("*.py"):
        text = path.read_text(encoding="utf-8")
        for match in re.finditer(r"(?<![./\w])(SPEC|SCENES)\.md", text):
            line = text[:match.start()].rsplit("\n", 1)[-1]
            assert "../shared/" in line, f"{path.relative_to(ROOT)} cites {match.group(0)}"
        cited.update(re.findall(r"docs/((?:guide/)?[\w-]+\.md)", text))
    assert cited >= {"scenes.md", "commands.md", "json.md", "guide/quantities.md"}
    for page in cited:
        assert (ROOT / "docs" / page).is_file(), page


def test_scene_counts_in_the_prose_are_the_catalogs():
    """README, the docs' index and the scenes guide name how many scenes there are (and the
    guide lists them by command): those numbers and lists follow the catalog."""
    from dyncalc.cli.scenes import scene_commands
    from dyncalc.scenes import catalog

    root = Path(__file__).resolve().parents[1]
    taken = scene_commands()
    natural = [n for n in taken["natural-frequency"] if not catalog()[n].no_frequency]
    readme = (root / "README.md").read_text()
    assert f"lists the {len(catalog())} scenes" in readme
    index = (root / "docs" / "index.md").read_text()
    assert f"omega, f, T of {len(natural)} scenes" in index
    guide = " ".join((root / "docs" / "guide" / "scenes.md").read_text().split())
    assert f"lists all {len(catalog())} scenes of the catalog: the " \
        f"{len(taken['natural-frequency'])} that `natural-frequency` takes" in guide
    assert f"the {len(taken['rigid-body'])} of `rigid-body` (" \
        f"{', '.join(taken['rigid-body'])})" in guide
    assert f"the {len(taken['coriolis'])} of `coriolis` ({', '.join(taken['coriolis'])})" in guide
    listed = guide.split("takes (", 1)[1].split(";", 1)[0].split(", ")
    assert listed == taken["natural-frequency"]
