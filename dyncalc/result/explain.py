"""Formula lines for explanations, in LaTeX and in plain text, from one template.

A template is one line of LaTeX in which ``$name`` stands for a parameter or result
(``r"$omega = \\sqrt{\\frac{$k}{$m}}"``; ``${name}`` where a letter follows). Factors are
joined with ``\\,`` (``2\\,$k``), which becomes ``\\cdot`` once numbers stand there. Filled with
symbols it is the formula; filled with values and units it is the substituted line, ending in
the value of its left-hand side: ``\\omega = \\sqrt{\\frac{100\\,\\mathrm{N/m}}{2\\,\\mathrm{kg}}}
= 7.07107\\,\\mathrm{rad/s}``. :func:`tex_to_text` gives the plain-text twin of each line.

Nothing here prints; the three renderings of an explanation are in
:mod:`dyncalc.result.explain_render`.
"""
from __future__ import annotations

import math
import re
from typing import Any

from .entries import format_number
from ..records import Frozen

__all__ = ["Term", "Formula", "latex_escape", "unit_latex", "number_latex", "symbol_latex",
           "quantity_latex", "quantity_text", "tex_to_text", "render_formulas", "template_terms",
           "DIGITS"]

DIGITS = 6

_GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "kappa",
          "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "phi", "chi", "psi", "omega",
          "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega"}
_SPECIAL = {"kt": "k_{t}", "amplitude": r"\theta_{0}", "EI": "EI", "EA": "EA", "GJ": "GJ",
            "decrement": r"\delta", "vr": "v_{r}"}
_LATEX_SPECIAL = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&",
                  "#": r"\#", "%": r"\%", "_": r"\_", "~": r"\textasciitilde{}",
                  "^": r"\textasciicircum{}"}


def latex_escape(text: str) -> str:
    """``text`` safe in LaTeX text mode: ``_ % & # $ { } ~ ^ \\`` escaped."""
    return "".join(_LATEX_SPECIAL.get(ch, ch) for ch in str(text))


def symbol_latex(name: str) -> str:
    """The LaTeX symbol of a name: ``omega_0`` -> ``\\omega_{0}``, ``theta_eq`` ->
    ``\\theta_{\\mathrm{eq}}``, ``k1`` -> ``k_{1}``, ``Omega`` -> ``\\Omega``."""
    if name in _SPECIAL:
        return _SPECIAL[name]
    m = re.fullmatch(r"([A-Za-z]+?)_?(\d+|[A-Za-z]+)?", name)
    if m is None:
        return r"\mathrm{" + latex_escape(name) + "}"
    base, sub = m.group(1), m.group(2)
    if sub is not None and "_" not in name and not sub.isdigit():
        base, sub = name, None  # a plain word such as "amplitude"
    if len(base) > 1 and base not in _GREEK:
        head = r"\mathrm{" + base + "}"
    else:
        head = "\\" + ("varphi" if base == "phi" else base) if base in _GREEK else base
    if sub is None:
        return head
    if sub.isdigit() or len(sub) == 1:
        return f"{head}_{{{sub}}}"
    return f"{head}_{{\\mathrm{{{sub}}}}}"


_UNIT_TOKEN = re.compile(r"\s*(\*\*|\^|[*/·()]|-?\d+(?:\.\d+)?|[^\s*/^·()]+)")


