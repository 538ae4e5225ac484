"""The command-line contract (SPEC.md): output forms, exit codes, error lines."""
import io
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from dyncalc.cli import cli

ROOT = Path(__file__).resolve().parents[1]
COMMANDS_ALL = ["spring-series", "spring-parallel", "natural-frequency", "damping-ratio",
         "rolling-onset", "coriolis", "forced-response", "modes", "inertia", "rigid-body",
         "eom", "scenes"]


def run(*args, env=None):
    runner = CliRunner()
    return runner.invoke(cli, list(args), env=env)


def error_line(result):
    """The one stderr line of a refusal (asserting it is exactly one line)."""
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    assert "Traceback" not in result.stderr
    return lines[0]


# --- program -----------------------------------------------------------------------------

def test_version():
    from dyncalc import __version__

    result = run("--version")
    assert result.exit_code == 0
    assert result.stdout == f"dyncalc {__version__}\n"


def test_help_lists_every_command():
    result = run("--help")
    assert result.exit_code == 0
    listed = [line.split()[0] for line in result.stdout.split("Commands:")[1].splitlines()
              if line.startswith("  ") and not line.startswith("    ")]
    assert sorted(listed) == sorted(COMMANDS_ALL)


@pytest.mark.parametrize("command", COMMANDS_ALL)
def test_every_command_has_help_with_an_example(command):
    result = run(command, "--help")
    assert result.exit_code == 0
    assert "Example" in result.stdout and f"dyncalc {command}" in result.stdout


def test_python_dash_m_is_the_same_program():
    proc = subprocess.run([sys.executable, "-m", "dyncalc", "spring-series", "200 N/m",
                           "300 N/m", "--value", "k_eq"], capture_output=True, text=True,
                          timeout=60)
    assert (proc.returncode, proc.stdout, proc.stderr) == (0, "120.0\n", "")


def test_python_dash_O_gives_the_same_answer():
    """pint's parser leans on assert; dyncalc's must not change under python -O."""
    args = ["-m", "dyncalc", "spring-parallel", "1.5e3 lbf/in", "2 kN/m", "--value", "k_eq"]
    plain = subprocess.run([sys.executable, *args], capture_output=True, text=True, timeout=60)
    optimised = subprocess.run([sys.executable, "-O", *args], capture_output=True, text=True,
                               timeout=60)
    assert plain.returncode == optimised.returncode == 0
    assert plain.stdout == optimised.stdout
    assert float(plain.stdout) == pytest.approx(1.5e3 * 4.4482216152605 / 0.0254 + 2000,
                                                rel=1e-15)


# --- the three output forms ----------------------------------------------------------------

def test_json_shape_and_numbers():
    result = run("spring-series", "200 N/m", "300 N/m", "--json")
    assert result.exit_code == 0
    data = json.loads(result.stdout)
    assert data == {
        "schema": "dyncalc/2", "command": "spring-series", "scene": None, "model": "series",
        "method": "closed-form",
        "inputs": {"k1": {"value": 200.0, "unit": "N/m", "text": "200 N/m"},
                   "k2": {"value": 300.0, "unit": "N/m", "text": "300 N/m"}},
        "results": {"k_eq": {"value": 120.0, "unit": "N/m"}},
        "warnings": [],
        "extra": {},
    }


def test_json_units_parse_back_in_pint():
    from dyncalc.units import registry

    result = run("spring-series", "3 kN*m/rad", "torsion-bar(l=0.5m, G=80GPa, J_t=1e-8m^4)",
                 "--json")
    data = json.loads(result.stdout)
    ureg = registry()
    for section in ("inputs", "results"):
        for item in data[section].values():
            ureg.Quantity(1, item["unit"])  # raises if pint cannot read it
    assert data["results"]["k_eq"]["value"] == pytest.approx(1 / (1 / 3000 + 1 / 1600),
                                                             rel=1e-15)


