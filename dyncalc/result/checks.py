"""``--check NAME=QUANTITY``: compare a result with the user's answer, unit-aware."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

from ..errors import InputError
from .entries import Result
from ..units import convert, parse_quantity

__all__ = ["Check", "run_checks", "split_assignment"]

DEFAULT_CHECK_RTOL = 1e-2

_ASSIGN_RE = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_.]*)\s*=(.*)$", re.S)


def split_assignment(text: str, option: str) -> tuple[str, str]:
    """``"f=1.13Hz"`` -> ``("f", "1.13Hz")``; refuses anything else with the option's name."""
    m = _ASSIGN_RE.match(text)
    if not m or not m.group(2).strip():
        example = f"{option} f=1.13Hz" if option.startswith("-") else "m=2kg"
        raise InputError(f"{option} takes NAME=VALUE (for example {example}); "
                         f"got {text[:60]!r}")
    return m.group(1), m.group(2)


@dataclass
class Check:
    """One comparison: values in the unit the user gave (``unit``), their relative difference."""

    name: str
    expected: float
    given: float
    unit: str
    rel_diff: float
    rtol: float
    diagnosis: str | None = None  # the common slip the given answer matches, if one does

    @property
    def passed(self) -> bool:
        return self.rel_diff <= self.rtol

    def as_dict(self) -> dict:
        data = {"name": self.name, "expected": self.expected, "given": self.given,
                "unit": self.unit, "rel_diff": self.rel_diff, "rtol": self.rtol,
                "pass": self.passed}
        if self.diagnosis is not None:
            data["diagnosis"] = self.diagnosis
        return data


def run_checks(result: Result, specs: list[str], rtol: float | None) -> list[Check]:
    """Compare each ``NAME=QUANTITY`` of ``specs`` with the result of that name.

    The relative difference is ``|given - expected| / |expected|`` in SI (the absolute
    difference when the expected value is zero); a check passes when it is at most ``rtol``
    (default 1e-2).
    """
    tol = DEFAULT_CHECK_RTOL if rtol is None else rtol
    checks = []
    for spec in specs:
        name, text = split_assignment(spec, "--check")
        entry = result.results.get(name)
        if entry is None and name in getattr(result, "unavailable", {}):
            raise InputError(f"--check {name}: {result.unavailable[name]}")
        if entry is None:
            raise InputError(f"--check {name}: there is no result named {name!r}; the results "
                             f"are {', '.join(result.results)}")
        if entry.dim is None or not isinstance(entry.si, float):
            raise InputError(f"--check {name}: only a single number can be checked")
        parsed = parse_quantity(text, entry.dim, label=f"--check {name}")
        if parsed.uncertainty is not None:  # SPEC: refused, never dropped
            raise InputError(f"--check {name}: a check takes no uncertainty (+/- or ±); give "
                             f"the answer alone and the tolerance with --rtol")
        expected, given = entry.si, parsed.si
        diff = abs(given - expected)
        rel = diff / abs(expected) if expected != 0 else diff
        if math.isnan(rel):  # inf against inf
            rel = 0.0 if given == expected else math.inf
        unit = parsed.unit_text or entry.dim.si
        if unit == entry.dim.si:
            shown_expected, shown_given = expected, given
        else:
            label = f"--check {name}"
            shown_expected = float(convert(expected, entry.dim, unit, label=label, name=name))
            shown_given = float(convert(given, entry.dim, unit, label=label, name=name))
        check = Check(name, shown_expected, shown_given, unit, rel, tol)
        if not check.passed:
            check.diagnosis = diagnose(result, name, given, tol)
        checks.append(check)
    return checks


TWO_PI = 2.0 * math.pi
_FAMILY_RE = re.compile(r"^(omega|f|T)(_\w+)?$")


