"""What a computation hands to the renderer: named values with their dimensions and units.

Values are carried as SI magnitudes (floats, or numpy arrays for vectors) beside their
:class:`~dyncalc.units.Dim` and the unit they are shown in by default; conversion for display
(``--unit``) happens in the renderer through :func:`dyncalc.units.convert`.
"""
from __future__ import annotations

import math
import re
from typing import Any, Callable

from ..records import Record
from ..units import Dim, Parsed, convert

__all__ = ["Entry", "Explanation", "Result", "entry_from_parsed", "format_number"]


def format_number(value, digits: int) -> str:
    """``value`` to ``digits`` significant figures (vectors as ``(x, y, z)``, matrices as
    ``[[a, b], [c, d]]``)."""
    if isinstance(value, str):
        return value
    if getattr(value, "ndim", 1) == 2:
        return "[" + ", ".join("[" + ", ".join(format_number(float(v), digits) for v in row)
                               + "]" for row in value) + "]"
    if hasattr(value, "__len__"):
        return "(" + ", ".join(format_number(float(v), digits) for v in value) + ")"
    value = float(value)
    if math.isinf(value):
        return "inf" if value > 0 else "-inf"
    return f"{value:.{digits}g}"


def matrix_with_units(value, units, number) -> str:
    """A matrix whose entries have units of their own, in the matrix grammar's per-entry form
    (``[[4 kg, -0.1 kg*m], [-0.1 kg*m, 0.015 kg*m^2]]``: ``modes --M`` reads it back);
    ``number`` writes one float."""
    return "[" + ", ".join(
        "[" + ", ".join(f"{number(float(v))} {u}".rstrip() for v, u in zip(row, unit_row))
        + "]" for row, unit_row in zip(value, units)) + "]"


class Entry(Record):
    """One named input or result.

    ``si`` is the magnitude in ``dim.si`` (float, array, or ``str`` for a word such as a
    regime); ``unit`` is the unit it is shown in unless ``--unit`` says otherwise; ``symbol`` and
    ``description`` are for the human table; ``assumed_si`` marks a bare number read as SI;
    ``text`` is an input as the user typed it (or the default's text), ``None`` on results;
    ``reading`` is an input typed as an expression (``1500 N / 7 mm``) with the parentheses
    the grammar implies made explicit (``1500 N / (7 mm)``), ``""`` otherwise; ``units``, on
    a matrix whose entries differ in unit (translations and rotations mixed), the SI unit of
    each entry (rows of texts): the table and ``--value`` write each entry with its unit.

    A plain class, not a dataclass (no code generated at import: start-up), with a
    dataclass's repr and equality from :class:`~dyncalc.records.Record`.
    """

    __slots__ = ("name", "si", "dim", "unit", "symbol", "description", "assumed_si", "exact",
                 "overflowed", "uncertainty", "text", "reading", "units")

    def __init__(self, name: str, si: Any, dim: Dim | None, unit: str = "", symbol: str = "",
                 description: str = "", assumed_si: bool = False, exact: Any = None,
                 overflowed: bool = False, uncertainty: Any = None, text: str | None = None,
                 reading: str = "", units: Any = None):
        self.name, self.si, self.dim, self.unit = name, si, dim, unit
        self.symbol, self.description, self.assumed_si = symbol, description, assumed_si
        self.exact = exact  # the magnitude in ``unit`` exactly as typed or computed
        self.overflowed = overflowed  # a finite true value beyond float64: shown as inf / null
        self.uncertainty = uncertainty  # standard uncertainty in ``dim.si``, if any
        self.text = text  # an input's text as typed (JSON ``inputs.NAME.text``)
        self.reading = reading  # an expression input as read, parentheses made explicit
        self.units = units  # a mixed matrix: each entry's SI unit


    @property
    def canonical_unit(self) -> str:
        """The unit ``--value``, ``--json`` and batch output give this entry in unless
        ``--unit`` names another (docs/json.md, "Canonical units"): the SI coherent unit of its
        dimension (``rad/s`` for an angular rate, ``Hz`` for a cycle rate, ``rad`` for an
        angle, ``N*m/rad`` for a torsional stiffness); ``""`` for a pure number or a word."""
        return self.dim.si if self.dim is not None else ""

    def uncertainty_in(self, unit: str | None = None):
        """The standard uncertainty in ``unit`` (default: the display unit), or ``None``."""
        if self.uncertainty is None or self.dim is None:
            return None
        target = self.unit if unit is None else unit
        if target == self.dim.si or (not target and not self.dim.si):
            return self.uncertainty
        return convert(self.uncertainty, self.dim, target, label=f"--unit {self.name}",
                       name=self.name)

    def value_in(self, unit: str | None = None):
        """The magnitude in ``unit`` (default: this entry's display unit)."""
        if self.dim is None or isinstance(self.si, str):
            return self.si
        if self.exact is not None and (unit is None or unit == self.unit):
            return self.exact
        target = self.unit if unit is None else unit
        if target == self.dim.si or (not target and not self.dim.si):
            return self.si
        return convert(self.si, self.dim, target, label=f"--unit {self.name}", name=self.name)


