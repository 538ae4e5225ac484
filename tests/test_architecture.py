"""The layout of ARCHITECTURE.md, enforced: the layers contract of pyproject.toml
(import-linter), no import cycle between any two modules, a cli/X.py + commands/X.py pair per
command, and a docstring on every module."""
from __future__ import annotations

import ast
import os
import shutil
import subprocess
import sys
from pathlib import Path

import grimp
import pytest

from dyncalc.cli import COMMAND_MODULES

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "dyncalc"


def test_layers_contract_is_kept():
    """`lint-imports` checks the layers of pyproject.toml: nothing imports upward."""
    lint = shutil.which("lint-imports", path=os.path.dirname(sys.executable))
    assert lint is not None, "import-linter is not installed (pip install '.[test]')"
    run = subprocess.run([lint, "--no-cache"], cwd=ROOT, capture_output=True, text=True,
                         timeout=120)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-2000:]
    assert "1 kept, 0 broken" in run.stdout


def _cycles(graph) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    on_stack: set[str] = set()
    stack: list[str] = []
    found: list[list[str]] = []
    counter = 0
    for root in sorted(graph.modules):
        if root in index:
            continue
        work = [(root, iter(sorted(graph.find_modules_directly_imported_by(root))))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(
                        graph.find_modules_directly_imported_by(child)))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def test_no_import_cycles():
    """No two modules import each other, directly or round a longer loop (imports inside
    functions count: grimp reads every import statement)."""
    graph = grimp.build_graph("dyncalc")
    assert _cycles(graph) == []


def test_the_cycle_finder_finds_a_cycle():
    class Graph:
        modules = {"a", "b", "c", "d"}
        edges = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}

        def find_modules_directly_imported_by(self, name):
            return self.edges[name]

    assert _cycles(Graph()) == [["a", "b", "c"]]


@pytest.mark.parametrize("command", sorted(set(COMMAND_MODULES) - {"scenes"}))
def test_every_command_is_a_cli_and_commands_pair(command):
    module = COMMAND_MODULES[command]
    assert (PACKAGE / "cli" / f"{module}.py").is_file()
    assert (PACKAGE / "commands" / f"{module}.py").is_file()
    assert module.replace("_", "-") in command or module == "springs"


@pytest.mark.parametrize("path", sorted(str(p.relative_to(ROOT)) for p in PACKAGE.rglob("*.py")))
def test_every_module_says_what_lives_there(path):
    tree = ast.parse((ROOT / path).read_text())
    docstring = ast.get_docstring(tree)
    if path.endswith("_version.py") or path.endswith("__main__.py"):
        return
    assert docstring and docstring.strip(), f"{path} has no module docstring"


@pytest.mark.parametrize("name", __import__("dyncalc").__all__)
def test_every_public_name_resolves(name):
    """Each name of ``dyncalc.__all__`` is loaded from where it lives now (a moved module
    must not leave the public API pointing at a file that is gone)."""
    import dyncalc

    assert getattr(dyncalc, name) is not None


def test_network_stiffness_through_the_public_api():
    import dyncalc

    assert dyncalc.network_stiffness("series", ["200 N/m", "300 N/m"]).results["k_eq"].si == 120.0


def test_help_of_every_command_loads_nothing_heavy():
    """Every command module (and so every Command record) loads without pint, numpy, scipy or
    rich: ``dyncalc --help`` and completion stay fast (numpy comes in through ``dyncalc.lazy``
    the first time a computation uses it)."""
    code = ("import sys\nfrom dyncalc.cli import cli\n"
            "commands = list(cli.commands.values())\n"
            "assert len(commands) >= 7, commands\n"
            "print(sorted(m for m in ('pint', 'numpy', 'scipy', 'rich', 'sympy') if m in sys.modules))")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=60, env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "[]"


def test_click_options_are_generated_from_the_records():
    """The options of each computing command are its record's parameters, in order, then the
    shared output options; the record rides on the click command (for completion)."""
    from dyncalc.cli import cli

    for name, command in cli.commands.items():
        if name == "scenes":
            continue
        record = command.record
        options = [p.opts[0] for p in command.params if isinstance(p, __import__("click").Option)]
        flags = [p.flag for p in record.parameters]
        assert options[:len(flags)] == flags, name
        assert options[len(flags)] == "--json", name
        assert (record.words is None) == all(
            not isinstance(p, __import__("click").Argument) for p in command.params), name


def test_every_scene_physics_function_checks_the_scene_dimensions():
    """One physics face: every scene's physics function checks on entry the dimension of each
    quantity the scene passes it, the same dimension the scene's parameter declares."""
    from dyncalc.scenes import catalog
    from dyncalc.units import DIMENSIONLESS

    for scene in catalog().values():
        declared = scene.compute.dimensions
        for param in scene.params:
            if param.dim is None or param.dim is DIMENSIONLESS or param.name == "zeta":
                continue
            assert declared.get(param.name) is param.dim, (scene.name, param.name)


def test_a_physics_function_refuses_a_wrong_dimension():
    from dyncalc.errors import InputError
    from dyncalc.physics.oscillators import mass_spring, pendulum
    from dyncalc.units import Q_

    with pytest.raises(InputError) as raised:
        mass_spring(Q_(5, "kg"), Q_(2, "kg"))
    assert str(raised.value) == "k must be a stiffness [force]/[length]; got 5 kilogram ([mass])"
    with pytest.raises(InputError) as raised:
        pendulum(Q_(1, "m"), Q_(9.81, "m/s^2"), Q_(30, "deg/s"))
    assert str(raised.value).startswith("amplitude must be an angle [angle]; got 30 ")
    assert mass_spring(100.0, 2.0).values["omega"].magnitude == pytest.approx(50 ** 0.5,
                                                                              rel=1e-15)
