"""Generate the reference pages ``docs/scenes.md`` (from the scene data) and
``docs/commands.md`` (from the Command records of ``dyncalc/commands/``).

    python tools/gen_docs.py          # (re)write docs/scenes.md and docs/commands.md
    python tools/gen_docs.py --check  # exit 1 if the committed file is out of date

Everything on the page comes from :func:`dyncalc.scenes.catalog` (the ``Scene`` and ``Param``
records of ``dyncalc/scenes/``) and :func:`dyncalc.result.kinds.result_kind` (each result's
canonical unit and meaning), and from running every scene's example command through
:func:`dyncalc.commands.natural_frequency.natural_frequency`: the result names it lists are
the ones the scene really gives, and the values are its results, to 6 significant
digits. ``tests/test_docs.py`` fails when the committed page drifts from what this
script produces: regenerate after changing a scene, a result kind or a scene's physics.

The output is deterministic: no paths, no dates, no timings, ``\\n`` line endings.
"""
from __future__ import annotations

import argparse
import re
import shlex
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(Path(__file__).resolve().parent))
from generated_files import stale_files, write_files  # noqa: E402 (beside this script)
OUT_DIR = ROOT / "docs"

#: ``zeta`` used only to find which results a damping ratio adds (its values are not shown).
PROBE_ZETA = "0.1"
#: Significant digits of the example values (the human table's default).
DIGITS = 6

_ALLOWED = {"positive": "> 0", "nonnegative": ">= 0", "nonzero": "not 0", None: "any"}
_EXAMPLE_ID = re.compile(r"\bE\d+\.\d+\b")

__all__ = ["generate", "render_catalog", "render_commands", "write", "check", "main",
           "OUT_DIR"]


def _import_dyncalc() -> None:
    try:
        import dyncalc  # noqa: F401
    except ImportError:  # run from a checkout without the package installed
        sys.path.insert(0, str(ROOT))


# --- text helpers ------------------------------------------------------------------------------

def _cell(text: str) -> str:
    """Text for a table cell or a line of prose: ``|`` and ``*`` are literal, not markup."""
    return text.replace("\\", "\\\\").replace("|", "\\|").replace("*", "\\*")


def _code(text: str) -> str:
    """``text`` as inline code (in a table cell its ``|`` escaped, as GitHub reads it)."""
    return f"`{text}`"


def _code_cell(text: str) -> str:
    return _code(text.replace("|", "\\|"))


def _sentence(text: str) -> str:
    """A catalog phrase as a sentence: capital first letter, full stop at the end."""
    text = text.strip()
    if not text:
        return text
    text = text[0].upper() + text[1:]
    return text if text.endswith((".", "!", "?")) else text + "."


def _names(names) -> str:
    return ", ".join(_code(n) for n in names)


def example_ids(reference: str) -> list[str]:
    """The textbook example ids in a scene's reference (``E5.12``), in order."""
    return _EXAMPLE_ID.findall(reference)


# --- running the examples ----------------------------------------------------------------------

def parse_example(example: str) -> tuple[dict[str, str], list[str], str | None, str | None]:
    """A ``dyncalc natural-frequency ...`` command line -> (standard options, NAME=QUANTITY
    words, scene, method), as :func:`natural_frequency` takes them; a forced scene's
    ``dyncalc forced-response --scene NAME NAME=QUANTITY ...`` is read the same way (its scene
    and words are the same to either command); a relative-motion scene's ``dyncalc coriolis
    --scene NAME ...`` too."""
    from dyncalc.commands.natural_frequency import STANDARD

    words = shlex.split(example)
    if words[:2] not in (["dyncalc", "natural-frequency"], ["dyncalc", "forced-response"],
                         ["dyncalc", "rigid-body"], ["dyncalc", "coriolis"]):
        raise ValueError(f"not a natural-frequency command: {example!r}")
    options: dict[str, str] = {}
    assignments: list[str] = []
    scene = method = None
    rest = words[2:]
    while rest:
        word = rest.pop(0)
        if word.startswith("--"):
            name = word[2:]
            if not rest:
                raise ValueError(f"{word} has no value in {example!r}")
            value = rest.pop(0)
            if name == "scene":
                scene = value
            elif name == "method":
                method = value
            elif name in STANDARD:
                options[name] = value
            else:
                raise ValueError(f"the generator does not know option {word} ({example!r})")
        else:
            assignments.append(word)
    return options, assignments, scene, method


