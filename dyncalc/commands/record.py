"""The :class:`Command` record: one command's parameters, results and compute function, written
once. The click options (:func:`dyncalc.cli.options.build_command`), the shell completion of
result names, the help and the reference in ``docs/`` are generated from it, so adding an
option or a result is one edit in one file. No click here: this layer computes, it never
parses a command line.
"""
from __future__ import annotations

from typing import Any, Callable

from ..records import Frozen

__all__ = ["Parameter", "ResultName", "Command", "results_from_kinds"]

#: What a parameter is: a physics input read as a quantity of ``dim`` (``quantity``) or as free
#: text the command reads itself (``text``: a list of peaks, a vector, a network word); a choice
#: among fixed words (``choice``: validated by the option parser); a setting of the
#: computation that is no physics input and no batch column (``setting``: ``--scene``,
#: ``--method``); or an option acted on after computing (``after``: ``--plot``).
KINDS = ("quantity", "text", "choice", "setting", "after")


def _set(record, values: dict[str, Any]) -> None:
    for name in record.__slots__:
        object.__setattr__(record, name, values[name])


class Parameter(Frozen):
    """One parameter of a command.

    ``name`` is the option's name (``k`` for ``--k``); ``dim`` its
    :class:`~dyncalc.units.Dim` (``None`` for words and text); ``help`` one sentence for
    ``--help``; ``metavar`` what the help shows for its value; ``default`` the value when it is
    not given (a text, or ``None``); ``kind`` one of :data:`KINDS`; ``choices`` the words a
    ``choice`` takes or a setting completes to (a tuple, or a function of no arguments giving
    one, called only when completing).
    """

    __slots__ = ("name", "dim", "help", "metavar", "default", "kind", "choices")

    def __init__(self, name: str, dim: Any = None, help: str = "", metavar: str = "",
                 default: str | None = None, kind: str = "quantity",
                 choices: tuple[str, ...] | Callable[[], Any] | None = None):
        if kind not in KINDS:
            raise ValueError(f"parameter kind {kind!r} is not one of {KINDS}")
        _set(self, {"name": name, "dim": dim, "help": help,
                    "metavar": metavar or name.upper(), "default": default, "kind": kind,
                    "choices": choices})

    @property
    def flag(self) -> str:
        """The option as typed: ``--k``, ``--f-exc``."""
        return "--" + self.name.replace("_", "-")

    @property
    def is_input(self) -> bool:
        """Whether it is a physics input (a batch column), not a setting of the run."""
        return self.kind in ("quantity", "text", "choice")


class ResultName(Frozen):
    """One result a command can give: its name, the symbol of the human table, the
    *canonical unit* of ``--value``, ``--json`` and batch output (docs/json.md) and a few words.
    A name ending in ``<i>`` stands for a numbered family (``k<i>``: ``k1``, ``k2``, ...)."""

    __slots__ = ("name", "symbol", "unit", "description")

    def __init__(self, name: str, symbol: str, unit: str, description: str):
        _set(self, {"name": name, "symbol": symbol, "unit": unit, "description": description})


class Command(Frozen):
    """A command: its name (``natural-frequency``), a one-line ``summary``, the ``help`` text
    with its worked examples (click's ``\\b`` paragraphs), its ``parameters`` in the order of
    ``--help``, ``words`` (the metavar of its free words, ``[NAME=QUANTITY]...``, or ``None``),
    its ``results`` and ``compute``.

    ``compute(values, words, *, rtol, strict)`` takes the options as typed (name -> text or
    ``None``, settings included) and the free words, and returns a
    :class:`~dyncalc.result.Result`. ``columns(given, settings)``, where the command has
    one, is its batch adapter: the SI arrays of the columns a block of rows gives (by
    parameter name; vectors (n, 3), words as arrays of str) and the settings, to a
    :class:`~dyncalc.physics.columns.Columns` of the one-off's results (or ``None``). The
    batch adds to the settings ``units`` (the unit each column was typed in, ``""`` for
    bare numbers), ``typed`` (the magnitudes as typed), ``cells`` (the cells as typed, for
    warnings that quote them) and ``json``.
    """

    __slots__ = ("name", "summary", "help", "parameters", "words", "results", "compute",
                 "columns")

    def __init__(self, name: str, summary: str, help: str, parameters: tuple[Parameter, ...],
                 results: tuple[ResultName, ...], compute: Callable[..., Any],
                 words: str | None = None, columns: Callable[..., Any] | None = None):
        _set(self, {"name": name, "summary": summary, "help": help,
                    "parameters": tuple(parameters), "words": words,
                    "results": tuple(results), "compute": compute, "columns": columns})

    def parameter(self, name: str) -> Parameter | None:
        return next((p for p in self.parameters if p.name == name), None)

    @property
    def inputs(self) -> tuple[Parameter, ...]:
        """The physics inputs: the columns a batch file may name."""
        return tuple(p for p in self.parameters if p.is_input)

    def result_names(self) -> list[str]:
        """The result names (a family ``k<i>`` as ``k1``), for completion and messages."""
        return [r.name.replace("<i>", "1") for r in self.results]


def results_from_kinds(kinds: dict[str, tuple]) -> tuple[ResultName, ...]:
    """Result names from a command's table ``name -> (dim, display unit, symbol, ...,
    description)``: the canonical unit is the SI unit of the dimension (``""`` for words)."""
    out = []
    for name, kind in kinds.items():
        dim, symbol, description = kind[0], kind[2], kind[-1]
        out.append(ResultName(name, symbol, dim.si if dim is not None else "", description))
    return tuple(out)
