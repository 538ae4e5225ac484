"""``eom --scene NAME --batch`` on whole columns: each row's numbers come from the numpy
functions of the scene's derivation, generated at build time into
:mod:`dyncalc.scenes.eom_tables` (tools/gen_eom_columns.py), which the one-off evaluates too,
so both agree bit for bit by construction and the batch never imports sympy.

Taken here: one-coordinate scenes, not forced, whose equilibria do not depend on the values
(``pendulum``: 0 and pi), every row with the first row's stabilities; the equilibrium
linearised about is ``--about``'s (round 10), else the first stable one, else the first. One
that is unstable has no frequency: the one-off's warning, no ``omega_1``/``f_1`` and the
method ``symbolic``. ``--about`` on a scene whose equilibria depend on the values, or on two
coordinates, and every other row run the one-off (:func:`scene_columns` leaves them).
"""
from __future__ import annotations

import json
import math

from ..lazy import numpy as np
from ..physics.columns import text_column

__all__ = ["scene_columns", "derivation", "derive_scene", "scene_parameters", "light_probe",
           "table_plan"]

#: scene -> the table's numbers (:func:`derivation`), per process.
_CACHE: dict = {}


class _Derived:
    """What a block needs of one derivation: the equation texts, the :class:`Plan`, the
    constant equilibria, the coordinate and whether it is an angle, the one-off's warnings
    and (from the table) the units of the results; where the equilibria depend on the
    values, ``roots`` is ``None`` and ``rootf(*p)`` gives the columns of the closed-form
    candidates (:func:`~dyncalc.physics.eom_columns.equilibria_rows` makes them the rows'
    equilibria)."""

    __slots__ = ("texts", "plan", "roots", "coord", "angle", "warnings", "dims", "rootf")

    def __init__(self, **kw):
        for name in self.__slots__:
            setattr(self, name, kw.get(name))


def table_plan(scene: str | None):
    """The :class:`~dyncalc.physics.eom_columns.Plan` of the generated table's functions for
    ``scene`` (its parameters all of the scene's, sorted), or ``None``: not in the table."""
    from ..scenes.eom_tables import TABLES

    entry = TABLES.get(scene)
    if entry is None:
        return None
    from ..physics.eom_columns import Plan

    return Plan.of_table(entry)


def derivation(scene: str, given: frozenset = frozenset()) -> _Derived | None:
    """The scene's numbers from the generated table (once per process), or ``None`` where
    the vectorised path does not take it (the scene is not in the table)."""
    if scene not in _CACHE:
        from ..scenes.eom_tables import TABLES

        entry = TABLES.get(scene)
        _CACHE[scene] = None if entry is None else _Derived(
            texts=[entry["text"]], plan=table_plan(scene),
            roots=None if entry["roots"] is None else list(entry["roots"]),
            coord=entry["coord"], angle=entry["angle"], warnings=entry["warnings"],
            dims=entry["dims"], rootf=entry.get("R"))
    return _CACHE[scene]


def derive_scene(scene: str, given: frozenset):
    """The scene derived with sympy, every parameter a symbol (what tools/gen_eom_columns.py
    writes into the table and the tests compare it with), or ``None`` where the vectorised
    path does not take it."""
    from ..physics.eom_columns import plan_of
    from .eom import read
    from .eom_results import constant_roots, derive_system

    inputs = read({}, (), scene=scene)  # the defaults: the derivation does not use values
    if len(inputs.coords) != 1 or any(k.startswith("Q:") for k in inputs.trees) \
            or inputs.domain:
        return None
    names = set(inputs.values) | set(given)
    s, _exprs, system = derive_system(inputs)
    plan = plan_of(system, names)
    if plan is None:
        return None
    angle = inputs.coords[0] in inputs.angles
    roots, rootf = constant_roots(system, angle), None
    if not roots:
        import sympy

        from ..physics.eom_columns import value_roots

        found = value_roots(system, angle)
        if found is None:
            return None
        roots = None
        rootf = sympy.lambdify([system.symbols.param(n) for n in plan.names], found, "numpy")
    from ..physics.symbolic import text_of

    texts = [f"{c}'' = {text_of(a)}" for c, a in zip(inputs.coords, system.accelerations)]
    warnings = ("omega_i are the undamped natural frequencies (D is left out of them)",) \
        if "D" in inputs.trees else ()
    return _Derived(texts=texts, plan=plan, roots=roots, coord=inputs.coords[0],
                    angle=angle, warnings=warnings, rootf=rootf)