def run_example(scene):
    """``scene``'s example computed: (its Result, the names a ``zeta`` adds or ``None``)."""
    from dyncalc.commands.natural_frequency import natural_frequency

    options, words, name, method = parse_example(scene.example)
    if scene.example.split()[1] == "coriolis":
        from dyncalc.commands.coriolis_scenes import scene_result

        return scene_result(name, {}, words), None
    if scene.example.startswith("dyncalc rigid-body"):
        from dyncalc.commands.rigid_body import rigid_body

        result = rigid_body(options, words, scene=name)
    else:
        result = natural_frequency(options, words, scene=name, method=method)
    if result.scene != scene.name:
        raise ValueError(f"{scene.name}'s example runs scene {result.scene!r}: {scene.example}")
    added = None
    given = set(options) | {w.partition("=")[0] for w in words}
    if scene.accepts_zeta and "zeta" not in given:
        damped = natural_frequency({**options, "zeta": PROBE_ZETA}, words, scene=name,
                                   method=method)
        added = [n for n in damped.results if n not in result.results]
    return result, added


# --- the page ----------------------------------------------------------------------------------

_HEADER = """\
<!-- Generated by tools/gen_docs.py from the scene catalog (dyncalc/scenes/); do not edit.
     Regenerate with: python tools/gen_docs.py -->

# The scene catalog

A *scene* is a textbook set-up with exactly the parameters its answer needs. `dyncalc
natural-frequency --scene NAME NAME=QUANTITY ...` computes one; `dyncalc scenes NAME` prints
the same data as below.
{inference}

This page is generated from the scene records in `dyncalc/scenes/` by `tools/gen_docs.py`;
`tests/test_docs.py` fails when it drifts from them. A quantity may be typed in any unit of
its dimension; a bare number is read in the SI unit shown. The *canonical unit* of a result is
the SI coherent unit of its kind (`dyncalc/result/kinds.py`); the human table may show a
result in another unit (an angle in `deg`). `-` in a unit column means a pure number.

Each example's results are given to 6 significant digits in their canonical units; the
reference values were computed independently (mpmath, 30 digits) and
`tests/test_scenes.py` checks the example against them to a relative 1e-12.
"""


def _inference() -> str:
    """How ``natural-frequency`` chooses a scene without ``--scene``, from its own tables."""
    from dyncalc.commands.natural_frequency import INFERENCE, STANDARD

    option = {param: name for name, param in STANDARD.items()}
    choices = [f"{_code(scene)} ({', '.join(_code('--' + option.get(p, p)) for p in sorted(keys))})"
               for scene, keys in INFERENCE]
    return ("Without `--scene` the parameters given choose one of "
            + ", ".join(choices) + f"; with none of them, {_code(INFERENCE[0][0])}.")


def _index(scenes) -> list[str]:
    lines = ["| scene | what it is | textbook example |", "| --- | --- | --- |"]
    for scene in scenes.values():
        ids = ", ".join(example_ids(scene.reference)) or "-"
        lines.append(f"| [{scene.name}](#{scene.name}) | {_cell(scene.summary)} | {ids} |")
    return lines


def _status(param) -> str:
    if param.default is not None:
        return f"default {_code_cell(param.default)}"
    return "optional" if param.optional else "required"


def _choice_words(param) -> str:
    from dyncalc.result.entries import format_number

    words = []
    for word, value in param.choices.items():
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            words.append(f"{_code_cell(word)} ({format_number(value, DIGITS)})")
        else:
            words.append(_code_cell(word))
    return "one of " + ", ".join(words)


