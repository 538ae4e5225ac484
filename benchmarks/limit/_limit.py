"""What the limit scripts share: the CSV read as text columns (polars), float columns written as
``repr`` writes them, and lines assembled and written in one go.

A limit script is the one-off script a careful engineer would write for one clean file (units
in the header, no per-cell units, no bad rows): it reads the same CSV, does the same math and
writes the same bytes as ``dyncalc ... --batch FILE`` (``--json``: JSON lines), which
tests/test_benchmark_limits.py checks; benchmarks/limits.py times dyncalc against it.

    python benchmarks/limit/NAME.py FILE [--json] > OUT
"""
from __future__ import annotations

import sys

import numpy as np
import polars as pl

TWO_PI = 2.0 * np.pi


def arguments() -> tuple[str, bool]:
    """(the CSV path, whether to write JSON lines)."""
    return sys.argv[1], "--json" in sys.argv[2:]


def read(path: str) -> pl.DataFrame:
    """Every column as its text (so the cells can be echoed as typed)."""
    return pl.read_csv(path, infer_schema=False)


def number(df: pl.DataFrame, column: str) -> np.ndarray:
    """A text column as float64 (correctly rounded, as ``float``)."""
    return df[column].cast(pl.Float64).to_numpy()


def text(values: np.ndarray) -> pl.Series:
    """``repr`` of each float: polars writes the same shortest digits, in another notation
    between 1e-9 and 1e-4 and for inf/nan, which ``repr`` writes."""
    values = np.ascontiguousarray(values, dtype=np.float64)
    out = pl.Series(values).cast(pl.String)
    size = np.abs(values)
    odd = np.flatnonzero(((size < 1e-4) & (size >= 1e-9)) | ~(size < np.inf)
                         | ((size < 1e-9) & (size > 0)))
    if len(odd):
        out = out.scatter(odd, [repr(v) for v in values[odd].tolist()])
    return out


def vector(columns, sep: str) -> pl.Expr:
    """Three float columns as one text: ``x,y,z`` (CSV) or ``[x, y, z]`` (JSON)."""
    x, y, z = (pl.lit(text(c)) for c in columns)
    if sep == ",":
        return pl.concat_str([x, y, z], separator=",")
    return pl.concat_str([pl.lit("["), x, pl.lit(", "), y, pl.lit(", "), z, pl.lit("]")])


def write(parts: list, header: str | None = None) -> None:
    """Each row's line: the ``parts`` (a str is the same on every row; a Series or an
    expression one text a row) concatenated; all lines written at once."""
    if header is not None:
        sys.stdout.write(header + "\n")
        sys.stdout.flush()
    exprs = [pl.lit(p) if isinstance(p, (str, pl.Series)) else p for p in parts]
    lines = pl.select(pl.concat_str(exprs).alias("line"))
    lines.write_csv(sys.stdout.buffer, include_header=False, quote_style="never")


def csv_line(df: pl.DataFrame, results: dict, header_of: dict) -> None:
    """CSV output: the input cells as typed, then the results (name -> Series or expression),
    quoted where a cell holds a comma, as csv.writer quotes."""
    out = df.with_columns(**{header_of[name]: pl.lit(values) if isinstance(values, str) else values
                             for name, values in results.items()})
    sys.stdout.flush()
    out.write_csv(sys.stdout.buffer, quote_style="necessary")


def json_lines(n: int, head: str, inputs: list, results: list, extra="{}") -> None:
    """JSON lines: ``inputs`` and ``results`` are lists of parts (str or Series), ``extra`` a
    str or such a list."""
    line = pl.Series(np.arange(2, n + 2)).cast(pl.String)
    extra = [extra] if isinstance(extra, str) else extra
    write(['{"line": ', line, ", " + head + ', "inputs": {', *inputs, '}, "results": {',
           *results, '}, "warnings": [], "extra": ', *extra, "}"])


