"""``eom --scene NAME --batch`` on whole columns for the two-coordinate scenes of the
generated :mod:`dyncalc.scenes.eom_tables2` (``coupled-blocks``, ``wheel-on-moving-beam``):
the matrices, determinants and accelerations are the numpy functions written from the
symbolic derivation at build time (tools/gen_eom_columns.py), the frequencies
:func:`~dyncalc.physics.eom_pairs.two_frequencies`; the one-off evaluates the same, so both
agree bit for bit by construction and the batch never imports sympy.

Taken here: every parameter with a value, every row with the first row's stabilities, the
state complete (both coordinates and rates) or absent, no ``--about``; the other rows run
the one-off (:func:`pair_columns` leaves them).
"""
from __future__ import annotations

import json
import math

from ..lazy import numpy as np
from ..physics.columns import text_column

__all__ = ["pair_entry", "derive_pair", "pair_roots", "pair_root_forms", "pair_columns"]


def pair_entry(scene: str | None) -> dict | None:
    """The generated table's entry of ``scene``, or ``None``: not a two-coordinate scene of
    the table."""
    if scene is None:
        return None
    from ..scenes.eom_tables2 import TABLES2

    return TABLES2.get(scene)


def pair_roots(system, angles) -> list[list] | None:
    """The equilibria of a two-coordinate derivation when sympy solves them to numbers (a
    free coordinate ``None``), ordered and wrapped as the numeric search gives them (angles
    to (-pi, pi], ``|q| < 1e-12`` made 0, sorted by ``sum |q|`` then the positive first);
    ``None`` where they depend on the values or sympy cannot solve them."""
    import sympy

    from ..physics import lagrange_equations as lagrange

    s = system.symbols
    free = set(lagrange.free_coordinates(system))
    unknowns = [q for i, q in enumerate(s.q) if i not in free]
    equations = [e for e in system.static if e != 0]
    if not equations or not lagrange.solvable(equations, unknowns):
        return None
    found = lagrange.symbolic_equilibria(system)
    if not found:
        return None
    points: list[list] = []
    for f in found:
        point = []
        for i, q in enumerate(s.q):
            if i in free:
                point.append(None)
                continue
            value = sympy.sympify(f.get(q, 0))
            if value.free_symbols:
                return None
            x = float(value)
            if not math.isfinite(x):
                return None
            if angles[i]:
                x = math.remainder(x, 2 * math.pi)
                x = math.pi if x <= -math.pi + 1e-12 else x
            point.append(0.0 if abs(x) < 1e-12 else x)
        if any(all(a is None or abs(a - b) <= 1e-7 * max(1.0, abs(a))
                   for a, b in zip(point, other)) for other in points):
            continue
        points.append(point)
    zeros = [[0.0 if v is None else v for v in p] for p in points]
    order = sorted(range(len(points)), key=lambda k: (sum(abs(v) for v in zeros[k]),
                                                      [-v for v in zeros[k]]))
    return [points[k] for k in order]


def pair_root_forms(system, angles, params) -> list | None:
    """The one equilibrium of a two-coordinate derivation as closed forms in ``params`` (a
    force moves it: ``x = F/k``), or ``None``: several or none, a free coordinate, an angle
    that depends on the values (its wrapping), or anything else ``pair_roots`` takes."""
    import sympy

    from ..physics import lagrange_equations as lagrange

    s = system.symbols
    equations = [e for e in system.static if e != 0]
    if lagrange.free_coordinates(system) or not equations \
            or not lagrange.solvable(equations, list(s.q)):
        return None
    found = lagrange.symbolic_equilibria(system)
    if not found or len(found) != 1:
        return None
    forms = [sympy.sympify(found[0].get(q, 0)) for q in s.q]
    if any(f.free_symbols - set(params) or (a and f.free_symbols)
           for f, a in zip(forms, angles)):
        return None
    return forms


def derive_pair(scene: str):
    """The two-coordinate scene derived with sympy, every parameter a symbol: a dict of the
    lambdified functions (``M``, ``K``, ``detM``, ``detK``, ``a``), ``names``, ``coords``,
    ``angles``, ``roots``, ``texts`` and ``warnings`` (what tools/gen_eom_columns.py writes
    into the table and the tests compare it with), or ``None`` where the table does not
    take it (forcing in ``t``, generalized forces, a domain, equilibria that depend on the
    values)."""
    import sympy

    from ..physics.symbolic import text_of
    from ..scenes.energies import energies
    from .eom import read
    from .eom_results import derive_system

    inputs = read({}, (), scene=scene)
    if len(inputs.coords) != 2 or inputs.domain:
        return None
    s, _exprs, system = derive_system(inputs)
    if system.forced or any(a.has(s.t) for a in system.accelerations):
        return None
    names = sorted(p.name for p in energies(scene).params)
    params = [s.param(n) for n in names]
    rest = {**{x: 0 for x in s.qd}, **{x: 0 for x in s.qdd}}
    M = system.mass.subs(rest)
    K = sympy.Matrix(2, 2, lambda i, j: sympy.diff(system.static[i], s.q[j]))
    if (M.free_symbols | K.free_symbols) - set(params) - set(s.q):
        return None
    angles = [c in inputs.angles for c in inputs.coords]
    roots = pair_roots(system, angles)
    forms = None if roots is not None else pair_root_forms(system, angles, params)
    if roots is None and forms is None:
        return None
    at = [*s.q, *params]

    def tidy(expr):
        return sympy.factor(sympy.simplify(expr))
    return {
        "names": names, "coords": tuple(inputs.coords), "angles": tuple(angles),
        "M": sympy.lambdify(at, list(M), "numpy"), "K": sympy.lambdify(at, list(K), "numpy"),
        "detM": sympy.lambdify(at, tidy(M.det()), "numpy"),
        "detK": sympy.lambdify(at, tidy(K.det()), "numpy"),
        "a": sympy.lambdify([*s.q, *s.qd, s.t, *params], list(system.accelerations), "numpy"),
        "roots": roots,
        "R": None if forms is None else sympy.lambdify(params, forms, "numpy"),
        "texts": tuple(f"{c}'' = {text_of(a)}" for c, a in zip(inputs.coords,
                                                                system.accelerations)),
        "warnings": ("omega_i are the undamped natural frequencies (D is left out of them)",)
        if "D" in inputs.trees else (),
    }


