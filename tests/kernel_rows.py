"""Compare a column kernel with its one-off physics function row by row (the kernel tests of
rotating, damping, nonlinear and coupled scenes).

For every row the one-off function is called with pint quantities in the SI unit of each
parameter; its results are converted to SI as the scene runner converts them. A row the kernel
marks exact must be one where the one-off raised nothing, warned nothing (its own warnings, and
the overflow and underflow warnings the runner adds), used the kernel's model, method and error
estimate, and gave the same result names in the same order with bitwise equal values.
"""
import math

import numpy as np

from dyncalc.errors import InputError, PhysicsError
from dyncalc.physics.columns import kernel_of
from dyncalc.scenes.runner import _entry
from dyncalc.units import Q_


def log_uniform(rng, low, high, n):
    """``n`` magnitudes spread evenly in log10 between ``10**low`` and ``10**high``."""
    return 10.0 ** rng.uniform(low, high, n)


def mixed(rng, ordinary, n):
    """``n`` values: the first half in the ordinary range ``(low, high)`` of log10, the rest
    over 1e-300..1e300."""
    half = n // 2
    return np.concatenate([log_uniform(rng, *ordinary, half),
                           log_uniform(rng, -300, 300, n - half)])


def ordinary_rows(n, extra=0):
    """The mask of :func:`mixed`'s ordinary half, with ``extra`` ordinary rows appended (a
    textbook example)."""
    return np.concatenate([np.arange(n) < n // 2, np.ones(extra, dtype=bool)])


def _runner_warns(outcome, values_si, inputs) -> bool:
    """Whether the scene runner adds an overflow or underflow warning (result/entries.py)."""
    for name, value in values_si.items():
        if isinstance(value, float) and math.isinf(value):
            omega = values_si.get("omega" + name[1:]) if name.startswith("T") else None
            if not (omega is not None and omega == 0.0):
                return True
    if all(v != 0.0 for v in inputs.values()):
        for name, value in values_si.items():
            if isinstance(value, float) and value == 0.0 and name not in outcome.exact_zeros:
                return True
    return False


def one_off(physics, row: dict, units: dict, scalars: dict):
    """``(outcome or None, SI values, clean)`` of one row."""
    kwargs = {name: (Q_(value, units[name]) if units.get(name) else value)
              for name, value in row.items()}
    try:
        outcome = physics(**kwargs, **scalars)
    except (PhysicsError, InputError, ValueError, ZeroDivisionError, OverflowError):
        return None, {}, False
    values = {name: _entry(name, value).si for name, value in outcome.values.items()}
    clean = not outcome.warnings and not _runner_warns(outcome, values, row)
    return outcome, values, clean


def check_kernel(physics, arrays: dict, units: dict, scalars: dict | None = None,
                 ordinary=None, min_share: float = 0.9) -> dict:
    """Run the kernel of ``physics`` once on ``arrays`` and the one-off row by row; assert
    every exact row matches bit for bit and at least ``min_share`` of the ``ordinary`` rows
    (a boolean mask; default all) that the one-off computes cleanly are exact. Returns counts for the caller's own checks."""
    scalars = scalars or {}
    kernel = kernel_of(physics)
    assert kernel is not None, f"{physics.__name__} has no column kernel"
    columns = kernel(**arrays, **scalars)
    assert columns is not None
    n = len(next(iter(arrays.values())))
    exact = np.broadcast_to(np.asarray(columns.exact, dtype=bool), (n,))
    names = list(columns.values)
    clean_rows = np.zeros(n, dtype=bool)
    for i in range(n):
        row = {name: float(a[i]) for name, a in arrays.items()}
        outcome, values, clean = one_off(physics, row, units, scalars)
        clean = clean and (outcome.model, outcome.method, outcome.error_estimate) == (
            columns.model, columns.method, columns.error_estimate)
        clean_rows[i] = clean
        if not exact[i]:
            continue
        assert clean, f"row {i} {row}: marked exact, but the one-off " + (
            "raised" if outcome is None else f"warned {outcome.warnings} or differs in model")
        assert list(values) == names, (i, row, list(values), names)
        for name in names:
            mine = np.asarray(columns.values[name][i], dtype=float)
            theirs = np.asarray(values[name], dtype=float)
            assert np.array_equal(mine.view(np.int64), theirs.view(np.int64)), (
                f"row {i} {row}: {name} = {mine!r}, one-off {theirs!r}")
    ordinary = np.ones(n, dtype=bool) if ordinary is None else ordinary
    usable = ordinary & clean_rows     # ordinary rows the one-off computes without a warning
    assert usable.sum() >= 0.25 * ordinary.sum(), "too few clean ordinary rows to judge"
    share = exact[usable].mean()
    assert share >= min_share, f"only {share:.1%} of the clean ordinary rows are exact"
    return {"exact": int(exact.sum()), "clean": int(clean_rows.sum()),
            "missed": int((clean_rows & ~exact).sum()), "n": n}
