"""``eom``: equations of motion from Lagrange's equations (../shared/SPEC.md v2, "eom").

:func:`read` gathers the coordinates and the energies (typed, or a scene's from
:mod:`dyncalc.scenes.energies`), parses them with the closed grammar
(:mod:`dyncalc.units.expression`) and sorts the ``NAME=QUANTITY`` words into parameters and
the state (``x=``, ``x_dot=``, ``t=``). :func:`compute` checks the dimensions
(:mod:`.eom_units`), derives the equations with sympy (:mod:`dyncalc.physics.lagrange_equations`),
finds the equilibria, linearises about the chosen one and, when every value is known, gives
the natural frequencies and the accelerations at the state.
"""
from __future__ import annotations

from ..errors import InputError
from ..result import Result
from ..units import ANGULAR_RATE, CYCLE_RATE
from ..units.expression import FUNCTIONS as _FUNCTION_NAMES
from .record import Command, Parameter, ResultName
from .words import gather_texts

__all__ = ["COMMAND", "EomInputs", "read", "compute", "eom", "MAX_COORDINATES"]

MAX_COORDINATES = 6  #: degrees of freedom eom derives (the derivation grows fast beyond)
_LAGRANGE = "d/dt(dT/dq') - dT/dq + dV/dq + dD/dq' = Q_q"


class EomInputs:
    """What :func:`read` checked: ``coords``; ``trees`` (``T``, ``V``, ``D``, ``Q:x`` ->
    expression trees); ``texts`` (the same as typed); ``values`` (parameter -> SI float),
    ``dims`` (parameter -> Dimension), ``param_texts``; ``state`` (``x``/``x_dot``/``t``
    -> SI float); ``angles`` (coordinates known to be angles, for a scene; None: inferred);
    ``signed`` (parameters that may be negative); ``about`` (text or None); ``scene``;
    ``parsed`` (a scene parameter -> (Parsed, Dim), to show it as typed)."""

    __slots__ = ("coords", "trees", "texts", "values", "dims", "param_texts", "state",
                 "angles", "signed", "about", "scene", "note", "reference", "parsed",
                 "domain", "warnings_out")

    def __init__(self, **kw):
        for name in self.__slots__:
            setattr(self, name, kw.get(name))


def _split_coords(text: str) -> list[str]:
    import re

    names = [c.strip() for c in re.split(r"[,;]", text)]
    if not names or any(not c for c in names):
        raise InputError(f"--coords takes names separated by commas, e.g. \"x, phi\"; got "
                         f"{text[:60]!r}")
    for c in names:
        if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]{0,31}", c) or c.endswith(("_dot", "_ddot")):
            raise InputError(f"--coords: {c[:40]!r} is not a coordinate name (a letter, then "
                             "letters, digits or _; not ending in _dot)")
        if c in ("t", "pi") or c in _FUNCTION_NAMES:
            raise InputError(f"--coords: {c!r} is reserved (time, pi or a function)")
    if len(set(names)) != len(names):
        raise InputError("--coords names a coordinate twice")
    if len(names) > MAX_COORDINATES:
        raise InputError(f"--coords: eom derives at most {MAX_COORDINATES} coordinates; got "
                         f"{len(names)}")
    return names


def _split_forces(text: str, coords: list[str]) -> dict[str, str]:
    out: dict[str, str] = {}
    for part in text.split(";"):
        if not part.strip():
            continue
        name, sep, expr = part.partition(":")
        name = name.strip()
        if not sep or not expr.strip():
            raise InputError(f"--Q takes \"COORDINATE: EXPR; ...\", e.g. \"x: F0*cos(w*t)\"; "
                             f"got {part.strip()[:60]!r}")
        if name not in coords:
            raise InputError(f"--Q: {name[:40]!r} is not a coordinate (the coordinates are "
                             f"{', '.join(coords)})")
        if name in out:
            raise InputError(f"--Q gives the force on {name} twice")
        out[name] = expr
    return out