def unit_latex(unit: str) -> str:
    """A unit as typed, in upright LaTeX: ``kg*m^2`` -> ``\\mathrm{kg\\,m^{2}}``, ``N*m/rad`` ->
    ``\\mathrm{N\\,m/rad}``, ``m/s**2`` -> ``\\mathrm{m/s^{2}}``; ``deg`` -> ``{}^{\\circ}``."""
    unit = unit.strip()
    if not unit:
        return ""
    if unit in ("deg", "degree", "degrees", "°"):
        return r"{}^{\circ}"
    out: list[str] = []
    tokens = _UNIT_TOKEN.findall(unit)
    i = 0
    while i < len(tokens):
        tok = tokens[i]
        if tok in ("^", "**"):
            exponent = tokens[i + 1] if i + 1 < len(tokens) else ""
            if exponent == "(":
                j = tokens.index(")", i + 1) if ")" in tokens[i + 1:] else len(tokens)
                exponent = "".join(tokens[i + 2:j])
                i = j
            else:
                i += 1
            out.append("^{" + latex_escape(exponent) + "}")
        elif tok in ("*", "·"):
            out.append(r"\,")
        elif tok in ("/", "(", ")"):
            out.append(tok)
        else:
            if out and out[-1] not in (r"\,", "/", "("):
                out.append(r"\,")  # juxtaposed: "N m"
            word = tok.replace("µ", r"\mu{}").replace("μ", r"\mu{}").replace("°", r"^{\circ}")
            out.append(word if "\\" in word else latex_escape(word))
        i += 1
    return r"\mathrm{" + "".join(out) + "}"


def number_latex(value, digits: int = DIGITS) -> str:
    """A number to ``digits`` significant figures, ``1e-05`` as ``1\\times10^{-5}``."""
    if isinstance(value, str):
        return r"\text{" + latex_escape(value) + "}"
    if hasattr(value, "__len__"):
        return r"\left(" + ", ".join(number_latex(float(v), digits) for v in value) + r"\right)"
    value = float(value)
    if math.isinf(value):
        return r"\infty" if value > 0 else r"-\infty"
    text = format_number(value, digits)
    mantissa, e, exponent = text.partition("e")
    if not e:
        return text
    return f"{mantissa}\\times 10^{{{int(exponent)}}}"


def quantity_latex(value, unit: str, digits: int = DIGITS) -> str:
    number = number_latex(value, digits)
    if not unit:
        return number
    tex = unit_latex(unit)
    return number + (tex if tex.startswith("{}^") else r"\," + tex)


def quantity_text(value, unit: str, digits: int = DIGITS) -> str:
    number = format_number(value, digits)
    return f"{number} {unit}" if unit else number


class Term(Frozen):
    """What ``$name`` stands for: its symbol (LaTeX) and its value in ``unit``."""

    __slots__ = ("symbol", "value", "unit")

    def __init__(self, symbol: str, value: Any = None, unit: str = ""):
        _set(self, symbol=symbol, value=value, unit=unit)

    def tex(self, digits: int) -> str:
        return quantity_latex(self.value, self.unit, digits)

    def text(self, digits: int) -> str:
        return quantity_text(self.value, self.unit, digits)

    @property
    def negative(self) -> bool:
        return isinstance(self.value, (int, float)) and self.value < 0


class Formula(Frozen):
    """A template used only ``when`` a predicate on the SI values by name holds."""

    __slots__ = ("template", "when")

    def __init__(self, template: str, when: Any = None):
        _set(self, template=template, when=when)


def _set(record, **values) -> None:
    """Fill a frozen record's fields (plain classes: no dataclass code made at import)."""
    for name, value in values.items():
        object.__setattr__(record, name, value)


# --- LaTeX -> plain text ------------------------------------------------------------------

_WORDS = {"pi": "pi", "cdot": "×", "times": "×", "sin": "sin", "cos": "cos", "tan": "tan",
          "arctan": "atan", "arccos": "acos", "arcsin": "asin", "ln": "ln", "exp": "exp",
          "approx": "~", "le": "<=", "ge": ">=", "lt": "<", "gt": ">", "quad": "  ",
          "qquad": "  ", "infty": "inf", "lvert": "|", "rvert": "|", "varphi": "phi",
          "sum": "sum", "circ": "deg"}


