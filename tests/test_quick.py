"""The quick path (dyncalc/quick) against the full one: the same stdout, stderr and exit
status for every command line it answers, and the unit table it reads against pint.

The full path runs in-process (dyncalc.cli's group, its output captured); the quick path's
answer is what :func:`dyncalc.quick.answer` returns, printed by ``main`` with a newline and
exit status 0 and nothing on stderr. A command line the quick path declines is not compared
(the full path runs it as before); the test also counts that the common forms are answered.
"""
from __future__ import annotations

import contextlib
import io
import math
import os
import random
import subprocess
import sys
from pathlib import Path

import pytest

from dyncalc.cli import cli
from dyncalc.quick import answer
from dyncalc.quick.natural import PARAMETERS as _PARAMETERS
from dyncalc.quick.table import UNITS

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
import gen_unit_table  # noqa: E402 (tools/ is no package)

#: output options, every combination the quick path takes (and a few it declines)
OUTPUTS = ([], ["--json"], ["--value", "omega"], ["--value", "T", "--value", "f"],
           ["--digits", "17"], ["--digits=3"], ["--json", "--value", "f"],
           ["--digits", "1", "--json"], ["--value", "omega", "--value", "omega"],
           ["--value", "x"], ["--digits", "18"], ["--digits", "05"], ["--json", "--json"],
           ["--explain"], ["--unit", "f=kHz"], ["--value=f"], ["--k"])
#: the other parameter of each scene, fixed
PARTNERS = {"--k": ["--m", "2 kg"], "--m": ["--k", "100 N/m"],
            "--kt": ["--inertia", "2 kg*m^2"], "--inertia": ["--kt", "10 N*m/rad"],
            "--length": [], "--g": ["--length", "1 m"]}


@pytest.fixture(autouse=True)
def _plain_environment(monkeypatch):
    for name in ("COLUMNS", "FORCE_COLOR", "NO_COLOR", "DYNCALC_PLAIN", "_DYNCALC_COMPLETE"):
        monkeypatch.delenv(name, raising=False)


def full(args: list[str]) -> tuple[str, str, int]:
    """(stdout, stderr, exit status) of the full path, in-process."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli.main(args=list(args), prog_name="dyncalc", standalone_mode=False)
    return out.getvalue(), err.getvalue(), code


def compare(args: list[str]) -> bool:
    """Whether the quick path answered ``args``; when it did, its output is the full path's."""
    with contextlib.redirect_stdout(io.StringIO()):  # not a terminal, as when piped
        text = answer(list(args))
    if text is None:
        return False
    assert (text + "\n", "", 0) == full(args), args
    return True


def magnitudes(rng: random.Random, count: int) -> list[str]:
    """Random magnitudes 1e-300..1e300 as typed in several ways, and ones to be refused."""
    out = ["1", "2.5", ".5", "3.", "1E5", "007", "0", "0.0", "1e-400", "1e400",
           "5e-324", "1.7976931348623157e308", "-2", "inf", "2_0", "0x10", "\u0663", "1\u0663",
           "\uff13", "1e", "2e+3", "+2", "1 000", "1,5", "1.2.3"]
    for _ in range(count):
        x = 10.0 ** rng.uniform(-300, 300) * rng.uniform(1, 10)
        out.append(repr(x) if rng.random() < 0.7 else f"{x:.3e}")
    return out


def quantity_texts(rng: random.Random, dimension: str, count: int) -> list[str]:
    """Every table unit of ``dimension`` with random magnitudes, spaced several ways, a bare
    number, and units of other dimensions (which the full path refuses)."""
    units = [u for u, dims in UNITS.items() if dimension in dims]
    others = [u for u, dims in UNITS.items() if dimension not in dims]
    texts = []
    for unit in units:
        for number in rng.sample(magnitudes(rng, 3 * count), 4) + [repr(rng.uniform(0.1, 9))]:
            texts.append(rng.choice(["{} {}", "{}{}", " {}  {} ", "{}\t{}"]).format(number, unit))
    texts += [repr(rng.uniform(1, 1000)), "12", "1 kN /m", "1 fathom", "(2) kg", "1 kg ± 1 g"]
    texts += [f"3 {u}" for u in rng.sample(others, 6)]
    return texts


@pytest.mark.parametrize("option", sorted(_PARAMETERS))
def test_every_table_unit_reads_as_the_full_path_reads_it(option):
    rng = random.Random(option)
    dimension = _PARAMETERS[option][1]
    answered = 0
    for text in quantity_texts(rng, dimension, 8):
        for output in rng.sample(OUTPUTS, 3) + [[]]:
            answered += compare(["natural-frequency", option, text, *PARTNERS[option],
                                 *output])
    assert answered > 50  # the quick path really answers the common forms


