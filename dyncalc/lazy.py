"""The one seam of lazy imports: ``from ..lazy import numpy as np`` gives a stand-in that
imports numpy the first time one of its names is used, so a module that needs numpy only to
compute can be imported (for its Command record, for ``--help``) without loading it.

After the first use the module's names are copied onto the stand-in, so later lookups cost
what a module attribute costs.
"""
from __future__ import annotations

import importlib

__all__ = ["numpy"]


class LazyModule:
    """A module imported on the first attribute looked up through it."""

    def __init__(self, name: str):
        object.__setattr__(self, "_lazy_name", name)

    def __getattr__(self, attr: str):
        module = importlib.import_module(object.__getattribute__(self, "_lazy_name"))
        self.__dict__.update(module.__dict__)
        return getattr(module, attr)

    def __repr__(self) -> str:
        return f"<lazy module {object.__getattribute__(self, '_lazy_name')!r}>"


numpy = LazyModule("numpy")
