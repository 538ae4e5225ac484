"""--explain in its three formats (text, markdown, latex) for every scene and every command;
the LaTeX is balanced, and compiles when a TeX engine is on PATH."""
import json
import re
import shlex
import shutil
import subprocess

import pytest
from click.testing import CliRunner

from dyncalc.cli import cli
from dyncalc.result.explain_render import latex, markdown, render_explanation, text_lines
from dyncalc.result.explain import latex_escape, number_latex, tex_to_text, unit_latex
from dyncalc.result import Explanation
from dyncalc.scenes import catalog, scene_names

FORMATS = ("text", "markdown", "latex")

#: Every command other than natural-frequency, in the forms its explanation differs.
COMMANDS = {
    "damping-c": "damping-ratio --c 2N*s/m --k 100N/m --m 1kg",
    "damping-decrement": "damping-ratio --decrement 0.5 --omega 10rad/s",
    "damping-ratio": "damping-ratio --ratio 2 --cycles 3 --k 100N/m --m 1kg",
    "damping-amplitudes": "damping-ratio --amplitudes 1,0.8,0.64,0.51",
    "damping-scene": 'damping-ratio --scene rod-in-fluid m=1.5kg l=0.8m "beta=2 N*s/m^2"',
    "rolling-onset": 'rolling-onset --v0 "5 m/s" --mu 0.3',
    "rolling-onset-incline": 'rolling-onset --v0 "2 m/s" --mu 0.2 --radius 28.5mm '
                             '--omega0 "-300 rad/s" --incline 5deg',
    "coriolis-scalar": "coriolis --omega 2rad/s --vr 3m/s --r 1m --alpha 1rad/s^2 --mass 2kg",
    "coriolis-vector": 'coriolis --omega "0,0,30 rpm" --vr "0.5,0,0 m/s" --r "0.2,0,0 m"',
    "coriolis-earth": 'coriolis --latitude 45deg --speed "180 km/h" --heading 0deg',
    "spring-series": "spring-series 200N/m 300N/m",
    "spring-parallel": "spring-parallel 2kN/m \"12 lbf/in\"",
    "spring-network": 'spring-series "parallel(cantilever(l=2m), cantilever(l=1m))" 5kN/m '
                      'EI="2e4 N*m^2"',
}


def run(*args):
    return CliRunner().invoke(cli, list(args))


def example_words(name):
    words = shlex.split(catalog()[name].example)
    assert words[0] == "dyncalc"
    return words[1:]


# --- balance ----------------------------------------------------------------------------------

def assert_balanced_latex(tex):
    depth = 0
    for i, ch in enumerate(tex):
        if ch == "{" and (i == 0 or tex[i - 1] != "\\"):
            depth += 1
        elif ch == "}" and (i == 0 or tex[i - 1] != "\\"):
            depth -= 1
        assert depth >= 0, f"unbalanced }} at {i}: {tex[max(0, i - 60):i + 1]!r}"
    assert depth == 0, "unbalanced {"
    stack = []
    for kind, env in re.findall(r"\\(begin|end)\{(\w+\*?)\}", tex):
        if kind == "begin":
            stack.append(env)
        else:
            assert stack and stack.pop() == env, f"\\end{{{env}}} without its \\begin"
    assert not stack, f"unclosed environments {stack}"
    assert len(re.findall(r"\\left\b", tex)) == len(re.findall(r"\\right\b", tex))
    assert len(re.findall(r"(?<!\\)\$", tex)) % 2 == 0, "unbalanced $"


def test_balance_check_catches_mistakes():
    for bad in (r"\frac{a}{b", r"\begin{align*} x", r"\left( x )", r"$x"):
        with pytest.raises(AssertionError):
            assert_balanced_latex(bad)
    assert_balanced_latex(r"\begin{align*} \left( \{x\} \right) \end{align*} \$")


# --- every scene, every format ----------------------------------------------------------------

def test_every_scene_has_latex_formulas():
    assert len(scene_names()) >= 23
    for name, scene in catalog().items():
        assert scene.latex, f"{name} has no LaTeX formula"


