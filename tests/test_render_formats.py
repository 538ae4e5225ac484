"""The human forms of a result: fitted to the width (40, 80, 200 columns, piped with
``COLUMNS`` and on a pseudo-terminal), ``FORCE_COLOR``, ``--format table|markdown|csv|tsv`` and
``--explain=markdown|latex`` as whole documents, and the combinations refused.

The numbers are derived here: omega = sqrt(k/m), f = omega/(2 pi), T = 1/f; a series pair
k1 k2/(k1 + k2) with 1 lbf = 4.4482216152605 N and 1 in = 0.0254 m (exact definitions).
"""
from __future__ import annotations

import math
import os
import re
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from dyncalc.cli import cli
from helpers import on_a_terminal

DYNCALC = Path(sys.executable).with_name("dyncalc")
ANSI = re.compile(r"\x1b\[[0-9;]*m")
CLEAN = {"NO_COLOR": None, "FORCE_COLOR": None, "DYNCALC_PLAIN": None, "COLUMNS": None}

NF = ["natural-frequency", "--k", "100 N/m ± 2 N/m", "--m", "3.077kg"]
OMEGA = math.sqrt(100 / 3.077)
F, T = OMEGA / (2 * math.pi), 2 * math.pi / OMEGA
U = 0.01  # relative standard uncertainty of omega, f and T: half that of k (2 %)

SS = ["spring-series", "200N/m", "300lbf/in"]
K2 = 300 * 4.4482216152605 / 0.0254
K_EQ = 200 * K2 / (200 + K2)
#: how the inputs were read: k2 in the unit typed, then in the canonical unit
SS_INPUTS = f"k1 = 200 N/m, k2 = 300 lbf/in = {K2:.6g} N/m"


def g(x: float, digits: int = 6) -> str:
    return f"{x:.{digits}g}"


def run(args, **env):
    result = CliRunner(env={**CLEAN, **env}).invoke(cli, args)
    # the bytes: click's ``stdout`` turns the CSV's CRLF into LF
    return result.exit_code, result.stdout_bytes.decode(), result.stderr


# --- the plain table at 40, 80 and 200 columns -------------------------------------------------

def _nf_table(width: int) -> list[str]:
    rows = [("omega", "ω", f"{g(OMEGA)} ± {g(U * OMEGA, 2)}", "rad/s"),
            ("f", "f", f"{g(F)} ± {g(U * F, 2)}", "Hz"),
            ("T", "T", f"{g(T)} ± {g(U * T, 2)}", "s")]
    value = max(len(r[2]) for r in rows)
    head = f"{'result':<6}  symbol  {'value':<{value}}  unit"
    return [head] + [f"{a:<6}  {b:<6}  {c:<{value}}  {d}" for a, b, c, d in rows]


@pytest.mark.parametrize("width", [40, 80, 200])
def test_natural_frequency_fits_the_width(width):
    status, out, err = run(NF, COLUMNS=str(width))
    assert (status, err) == (0, "")
    title = (["natural-frequency   scene: mass-spring   model: linear   method: closed-form"]
             if width >= 76 else
             ["natural-frequency   scene: mass-spring", "model: linear   method: closed-form"])
    assert out.splitlines() == title + _nf_table(width) + [
        "inputs: k = 100 ± 2 N/m, m = 3.077 kg"]
    assert max(map(len, out.splitlines())) <= width


@pytest.mark.parametrize("width", [40, 80, 200])
def test_spring_series_fits_the_width(width):
    status, out, _ = run(SS, COLUMNS=str(width))
    assert status == 0
    title = (["spring-series   model: series   method: closed-form"] if width >= 51 else
             ["spring-series   model: series", "method: closed-form"])
    value = g(K_EQ)
    inputs = f"inputs: {SS_INPUTS}"
    assert out.splitlines() == title + [
        f"result  symbol  {'value':<{len(value)}}  unit",
        f"k_eq    k_eq    {value}  N/m"] + (
        [inputs] if len(inputs) <= width else
        ["inputs: k1 = 200 N/m,", f"  k2 = 300 lbf/in = {g(K2)} N/m"])


def test_narrower_still_lists_one_result_a_line_and_wraps_words_not_numbers():
    status, out, _ = run([*NF, "--check", "f=0.8Hz"], COLUMNS="30")
    assert status == 1
    assert out.splitlines() == [
        "natural-frequency", "scene: mass-spring", "model: linear", "method: closed-form",
        "omega (ω) =", f"  {g(OMEGA)} ± {g(U * OMEGA, 2)} rad/s",
        f"f = {g(F)} ± {g(U * F, 2)} Hz",
        f"T = {g(T)} ± {g(U * T, 2)} s",
        "inputs: k = 100 ± 2 N/m,", "  m = 3.077 kg",
        f"check f: expected {g(F)} Hz,", "  given 0.8 Hz, relative",
        f"  difference {(F - 0.8) / F:.2g} (tolerance", "  0.01): FAIL"]


