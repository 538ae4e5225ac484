"""The quick path at a terminal (dyncalc.quick.forms.terminal) against rich: for every quick
case, at several terminal widths, the quick answer is byte for byte what the full path prints
through rich on a forced terminal of that width, or the quick path declines (a line or the
table wider than the terminal) and the full path prints it."""
from __future__ import annotations

import contextlib
import io
import random

import pytest
from rich.console import Console

import dyncalc.quick as quick
from dyncalc.cli import cli, render
from dyncalc.quick import answer
from dyncalc.quick.table import UNITS

WIDTHS = (200, 80, 60, 50, 40, 30)
SCENES = (["--k", "2 kN/m", "--m", "4kg"], ["--k", "100 N/m", "--m", "2 kg"],
          ["--kt", "3 kN*m/rad", "--inertia", "1.2"], ["--length", "0.5 ft"],
          ["--length", "1 m", "--g", "1.62 m/s^2"], ["--k", "1e300 N/m", "--m", "1e-300 kg"],
          ["--k", "3", "--m", "7"], ["--kt", "2 lbf*in/rad", "--inertia", "3 lb*in^2"])
DIGITS = ([], ["--digits", "17"], ["--digits=3"], ["--digits", "1"])


class Terminal(io.StringIO):
    def isatty(self):
        return True


@pytest.fixture(autouse=True)
def _terminal_environment(monkeypatch):
    for name in ("COLUMNS", "FORCE_COLOR", "NO_COLOR", "DYNCALC_PLAIN", "_DYNCALC_COMPLETE",
                 "TTY_COMPATIBLE", "TTY_INTERACTIVE", "COLORTERM", "LINES"):
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("TERM", "xterm-256color")


def at_width(monkeypatch, width: int) -> None:
    """A terminal ``width`` columns wide, to both paths (rich's console forced to be one)."""
    monkeypatch.setattr(quick, "_terminal_width", lambda: width)
    monkeypatch.setattr(render, "_console", lambda: Console(width=width, force_terminal=True))


def compare(args: list[str]) -> bool:
    """Whether the quick path answered ``args`` at the terminal; when it did, its output is
    the full path's (rich's) to the byte."""
    with contextlib.redirect_stdout(Terminal()):
        text = answer(list(args))
    if text is None:
        return False
    out, err = Terminal(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli.main(args=list(args), prog_name="dyncalc", standalone_mode=False)
    assert "\x1b[1m" in out.getvalue()  # rich drew it for a terminal
    assert (text + "\n", "", 0) == (out.getvalue(), err.getvalue(), code), (args, text)
    return True


@pytest.mark.parametrize("width", WIDTHS)
def test_natural_frequency_at_a_terminal_is_riches(monkeypatch, width):
    at_width(monkeypatch, width)
    answered = sum(compare(["natural-frequency", *scene, *digits])
                   for scene in SCENES for digits in DIGITS)
    if width >= 200:
        assert answered == len(SCENES) * len(DIGITS)
    if width == 80:  # all but an input line of 17 digits in a long unit
        assert answered >= len(SCENES) * len(DIGITS) - 2
    if width <= 30:
        assert answered == 0  # the title alone is wider


@pytest.mark.parametrize("width", WIDTHS)
@pytest.mark.parametrize("how", ["series", "parallel"])
def test_spring_networks_at_a_terminal_are_riches(monkeypatch, width, how):
    at_width(monkeypatch, width)
    rng = random.Random(f"{how}{width}")
    units = [u for u, dims in UNITS.items()
             if "stiffness" in dims or "torsional stiffness" in dims] + [""]
    answered = 0
    for unit in units:
        count = rng.randint(1, 4)
        words = [f"{rng.choice(['1', '2.5', '300', '1e-3', '7e12'])} {unit}".strip()
                 for _ in range(count)]
        for digits in rng.sample(DIGITS, 2):
            answered += compare([f"spring-{how}", *words, *digits])
    assert answered > {200: len(units), 80: len(units) // 2}.get(width, -1)


def test_no_colour_keeps_bold_and_dim_as_rich_does(monkeypatch):
    """NO_COLOR: rich drops colours only; the quick form has none."""
    at_width(monkeypatch, 80)
    monkeypatch.setenv("NO_COLOR", "1")
    assert compare(["natural-frequency", "--k", "100 N/m", "--m", "2 kg"])


def test_the_form_at_a_terminal(monkeypatch):
    at_width(monkeypatch, 80)
    with contextlib.redirect_stdout(Terminal()):
        text = answer(["natural-frequency", "--k", "100 N/m", "--m", "2 kg"])
    bold, dim, reset = "\x1b[1m", "\x1b[2m", "\x1b[0m"
    head = "".join(f"{bold} {reset}{bold}{cell}{reset}{bold} {reset}┃"
                   for cell in ("result", "symbol", "   value", "unit "))
    assert text.splitlines() == [
        f"{bold}natural-frequency   scene: mass-spring   model: linear   method: closed-form"
        f"{reset}",
        "┏━━━━━━━━┳━━━━━━━━┳━━━━━━━━━━┳━━━━━━━┓",
        "┃" + head,
        "┡━━━━━━━━╇━━━━━━━━╇━━━━━━━━━━╇━━━━━━━┩",
        "│ omega  │ ω      │  7.07107 │ rad/s │",
        "│ f      │ f      │   1.1254 │ Hz    │",
        "│ T      │ T      │ 0.888577 │ s     │",
        "└────────┴────────┴──────────┴───────┘",
        f"{dim}inputs: k = 100 N/m, m = 2 kg{reset}"]


@pytest.mark.parametrize("name, value", [("TERM", "dumb"), ("TERM", "unknown"),
                                         ("TTY_COMPATIBLE", "1"), ("TTY_COMPATIBLE", "0"),
                                         ("FORCE_COLOR", "1"), ("COLUMNS", "80"),
                                         ("COLUMNS", "")])
def test_declines_where_rich_would_draw_otherwise(monkeypatch, name, value):
    at_width(monkeypatch, 80)
    monkeypatch.setenv(name, value)
    with contextlib.redirect_stdout(Terminal()):
        assert answer(["natural-frequency", "--k", "100 N/m", "--m", "2 kg"]) is None


def test_plain_at_a_terminal_with_dyncalc_plain(monkeypatch):
    monkeypatch.setenv("DYNCALC_PLAIN", "1")
    args = ["natural-frequency", "--k", "100 N/m", "--m", "2 kg"]
    with contextlib.redirect_stdout(Terminal()):
        text = answer(args)
    out = Terminal()
    with contextlib.redirect_stdout(out):
        cli.main(args=args, prog_name="dyncalc", standalone_mode=False)
    assert text + "\n" == out.getvalue() and "\x1b" not in text