def read(options: dict[str, str | None], words=(), *, scene: str | None = None,
         rtol: float | None = None, strict: bool = False) -> EomInputs:
    """The options (``coords``, ``T``, ``V``, ``D``, ``Q``, ``about``) and the words ->
    :class:`EomInputs` (everything parsed, nothing derived)."""
    from ..units.expression import parse_expression

    given, _labels = gather_texts({}, words, "a parameter")
    typed = {k: options.get(k) for k in ("coords", "T", "V", "D", "Q")}
    record = None
    if scene is not None:
        from ..scenes.energies import energies

        record = energies(scene)
        for key, value in typed.items():
            if value is not None:
                raise InputError(f"--{key} does not go with --scene {record.name}: the scene "
                                 "carries its coordinates and energies")
        coords = list(record.coords)
        texts = {"T": record.T, "V": record.V}
        if record.D:
            texts["D"] = record.D
        forces = dict(record.Q)
    else:
        if typed["coords"] is None or typed["T"] is None:
            raise InputError("eom needs --coords and --T (and usually --V), or --scene NAME")
        coords = _split_coords(typed["coords"])
        texts = {"T": typed["T"], "V": typed["V"] if typed["V"] is not None else "0"}
        if typed["D"] is not None:
            texts["D"] = typed["D"]
        forces = _split_forces(typed["Q"], coords) if typed["Q"] is not None else {}
    state, params = _sort_words(given, coords)
    values, dims, param_texts, signed, parsed = _parameters(params, record, strict)
    names = set(values) | ({p.name for p in record.params} if record else set())
    trees = {}
    for key, text in texts.items():
        trees[key] = parse_expression(text, label=f"--{key}", coordinates=coords, names=names,
                                      free_names=record is None)
    for c, text in forces.items():
        trees[f"Q:{c}"] = parse_expression(text, label=f"--Q {c}", coordinates=coords,
                                           names=names, free_names=record is None)
        texts[f"Q:{c}"] = text
    if record is None:
        used = set()
        from ..units.expression import names_in

        for tree in trees.values():
            used |= names_in(tree)
        unused = sorted(set(values) - used)
        if unused:
            raise InputError(f"{unused[0]}= is not a name of --T, --V, --D or --Q (the names "
                             f"there are {', '.join(sorted(used - set(coords) - {'t'})) or 'none'})")
    return EomInputs(coords=coords, trees=trees, texts=texts, values=values, dims=dims,
                     param_texts=param_texts, state=state,
                     angles=None if record is None else set(record.angles),
                     signed=signed, about=options.get("about"), scene=scene, parsed=parsed,
                     note=record.note if record else "",
                     reference=record.reference if record else "",
                     domain=record.domain if record else {})


def _sort_words(given: dict[str, str], coords: list[str]):
    state, params = {}, {}
    for name, text in given.items():
        base = name[:-4] if name.endswith("_dot") else name
        if base in coords or name == "t":
            state[name] = text
        elif name.endswith("_ddot") and name[:-5] in coords:
            raise InputError(f"{name} is a result (the acceleration at the state), not an "
                             "input")
        else:
            params[name] = text
    return state, params


def _parameters(params: dict[str, str], record, strict: bool):
    """SI values, dimensions, texts and the signed names of the parameters given (a scene's
    defaults filled in; ``body=`` read as its kappa)."""
    from .eom_units import dimension_of_dim
    from ..units import parse_quantity
    from ..units.grammar import quantity_in_base

    values, dims, texts, signed, parsed_inputs = {}, {}, {}, set(), {}
    if record is None:
        for name, text in params.items():
            if not _is_name(name):
                raise InputError(f"{name[:40]!r}= is not a parameter name")
            value, powers, _reading = quantity_in_base(text, label=f"{name}=")
            from ..units.expression import Dimension

            values[name], dims[name], texts[name] = value, Dimension(powers), text
            if value <= 0:
                signed.add(name)
        return values, dims, texts, signed, parsed_inputs
    if "body" in params:
        from ..physics.bodies import KAPPA

        if record.param("kappa") is None:
            raise InputError(f"body= does not go with --scene {record.name}: it has no "
                             "rolling body")
        if "kappa" in params:
            raise InputError("give body= or kappa=, not both")
        word = params.pop("body")
        if word not in KAPPA:
            raise InputError(f"body={word[:40]}: unknown body; the bodies are "
                             f"{', '.join(KAPPA)}")
        params["kappa"] = repr(KAPPA[word])
    for name in params:
        if record.param(name) is None:
            import difflib

            names = [p.name for p in record.params]
            close = [n for n in names if n.lower() == name.lower()] or \
                difflib.get_close_matches(name, names, n=1)
            hint = f" (did you mean {close[0]}?)" if close else ""
            raise InputError(f"{name}= is not a parameter of --scene {record.name}{hint}; its "
                             f"parameters are {', '.join(names)}")
    for p in record.params:
        text = params.get(p.name, p.default)
        dims[p.name] = dimension_of_dim(p.dim)
        if p.signed:
            signed.add(p.name)
        if text is None:
            continue
        constraint = None if p.signed else ("nonnegative" if p.name in ("kappa", "b")
                                            else "positive")
        parsed = parse_quantity(text, p.dim, label=f"{p.name}=", strict=strict,
                                constraint=constraint)
        if parsed.uncertainty is not None:
            raise InputError(f"{p.name}=: an uncertainty is not read here (eom does not "
                             "propagate one); give the value alone")
        values[p.name], texts[p.name] = parsed.si, text
        parsed_inputs[p.name] = (parsed, p.dim)
    return values, dims, texts, signed, parsed_inputs