def slips(result: Result, name: str) -> list[tuple[str, float]]:
    """The values (SI) that common slips give for result ``name``, each with its words.

    The list of the contract (docs/guide/homework.md, "--check") and issue 10: omega given for f (a factor 2
    pi) and f for omega, the damped omega_d for the undamped omega_n and back, degrees for
    radians (180/pi), a mass in grams read as kilograms (a factor 1000, or its square root where
    the result goes as m^(1/2)), the decrement per cycle for the one per radian (a factor 2 pi,
    or delta given as zeta), and series for parallel, at the top of a network or throughout it
    (the slips the command itself computed, :attr:`Result.slips`)."""
    entry = result.results[name]
    value = entry.si
    out: list[tuple[str, float]] = []
    kind = entry.dim.kind if entry.dim is not None else ""
    family = _FAMILY_RE.match(name)
    stem, suffix = (family.group(1), family.group(2) or "") if family else ("", "")
    omega, f = f"omega{suffix}", f"f{suffix}"
    named = family and omega in result.results and f in result.results
    if kind == "cycle-rate" and named:
        out.append((f"that is {omega} in rad/s, not {name} in Hz: {name} = {omega} / 2 pi",
                    value * TWO_PI))
    elif kind == "angular-rate" and named:
        out.append((f"that is {f} in Hz, not {name} in rad/s: {name} = 2 pi {f}",
                    value / TWO_PI))
    elif kind == "cycle-rate":
        out.append((f"that is the rate in rad/s, not {name} in Hz (cycles): a factor 2 pi",
                    value * TWO_PI))
    elif kind == "angular-rate":
        out.append((f"that is the rate in Hz (cycles), not {name} in rad/s: a factor 2 pi",
                    value / TWO_PI))
    elif stem == "T" and named:
        out.append((f"that is 1/{omega}: the period is {name} = 2 pi / {omega}",
                    value / TWO_PI))
        out.append((f"that is 2 pi/{f}: the period is {name} = 1 / {f}", value * TWO_PI))
    other = f"{stem}_d" if family and suffix == "" else stem if suffix == "_d" else None
    if other is not None and other in result.results:
        what = "period" if stem == "T" else "frequency"
        if suffix == "":
            relation = "/" if stem == "T" else ""
            out.append((f"that is the damped {what} {other}, not {name} ({other} = {name} "
                        f"{relation + ' ' if relation else ''}sqrt(1 - zeta^2))",
                        result.results[other].si))
        else:
            out.append((f"that is the undamped natural {what} {other}, not {name}",
                        result.results[other].si))
    if name == "zeta" and "delta" in result.results:
        out.append(("that is the logarithmic decrement per cycle (delta); zeta is about "
                    "delta / 2 pi (exactly delta / sqrt(4 pi^2 + delta^2))",
                    result.results["delta"].si))
    if name == "delta":
        out.append(("that is the decrement per radian (delta / 2 pi); delta is per cycle",
                    value / TWO_PI))
    out.append(("a factor 180/pi: degrees and radians mixed up", value * 180.0 / math.pi))
    out.append(("a factor pi/180: degrees and radians mixed up", value * math.pi / 180.0))
    for factor, words in ((1e3, "1000"), (1e-3, "1/1000"), (1e3 ** 0.5, "sqrt(1000) = 31.6"),
                          (1e-3 ** 0.5, "1/sqrt(1000)")):
        out.append((f"a factor {words}: a mass in grams taken as kilograms (or the reverse)",
                    value * factor))
    out += list(result.slips.get(name, {}).items())
    return out


def diagnose(result: Result, name: str, given: float, rtol: float) -> str | None:
    """The first slip of :func:`slips` whose value matches ``given`` (SI) within ``rtol``;
    ``None`` if none does or the expected value itself matches (a right answer never has a
    diagnosis)."""
    expected = result.results[name].si
    if not math.isfinite(given) or abs(given - expected) <= rtol * abs(expected):
        return None
    for words, value in slips(result, name):
        if (isinstance(value, float) and math.isfinite(value) and value != 0
                and abs(given - value) <= rtol * abs(value)):
            return words
    return None