def _parameters(scene) -> list[str]:
    lines = ["| parameter | dimension | SI unit | given | allowed | description |",
             "| --- | --- | --- | --- | --- | --- |"]
    for p in scene.params:
        if p.dim is None:
            dimension, unit, allowed = "choice", "-", "-"
            description = f"{_cell(p.description)}: {_choice_words(p)}"
        else:
            dimension = _code_cell(p.dim.display)
            unit = _code_cell(p.dim.si) if p.dim.si else "-"
            allowed, description = _ALLOWED[p.constraint], _cell(p.description)
        lines.append(f"| {_code_cell(p.name)} | {dimension} | {unit} | {_status(p)} | "
                     f"{allowed} | {description} |")
    return lines


def _rules(scene) -> list[str]:
    """Alternatives, constraints, methods, damping and assumptions, in words (bullets)."""
    lines = []
    for group in scene.one_of:
        defaults = [n for n in group if scene.param(n).default is not None]
        if defaults:
            first = scene.param(defaults[0])
            lines.append(f"* Give at most one of {_names(group)}; with neither, "
                         f"{_code(first.name)} is {_code(first.default)}.")
        else:
            lines.append(f"* Give exactly one of {_names(group)}.")
    for constraint in scene.constraints:
        lines.append(f"* Must hold: {_cell(constraint.text + constraint.why)}.")
    if scene.methods:
        lines.append(f"* Methods (`--method`): `auto` (the default: the cheapest whose "
                     f"error bound meets `--rtol`), {_names(scene.methods)}.")
    else:
        lines.append("* Methods (`--method`): `auto` only.")
    if scene.accepts_zeta:
        lines.append("* Damping: `zeta=` (or `--zeta`) adds the damped results (`from` "
                     "`zeta=` below).")
    else:
        lines.append(f"* Damping: takes no `zeta`; {_cell(scene.no_zeta_because)}.")
    for assumption in scene.assumptions:
        lines.append(f"* Assumes: {_cell(assumption)}.")
    return lines


def _results(result, added) -> list[str]:
    from dyncalc.scenes import get_scene
    from dyncalc.scenes.runner import scene_kind

    lines = ["| result | symbol | canonical unit | meaning | from |",
             "| --- | --- | --- | --- | --- |"]
    rows = [(name, "the example") for name in result.results]
    rows += [(name, "`zeta=`") for name in added or ()]
    for name, when in rows:
        kind = scene_kind(get_scene(result.scene), name)
        unit = _code_cell(kind.dim.si) if kind.dim.si else "-"
        lines.append(f"| {_code_cell(name)} | {_cell(kind.symbol)} | {unit} | "
                     f"{_cell(kind.description)} | {when} |")
    return lines


def _example_values(result) -> str:
    return _example_values_of(result.results)


def _example_values_of(results) -> str:
    from dyncalc.result.entries import format_number

    shown = []
    for name, entry in results.items():
        unit = entry.canonical_unit
        value = format_number(entry.value_in(unit), DIGITS)
        shown.append(_code(f"{name} = {value} {unit}".rstrip()))
    return ", ".join(shown)


def _example(scene, result) -> list[str]:
    lines = [f"**Example** (reference: {_cell(scene.reference)}):", "",
             "```sh", scene.example, "```", "",
             f"gives (model `{result.model}`, method `{result.method}`): "
             f"{_example_values(result)}."]
    if result.warnings:
        lines += ["", "With the warnings: " + "; ".join(_cell(w) for w in result.warnings)
                  + "."]
    if scene.example_result:
        reference = ", ".join(_code(f"{name} = {text}")
                              for name, text in scene.example_result.items())
        lines += ["", f"Reference values: {reference}."]
    return lines


def _card_head(scene) -> list[str]:
    """A scene card's heading, summary, figure, equation, formula, parameters and rules."""
    return [f"## {scene.name}", "",
            _sentence(_cell(scene.summary)), "",
            f"**Figure.** {_sentence(_cell(scene.figure))}", "",
            f"* Equation of motion: {_code(scene.equation)}", *_derived(scene),
            f"* Formula: {_code(scene.formula)}", "",
            "**Parameters** (`NAME=QUANTITY`):", "", *_parameters(scene), "",
            *_rules(scene), ""]