def test_without_columns_a_pipe_has_no_width():
    _status, out, _ = run(NF)
    assert out.splitlines()[0] == ("natural-frequency   scene: mass-spring   model: linear   "
                                   "method: closed-form")


def _on_a_terminal(args, columns: int) -> str:
    env = {k: v for k, v in os.environ.items() if k not in CLEAN}
    env["COLUMNS"] = str(columns)
    status, out, _err = on_a_terminal([str(DYNCALC), *args], env)
    assert status == 0
    return ANSI.sub("", out.decode()).replace("\r\n", "\n")


@pytest.mark.parametrize("width", [40, 80, 200])
def test_a_terminal_of_each_width_gets_every_line_within_it(width):
    args = ["coriolis", "--omega", "0,0,30 rpm", "--vr", "0.5,0,0 m/s", "--r", "0.2,0,0 m",
            "--mass", "2kg"]
    out = _on_a_terminal(args, width)
    lines = out.splitlines()
    assert max(map(len, lines)) <= width, out
    assert "…" not in out
    # a_c = 2 Omega x v_r with Omega = pi rad/s about z, v_r = 0.5 m/s along x: pi along y
    assert f"(0, {g(math.pi)}, 0)" in out and f"(0, {g(-2 * math.pi)}, 0)" in out
    assert f"({g(-math.pi ** 2 * 0.2)}, 0, 0)" in out  # Omega x (Omega x r)
    assert any("model: vectors" in line for line in lines)
    assert any("method: closed-form" in line for line in lines)
    boxed = "┃" in out
    assert boxed == (width >= 80)  # the rich table where it fits, whole lines where not


# --- colour --------------------------------------------------------------------------------------

def test_force_color_colours_a_pipe():
    status, out, _ = run(SS, FORCE_COLOR="1", COLUMNS="80")
    assert status == 0
    assert "\x1b[" in out and "┃" in out  # the terminal table, with its styles
    assert g(K_EQ) in ANSI.sub("", out)


def test_no_color_wins_over_force_color():
    _status, out, _ = run(SS, FORCE_COLOR="1", NO_COLOR="1", COLUMNS="80")
    assert "\x1b[" not in out
    assert out.splitlines()[1].split() == ["result", "symbol", "value", "unit"]


def test_no_colour_in_a_pipe_without_force_color():
    _status, out, _ = run(SS, COLUMNS="80")
    assert "\x1b[" not in out


# --- --format markdown, --explain=markdown|latex --------------------------------------------------

def test_markdown_of_natural_frequency():
    status, out, _ = run([*NF, "--format", "markdown"])
    assert status == 0
    assert out == "\n".join([
        "## natural-frequency", "",
        "scene: mass-spring; model: linear; method: closed-form", "",
        "| result | symbol | value | unit |",
        "| --- | --- | ---: | --- |",
        f"| omega | ω | {g(OMEGA)} ± {g(U * OMEGA, 2)} | rad/s |",
        f"| f | f | {g(F)} ± {g(U * F, 2)} | Hz |",
        f"| T | T | {g(T)} ± {g(U * T, 2)} | s |", "",
        "**Inputs:** k = 100 ± 2 N/m, m = 3.077 kg", ""])


def test_markdown_of_spring_series_escapes_and_explains():
    status, out, _ = run([*SS, "--explain=markdown"])
    assert status == 0
    head, _sep, explanation = out.partition("### Explanation\n")
    assert head == "\n".join([
        "## spring-series", "", "model: series; method: closed-form", "",
        "| result | symbol | value | unit |", "| --- | --- | ---: | --- |",
        f"| k\\_eq | k\\_eq | {g(K_EQ)} | N/m |", "",
        f"**Inputs:** {SS_INPUTS}", "", ""])
    assert explanation.startswith("\n**Formula**\n")
    # --format markdown --explain is the same document
    assert run([*SS, "--format", "markdown", "--explain"])[1] == out