def test_json_rigid_network_gives_null_and_a_warning():
    data = json.loads(run("spring-parallel", "1 N/m", "inf", "--json").stdout)
    assert data["results"]["k_eq"] == {"value": None, "unit": "N/m"}
    assert data["warnings"] == ["k_eq is infinite: the network is rigid (a rigid element "
                                "carries the load alone); JSON gives its value as null"]


def test_json_marks_assumed_si():
    data = json.loads(run("spring-series", "200", "300 N/m", "--json").stdout)
    assert data["inputs"]["k1"] == {"value": 200.0, "unit": "N/m", "text": "200",
                                    "assumed_si": True}
    assert data["inputs"]["k2"] == {"value": 300.0, "unit": "N/m", "text": "300 N/m"}


def test_value_is_full_precision_repr():
    result = run("spring-series", "1 N/m", "3 N/m", "--value", "k_eq")
    assert result.exit_code == 0
    assert result.stdout == f"{0.75!r}\n"
    result = run("spring-series", "1 N/m", "7 N/m", "--value", "k_eq")
    assert result.stdout == f"{7 / 8!r}\n"
    result = run("spring-parallel", "0.1 N/m", "0.2 N/m", "--value", "k_eq")
    assert result.stdout == "0.30000000000000004\n"  # correctly rounded 0.1 + 0.2


def test_value_unknown_name():
    result = run("spring-series", "1 N/m", "--value", "omega")
    assert result.exit_code == 2
    assert error_line(result) == ("Error: --value omega: there is no result named 'omega'; the "
                                  "results are k_eq")


def test_value_warnings_go_to_stderr():
    result = run("spring-parallel", "1 N/m", "inf", "--value", "k_eq")
    assert result.exit_code == 0
    assert result.stdout == "inf\n"
    assert result.stderr.startswith("warning: k_eq is infinite")


def test_human_table_plain_when_piped():
    result = run("spring-series", "200 N/m", "300 N/m")
    assert result.exit_code == 0
    assert result.stdout.splitlines() == [
        "spring-series   model: series   method: closed-form",
        "result  symbol  value  unit",
        "k_eq    k_eq    120    N/m",
        "inputs: k1 = 200 N/m, k2 = 300 N/m",
    ]
    assert "\x1b[" not in result.stdout


def test_human_marks_assumed_si():
    result = run("spring-series", "200", "300")
    assert "inputs: k1 = 200 N/m (assumed SI), k2 = 300 N/m (assumed SI)" in result.stdout


def test_digits():
    result = run("spring-series", "1 N/m", "2 N/m", "--digits", "3")
    assert "k_eq    k_eq    0.667  N/m" in result.stdout
    result = run("spring-series", "1 N/m", "2 N/m", "--digits", "12")
    assert "0.666666666667" in result.stdout
    result = run("spring-series", "1 N/m", "--digits", "0")
    assert result.exit_code == 2
    assert error_line(result).startswith("Error: Invalid value for '--digits'")


def test_unit_conversion_of_a_result():
    result = run("spring-parallel", "2 kN/m", "12 lbf/in", "--unit", "k_eq=N/mm", "--json")
    data = json.loads(result.stdout)
    expected = (2000 + 12 * 4.4482216152605 / 0.0254) / 1000
    assert data["results"]["k_eq"]["unit"] == "N/mm"
    assert data["results"]["k_eq"]["value"] == pytest.approx(expected, rel=1e-15)
    result = run("spring-parallel", "2 kN/m", "--unit", "k_eq=lbf/in", "--value", "k_eq")
    assert float(result.stdout) == pytest.approx(2000 * 0.0254 / 4.4482216152605, rel=1e-15)


@pytest.mark.parametrize("spec, message", [
    ("k_eq=kg", "Error: --unit k_eq: kg is not a unit of [force]/[length]; k_eq is a "
                "stiffness"),
    ("omega=rad/s", "Error: --unit omega: there is no result named 'omega'; the results are "
                    "k_eq"),
    ("k_eq", "Error: --unit takes NAME=VALUE (for example --unit f=1.13Hz); got 'k_eq'"),
    ("k_eq=2 N/m", "Error: --unit k_eq: cannot read '2 N/m': give a unit, not a quantity"),
])
def test_unit_refusals(spec, message):
    result = run("spring-series", "1 N/m", "--unit", spec)
    assert result.exit_code == 2
    assert error_line(result) == message