def _is_name(name: str) -> bool:
    import re

    return bool(re.fullmatch(r"[A-Za-z][A-Za-z0-9_]{0,31}", name)) and name not in (
        "t", "pi") and name not in _FUNCTION_NAMES


def compute(inputs: EomInputs) -> Result:
    """Derive, find the equilibria, linearise; the Result (:mod:`.eom_results`)."""
    from .eom_results import build

    return build(inputs)


def eom(options: dict[str, str | None], words=(), *, scene: str | None = None,
        rtol: float | None = None, strict: bool = False) -> Result:
    """The command: the options as typed and the ``NAME=QUANTITY`` words -> the Result.

    >>> r = eom({"coords": "x", "T": "m*x'^2/2", "V": "k*x^2/2"}, ["m=2kg", "k=200N/m"])
    >>> r.results["eom_1"].si, r.results["omega_1"].si
    ("x'' = -k*x/m", 10.0)
    """
    return compute(read(options, words, scene=scene, rtol=rtol, strict=strict))


def _run(values: dict[str, str | None], words=(), *, rtol=None, strict=False) -> Result:
    return eom({p.name: values.get(p.name) for p in COMMAND.parameters}, words,
               scene=values.get("scene"), rtol=rtol, strict=strict)


def _scene_choices():
    from ..scenes.energies import energy_scene_names

    return energy_scene_names()


COMMAND = Command(
    "eom",
    "Equations of motion from Lagrange's equations: equilibria, linearisation, frequencies.",
    """Derive the equations of motion from the kinetic energy T, the potential energy V, a
    Rayleigh dissipation function D and generalized forces Q (Lagrange's equations, solved for
    the accelerations x''), find every equilibrium with its stability, linearise about one
    (--about, default the first stable one) into mass_matrix and stiffness_matrix, and give
    the natural frequencies when every parameter has a value. With a state (x=, x_dot= for
    each coordinate) also the accelerations x_ddot there.

    Expressions use a closed grammar: numbers with units (9.81 m/s^2, 30deg), parameter
    names, coordinates and their rates x' (t is time), + - * / ^, the functions sin cos tan
    exp log sqrt sinh cosh atan2 abs, and pi; write products with * (2 m is two metres,
    2*m twice the parameter m). Parameters without a value stay symbols (taken positive).

    \b
    Examples:
      dyncalc eom --coords x --T "m*x'^2/2" --V "k*x^2/2" m=2kg k=200N/m
      dyncalc eom --coords phi --T "m*l^2*phi'^2/2" --V "m*g*l*(1 - cos(phi))"
      dyncalc eom --scene bead-on-rotating-ring r=0.2m Omega=10rad/s
      dyncalc eom --scene pendulum-on-sliding-block m1=2kg m2=1kg l=0.5m phi=30deg \\
          phi_dot=0 x_dot=0
      dyncalc eom --scene pendulum l=1m --explain=latex
    """,
    (
        Parameter("scene", None, "A catalog scene with its own energies and parameters as "
                  "NAME=QUANTITY words (dyncalc scenes lists them).", "NAME", kind="setting",
                  choices=_scene_choices),
        Parameter("coords", None, "The generalized coordinates, e.g. \"x, phi\" (at most "
                  f"{MAX_COORDINATES}).", "NAMES", kind="text"),
        Parameter("T", None, "Kinetic energy (or per unit mass), e.g. \"m*x'^2/2\".", "EXPR",
                  kind="text"),
        Parameter("V", None, "Potential energy (default 0), e.g. \"k*x^2/2\".", "EXPR",
                  kind="text"),
        Parameter("D", None, "Rayleigh dissipation function: the force on q is -dD/dq', "
                  "e.g. \"c*x'^2/2\".", "EXPR", kind="text"),
        Parameter("Q", None, "Generalized forces, e.g. \"x: F0*cos(w*t); phi: 0\".",
                  "\"q: EXPR; ...\"", kind="text"),
        Parameter("about", None, "The equilibrium to linearise about, e.g. \"phi=0\" or "
                  "\"phi=pi\" (default the first stable one).", "\"q=VALUE, ...\"",
                  kind="setting"),
    ),
    (
        ResultName("eom_<i>", "eom", "", "equation of motion i, solved for the acceleration"),
        ResultName("equilibria", "eq", "", "every equilibrium found, with its stability"),
        ResultName("mass_matrix", "M", "", "linearised mass matrix about the equilibrium"),
        ResultName("stiffness_matrix", "K", "", "linearised stiffness matrix about the "
                                                "equilibrium"),
        ResultName("omega_<i>", "ω", ANGULAR_RATE.si, "natural angular frequency i "
                                                      "(ascending)"),
        ResultName("f_<i>", "f", CYCLE_RATE.si, "natural frequency i"),
        ResultName("<coordinate>_ddot", "q''", "", "acceleration at the state given"),
    ),
    _run,
    words="[NAME=QUANTITY]...",
)