def pair_columns(arrays: dict, settings: dict, entry: dict, values: dict, exact, n: int):
    """The :class:`~dyncalc.physics.columns.Columns` of a two-coordinate scene of the table
    (``values``: every parameter's SI column; ``exact`` updated in place), or ``None``: the
    first row has no stable equilibrium or the state is incomplete (the one-off answers)."""
    from ..physics.columns import Columns
    from ..physics.eom_pairs import PairPlan, finite_rows, two_frequencies
    from .eom_results import _equilibria_text

    plan, coords = PairPlan(entry), entry["coords"]
    state = [k for k in arrays if k not in values]
    rates = [c + "_dot" for c in coords]
    if state and any(k not in arrays for k in (*coords, *rates)):
        return None  # the one-off asks for the rest of the state
    moved = entry["roots"] is None  # (the one equilibrium of each row, its closed forms)
    with np.errstate(all="ignore"):
        stable, at = [], []
        rows = [plan.root_rows(values, n)] if moved else [
            [np.full(n, 0.0 if v is None else v) for v in root] for root in entry["roots"]]
        for q in rows:
            exact &= np.isfinite(q[0]) & np.isfinite(q[1])
            M, K, dm, dk = plan.matrices(*q, values)
            stable.append(two_frequencies(M, K, dm, dk)[1])
            exact &= finite_rows(M, K, dm, dk)  # (elsewhere the one-off goes symbolic)
            at.append((M, K, dm, dk))
        settled = exact & np.logical_or.reduce(stable)  # (a row with a stable equilibrium)
        first = int(np.argmax(settled)) if settled.any() else 0
        pattern = [bool(s[first]) for s in stable]
        for s, want in zip(stable, pattern):
            exact &= s == want
        if not any(pattern):
            return None  # the one-off linearises about an unstable one: warnings, no omega
        k = pattern.index(True)
        M, K, dm, dk = at[k]
        omega, _stable = two_frequencies(M, K, dm, dk)
        exact &= np.isfinite(omega).all(axis=1)
        out = {f"eom_{i}": text_column(n, t)
               for i, t in enumerate(entry["texts"], start=1)}
        if moved:
            out["equilibria"], extras = _moved_texts(coords, rows[0], entry)
        else:
            chosen = entry["roots"][k]
            text = _equilibria_text(list(coords), [list(r) for r in entry["roots"]], pattern,
                                    True, {})
            out["equilibria"] = text_column(n, text)
        out["mass_matrix"], out["stiffness_matrix"] = M, K
        out["omega_1"], out["omega_2"] = omega[:, 0], omega[:, 1]
        out["f_1"], out["f_2"] = omega[:, 0] / (2 * math.pi), omega[:, 1] / (2 * math.pi)
        if state:
            columns = [np.asarray(arrays[k], dtype=float) for k in (*coords, *rates)]
            accs = plan.accelerations(*columns, np.zeros(n), values)
            for c, acc in zip(coords, accs):
                out[f"{c}_ddot"] = acc
                exact &= np.isfinite(acc)
            for column in columns:
                exact &= np.isfinite(column)
    if not moved:
        extra = {"equilibria": [{**dict(zip(coords, r)), "stable": s}
                                for r, s in zip(entry["roots"], pattern)],
                 "about": dict(zip(coords, chosen))}
        extra.update(_units_extra(entry))
        extras = lambda _keep, line=json.dumps(extra): [line]  # noqa: E731
    warnings = entry["warnings"]
    return Columns(out, exact, model="lagrange", method="symbolic + numeric equilibria",
                   warnings=warnings, warned=np.ones(n, dtype=bool) if warnings else None,
                   extras=extras)


def _units_extra(entry) -> dict:
    """The one-off's ``extra.matrix_units`` (after ``about``), or nothing."""
    if not entry.get("matrix_units"):
        return {}
    return {"matrix_units": {name: [list(row) for row in units]
                             for name, units in entry["matrix_units"].items()}}


def _moved_texts(coords, q, entry):
    """``(texts, extras)`` of the one stable equilibrium each row has (``q``: its two
    columns): the equilibria text one format call a row, and the JSON ``extra`` (made for
    JSON only, for the rows kept)."""
    names = list(coords)
    template = ", ".join(f"{c}={{:.6g}}" for c in names) + " (stable)"
    texts = np.empty(len(q[0]), dtype=object)
    texts[:] = list(map(template.format, q[0].tolist(), q[1].tolist()))
    tail = json.dumps(_units_extra(entry))[1:-1]
    tail = "}" if not tail else ", " + tail + "}"

    def extras(keep):
        a, b = ([repr(v) for v in col[keep].tolist()] for col in q)
        first, second = json.dumps(names[0]), json.dumps(names[1])
        return [f'{{"equilibria": [{{{first}: ', a, f", {second}: ", b,
                f', "stable": true}}], "about": {{{first}: ', a, f", {second}: ", b, "}" + tail]
    return texts, extras