# --- checks ----------------------------------------------------------------------------------

def test_check_pass_exit_0():
    result = run("spring-series", "200 N/m", "300 N/m", "--check", "k_eq=121N/m")
    assert result.exit_code == 0
    assert ("check k_eq: expected 120 N/m, given 121 N/m, relative difference 0.0083 "
            "(tolerance 0.01): pass") in result.stdout


def test_check_fail_exit_1():
    result = run("spring-series", "200 N/m", "300 N/m", "--check", "k_eq=130N/m")
    assert result.exit_code == 1
    assert ("check k_eq: expected 120 N/m, given 130 N/m, relative difference 0.083 "
            "(tolerance 0.01): FAIL") in result.stdout


def test_check_in_other_units_and_rtol():
    # 120 N/m = 0.685219... lbf/in
    answer = 120 * 0.0254 / 4.4482216152605
    result = run("spring-series", "200 N/m", "300 N/m", "--check", f"k_eq={answer:.4f} lbf/in",
                 "--rtol", "1e-4", "--json")
    assert result.exit_code == 0
    check = json.loads(result.stdout)["extra"]["checks"][0]
    assert check["unit"] == "lbf/in" and check["pass"] is True
    assert check["expected"] == pytest.approx(answer, rel=1e-14)
    result = run("spring-series", "200 N/m", "300 N/m", "--check", "k_eq=0.68 lbf/in",
                 "--rtol", "1e-4")
    assert result.exit_code == 1


def test_several_checks_one_fails():
    result = run("spring-series", "cantilever(l=1m, EI=1e3 N*m^2)", "3 kN/m",
                 "--check", "k_eq=1.5kN/m", "--check", "k1=2kN/m")
    assert result.exit_code == 1
    assert ("check k_eq: expected 1.5 kN/m, given 1.5 kN/m, relative difference 0 "
            "(tolerance 0.01): pass") in result.stdout
    assert ("check k1: expected 3 kN/m, given 2 kN/m, relative difference 0.33 "
            "(tolerance 0.01): FAIL") in result.stdout


def test_check_with_value_reports_failure_on_stderr():
    result = run("spring-series", "200 N/m", "300 N/m", "--check", "k_eq=1N/m",
                 "--value", "k_eq")
    assert result.exit_code == 1
    assert result.stdout == "120.0\n"
    assert "FAIL" in result.stderr


@pytest.mark.parametrize("spec, message", [
    ("k_eq=5kg", "Error: --check k_eq must be a stiffness [force]/[length]; got 5 kilogram "
                 "([mass])"),
    ("f=1Hz", "Error: --check f: there is no result named 'f'; the results are k_eq"),
    ("k_eq=", "Error: --check takes NAME=VALUE (for example --check f=1.13Hz); got 'k_eq='"),
])
def test_check_refusals(spec, message):
    result = run("spring-series", "200 N/m", "--check", spec)
    assert result.exit_code == 2
    assert error_line(result) == message


@pytest.mark.parametrize("rtol", ["0", "-1", "1", "nan"])
def test_rtol_out_of_range(rtol):
    result = run("spring-series", "200 N/m", "--check", "k_eq=200N/m", "--rtol", rtol)
    assert result.exit_code == 2
    assert error_line(result).startswith("Error: Invalid value for '--rtol'")


# --- explain, strict, debug ----------------------------------------------------------------