@pytest.mark.parametrize("name", scene_names())
@pytest.mark.parametrize("fmt", FORMATS)
def test_scene_explains_in_every_format(name, fmt):
    words = example_words(name)
    option = "--explain" if fmt == "text" else f"--explain={fmt}"
    result = run(*words, option)
    assert result.exit_code == 0, result.output
    data = json.loads(run(*words, option, "--json").stdout)
    ex = data["extra"]["explanation"]
    assert ex["latex"]["formula"] and ex["latex"]["substituted"], name
    # the substituted lines end in the results they compute, to 6 digits
    omega = next((v for k, v in data["results"].items() if k.startswith("omega")),
                 next(iter(data["results"].values())))  # a scene with no frequency: the first
    shown = f"{omega['value']:.6g}"
    assert any(shown in line for line in ex["substituted"]), (name, ex["substituted"])
    assert any(shown in line for line in ex["latex"]["substituted"]), name
    assert ex["example"].startswith(catalog()[name].example)
    if fmt == "text":
        assert "rendered" not in ex
        assert "values:" in result.stdout and "example: dyncalc " in result.stdout
    else:
        assert ex["rendered"] in result.stdout + "\n"
    if fmt == "latex":
        assert_balanced_latex(ex["rendered"])
        assert r"\begin{align*}" in ex["rendered"]
        assert shown in ex["rendered"]
    if fmt == "markdown":
        assert ex["rendered"].count("$$") % 2 == 0
        for line in ex["latex"]["substituted"]:
            assert f"$$ {line} $$" in ex["rendered"]
            assert_balanced_latex(line)


@pytest.mark.parametrize("key", COMMANDS)
@pytest.mark.parametrize("fmt", FORMATS)
def test_command_explains_in_every_format(key, fmt):
    words = shlex.split(COMMANDS[key])
    option = "--explain" if fmt == "text" else f"--explain={fmt}"
    result = run(*words, option)
    assert result.exit_code == 0, result.output
    ex = json.loads(run(*words, option, "--json").stdout)["extra"]["explanation"]
    assert set(ex) >= {"formula", "substituted", "assumptions", "reference", "latex",
                       "example", "variance"}
    assert ex["latex"]["formula"], key
    for line in ex["latex"]["formula"] + ex["latex"]["substituted"]:
        assert_balanced_latex(line)
    if fmt == "latex":
        assert_balanced_latex(ex["rendered"])
    elif fmt == "markdown":
        assert ex["rendered"].count("$$") % 2 == 0


# --- exact content ----------------------------------------------------------------------------

def test_mass_spring_substitutes_the_values():
    data = json.loads(run("natural-frequency", "--k", "100N/m", "--m", "2kg", "--explain",
                          "--json").stdout)
    ex = data["extra"]["explanation"]
    assert ex["substituted"][0] == "omega = sqrt((100 N/m) / (2 kg)) = 7.07107 rad/s"
    assert ex["latex"]["formula"][0] == r"\omega = \sqrt{\frac{k}{m}}"
    assert ex["latex"]["substituted"][0] == (
        r"\omega = \sqrt{\frac{100\,\mathrm{N/m}}{2\,\mathrm{kg}}} = 7.07107\,\mathrm{rad/s}")
    assert ex["example"] == ("dyncalc natural-frequency --k 100N/m --m 2kg gives omega = "
                             "7.0710678118654755 rad/s, f = 1.1253953951963828 Hz, "
                             "T = 0.8885765876316732 s")
    assert ex["variance"] == {}
    assert "rendered" not in ex


def test_assumption_sizes():
    def assumptions(*words):
        return json.loads(run("natural-frequency", *words, "--explain", "--json")
                          .stdout)["extra"]["explanation"]["assumptions"]

    found = assumptions("--length", "1m", "--amplitude", "30deg")
    assert any("1.71% short at an amplitude of 30 deg" in a for a in found)
    found = assumptions("--k", "100N/m", "--m", "2kg", "--zeta", "0.1")
    assert ("damping lowers the frequency: omega_d = omega sqrt(1 - zeta^2) is 0.501% below "
            "omega at zeta = 0.1") in found
    found = assumptions(*example_words("frame-brace-damper")[1:])
    assert any("small-damping peak y_max = y0/(2 zeta) is 0.25% below" in a for a in found)
    found = assumptions("--scene", "rolling-in-track", "R=1m", "r=0.2m")
    assert any(a.startswith("no amplitude is given") for a in found)


def test_explain_equals_rewrite_keeps_the_flag_a_flag():
    result = run("natural-frequency", "--explain", "k=2N/m", "m=1kg")
    assert result.exit_code == 0, result.output
    assert "omega = sqrt((2 N/m) / (1 kg)) = 1.41421 rad/s" in result.stdout
    result = run("natural-frequency", "--explain=latex", "k=2N/m", "m=1kg")
    assert result.exit_code == 0 and r"\begin{align*}" in result.stdout


def test_explain_unknown_format():
    result = run("natural-frequency", "--k", "1N/m", "--m", "1kg", "--explain=bogus")
    assert result.exit_code == 2
    assert result.output == ("Error: --explain=bogus: the formats are text, markdown, latex "
                             "(--explain alone is text)\n")