_PLAIN_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")


def entry_from_parsed(name: str, parsed: Parsed, dim: Dim, **kw) -> Entry:
    """An input entry shown in the unit the user typed (SI when a bare number was given);
    an input typed as an expression keeps its reading (:attr:`Entry.reading`)."""
    typed = bool(parsed.unit_text) and dim.kind not in ("angular-rate", "cycle-rate")
    expression = (not parsed.unit_text and parsed.reading
                  and not _PLAIN_NUMBER.fullmatch(parsed.reading))
    return Entry(name, parsed.si, dim, unit=parsed.unit_text or dim.si,
                 assumed_si=parsed.assumed_si,
                 exact=float(parsed.quantity.magnitude) if typed else None,
                 uncertainty=parsed.uncertainty, text=parsed.text,
                 reading=parsed.reading if expression else "", **kw)


class Explanation(Record):
    """The formula, the same with values substituted, the model's assumptions, the reference.

    ``formula`` and ``substituted`` are plain text; ``latex`` and ``latex_substituted`` the
    same lines in LaTeX math (either may be empty); ``example`` the textbook example the model
    reproduces (a runnable command and what it gives); ``variance`` maps a result to the share
    of its variance each uncertain input contributes (``{"omega": {"k": 0.2, "m": 0.8}}``).
    """

    __slots__ = ("formula", "substituted", "assumptions", "reference", "latex",
                 "latex_substituted", "example", "variance")

    def __init__(self, formula: list[str], substituted: list[str] | None = None,
                 assumptions: list[str] | None = None, reference: str = "",
                 latex: list[str] | None = None, latex_substituted: list[str] | None = None,
                 example: str = "", variance: dict[str, dict[str, float]] | None = None):
        self.formula = formula
        self.substituted = [] if substituted is None else substituted
        self.assumptions = [] if assumptions is None else assumptions
        self.reference = reference
        self.latex = [] if latex is None else latex
        self.latex_substituted = [] if latex_substituted is None else latex_substituted
        self.example = example
        self.variance = {} if variance is None else variance

    def as_dict(self) -> dict:
        return {"formula": self.formula, "substituted": self.substituted,
                "assumptions": self.assumptions, "reference": self.reference,
                "latex": {"formula": self.latex, "substituted": self.latex_substituted},
                "example": self.example,
                "variance": {name: dict(shares) for name, shares in self.variance.items()}}