def _derived(scene) -> list[str]:
    """The equations ``eom`` derives from the scene's energies (dyncalc/scenes/derived.py)."""
    from dyncalc.scenes.derived import DERIVED

    equations = DERIVED.get(scene.name)
    if not equations:
        return []
    return ["* Derived by `eom --scene " + scene.name + "` from the energies: "
            + "; ".join(_code(text) for text in equations)]


def _refused_scene(scene) -> list[str]:
    """A scene that ``natural-frequency`` and ``modes`` refuse on purpose
    (``scene.no_frequency``: no equilibrium): its card, the refusal, and its runnable ``eom``
    example with the accelerations it gives."""
    import shlex

    from dyncalc.commands.eom import eom

    words = shlex.split(scene.example)
    if words[:4] != ["dyncalc", "eom", "--scene", scene.name]:
        raise ValueError(f"{scene.name} is refused by natural-frequency; its example must be "
                         f"dyncalc eom --scene {scene.name} ...: {scene.example}")
    result = eom({}, words[4:], scene=scene.name)
    shown = {name: entry for name, entry in result.results.items() if name.endswith("_ddot")}
    reference = ", ".join(_code(f"{name} = {text}")
                          for name, text in scene.example_result.items())
    return [*_card_head(scene),
            f"**Refused on purpose.** `natural-frequency` and `modes` refuse it (exit status 2): "
            f"{_code('Error: ' + scene.no_frequency)}", "",
            f"**Example** (`eom`, reference: {_cell(scene.reference)}):", "",
            "```sh", scene.example, "```", "",
            f"gives the equations of motion and, at that state, "
            f"{_example_values_of(shown)}.", "", f"Reference values: {reference}."]


def _driven(scene) -> list[str]:
    """How ``forced-response --scene`` drives a single-degree-of-freedom scene."""
    from dyncalc.scenes.sdof import COORDINATES, forced_example

    coordinate = COORDINATES.get(scene.name)
    if coordinate is None:
        return []
    added = (f" It takes the mass {_code('m')} ({coordinate.mass}) besides the parameters "
             "above." if coordinate.mass else "")
    return ["", f"**Driven** (`forced-response`): {_sentence(_cell(coordinate.sentence()))}"
            f"{added}", "", "```sh", forced_example(scene.name), "```"]


def _scene(scene) -> list[str]:
    if scene.no_frequency:
        return _refused_scene(scene)
    result, added = run_example(scene)
    return [*_card_head(scene),
            "**Results** (those of the example command, and those a `zeta` adds; other "
            "inputs may give others):", "", *_results(result, added), "",
            *_example(scene, result), *_driven(scene)]


def render_catalog(scenes) -> str:
    """The text of ``docs/scenes.md`` for ``scenes`` (name -> Scene, in catalog order)."""
    lines = [_HEADER.format(inference=_inference()).rstrip("\n"), "", "## Index", "",
             *_index(scenes)]
    for scene in scenes.values():
        lines += ["", *_scene(scene)]
    return "\n".join(lines) + "\n"


_COMMANDS_HEADER = """\
# Commands

Generated by `tools/gen_docs.py` from the Command records (`COMMAND` in each module of
`dyncalc/commands/`); do not edit. The click options, the completion of result names and this
page all come from the same record, so they cannot drift apart.

Every computing command also takes the output options `--json`, `--value NAME`,
`--unit NAME=UNIT`, `--digits N`, `--check NAME=QUANTITY`, `--rtol`, `--explain[=FORMAT]`,
`--format table|markdown|csv|tsv`, `--strict-units`, `--batch FILE`, `--on-error` and
`--debug`. `--value`, `--json`, `--format csv|tsv` and batch output give each result in its
*canonical unit* (the column below) unless `--unit` names another. A bare number is read in
the parameter's SI unit. `--explain=markdown|latex` and `--format markdown` make the whole
human output Markdown or LaTeX; `--format csv|tsv` prints the results table alone
(`name,value,unit`, full precision). The [output guide](guide/output.md) has the details.
"""

_KIND_WORDS = {"quantity": "", "text": "text", "choice": "one of", "setting": "setting",
               "after": "output"}


