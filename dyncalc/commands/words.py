"""The texts a command reads by parameter: its options, then the ``NAME=QUANTITY`` words."""
from __future__ import annotations

from ..errors import InputError

__all__ = ["gather_texts"]


def gather_texts(flagged: dict[str, tuple[str | None, str]], words, what: str
                 ) -> tuple[dict[str, str], dict[str, str]]:
    """(texts by parameter, labels by parameter) of the options given and the words.

    ``flagged`` maps a parameter to (its option's text or ``None``, the option's label, e.g.
    ``--k``); each word ``NAME=TEXT`` adds ``NAME`` with the label ``NAME=``; ``what`` names a
    word in :func:`~dyncalc.result.checks.split_assignment`'s refusal. A parameter given twice
    is refused naming both places.

    >>> gather_texts({"k": ("2 kN/m", "--k"), "m": (None, "--m")}, ["M=10kg"], "a parameter")
    ({'k': '2 kN/m', 'M': '10kg'}, {'k': '--k', 'M': 'M='})
    """
    texts: dict[str, str] = {}
    labels: dict[str, str] = {}
    for name, (text, label) in flagged.items():
        if text is not None:
            texts[name], labels[name] = text, label
    for word in words:
        from ..result.checks import split_assignment  # only when words are given (start-up)

        name, text = split_assignment(word, what)
        if name in texts:
            raise InputError(f"{name} is given twice ({labels[name]} and {name}=)")
        texts[name], labels[name] = text, f"{name}="
    return texts, labels