class Result:
    """Everything one command computed, on its way from physics to rendering.

    ``explanation`` may be given as an :class:`Explanation` or as a function of no arguments
    that builds one: it is then built the first time it is read (``--explain``, or the
    variance shares of an uncertain input), so a run that shows no explanation never pays
    for one. ``slips`` maps a result name to {a common slip, in words: the value (SI) that
    slip gives}, for the diagnosis of a failed ``--check`` (:mod:`dyncalc.result.checks`).
    ``sensitivity``, set by a command that reads its inputs and then computes, is a function
    of no arguments giving a :class:`dyncalc.result.propagate.Sensitivity` (the derivatives of
    the results with respect to the uncertain inputs, worked out on the parsed inputs); it
    is called only when an input carries an uncertainty.
    """

    __slots__ = ("command", "results", "inputs", "scene", "model", "method", "warnings",
                 "_explanation", "extra", "slips", "sensitivity", "unavailable")

    def __init__(self, command: str, results: dict[str, Entry],
                 inputs: dict[str, Entry] | None = None, scene: str | None = None,
                 model: str = "", method: str = "closed-form",
                 warnings: list[str] | None = None,
                 explanation: Explanation | Callable[[], Explanation] | None = None,
                 extra: dict[str, Any] | None = None,
                 slips: dict[str, dict[str, float]] | None = None):
        self.command, self.results, self.scene = command, results, scene
        self.inputs = {} if inputs is None else inputs
        self.model, self.method = model, method
        self.warnings = [] if warnings is None else warnings
        self._explanation = explanation
        self.extra = {} if extra is None else extra
        self.slips = {} if slips is None else slips
        self.sensitivity: Callable[[], Any] | None = None
        #: result name -> why this run does not give it (what is missing), for the messages
        #: of --value, --check and --unit; not part of the output
        self.unavailable: dict[str, str] = {}

    @property
    def explanation(self) -> Explanation | None:
        if callable(self._explanation):
            self._explanation = self._explanation()
        return self._explanation

    @explanation.setter
    def explanation(self, value) -> None:
        self._explanation = value

    def amend_explanation(self, change: Callable[[Explanation], None]) -> bool:
        """Apply ``change`` to the explanation when it is built (still lazily); ``False``
        when there is no explanation to amend."""
        base = self._explanation
        if base is None:
            return False

        def build():
            explanation = base() if callable(base) else base
            if explanation is not None:
                change(explanation)
            return explanation
        self._explanation = build
        return True

    def __repr__(self) -> str:
        return (f"Result(command={self.command!r}, scene={self.scene!r}, "
                f"results={list(self.results)!r}, warnings={self.warnings!r})")

    def add_underflow_warnings(self, exact_zeros: set[str] = frozenset()) -> None:
        """Warn about a result that underflowed to zero from non-zero inputs (docs/guide/springs.md,
        "Numerics of spring networks");
        ``exact_zeros`` are results that are zero by the physics."""
        inputs_nonzero = all(
            not isinstance(e.si, (int, float)) or e.si != 0 for e in self.inputs.values())
        for entry in self.results.values():
            if (isinstance(entry.si, float) and entry.si == 0.0 and inputs_nonzero
                    and self.inputs and entry.name not in exact_zeros):
                self.warnings.append(f"{entry.name} underflows to zero (below 4.9e-324 "
                                     f"{entry.dim.si if entry.dim else ''}) although no input "
                                     f"is zero")

    def add_overflow_warnings(self) -> None:
        """Mark results that overflowed float64 (a finite true value beyond 1.8e308) and warn.

        They stay ``inf`` (JSON ``null``), so the results that did not overflow are still
        given; ``--value`` of such a result is refused. The one meaningful infinity, a period
        ``T...`` of a mode whose frequency is exactly zero (a drift, a bifurcation), is not an
        overflow.
        """
        for name, entry in self.results.items():
            if entry.overflowed or not (isinstance(entry.si, float) and math.isinf(entry.si)):
                continue
            if name.startswith("T"):
                omega = self.results.get("omega" + name[1:])
                if omega is not None and omega.si == 0.0:
                    continue
            entry.overflowed = True
            unit = f" {entry.dim.si}" if entry.dim is not None and entry.dim.si else ""
            self.warnings.append(f"{name} overflows float64 at these inputs (beyond 1.8e308"
                                 f"{unit}); it is left out (null in JSON)")
