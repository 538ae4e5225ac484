"""The C allocator told to keep freed memory for the next chunk of a long batch run.

A batch run makes and drops the same few megabytes of text every step (a chunk's cells, a
step's float texts, its joined lines and their UTF-8 bytes). glibc's ``malloc`` serves an
allocation above its mmap threshold (128 kB at first, raised as such blocks are freed) with
a fresh ``mmap`` and returns the top of its heap to the system above its trim threshold, so
every step touched new pages: 450,000 minor page faults and 0.7 s of system time in a
10^6-row ``eom --scene pendulum --json`` run of 2.6 s (``/usr/bin/time -f "%R %S"``). With
both thresholds at 32 MiB (glibc's largest mmap threshold on 64-bit) the freed blocks are
reused: 14,000 faults, 0.06 s of system time, 1.8 s in all, and the same peak resident size
(to 0.1 % for ``coriolis`` over times, the widest), since memory is kept only up to the run's
own high-water mark. 8 MiB served these runs too, but a step whose
blocks outgrow it (tests/test_batch_memory.py: three blocks of 6 MiB) thrashes again.

Only the command line does this (:meth:`dyncalc.cli.options.Output.run_batch`): the process
is dyncalc's own. A library caller's process keeps its allocator as it is.

Example (the command line, before a ``--batch`` run; ``True`` on glibc)::

    from dyncalc.batch.memory import hold_freed_memory
    hold_freed_memory()

Reference: glibc manual, "Malloc Tunable Parameters" (``M_MMAP_THRESHOLD``,
``M_TRIM_THRESHOLD``).
"""
from __future__ import annotations

import os

#: glibc's ``mallopt`` parameter numbers (malloc.h).
M_TRIM_THRESHOLD, M_MMAP_THRESHOLD = -1, -3
#: Both thresholds: glibc's largest mmap threshold on 64-bit (``HEAP_MAX_SIZE / 2``).
HOLD_BYTES = 32 * 1024 * 1024


def hold_freed_memory() -> bool:
    """Set glibc's mmap and trim thresholds to :data:`HOLD_BYTES`; whether both were set
    (``False`` where the C library is not glibc or refuses them: nothing is changed then)."""
    try:
        if not (os.confstr("CS_GNU_LIBC_VERSION") or "").startswith("glibc"):
            return False
        import ctypes

        mallopt = ctypes.CDLL(None).mallopt
    except (ValueError, OSError, AttributeError, ImportError):  # not glibc, no ctypes or mallopt
        return False
    mallopt.argtypes, mallopt.restype = [ctypes.c_int, ctypes.c_int], ctypes.c_int
    return mallopt(M_MMAP_THRESHOLD, HOLD_BYTES) == 1 and \
        mallopt(M_TRIM_THRESHOLD, HOLD_BYTES) == 1