class _Probe:
    """What a block takes of a probe (a one-off Result) when the table gives it: the scene,
    the inputs the one-off adds (the defaults, in its order) and the units of the results."""

    __slots__ = ("scene", "inputs", "results")

    def __init__(self, scene, inputs, results):
        self.scene, self.inputs, self.results = scene, inputs, results


class _Named:
    __slots__ = ("dim",)

    def __init__(self, dim):
        self.dim = dim


class MatrixUnits:
    """The unit of a result column of matrices whose entries have units of their own
    (``entry_units``, row by row; the batch writer shows each cell as the one-off does)."""

    __slots__ = ("entry_units",)
    si = ""

    def __init__(self, entry_units):
        self.entry_units = entry_units


def light_probe(spec, given_names, out):
    """A stand-in for the probe of a block of ``eom --scene --batch`` when the scene is in
    the table (no one-off, so no sympy): the inputs are the scene's parameters in its order
    (the defaults parsed as the one-off parses them), the results' units from the table.
    ``None``: not a scene of the table (the block probes the one-off)."""
    from .eom_pairs import pair_entry

    scene = spec.settings.get("scene")
    d = derivation(scene) if scene is not None else None
    pair = pair_entry(scene) if d is None else None
    dims = pair["dims"] if pair is not None else (None if d is None else d.dims)
    if pair is not None and pair.get("matrix_units"):
        dims = {**dims, **{name: MatrixUnits(units)
                           for name, units in pair["matrix_units"].items()}}
    if dims is None or spec.settings.get("about") is not None:
        return None
    from ..result import entry_from_parsed
    from ..scenes.energies import energies
    from ..units import parse_quantity

    inputs = {}
    for p in energies(scene).params:
        if p.name in given_names:
            inputs[p.name] = None  # (the column's own cells)
        elif p.default is not None:
            constraint = None if p.signed else ("nonnegative" if p.name in ("kappa", "b")
                                                else "positive")
            parsed = parse_quantity(p.default, p.dim, label=f"{p.name}=",
                                    constraint=constraint)
            inputs[p.name] = entry_from_parsed(p.name, parsed, p.dim)
        else:
            return None
    results = {name: _Named(dims.get(name)) for name in out.values}
    return _Probe(scene, inputs, results)


def scene_parameters(scene: str) -> dict:
    """Column key -> :class:`~dyncalc.commands.record.Parameter` of the columns the
    vectorised path reads: the scene's parameters and the state (coordinate, rate, ``t``)."""
    from ..scenes.energies import energies
    from ..units import ANGLE, ANGULAR_RATE, LENGTH, TIME, VELOCITY
    from .record import Parameter

    record = energies(scene)
    out = {p.name: Parameter(p.name, p.dim, p.description) for p in record.params}
    for c in record.coords:
        angle = c in record.angles
        out[c] = Parameter(c, ANGLE if angle else LENGTH, "coordinate")
        out[c + "_dot"] = Parameter(c + "_dot", ANGULAR_RATE if angle else VELOCITY, "rate")
    out["t"] = Parameter("t", TIME, "time")
    return out


def _defaults(record, given, n: int):
    """SI arrays of the parameters not given, from their defaults; ``None`` where one has
    none (the one-off keeps it a symbol)."""
    from ..units import parse_quantity

    out = {}
    for p in record.params:
        if p.name in given:
            continue
        if p.default is None:
            return None
        out[p.name] = np.full(n, parse_quantity(p.default, p.dim, label=p.name).si)
    return out