def test_explain_text_and_json():
    result = run("spring-series", "parallel(cantilever(l=2m), cantilever(l=1m))", "5kN/m",
                 "EI=2e4 N*m^2", "--explain")
    assert "  k_eq = 1/(1/(k1 + k2) + 1/k3)" in result.stdout
    assert "  k1 = 3 EI / l^3  (cantilever)" in result.stdout
    assert "  k3 = 5000 N/m" in result.stdout
    data = json.loads(run("spring-series", "1 N/m", "1 N/m", "--explain", "--json").stdout)
    assert data["extra"]["explanation"]["formula"] == ["k_eq = 1/(1/k1 + 1/k2)"]
    assert "explanation" not in json.loads(run("spring-series", "1 N/m", "--json").stdout)[
        "extra"]


def test_strict_units():
    result = run("spring-series", "200", "--strict-units")
    assert result.exit_code == 2
    assert error_line(result) == ("Error: element k1 (200): '200' has no unit and "
                                  "--strict-units is on; write it with a unit, e.g. 200 N/m")


def test_internal_error_one_line_and_debug_traceback(monkeypatch):
    import dyncalc.commands.springs

    def boom(*a, **k):
        raise RuntimeError("simulated bug")

    monkeypatch.setattr(dyncalc.commands.springs, "network_stiffness", boom)
    result = run("spring-series", "1 N/m")
    assert result.exit_code == 2
    assert error_line(result) == ("Error: internal error (RuntimeError: simulated bug); please "
                                  "report it, with --debug for the traceback")
    result = run("spring-series", "1 N/m", "--debug")
    assert isinstance(result.exception, RuntimeError)


# --- errors ----------------------------------------------------------------------------------

@pytest.mark.parametrize("args, message", [
    (["spring-series", "5 kg"], "Error: element k1 (5 kg) must be a stiffness [force]/[length] "
                                "or [force]*[length]/[angle]; got 5 kilogram ([mass])"),
    (["spring-series", "--xyzzy"], "Error: No such option '--xyzzy'; see 'dyncalc "
                                 "spring-series --help'"),
    (["spring-series", "--jsn"], "Error: No such option '--jsn' (did you mean '--json'?); "
                                 "see 'dyncalc spring-series --help'"),
    (["frobnicate"], "Error: No such command 'frobnicate'; see 'dyncalc --help'"),
    (["spring-parallel", "1e308N/m", "1e308N/m"], "Error: k_eq overflows float64 (the largest "
                                                  "is 1.8e308 N/m)"),
    (["spring-series", "1e400 N/m"], "Error: element k1 (1e400 N/m): cannot read '1e400 N/m': "
                                     "1e400 overflows float64 (the largest is 1.8e308)"),
    (["spring-series", "10**10**10 N/m"], "Error: element k1 (10**10**10 N/m): cannot read "
                                          "'10**10**10 N/m': chained powers (a**b**c) are not "
                                          "read; use parentheses"),
    (["spring-series", "1,5 N/m"], "Error: element k1 (1,5 N/m): cannot read '1,5 N/m': a "
                                   "comma is neither a decimal point nor a thousands separator "
                                   "here; write 1.5 or 1500"),
    (["scenes", "no-such-scene"], "Error: there is no scene 'no-such-scene'; the scenes are: "
                                  + ", ".join(__import__("dyncalc.scenes", fromlist=["x"])
                                              .scene_names())),
])
def test_errors_are_one_line_exit_2(args, message):
    result = run(*args)
    assert result.exit_code == 2
    assert error_line(result) == message
    assert result.stdout == ""


@pytest.mark.parametrize("text", ["[/]", "[link=https://x]5 N/m", "[bold red]5[/] N/m"])
def test_markup_in_input_is_not_interpreted(text):
    result = run("spring-series", text)
    assert result.exit_code == 2
    line = error_line(result)
    assert line.startswith("Error: element k1 (")
    assert text[:20] in line