def test_each_output_form_matches_and_is_answered():
    """Every output combination on each scene; the plain forms are answered quickly."""
    scenes = (["--k", "2 kN/m", "--m", "4kg"], ["--kt", "3 kN*m/rad", "--inertia", "1.2"],
              ["--length", "0.5 ft"], ["--length", "1 m", "--g", "1.62 m/s^2"])
    for scene in scenes:
        for output in OUTPUTS:
            answered = compare(["natural-frequency", *scene, *output])
            plain = output in ([], ["--json"], ["--value", "omega"], ["--digits", "17"])
            assert answered or not plain, output
            for order in (output + scene, scene[2:] + output + scene[:2]):
                compare(["natural-frequency", *order])


def test_results_beyond_float64_and_odd_lines_are_left_to_the_full_path():
    """Overflowing, underflowing and refused inputs, repeated options and other commands:
    declined (or, where answered, the same as the full path)."""
    lines = [["natural-frequency", "--k", "1e308 N/m", "--m", "5e-324 kg"],
             ["natural-frequency", "--k", "5e-324 N/m", "--m", "1e308 kg", "--json"],
             ["natural-frequency", "--kt", "5e-324", "--inertia", "1e308", "--value", "f"],
             ["natural-frequency", "--k", "1 N/m", "--k", "2 N/m", "--m", "1 kg"],
             ["natural-frequency", "--k", "1 N/m", "--m", "1 kg", "--", "x"],
             ["natural-frequency", "--k", "1 N/m", "--m", "1 kg", "--scene", "mass-spring"],
             ["natural-frequency", "--k", "1 N/m", "--m", "1 kg", "--zeta", "0.1"],
             ["natural-frequency", "--k", "1 N/m"], ["natural-frequency", "--m", "1 kg"],
             ["natural-frequency", "--k", "1 N/m", "--m", "1 kg", "--length", "1 m"],
             ["natural-frequency", "k=1N/m", "m=1kg"], ["natural-frequency", "--help"],
             ["spring-series", "1 N/m", "2 N/mm"], ["spring-parallel"], ["--version"], []]
    assert not any(compare(args) for args in lines)
    assert compare(["natural-frequency", "--k", "1e300 N/m", "--m", "1e-300 kg"])


SPRING_OUTPUTS = ([], ["--json"], ["--value", "k_eq"], ["--digits", "17"],
                  ["--value=k_eq", "--value", "k_eq"], ["--digits", "2", "--json"],
                  ["--value", "k1"], ["--unit", "k_eq=N/mm"], ["--strict-units"], ["--"])


@pytest.mark.parametrize("how", ["series", "parallel"])
def test_spring_networks_read_as_the_full_path_reads_them(how):
    """1 to 4 elements in each stiffness unit of the table (and bare numbers), random
    magnitudes, every output option; mixed units, groups and element functions declined or
    the same."""
    rng = random.Random(how)
    answered = 0
    units = [u for u, dims in UNITS.items()
             if "stiffness" in dims or "torsional stiffness" in dims] + [""]
    for unit in units:
        for _ in range(3):
            count = rng.randint(1, 4)
            numbers = magnitudes(rng, 80)  # mostly readable ones, some refused
            words = [f"{rng.choice(numbers)} {unit}".strip() for _ in range(count)]
            for output in rng.sample(SPRING_OUTPUTS, 2) + [[]]:
                answered += compare([f"spring-{how}", *words, *output])
    for words in (["200 N/m", "0.3 N/mm"], ["1", "2 N/m"], ["2 N/m", "parallel(1 N/m, 2 N/m)"],
                  ["cantilever(l=2m)", "EI=2e4 N*m^2"], ["1 N/m", "inf"], ["1e308", "1e308"],
                  ["5e-324 N/m", "5e-324 N/m"], ["3 N*m", "4 N*m"], ["2 N/m", "3 N*m/rad"]):
        compare([f"spring-{how}", *words])
    assert answered > 100


def test_declines_on_a_dumb_terminal_and_when_width_or_colour_is_set(monkeypatch):
    """(A terminal rich draws on: tests/test_quick_terminal.py.)"""
    args = ["natural-frequency", "--k", "100 N/m", "--m", "2 kg"]

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    monkeypatch.setenv("TERM", "dumb")
    with contextlib.redirect_stdout(Terminal()):
        assert answer(args) is None
        assert answer(args + ["--json"]) is not None  # --json is the same on a terminal
    for name, value in (("COLUMNS", "40"), ("FORCE_COLOR", "1")):
        monkeypatch.setenv(name, value)
        assert answer(args) is None
        monkeypatch.delenv(name)
    monkeypatch.setenv("_DYNCALC_COMPLETE", "bash_complete")
    assert answer(args + ["--json"]) is None


def _run(code: str, *args: str) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k not in ("COLUMNS", "FORCE_COLOR")}
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True,
                          env=env, timeout=60)


