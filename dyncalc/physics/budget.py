"""A wall-clock budget for symbolic work that may run away (sympy's ``integrate``, ``solve``).

``with time_budget(2.0): ...`` raises :class:`OverBudget` inside the block once 2 s have
passed. It uses SIGALRM, which Python offers only in the main thread of a POSIX process;
elsewhere the block runs unbounded. The caller's own ``ITIMER_REAL`` and SIGALRM handler are
saved and given back: the timer is re-armed with the time it had left (and its interval), so
a timer due during the block fires as soon as the block ends (late by at most the block's
length). Budgets nest: an inner one restores the outer one's timer.

Used by ``eom`` (the whole derivation: refused beyond its budget) and by ``coriolis --t``
(a closed-form integral of the frame's rate: quadrature beyond its budget).
"""
from __future__ import annotations

import contextlib

__all__ = ["OverBudget", "time_budget"]


class OverBudget(Exception):
    """The block of a :func:`time_budget` ran out of time."""


@contextlib.contextmanager
def time_budget(seconds: float):
    """Raise :class:`OverBudget` in the enclosed block after ``seconds`` of wall time.

    Example::

        with time_budget(5.0):
            derive()
    """
    import signal
    import threading
    import time

    usable = hasattr(signal, "setitimer") and threading.current_thread() is \
        threading.main_thread()
    if not usable:
        yield
        return

    def expire(signum, frame):
        raise OverBudget()

    previous = signal.signal(signal.SIGALRM, expire)
    started = time.monotonic()
    their_delay, their_interval = signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
        if their_delay > 0.0:
            left = their_delay - (time.monotonic() - started)
            signal.setitimer(signal.ITIMER_REAL, max(left, 1e-6), their_interval)
