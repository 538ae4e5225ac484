"""A wall-clock budget for symbolic work that may run away (sympy's ``integrate``, ``solve``).

``with time_budget(2.0): ...`` raises :class:`OverBudget` inside the block once 2 s have
passed. It uses SIGALRM, which Python offers only in the main thread of a POSIX process;
elsewhere the block runs unbounded. The caller's own ``ITIMER_REAL`` and SIGALRM handler are
saved and given back: the timer is re-armed with the time it had left (and its interval), so
a timer due during the block fires as soon as the block ends (late by at most the block's
length). Budgets nest: an inner one restores the outer one's timer.

The exception raised from a signal handler can be lost: if the signal lands while Python runs
a garbage-collector callback or a ``__del__`` it is printed as "unraisable" and dropped, and a
library's ``except Exception`` may swallow it. So once the budget has run out it is raised
again every :data:`RETRY` seconds until it leaves the block, and a block that ends after its
budget ran out (normally, or with another ``Exception`` the lost one may have caused) raises
:class:`OverBudget` on leaving. The block is never reported within its budget when it was not.

Used by ``eom`` (the whole derivation: refused beyond its budget) and by ``coriolis --t``
(a closed-form integral of the frame's rate: quadrature beyond its budget).
"""
from __future__ import annotations

__all__ = ["OverBudget", "RETRY", "time_budget"]

#: Seconds between raising :class:`OverBudget` again once the budget has run out.
RETRY = 0.01


class OverBudget(Exception):
    """The block of a :func:`time_budget` ran out of time."""


class time_budget:  # noqa: N801 - used as a function: ``with time_budget(5.0):``
    """Raise :class:`OverBudget` in the enclosed block after ``seconds`` of wall time.

    Parameters: seconds -- the budget [s], > 0.

    Example::

        with time_budget(5.0):
            derive()
    """

    def __init__(self, seconds: float):
        self.seconds = seconds
        self.armed = False
        self.expired = False

    def __enter__(self):
        import signal
        import threading
        import time

        if not (hasattr(signal, "setitimer")
                and threading.current_thread() is threading.main_thread()):
            return self
        self.previous = signal.signal(signal.SIGALRM, self._expire)
        self.started = time.monotonic()
        self.theirs = signal.setitimer(signal.ITIMER_REAL, self.seconds)
        self.armed = True
        return self

    def _expire(self, signum, frame):
        import signal

        if frame is not None and frame.f_code is _LEAVING:
            return  # the block is over and __exit__ is disarming: nothing to interrupt
        self.expired = True
        signal.setitimer(signal.ITIMER_REAL, RETRY)  # again, should this one be swallowed
        raise OverBudget()

    def __exit__(self, exc_type, exc, tb):
        if not self.armed:
            return False
        import signal
        import time

        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, self.previous)
        their_delay, their_interval = self.theirs
        if their_delay > 0.0:
            left = their_delay - (time.monotonic() - self.started)
            signal.setitimer(signal.ITIMER_REAL, max(left, 1e-6), their_interval)
        self.armed = False
        if self.expired and (exc_type is None or (issubclass(exc_type, Exception)
                                                  and not issubclass(exc_type, OverBudget))):
            raise OverBudget() from exc  # ran out, and the raise was lost on the way
        return False


_LEAVING = time_budget.__exit__.__code__
