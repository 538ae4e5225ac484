"""Plain records with the repr, equality (and, frozen, the hash and immutability) of a
dataclass, written out by hand: ``@dataclass`` generates and compiles its methods at import,
which every run of the program would pay for (start-up, issue 8)."""
from __future__ import annotations

from dataclasses import FrozenInstanceError

__all__ = ["Record", "Frozen"]

# --------------------------------------------------------------------------------------------
# Records
#
# Dim and Parsed behave as frozen dataclasses (the same constructor, repr, equality, hash and
# immutability), and _Tok and _Reading as plain ones; they are written out by hand because
# @dataclass generates and compiles their methods at import, which every run of the program
# would pay for (start-up, issue 8).


class Record:
    """The repr and equality of a dataclass, from the field names in ``_fields()``
    (``__slots__`` unless a class names them in ``_FIELDS``)."""

    __slots__ = ()

    def _fields(self) -> tuple[str, ...]:
        return getattr(self, "_FIELDS", self.__slots__)

    def _values(self) -> tuple:
        return tuple(getattr(self, name) for name in self._fields())

    def __repr__(self) -> str:
        fields = ", ".join(f"{name}={getattr(self, name)!r}" for name in self._fields())
        return f"{type(self).__qualname__}({fields})"

    def __eq__(self, other):
        if other.__class__ is self.__class__:
            return self._values() == other._values()
        return NotImplemented


class Frozen(Record):
    """Equality, hash, repr and immutability of a frozen dataclass, from ``__slots__``."""

    __slots__ = ()

    def __hash__(self) -> int:
        return hash(self._values())

    def __setattr__(self, name, value):
        raise FrozenInstanceError(f"cannot assign to field {name!r}")

    def __delattr__(self, name):
        raise FrozenInstanceError(f"cannot delete field {name!r}")

    def __reduce__(self):  # copy and pickle: rebuilt through the constructor
        return type(self), self._values()
