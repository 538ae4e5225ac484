"""``--check NAME=QUANTITY``: compare a result with the user's answer, unit-aware."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

from .errors import InputError
from .result import Result
from .units import convert, parse_quantity

__all__ = ["Check", "run_checks", "split_assignment"]

DEFAULT_CHECK_RTOL = 1e-2

_ASSIGN_RE = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_.]*)\s*=(.*)$", re.S)


def split_assignment(text: str, option: str) -> tuple[str, str]:
    """``"f=1.13Hz"`` -> ``("f", "1.13Hz")``; refuses anything else with the option's name."""
    m = _ASSIGN_RE.match(text)
    if not m or not m.group(2).strip():
        raise InputError(f"{option} takes NAME=VALUE (for example {option} f=1.13Hz); "
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

    @property
    def passed(self) -> bool:
        return self.rel_diff <= self.rtol

    def as_dict(self) -> dict:
        return {"name": self.name, "expected": self.expected, "given": self.given,
                "unit": self.unit, "rel_diff": self.rel_diff, "rtol": self.rtol,
                "pass": self.passed}


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
        if entry is None:
            raise InputError(f"--check {name}: there is no result named {name!r}; the results "
                             f"are {', '.join(result.results)}")
        if entry.dim is None or not isinstance(entry.si, float):
            raise InputError(f"--check {name}: only a single number can be checked")
        parsed = parse_quantity(text, entry.dim, label=f"--check {name}")
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
        checks.append(Check(name, shown_expected, shown_given, unit, rel, tol))
    return checks