class _TexReader:
    def __init__(self, tex: str):
        self.tex, self.i = tex, 0

    def group(self) -> str:
        """The next argument: a ``{...}`` group or one character/command, as text."""
        while self.i < len(self.tex) and self.tex[self.i] == " ":
            self.i += 1
        if self.i < len(self.tex) and self.tex[self.i] == "{":
            depth, start = 0, self.i
            while self.i < len(self.tex):
                ch = self.tex[self.i]
                depth += ch == "{"
                depth -= ch == "}"
                self.i += 1
                if depth == 0:
                    break
            return _to_text(self.tex[start + 1:self.i - 1])
        if self.i < len(self.tex) and self.tex[self.i] == "\\":
            return self.command()
        ch = self.tex[self.i:self.i + 1]
        self.i += 1
        return ch

    def command(self) -> str:
        m = re.compile(r"\\([A-Za-z]+|.)").match(self.tex, self.i)
        self.i = m.end()
        name = m.group(1)
        if name in ("frac", "tfrac", "dfrac"):
            top, bottom = self.group(), self.group()
            return f"{_wrap(top)} / {_wrap(bottom)}"
        if name == "sqrt":
            return f"sqrt({self.group()})"
        if name in ("mathrm", "text", "operatorname", "mathit", "boldsymbol", "vec"):
            return self.group()
        if name in ("left", "right", "big", "Big"):
            return ""
        if name in (",", ";", ":", " ", "!"):
            return " " if name != "!" else ""
        if name in _GREEK:
            return name
        if name in _WORDS:
            return _WORDS[name]
        return name


def _enclosed(part: str) -> bool:
    """``(...)`` or ``sqrt(...)`` whose first parenthesis closes at the end."""
    start = part.find("(")
    if start < 0 or not part.endswith(")") or part[:start] not in ("", "sqrt"):
        return False
    depth = 0
    for i, ch in enumerate(part[start:], start):
        depth += (ch == "(") - (ch == ")")
        if depth == 0:
            return i == len(part) - 1
    return False


def _wrap(part: str) -> str:
    part = part.strip()
    if not part or re.fullmatch(r"[\w.$]+(\^[\w.]+)?", part) or _enclosed(part):
        return part
    return f"({part})"


def _to_text(tex: str) -> str:
    reader = _TexReader(tex)
    out: list[str] = []
    while reader.i < len(tex):
        ch = tex[reader.i]
        if ch == "\\":
            word = reader.command()
            if word[:1].isalpha() and out and out[-1][-1:].isalnum():
                word = " " + word  # 2\pi -> 2 pi
            out.append(word)
        elif ch in "^_":
            reader.i += 1
            arg = reader.group()
            simple = re.fullmatch(r"[\w.$-]+", arg) is not None
            out.append(ch + (arg if simple or ch == "_" else f"({arg})"))
        elif ch == "{":
            out.append(reader.group())
        else:
            out.append(ch)
            reader.i += 1
    return "".join(out)


def tex_to_text(tex: str) -> str:
    """A LaTeX formula as plain text: ``\\frac{a}{b+c}`` -> ``a / (b+c)``, ``\\sqrt{x}`` ->
    ``sqrt(x)``, ``\\omega_{0}`` -> ``omega_0``; ``$name`` placeholders are kept."""
    text = _to_text(tex)
    text = re.sub(r" *× *", " × ", text)
    return re.sub(r"  +", " ", text).replace("( ", "(").replace(" )", ")").strip()


# --- filling templates ----------------------------------------------------------------------

_PLACEHOLDER = re.compile(r"\$(?:\{(\w+)\}|(\w+))")


def _names(template: str) -> list[str]:
    return [a or b for a, b in _PLACEHOLDER.findall(template)]


def _split(template: str) -> tuple[str, str]:
    lhs, sep, rhs = template.partition(" = ")
    return (lhs, rhs) if sep else ("", template)


def _fill_values_tex(rhs: str, terms: dict[str, Term], digits: int) -> str:
    rhs = rhs.replace(r"\,", r" \cdot ")

    def one(m: re.Match) -> str:
        term = terms[m.group(1) or m.group(2)]
        tex = term.tex(digits)
        follows = rhs[m.end():m.end() + 1]
        if follows == "^" or term.negative:
            return r"\left(" + tex + r"\right)"
        return tex

    return _PLACEHOLDER.sub(one, rhs)


