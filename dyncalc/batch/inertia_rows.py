"""``inertia --batch``: one composite per row.

Columns ``b1``, ``b2``, ... each hold one body word as typed on the command line (quoted in
the CSV: ``"disk(m=4kg, r=0.2m)"``; a leading ``-`` cuts it out); a row's bodies are its
non-empty body cells in column order, so its input entries are ``b1.m``, ``b2.r``, ... as
the one-off's. An ``axis`` column gives ``--axis`` (``z``, ``"(1, 1, 0)"``,
``"z through (0.1, 0, 0) m"``); empty, the row has no ``J_axis``. The vectorised path
(:mod:`.fast_inertia`) takes the rows of one body at the origin along z.
"""
from __future__ import annotations

import re

from .fast_inertia import inertia_fast
from .rows import RowSpec

__all__ = ["InertiaRows"]

_BODY_COLUMN_RE = re.compile(r"^b[1-9][0-9]*$")


class InertiaRows(RowSpec):
    """``inertia``: body columns ``b1``, ``b2``, ... and ``axis``."""

    command = "inertia"
    example_header = "b1,b2,axis"
    #: a placed body's five literals a row, its cells and text: 16384 rows held 34 MB above
    #: the start-up's 51 (10^7 rows of two placed disks: 105 MB); 8192 hold 17
    csv_rows = 8192

    def __init__(self, *, strict: bool = False):
        self.strict = strict
        self.fast = inertia_fast

    @staticmethod
    def is_body(key: str) -> bool:
        return bool(_BODY_COLUMN_RE.match(key))

    def key(self, name):
        return name if name == "axis" or self.is_body(name) else None

    def known(self):
        return ("inertia reads body columns b1, b2, ... (one body word a cell, e.g. "
                "\"disk(m=4kg, r=0.2m)\") and axis")

    def compute(self, texts, labels):
        from ..commands.inertia import inertia

        bodies = [text for key, text in texts.items() if self.is_body(key)]
        if not bodies:
            from ..errors import InputError

            raise InputError("no body: give at least one body cell (b1, b2, ...)")
        return inertia(bodies, texts.get("axis"), self.strict)