def test_explain_format_still_refused_with_batch():
    result = run("natural-frequency", "--batch", "-", "--explain=latex")
    assert result.exit_code == 2
    assert "--explain does not go with --batch" in result.output


def test_user_text_is_escaped_in_latex_and_markdown():
    ex = Explanation(formula=["x = y"], assumptions=["50% of k_1 & $5 #1 {a} ~ ^ \\ [b]"],
                     reference="E5.12", example="dyncalc x --k 1N/m gives k = 1 N/m")
    tex = latex(ex)
    assert r"50\% of k\_1 \& \$5 \#1 \{a\} \textasciitilde{} \textasciicircum{} " \
           r"\textbackslash{} [b]" in tex
    assert_balanced_latex(tex)
    md = markdown(ex)
    assert r"k\_1" in md and r"\$5" in md and r"\[b\]" in md
    assert "`dyncalc x --k 1N/m` gives k = 1 N/m" in md


# --- variance shares (set by uncertainty propagation) -----------------------------------------

def test_variance_shares_in_every_format():
    ex = Explanation(formula=["omega = sqrt(k/m)"], latex=[r"\omega = \sqrt{\frac{k}{m}}"],
                     variance={"omega": {"k": 0.2, "m": 0.8}})
    assert "variance of omega: m 80.0 %, k 20.0 %" in text_lines(ex)
    assert "- variance of omega: m 80.0 %, k 20.0 %" in markdown(ex)
    assert r"\item variance of omega: m 80.0 \%, k 20.0 \%" in latex(ex)
    assert ex.as_dict()["variance"] == {"omega": {"k": 0.2, "m": 0.8}}
    assert "variance" not in render_explanation(Explanation(formula=["x"]), "text")


# --- the pieces -------------------------------------------------------------------------------

@pytest.mark.parametrize("unit, tex", [
    ("N/m", r"\mathrm{N/m}"), ("kg*m^2", r"\mathrm{kg\,m^{2}}"),
    ("N*m/rad", r"\mathrm{N\,m/rad}"), ("m/s^2", r"\mathrm{m/s^{2}}"),
    ("m/s**2", r"\mathrm{m/s^{2}}"), ("kN*s/m", r"\mathrm{kN\,s/m}"), ("N m", r"\mathrm{N\,m}"),
    ("1/s", r"\mathrm{1/s}"), ("s^-1", r"\mathrm{s^{-1}}"), ("deg", r"{}^{\circ}"),
    ("lbf/in", r"\mathrm{lbf/in}"), ("kg*m^(2)", r"\mathrm{kg\,m^{2}}"), ("", ""),
])
def test_unit_latex(unit, tex):
    assert unit_latex(unit) == tex


def test_numbers_and_text():
    assert number_latex(1.5e-05) == r"1.5\times 10^{-5}"
    assert number_latex(7.0710678) == "7.07107"
    assert latex_escape("a_b%") == r"a\_b\%"
    assert tex_to_text(r"\sqrt{\frac{2\,k}{M + 2\,m}}") == "sqrt((2 k) / (M + 2 m))"
    assert tex_to_text(r"\frac{2\pi}{\omega_{0}}") == "(2 pi) / omega_0"


# --- compiling --------------------------------------------------------------------------------

def _fragments():
    out = []
    for name in scene_names():
        ex = json.loads(run(*example_words(name), "--explain=latex", "--json").stdout)
        out.append(ex["extra"]["explanation"]["rendered"])
    for words in COMMANDS.values():
        ex = json.loads(run(*shlex.split(words), "--explain=latex", "--json").stdout)
        out.append(ex["extra"]["explanation"]["rendered"])
    return out


def test_latex_of_everything_is_balanced_and_compiles_if_tex_is_here(tmp_path):
    fragments = _fragments()
    for fragment in fragments:
        assert_balanced_latex(fragment)  # always, with or without a TeX engine
    engine = shutil.which("pdflatex") or shutil.which("lualatex")
    if engine is None:
        return  # balance checked above; nothing to compile with here
    body = "\n\\clearpage\n".join(fragments)
    document = ("\\documentclass{article}\n\\usepackage[T1]{fontenc}\n\\usepackage{amsmath}\n"
                "\\begin{document}\n" + body + "\n\\end{document}\n")
    (tmp_path / "explain.tex").write_text(document, encoding="utf-8")
    done = subprocess.run([engine, "-interaction=nonstopmode", "-halt-on-error", "explain.tex"],
                          cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stdout[-3000:]
    assert (tmp_path / "explain.pdf").exists()
