"""The errors dyncalc shows to its users.

Everything the user can get wrong is raised as :class:`InputError` (exit status 2, one
``Error:`` line on stderr). Nothing else is meant to reach the user; any other exception is a bug
and the CLI reports it as one (also exit 2, with the traceback only under ``--debug``).
"""

__all__ = ["InputError", "PhysicsError", "EXIT_OK", "EXIT_CHECK_FAILED", "EXIT_BAD_INPUT"]

EXIT_OK = 0
EXIT_CHECK_FAILED = 1
EXIT_BAD_INPUT = 2


class InputError(ValueError):
    """Bad input or usage: the message says what to change (it becomes ``Error: <message>``)."""


class PhysicsError(InputError):
    """A well-formed request the physics cannot answer (a slope too steep to roll, resonance)."""