def test_a_quick_run_imports_neither_pint_numpy_nor_click():
    code = ("import atexit, sys\n"
            "atexit.register(lambda: print(sorted(m for m in ('pint', 'numpy', 'click', "
            "'scipy', 'rich') if m in sys.modules), file=sys.stderr))\n"
            "from dyncalc.quick import main\nmain(sys.argv[1:])\n")
    quick = _run(code, "natural-frequency", "--k", "100 N/m", "--m", "2 kg", "--value", "f")
    assert (quick.returncode, quick.stdout, quick.stderr) == (0, "1.1253953951963827\n", "[]\n")
    declined = _run(code, "natural-frequency", "--k", "100 N/m", "--m", "2 kg", "--explain")
    assert declined.returncode == 0 and "click" in declined.stderr and "pint" in declined.stderr
    assert "omega = sqrt(k / m)" in declined.stdout or "omega" in declined.stdout


def test_the_full_path_keeps_pint_from_importing_dask(tmp_path):
    """pint imports dask at its own import where dask is installed (+75 ms, +12 MB a run); a
    command line never holds a dask array, so the console entry hides it from pint. Shown
    with a stand-in dask on the path whose import fails loudly: without the hiding, pint
    imports it and the run fails; with it, the run is the same as without a dask at all,
    and pint takes dask for absent."""
    fake = tmp_path / "dask"
    fake.mkdir()
    (fake / "__init__.py").write_text("raise RuntimeError('dask was imported')\n")
    code = ("import atexit, sys\n"
            "atexit.register(lambda: print('pint' in sys.modules, "
            "sys.modules.get('pint.compat') and sys.modules['pint.compat'].HAS_DASK, "
            "file=sys.stderr))\n"
            "sys.path.insert(0, sys.argv.pop(1))\n"
            "from dyncalc.quick import main\nmain(sys.argv[1:])\n")
    args = ["damping-ratio", "--c", "10 N*s/m", "--k", "1 kN/m", "--m", "2 kg", "--value",
            "zeta"]
    run = _run(code, str(tmp_path), *args)
    assert (run.returncode, run.stdout, run.stderr) == (0, "0.11180339887498948\n",
                                                        "True False\n")
    # the stand-in does fail an import that is not hidden (so the test can fail)
    bare = _run("import sys; sys.path.insert(0, sys.argv[1]); import pint", str(tmp_path))
    assert bare.returncode == 1 and "dask was imported" in bare.stderr


def test_console_script_output_is_the_full_paths_in_a_subprocess():
    """A sample through ``python -m dyncalc`` (quick) and the full path (``dyncalc.cli``)."""
    for args in (["natural-frequency", "--k", "2 kN/m", "--m", "4 kg"],
                 ["natural-frequency", "--length", "3 ft", "--json"],
                 ["natural-frequency", "--k", "0 N/m", "--m", "4 kg"],
                 ["natural-frequency", "--kt", "3 kN*m/rad", "--inertia", "1.2 kg*m^2",
                  "--value", "T"]):
        quick = _run("import sys; from dyncalc.quick import main; main(sys.argv[1:])", *args)
        slow = _run("import sys; from dyncalc.cli import main; main(sys.argv[1:])", *args)
        assert (quick.returncode, quick.stdout, quick.stderr) == (
            slow.returncode, slow.stdout, slow.stderr)
    assert slow.stdout  # the last one printed something


# --- the unit table ---------------------------------------------------------------------------

def test_the_committed_table_is_what_the_generator_makes():
    assert (ROOT / "dyncalc" / "quick" / "table.py").read_text(encoding="utf-8") == \
        gen_unit_table.render()


@pytest.mark.parametrize("unit", sorted(UNITS))
def test_every_table_entry_is_pints_conversion_bit_for_bit(unit):
    """The factor is pint's own (1 unit converted to SI), ``x unit`` reads as ``x * factor``
    for random magnitudes, and a dimension the table leaves out is refused by the grammar."""
    from dyncalc.errors import InputError
    from dyncalc.units import Q_, parse_quantity, parse_unit

    dims = {d.name: d for d in gen_unit_table._dims()}
    rng = random.Random(unit)
    for name, dim in dims.items():
        entry = UNITS[unit].get(name)
        if entry is None:
            with pytest.raises(InputError):
                parse_quantity(f"1 {unit}", dim, label="x")
            continue
        factor, canonical = entry
        if dim.kind not in ("angular-rate", "cycle-rate"):  # pint's plain conversion
            pint_factor = Q_(1.0, parse_unit(unit)).to(dim.si.replace("^", "**")).magnitude
            assert pint_factor.hex() == factor.hex()
        assert canonical == (parse_unit(unit) == parse_unit(dim.si))
        for _ in range(40):
            x = 10.0 ** rng.uniform(-290, 290) * rng.uniform(1, 10)
            expected = x * factor
            if not 0.0 < expected < math.inf:
                continue
            assert parse_quantity(f"{x!r} {unit}", dim, label="x").si.hex() == expected.hex()
