"""What comes out of a computation: the Result and its entries (:mod:`.entries`), the result
kinds with each name's canonical unit (:mod:`.kinds`), explanations (:mod:`.explain`), checks
of a user's answer (:mod:`.checks`) and the propagation of uncertainties (:mod:`.propagate`)."""
from __future__ import annotations

from .entries import Entry, Explanation, Result, entry_from_parsed, format_number

__all__ = ["Entry", "Explanation", "Result", "entry_from_parsed", "format_number"]