def _command(record) -> list[str]:
    usage = f"dyncalc {record.name}"
    if record.words:
        usage += f" {record.words}"
    usage += " [OPTIONS]"
    lines = [f"## {record.name}", "", _sentence(_cell(record.summary)), "", "```",
             usage, "```", ""]
    if record.parameters:
        lines += ["| option | dimension | SI unit | default | what it is |",
                  "| --- | --- | --- | --- | --- |"]
        for p in record.parameters:
            dim = p.dim.display if p.dim is not None else _KIND_WORDS[p.kind]
            if isinstance(p.choices, tuple):
                dim = "one of " + ", ".join(p.choices)
            si = _code_cell(p.dim.si) if p.dim is not None and p.dim.si else ""
            default = _code_cell(p.default) if p.default is not None else ""
            lines.append(f"| `{p.flag} {p.metavar}` | {_cell(dim)} | {si} | {default} | "
                         f"{_cell(p.help)} |")
        lines.append("")
    lines += ["| result | symbol | canonical unit | what it is |", "| --- | --- | --- | --- |"]
    for r in record.results:
        unit = _code_cell(r.unit) if r.unit else "(pure number or word)"
        lines.append(f"| `{r.name}` | {_cell(r.symbol)} | {unit} | {_cell(r.description)} |")
    examples: list[str] = []
    continued = False
    for line in record.help.splitlines():
        line = line.strip()
        if continued or line.startswith("dyncalc "):
            examples.append(("    " if continued else "") + line)
            continued = line.endswith("\\")
    if examples:
        lines += ["", "Examples:", "", "```sh", *examples, "```"]
    return lines


def render_commands(records) -> str:
    """The text of ``docs/commands.md`` for ``records`` (Command records, in order)."""
    lines = [_COMMANDS_HEADER.rstrip("\n")]
    for record in records:
        lines += ["", *_command(record)]
    return "\n".join(lines) + "\n"


def command_records() -> list:
    """Every command's record, in the order of ``dyncalc --help``."""
    _import_dyncalc()
    from dyncalc.cli import cli

    return [command.record for name, command in sorted(cli.commands.items())
            if getattr(command, "record", None) is not None]


def generate(scenes=None, records=None) -> dict[str, str]:
    """The generated pages, as ``{file name under docs/: text}``; ``scenes`` defaults to the
    whole catalog, ``records`` to every command's record."""
    _import_dyncalc()
    if scenes is None:
        from dyncalc.scenes import catalog

        scenes = catalog()
    if records is None:
        records = command_records()
    return {"commands.md": render_commands(records), "scenes.md": render_catalog(scenes)}


def write(out_dir: Path = OUT_DIR) -> list[Path]:
    """Write every page to ``out_dir``; the paths written."""
    return write_files(generate(), out_dir)


def check(out_dir: Path = OUT_DIR) -> list[str]:
    """The names of the pages in ``out_dir`` that are missing or differ from :func:`generate`."""
    return stale_files(generate(), out_dir)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="gen_docs.py", description="Generate docs/scenes.md and docs/commands.md.")
    parser.add_argument("--check", action="store_true",
                        help="write nothing; exit 1 if a committed page differs")
    parser.add_argument("--out-dir", type=Path, default=OUT_DIR,
                        help="the folder of the pages (default: docs/ of this checkout)")
    args = parser.parse_args(argv)
    if args.check:
        stale = check(args.out_dir)
        for name in stale:
            print(f"{_shown(args.out_dir / name)} differs from the generated page; "
                  "run: python tools/gen_docs.py", file=sys.stderr)
        if not stale:
            print(f"{_shown(args.out_dir)}/ is up to date")
        return 1 if stale else 0
    for path in write(args.out_dir):
        print(f"wrote {_shown(path)}")
    return 0


def _shown(path: Path) -> str:
    """``path`` relative to the checkout where it is inside it (``docs/scenes.md``)."""
    path = path.resolve()
    return path.relative_to(ROOT).as_posix() if path.is_relative_to(ROOT) else str(path)


if __name__ == "__main__":
    sys.exit(main())