def scene_columns(arrays: dict, settings: dict):
    """The adapter of ``eom --scene --batch``: SI columns in, a
    :class:`~dyncalc.physics.columns.Columns` out (or ``None``: the one-off answers)."""
    from ..physics.columns import Columns
    from ..physics.eom_columns import one_frequency
    from ..scenes.energies import energies

    scene = settings.get("scene")
    if scene is None:
        return None
    record = energies(scene)
    params = {p.name: p for p in record.params}
    given = frozenset(k for k in arrays if k in params)
    from .eom_pairs import pair_columns, pair_entry

    d, pair = derivation(scene), pair_entry(scene)
    if d is None and pair is None:
        return None
    n = len(next(iter(arrays.values())))
    values = _defaults(record, given, n)
    if values is None:
        return None
    exact = np.ones(n, dtype=bool)
    for name in given:
        column = np.asarray(arrays[name], dtype=float)
        values[name] = column
        if not params[name].signed:  # the one-off's constraints: refused rows go there
            exact &= (column >= 0) if name in ("kappa", "b") else (column > 0)
        exact &= np.isfinite(column)
    state = [k for k in arrays if k not in params]
    about = settings.get("about")
    if about is not None and (pair is not None or d.roots is None):
        return None  # (--about: constant equilibria of one coordinate only)
    if pair is not None:
        return pair_columns(arrays, settings, pair, values, exact, n)
    wanted = None
    if about is not None:
        wanted = _about_value(about, d)
        if wanted is None:
            return None  # the one-off's refusal, a row at a time
    with np.errstate(all="ignore"):
        made = (_constant_equilibria(d, values, n, exact, wanted) if d.roots is not None
                else _value_equilibria(d, values, n, exact))
        if made is None:
            return None  # --about names no equilibrium: the one-off's message
        chosen, texts, extras, steady = made
        M, K = d.plan.matrices(chosen, values)
        omega, _stable = one_frequency(M, K)
        out = {"eom_1": text_column(n, d.texts[0]), "equilibria": texts}
        shape = (n, 1, 1) if settings.get("json") else (n,)
        out["mass_matrix"], out["stiffness_matrix"] = M.reshape(shape), K.reshape(shape)
        if steady:
            out["omega_1"], out["f_1"] = omega, omega / (2 * math.pi)
            exact &= np.isfinite(omega)
        if state:
            c = d.coord
            if c not in arrays or c + "_dot" not in arrays or (d.plan.uses_t
                                                               and "t" not in arrays):
                return None  # the one-off asks for the rest of the state
            t = arrays.get("t", np.zeros(n))
            acc = d.plan.accelerations(np.asarray(arrays[c], dtype=float),
                                       np.asarray(arrays[c + "_dot"], dtype=float),
                                       np.asarray(t, dtype=float), values)
            exact &= np.isfinite(acc) & np.isfinite(arrays[c]) & np.isfinite(arrays[c + "_dot"])
            out[f"{c}_ddot"] = acc
    warnings = d.warnings if steady else (*d.warnings, UNSTABLE)
    return Columns(out, exact, model="lagrange",
                   method="symbolic + numeric equilibria" if steady else "symbolic",
                   warnings=warnings, warned=np.ones(n, dtype=bool) if warnings else None,
                   extras=extras)


#: The one-off's warning where the equilibrium linearised about is unstable.
UNSTABLE = ("the equilibrium linearised about is unstable: no natural frequency (a small "
            "disturbance grows)")


def _about_value(about: str, d) -> float | None:
    """The coordinate's value ``--about`` names (SI), as the one-off reads it; ``None`` where
    it refuses the text (the generic path gives its message)."""
    from types import SimpleNamespace

    from ..errors import InputError
    from .eom_results import _parse_about

    try:
        wanted = _parse_about(SimpleNamespace(about=about, coords=[d.coord]), None, None)
    except InputError:
        return None
    return float(wanted[0]) if 0 in wanted else None