def test_latex_of_both_commands():
    status, out, _ = run([*SS, "--explain=latex"])
    assert status == 0
    head, _sep, explanation = out.partition("% dyncalc --explain=latex")
    assert head == "\n".join([
        "% dyncalc spring-series",
        r"\noindent\textbf{spring-series} (model: series; method: closed-form)", "",
        r"\begin{tabular}{llrl}", r"\hline", r"result & symbol & value & unit \\", r"\hline",
        rf"k\_eq & k\_eq & {g(K_EQ)} & N/m \\", r"\hline", r"\end{tabular}", "",
        rf"\noindent Inputs: {SS_INPUTS}", "", ""])
    assert r"\begin{align*}" in explanation
    status, out, _ = run([*NF, "--explain=latex"])
    assert status == 0
    assert (rf"omega & \ensuremath{{\omega}} & {g(OMEGA)} \ensuremath{{\pm}} "
            rf"{g(U * OMEGA, 2)} & rad/s \\") in out.splitlines()


# --- --format csv|tsv ------------------------------------------------------------------------------

def test_csv_of_natural_frequency_is_full_precision_in_canonical_units():
    status, out, _ = run(["natural-frequency", "--k", "100 N/m", "--m", "3077 g",
                          "--format", "csv"])
    assert status == 0
    assert out == (f"name,value,unit\r\nomega,{OMEGA!r},rad/s\r\nf,{F!r},Hz\r\n"
                   f"T,{1 / F!r},s\r\n")


def test_csv_honours_unit_and_tsv_uses_tabs():
    status, out, _ = run([*SS, "--format", "csv"])
    assert (status, out) == (0, f"name,value,unit\r\nk_eq,{K_EQ!r},N/m\r\n")
    status, out, _ = run([*SS, "--format", "tsv", "--unit", "k_eq=N/mm"])
    assert status == 0
    name, value, unit = out.splitlines()[1].split("\t")
    assert (name, unit) == ("k_eq", "N/mm")
    assert float(value) == pytest.approx(K_EQ / 1000, rel=1e-15)
    assert out.splitlines()[0] == "name\tvalue\tunit" and out.endswith("N/mm\n")


def test_csv_with_uncertainty_and_a_failed_check():
    status, out, err = run([*NF, "--format", "csv", "--check", "f=0.8Hz"])
    assert status == 1
    lines = out.split("\r\n")
    assert lines[0] == "name,value,uncertainty,unit" and lines[-1] == ""
    for line, (name, value, unit) in zip(lines[1:], [("omega", OMEGA, "rad/s"), ("f", F, "Hz"),
                                                     ("T", T, "s")]):
        got_name, got_value, sigma, got_unit = line.split(",")
        assert (got_name, got_unit) == (name, unit)
        assert float(got_value) == pytest.approx(value, rel=1e-15)
        assert float(sigma) == pytest.approx(U * value, rel=1e-9)
    assert err.startswith(f"check f: expected {g(F)} Hz, given 0.8 Hz")
    assert err.rstrip().endswith("FAIL")


def test_csv_quotes_a_vector():
    status, out, _ = run(["coriolis", "--omega", "0,0,2 rad/s", "--vr", "3,0,0 m/s",
                          "--format", "csv"])
    assert status == 0
    assert out.split("\r\n")[1] == 'a_c,"0.0,12.0,0.0",m/s^2'  # 2 (0,0,2) x (3,0,0)


# --- refusals ----------------------------------------------------------------------------------------

@pytest.mark.parametrize("extra, message", [
    (["--format", "csv", "--json"],
     "Error: --format does not go with --json: --json prints its own form; --format is for "
     "the human output"),
    (["--format", "markdown", "--value", "f"],
     "Error: --format does not go with --value: --value prints its own form; --format is for "
     "the human output"),
    (["--format", "tsv", "--explain"],
     "Error: --explain does not go with --format tsv: the TSV is the results table alone "
     "(use --format markdown --explain)"),
    (["--format", "markdown", "--explain=latex"],
     "Error: --explain=latex and --format markdown do not go together: --explain=latex makes "
     "the whole output LaTeX"),
    (["--format", "table", "--explain=markdown"],
     "Error: --explain=markdown and --format table do not go together: --explain=markdown "
     "makes the whole output Markdown"),
    (["--format", "html"],
     "Error: Invalid value for '--format': 'html' is not one of 'table', 'markdown', 'csv', "
     "'tsv'; see 'dyncalc natural-frequency --help'"),
])
def test_refusals(extra, message):
    status, out, err = run([*NF, *extra])
    assert (status, out, err) == (2, "", message + "\n")


def test_format_with_batch_is_refused(tmp_path):
    source = tmp_path / "rows.csv"
    source.write_text("k [N/m],m [kg]\n100,2\n")
    status, out, err = run(["natural-frequency", "--batch", str(source), "--format", "csv"])
    assert (status, out) == (2, "")
    assert err == ("Error: --format does not go with --batch: the output is CSV (or JSON "
                   "lines with --json)\n")