def test_rich_table_does_not_read_markup():
    """The terminal renderer wraps user text in rich Text objects, never markup strings."""
    from rich.console import Console

    from dyncalc.cli.render import rich_text
    from dyncalc.result import Entry, Result
    from dyncalc.units import STIFFNESS

    result = Result("spring-series", {"k_eq": Entry("k_eq", 1.0, STIFFNESS, unit="N/m",
                                                   symbol="[b]k[/b]")},
                    warnings=["[red]x[/red] stays literal"])
    buffer = io.StringIO()
    console = Console(file=buffer, force_terminal=True, width=100, color_system="standard")
    rich_text(result, {}, 6, [], False, console)
    out = buffer.getvalue()
    assert "[b]k[/b]" in out and "[red]x[/red] stays literal" in out


def test_no_color_on_a_terminal(monkeypatch):
    from rich.console import Console

    from dyncalc.cli.render import rich_text
    from dyncalc.commands.springs import network_stiffness

    monkeypatch.setenv("NO_COLOR", "1")
    buffer = io.StringIO()
    console = Console(file=buffer, force_terminal=True, width=100)
    rich_text(network_stiffness("parallel", ["1 N/m", "inf"]), {}, 6, [], False, console)
    assert "\x1b[3" not in buffer.getvalue()  # no foreground colour codes
    assert "warning: k_eq is infinite" in buffer.getvalue()


# --- scenes ----------------------------------------------------------------------------------

def test_scenes_lists_the_catalog():
    from dyncalc.scenes import catalog

    result = run("scenes")
    assert result.exit_code == 0
    lines = result.stdout.splitlines()
    assert len(lines) == 3 * len(catalog())
    assert lines[0].split()[0] == "mass-spring"
    assert lines[1].strip() == "k [force]/[length], m [mass], zeta dimensionless?"
    assert lines[2].strip() == ("examples: E5.11, E5.19, E5.26; commands: natural-frequency, "
                                "forced-response, eom")


def test_scenes_reads_the_registry(monkeypatch):
    from dyncalc import scenes as registry
    from dyncalc.units import MASS, STIFFNESS

    scene = registry.Scene(
        name="test-oscillator", summary="a block on a spring", figure="a block on a spring",
        params=(registry.Param("k", STIFFNESS, "spring stiffness"),
                registry.Param("m", MASS, "block mass", default="1 kg")),
        compute=math.sqrt, equation="m x'' + k x = 0", formula="omega^2 = k/m",
        reference="E5.11", example="dyncalc natural-frequency --k 100N/m --m 2kg")
    monkeypatch.setitem(registry._SCENES, scene.name, scene)
    listing = run("scenes").stdout.splitlines()
    at = [line.split()[0] for line in listing].index("test-oscillator")
    assert listing[at].split(None, 1)[1].strip() == "a block on a spring"
    assert listing[at + 1].strip() == "k [force]/[length], m [mass] = 1 kg"
    detail = json.loads(run("scenes", "test-oscillator", "--json").stdout)
    assert detail["params"][0] == {"name": "k", "dimension": "[force]/[length]", "unit": "N/m",
                                   "choices": None, "default": None, "required": True,
                                   "description": "spring stiffness"}
    assert "equation of motion: m x'' + k x = 0" in run("scenes", "test-oscillator").stdout
    assert scene.compute is math.sqrt


# --- the README and CI stay in step ----------------------------------------------------------

def test_readme_setup_commands_are_what_ci_runs():
    readme = (ROOT / "README.md").read_text()
    ci = (ROOT / ".ci" / "run").read_text()
    install_and_test = [line for line in ci.splitlines() if line.startswith("python3 -m venv")]
    assert install_and_test, "no set-up command in .ci/run"
    for line in install_and_test:
        assert line in readme, f"README does not show the command CI runs: {line}"


def test_readme_tours_every_command():
    readme = (ROOT / "README.md").read_text()
    for command in COMMANDS_ALL:
        assert f"dyncalc {command}" in readme, command


def test_no_heavy_imports_for_help():
    code = ("import sys, dyncalc.cli\n"
            "print(sorted(m for m in ('pint', 'numpy', 'scipy', 'rich') if m in sys.modules))")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=60, env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert proc.stdout.strip() == "[]"