def _constant_equilibria(d, values, n, exact, wanted: float | None = None):
    """``(chosen, texts, extras, steady)`` of a scene whose equilibria are constants: rows
    with the first row's stabilities are exact (``exact`` updated in place); the equilibrium
    chosen as the one-off chooses it (``wanted``, ``--about``'s value: the first equilibrium
    close to it; else the first stable one, else the first), ``steady`` whether it is stable;
    ``None``: ``wanted`` is no equilibrium."""
    from ..physics.eom_columns import one_frequency
    from .eom_results import _close, _equilibria_text

    stable = []
    for root in d.roots:
        M, K = d.plan.matrices(np.full(n, root), values)
        stable.append(one_frequency(M, K)[1])
        exact &= np.isfinite(M) & np.isfinite(K)
    first = int(np.argmax(exact)) if exact.any() else 0
    pattern = [bool(s[first]) for s in stable]
    for s, want in zip(stable, pattern):
        exact &= s == want
    if wanted is not None:
        near = [k for k, r in enumerate(d.roots) if _close(r, wanted, d.angle)]
        if not near:
            return None
        k = near[0]
    else:
        k = pattern.index(True) if any(pattern) else 0
    chosen = d.roots[k]
    text = _equilibria_text([d.coord], [[r] for r in d.roots], pattern, True, {})
    extra = {"equilibria": [{d.coord: r, "stable": s} for r, s in zip(d.roots, pattern)],
             "about": {d.coord: chosen}}
    return (np.full(n, chosen), text_column(n, text),
            lambda _keep, line=json.dumps(extra): [line], pattern[k])


def _value_equilibria(d, values, n, exact):
    """``(chosen, texts, extras, True)`` of a scene whose equilibria depend on the values: each
    row's closed-form roots (:func:`~dyncalc.physics.eom_columns.equilibria_rows`, as the
    one-off takes them), their stabilities from ``K / M``, the first stable one chosen; rows
    without a stable one are not exact (``exact`` updated in place)."""
    from ..physics.eom_columns import equilibria_rows, one_frequency, root_columns

    x, count = equilibria_rows(root_columns(d.rootf, [values[p] for p in d.plan.names], n),
                               d.angle)
    stable = np.zeros(x.shape, dtype=bool)
    for j in range(x.shape[1]):
        M, K = d.plan.matrices(x[:, j], values)
        there = j < count
        stable[:, j] = one_frequency(M, K)[1] & there
        exact &= ~there | (np.isfinite(M) & np.isfinite(K))
    exact &= stable.any(axis=1) & (count > 0)
    chosen = x[np.arange(n), np.argmax(stable, axis=1)]
    word = {True: " (stable)", False: " (unstable)"}
    c = d.coord
    texts = np.empty(n, dtype=object)
    # rows with the same roots count and stabilities share one format: the roots the same
    # on all of them (0, pi) written into it once, the others one format call a row
    kinds, which = np.unique(count * 2 ** x.shape[1] + stable @ (2 ** np.arange(x.shape[1])),
                             return_inverse=True)
    for g in range(len(kinds)):
        at = np.flatnonzero(which == g)
        k = int(count[at[0]])
        pieces, varying = [], []
        for j in range(k):
            col, w = x[at, j], word[bool(stable[at[0], j])]
            if (col == col[0]).all():
                pieces.append(f"{c}={col[0]:.6g}{w}".replace("{", "{{").replace("}", "}}"))
            else:
                pieces.append(f"{c}={{:.6g}}{w}")
                varying.append(col.tolist())
        template = "; ".join(pieces)
        texts[at] = list(map(template.format, *varying)) if varying else [template] * len(at)

    def extras(keep):  # (JSON only: made for the rows kept, one format call a row)
        keep = np.asarray(keep)
        out = np.empty(len(keep), dtype=object)
        for g in np.unique(which[keep]).tolist():
            at = keep[which[keep] == g]
            first, k = int(at[0]), int(count[at[0]])
            pieces, varying = [], []
            for j in range(k):
                col = x[at, j]
                if (col == col[0]).all():
                    value = repr(float(col[0]))
                else:
                    value, _ = "{%d!r}" % len(varying), varying.append(col.tolist())
                pieces.append(f'{{{{"{c}": {value}, "stable": '
                              f'{"true" if stable[first, j] else "false"}}}}}')
            col = chosen[at]
            if (col == col[0]).all():
                about = repr(float(col[0]))
            else:
                about, _ = "{%d!r}" % len(varying), varying.append(col.tolist())
            template = ('{{"equilibria": [' + ", ".join(pieces) + f'], "about": {{{{"{c}": '
                        + about + "}}}}")
            out[np.searchsorted(keep, at)] = list(map(template.format, *varying)) \
                if varying else [template.format()] * len(at)
        return [out.tolist()]
    return chosen, texts, extras, True