def json_input(df: pl.DataFrame, column: str, name: str, unit: str, first: bool = False):
    """The parts of one input entry: ``"k": {"value": 100.0, "unit": "N/m", "text": "100 N/m"}``."""
    values = text(number(df, column))
    suffix = f" {unit}" if unit else ""
    return [("" if first else ", ") + f'"{name}": {{"value": ', values,
            f', "unit": "{unit}", "text": "', df[column], suffix + '"}']


def json_result(name: str, values, unit: str, first: bool = False):
    """The parts of one result entry: ``"omega": {"value": 7.07, "unit": "rad/s"}``."""
    return [("" if first else ", ") + f'"{name}": {{"value": ', values,
            f', "unit": "{unit}"}}']


def joined(*parts) -> pl.Series:
    """One text a row: the ``parts`` (a str the same on every row, or a Series) concatenated."""
    return pl.select(pl.concat_str([pl.lit(p) for p in parts])).to_series()


def warning_lines(n: int, warning: str) -> None:
    """dyncalc's CSV ``warning: line N: TEXT`` lines on stderr, one a row (lines 2 to n + 1),
    after stdout is flushed."""
    sys.stdout.flush()
    lines = pl.select(pl.concat_str([pl.lit("warning: line "),
                                     pl.Series(np.arange(2, n + 2)).cast(pl.String),
                                     pl.lit(": " + warning)]).alias("w"))
    lines.write_csv(sys.stderr.buffer, include_header=False, quote_style="never")


def inverse_lines(df: pl.DataFrame, as_json: bool, scene: str, inputs: list, out: dict,
                  units: dict, unknown: str, goal: str) -> None:
    """The output of a rigid-body inverse row solved for ``unknown`` from the result ``goal``
    by the one-off's bracketed search: JSON lines (``inputs``: the input entries' parts) or
    CSV (the unknown and the goal as ``NAME_result`` columns)."""
    if as_json:
        head = ('"schema": "dyncalc/2", "command": "rigid-body", "scene": "' + scene + '", '
                '"model": "linear", "method": "closed-form"')
        results = [p for k, (n, v) in enumerate(out.items())
                   for p in json_result(n, v, units[n], k == 0)]
        json_lines(len(df), head, inputs, results,
                   '{"inverse": {"unknown": "' + unknown + '", "method": "bracketed-root", '
                   '"detail": "a sign change on a grid of ' + unknown + ', refined by '
                   'Brent\'s method"}}')
    else:
        header = {n: f"{n} [{u}]" for n, u in units.items()}
        for name in (unknown, goal):
            header[name] = f"{name}_result [{units[name]}]"
        csv_line(df, out, header)


def two_lams(m00, m01, m11, k00, k01, k11, det_m, det_k):
    """``(lo, hi)`` of ``det(K - lam M) = 0`` for 2x2 matrices, as dyncalc.physics.eom_pairs
    computes them (the same float operations): both scaled by ``diag(M_ii^-1/2)``, the
    symmetric reduction, the larger from mean + hypot (every mean here is >= 0), the other
    from ``det K / det M`` over it (significands divided, exponents summed)."""
    r0, r1 = np.sqrt(m00), np.sqrt(m11)
    r = m01 / r0 / r1
    s2 = det_m / m00 / m11
    a00, a01, a11 = k00 / r0 / r0, k01 / r0 / r1, k11 / r1 / r1
    c01 = (a01 - r * a00) / np.sqrt(s2)
    c11 = (a11 - 2 * r * a01 + r * r * a00) / s2
    hi = (a00 + c11) / 2 + np.hypot((a00 - c11) / 2, c01)
    (ma, ea), (mb, eb), (mc, ec) = np.frexp(det_k), np.frexp(det_m), np.frexp(hi)
    with np.errstate(all="ignore"):
        lo = np.where(hi != 0, np.ldexp(ma / mb / mc, ea - eb - ec), 0.0)
    return lo, hi