def _fill_values_text(rhs_text: str, terms: dict[str, Term], digits: int) -> str:
    alone = _PLACEHOLDER.fullmatch(rhs_text.strip()) is not None

    def one(m: re.Match) -> str:
        term = terms[m.group(1) or m.group(2)]
        text = term.text(digits)
        if not alone and (term.unit or term.negative):
            return f"({text})"
        return text

    return _PLACEHOLDER.sub(one, rhs_text)


def _fill_symbols(template: str, terms: dict[str, Term], *, text: bool) -> str:
    def one(m: re.Match) -> str:
        symbol = terms[m.group(1) or m.group(2)].symbol
        if text:
            return tex_to_text(symbol)
        # a symbol followed by a letter or a digit needs a separating space
        return symbol + (" " if re.match(r"[A-Za-z0-9]", template[m.end():m.end() + 1])
                         and symbol[-1].isalpha() else "")

    return _PLACEHOLDER.sub(one, template)


def render_formulas(templates, terms: dict[str, Term], si: dict[str, Any] | None = None,
                    digits: int = DIGITS) -> tuple[list[str], list[str], list[str]]:
    """Fill ``templates`` (strings or :class:`Formula`) from ``terms``.

    A template is used when every name in it has a term with a value (its left-hand side
    a result that was computed), its ``when`` holds on ``si`` and no earlier template gave
    the same left-hand side. Returns the LaTeX formula
    lines, the LaTeX substituted lines and the plain-text substituted lines.
    """
    formulas, substituted, text_lines = [], [], []
    done = set()
    for item in templates:
        formula = item if isinstance(item, Formula) else Formula(item)
        names = _names(formula.template)
        if any(n not in terms or terms[n].value is None for n in names):
            continue
        if formula.when is not None and not _holds(formula.when, si or {}):
            continue
        lhs, rhs = _split(formula.template)
        if _PLACEHOLDER.fullmatch(lhs.strip()) is None:
            lhs, rhs = "", formula.template  # an equation: its values on both sides
        elif lhs.strip() in done:
            continue  # the first template for a result wins
        done.add(lhs.strip())
        formulas.append(_fill_symbols(formula.template, terms, text=False))
        lhs_tex = _fill_symbols(lhs, terms, text=False)
        lhs_text = tex_to_text(_fill_symbols(lhs, terms, text=True)) if lhs else ""
        rhs_tex = _fill_values_tex(rhs, terms, digits)
        rhs_text = _fill_values_text(tex_to_text(rhs.replace(r"\,", r" \cdot ")), terms, digits)
        result = _PLACEHOLDER.fullmatch(lhs.strip()) if lhs else None
        tail_tex = tail_text = ""
        if result is not None and _PLACEHOLDER.fullmatch(rhs.strip()) is None:
            term = terms[result.group(1) or result.group(2)]
            tail_tex, tail_text = " = " + term.tex(digits), " = " + term.text(digits)
        head_tex = f"{lhs_tex} = " if lhs else ""
        head_text = f"{lhs_text} = " if lhs else ""
        substituted.append(head_tex + rhs_tex + tail_tex)
        text_lines.append(head_text + rhs_text + tail_text)
    return formulas, substituted, text_lines


def template_terms(entries, symbols: dict[str, str] | None = None) -> dict[str, Term]:
    """Terms from :class:`~dyncalc.result.Entry` objects (their display values and units)."""
    symbols = symbols or {}
    terms = {}
    for entry in entries:
        if entry.dim is None or isinstance(entry.si, str):
            continue
        value = entry.value_in()
        if hasattr(value, "__len__"):
            continue
        terms[entry.name] = Term(symbols.get(entry.name, symbol_latex(entry.name)),
                                 float(value), entry.unit)
    return terms


def _holds(when, si: dict) -> bool:
    """``when(si)``; a predicate that cannot be evaluated at these values does not hold."""
    try:
        return bool(when(si))
    except (ArithmeticError, KeyError, TypeError, ValueError):
        return False
