"""Shared check of a column kernel against its one-off physics function, row by row."""
from __future__ import annotations

import numpy as np

from dyncalc.errors import InputError, PhysicsError


def log_uniform(rng, n: int, low: float, high: float) -> np.ndarray:
    """``n`` magnitudes spread evenly in log10 between ``10**low`` and ``10**high``."""
    return 10.0 ** rng.uniform(low, high, n)


def check_kernel(columns, one_off, n: int):
    """Compare the kernel's ``columns`` with ``one_off(i)`` (the one-off Outcome of row ``i``,
    or a PhysicsError/InputError) on every row: rows marked exact must have the one-off's
    names, SI values to the bit, model, method and error estimate, and no warning or refusal.

    Returns ``(exact, refused, clean)`` boolean arrays for the caller's share checks:
    ``clean`` marks the rows the one-off computes without refusal or warning and with every
    value finite and nonzero (the rows a kernel could mark exact).
    """
    exact = np.broadcast_to(np.asarray(columns.exact, dtype=bool), (n,))
    refused = np.zeros(n, dtype=bool)
    warned = np.zeros(n, dtype=bool)
    names = list(columns.values)
    got = {name: np.broadcast_to(np.asarray(columns.values[name], dtype=float), (n,))
           for name in names}
    want = {name: np.zeros(n) for name in names}
    for i in range(n):
        try:
            out = one_off(i)
        except (PhysicsError, InputError):
            refused[i] = True
            continue
        warned[i] = bool(out.warnings)
        for name in names:
            want[name][i] = float(out.values[name].magnitude) if name in out.values else 0.0
        if not exact[i]:
            continue
        assert list(out.values) == names, (i, list(out.values))
        assert (out.model, out.method, out.error_estimate) == (
            columns.model, columns.method, columns.error_estimate), i
    assert not (exact & refused).any(), np.flatnonzero(exact & refused)[:5]
    assert not (exact & warned).any(), np.flatnonzero(exact & warned)[:5]
    for name in names:
        mismatch = got[name][exact].view(np.int64) != want[name][exact].view(np.int64)
        assert not mismatch.any(), (name, np.flatnonzero(exact)[mismatch][:5])
    clean = ~refused & ~warned
    for name in names:
        clean &= np.isfinite(want[name]) & (want[name] != 0.0)
    return exact, refused, clean
