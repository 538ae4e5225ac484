"""``eom --scene NAME --batch`` on whole columns for the two-coordinate scenes of the
generated :mod:`dyncalc.scenes.eom_tables2` (``coupled-blocks``, ``wheel-on-moving-beam``):
the matrices, determinants and accelerations are the numpy functions written from the
symbolic derivation at build time (tools/gen_eom_columns.py), the frequencies
:func:`~dyncalc.physics.eom_pairs.two_frequencies`; the one-off evaluates the same, so both
agree bit for bit by construction and the batch never imports sympy.

Taken here: every parameter with a value, the rows with a stable equilibrium in the scene's
domain (grouped by which equilibria lie there and which are stable) or, where no row has
one, those with none there (``disk-on-swinging-bar``'s ``no equilibrium``), the state
complete (both coordinates and rates) or absent, no ``--about``; the other rows run the
one-off (:func:`pair_columns` leaves them).
"""
from __future__ import annotations

import importlib
import json
import math

from ..lazy import numpy as np
from ..physics.columns import text_column

__all__ = ["pair_entry", "derive_pair", "pair_roots", "pair_root_forms", "pair_columns",
           "HAND_ROOTS"]

#: Scenes whose equilibria sympy gives only as a quartic's roots -> (module, function) of a
#: root function written by hand (``Rc(*p)``: the forms and the rows they cover), which the
#: generated table imports.
HAND_ROOTS = {
    "spring-coupled-pendulums": ("dyncalc.physics.pendulum_pair_roots", "spring_pendulum_roots"),
}


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
    """The equilibria of a two-coordinate derivation as closed forms in ``params``, each
    ``[q1, q2]`` (a force moves it: ``x = F/k``; a bar's pivot: ``phi = pi/2, x = -m1 l /
    (2 m2)``), angles wrapped to (-pi, pi] exactly (``3 pi/2`` is ``-pi/2``); or ``None``:
    none, a free coordinate, an angle that depends on the values (its wrapping), or
    anything else ``pair_roots`` takes. sympy's ``solve`` is asked even where
    :func:`~dyncalc.physics.lagrange_equations.solvable` would not (this runs at build time;
    tests/test_eom_tables2.py checks the forms against the numeric search)."""
    import sympy

    from ..physics import lagrange_equations as lagrange

    s = system.symbols
    equations = [e for e in system.static if e != 0]
    if lagrange.free_coordinates(system) or not equations:
        return None
    try:
        found = sympy.solve(equations, list(s.q), dict=True, check=False, simplify=False)
    except (NotImplementedError, ValueError, TypeError):
        return None
    forms: list[list] = []
    for f in found:
        root = [sympy.sympify(f.get(q, 0)) for q in s.q]
        if any(v.free_symbols - set(params) or v.has(sympy.I, sympy.oo, sympy.zoo)
               or (a and v.free_symbols) for v, a in zip(root, angles)):
            return None
        root = [_wrapped(v) if a else v for v, a in zip(root, angles)]
        if root not in forms:
            forms.append(root)
    return forms or None


def _wrapped(angle):
    """A constant angle moved by whole turns into (-pi, pi], exactly (sympy)."""
    import sympy

    turns = round(float(angle) / (2 * math.pi))
    out = sympy.nsimplify(angle - 2 * sympy.pi * turns) if turns else angle
    return sympy.pi if out == -sympy.pi else out


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
    if len(inputs.coords) != 2:
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
    hand = HAND_ROOTS.get(scene) if roots is None and forms is None else None
    if roots is None and forms is None and hand is None:
        return None
    at = [*s.q, *params]

    domain, bounds = _domain_forms(inputs, s)

    def tidy(expr):
        return sympy.factor(sympy.simplify(expr))
    return {
        "names": names, "coords": tuple(inputs.coords), "angles": tuple(angles),
        "M": sympy.lambdify(at, list(M), "numpy"), "K": sympy.lambdify(at, list(K), "numpy"),
        "detM": sympy.lambdify(at, tidy(M.det()), "numpy"),
        "detK": sympy.lambdify(at, tidy(K.det()), "numpy"),
        "a": sympy.lambdify([*s.q, *s.qd, s.t, *params], list(system.accelerations), "numpy"),
        "roots": roots,
        "R": None if forms is None else sympy.lambdify(params, [v for root in forms
                                                                for v in root], "numpy"),
        "Rc": None if hand is None else getattr(importlib.import_module(hand[0]), hand[1]),
        "domain": domain,
        "B": None if not domain else sympy.lambdify(params, bounds, "numpy"),
        "texts": tuple(f"{c}'' = {text_of(a)}" for c, a in zip(inputs.coords,
                                                                system.accelerations)),
        "warnings": ("omega_i are the undamped natural frequencies (D is left out of them)",)
        if "D" in inputs.trees else (),
    }


def _domain_forms(inputs, s) -> tuple[tuple, list]:
    """``(indices, ends)``: the coordinates the scene bounds and each one's lowest and
    highest as sympy forms in the parameters (the domain's texts read as the one-off reads
    them)."""
    from ..physics.symbolic import to_sympy
    from ..scenes.energies import energies
    from ..units.expression import parse_expression

    names = {p.name for p in energies(inputs.scene).params}
    indices, ends = [], []
    for c, pair in (inputs.domain or {}).items():
        indices.append(inputs.coords.index(c))
        ends += [to_sympy(parse_expression(text, names=names, free_names=False), s)
                 for text in pair]
    return tuple(indices), ends


def pair_columns(arrays: dict, settings: dict, entry: dict, values: dict, exact, n: int):
    """The :class:`~dyncalc.physics.columns.Columns` of a two-coordinate scene of the table
    (``values``: every parameter's SI column; ``exact`` updated in place), or ``None``: no
    row has a stable equilibrium in the scene's domain or none there at all, or the state
    is incomplete (the one-off answers).

    A row's pattern is which equilibria lie in the domain and which of those are stable.
    Where some rows have a stable one, those rows are taken, each pattern a group of its own
    (``Columns.groups``: its own equilibria text, JSON ``extra`` and probe); else the rows
    with none in the domain (the one-off's ``no equilibrium``). Rows whose equilibria there
    are all unstable run the one-off."""
    from ..physics.columns import Columns
    from ..physics.eom_pairs import PairPlan, frequency_rows, within

    plan, coords = PairPlan(entry), entry["coords"]
    state = [k for k in arrays if k not in values]
    rates = [c + "_dot" for c in coords]
    if state and any(k not in arrays for k in (*coords, *rates)):
        return None  # the one-off asks for the rest of the state
    moved = entry["roots"] is None  # (the equilibria of each row, their closed forms)
    with np.errstate(all="ignore"):
        if moved:
            rows, distinct, covered = plan.root_rows(values, n)
            exact &= distinct & covered
        else:
            rows = [[np.full(n, 0.0 if v is None else v) for v in root]
                    for root in entry["roots"]]
        bounds = plan.bound_rows(values, n)
        for lo, hi in bounds.values():
            exact &= np.isfinite(lo) & np.isfinite(hi)
        inside = [within(q, bounds) for q in rows]
        stable, at = [], []
        for q, there in zip(rows, inside):
            missing = np.isnan(q[0]) & np.isnan(q[1])  # (a row without this one)
            exact &= missing | (np.isfinite(q[0]) & np.isfinite(q[1]))
            if not (there & exact).any():  # (off the domain: never linearised)
                stable.append(np.zeros(n, dtype=bool))
                at.append(None)
                continue
            M, K, dm, dk = plan.matrices(*q, values)
            omega, steady, finite = frequency_rows(M, K, dm, dk)
            stable.append(steady)
            exact &= ~there | finite  # (elsewhere the one-off goes symbolic)
            at.append((M, K, omega))
        settled = np.logical_or.reduce([i & s for i, s in zip(inside, stable)])
        out = {f"eom_{i}": text_column(n, t)
               for i, t in enumerate(entry["texts"], start=1)}
        groups = None
        if not (exact & settled).any():
            if not (exact & ~np.logical_or.reduce(inside)).any():
                return None  # the one-off linearises about an unstable one: no omega
            exact &= ~np.logical_or.reduce(inside)
            out["equilibria"] = text_column(n, "none")
            warnings = ("no equilibrium: the system is never at rest at these values",)
            method = "symbolic"
            extras = lambda _keep: ['{"equilibria": []}']  # noqa: E731
        else:
            exact &= settled
            codes = _pattern_codes(inside, stable)
            made = _settled_groups(coords, entry, rows, at, codes, exact, n)
            out["equilibria"], M, K, omega, extras, several = made
            exact &= np.isfinite(omega).all(axis=1)
            groups = codes if several else None
            out["mass_matrix"], out["stiffness_matrix"] = M, K
            out["omega_1"], out["omega_2"] = omega[:, 0], omega[:, 1]
            out["f_1"], out["f_2"] = omega[:, 0] / (2 * math.pi), omega[:, 1] / (2 * math.pi)
            warnings, method = entry["warnings"], "symbolic + numeric equilibria"
        if state:
            columns = [np.asarray(arrays[k], dtype=float) for k in (*coords, *rates)]
            accs = plan.accelerations(*columns, np.zeros(n), values)
            for c, acc in zip(coords, accs):
                out[f"{c}_ddot"] = acc
                exact &= np.isfinite(acc)
            for column in columns:
                exact &= np.isfinite(column)
    if any(name not in entry["dims"] for name in out if not name.startswith(("eom_", "equi"))):
        return None  # (results the table has no units for: the one-off's)
    return Columns(out, exact, model="lagrange", method=method, warnings=warnings,
                   warned=np.ones(n, dtype=bool) if warnings else None, extras=extras,
                   groups=groups)


def _pattern_codes(inside, stable):
    """Each row's pattern as an integer: bit ``2 k`` whether equilibrium ``k`` lies in the
    domain, bit ``2 k + 1`` whether it is there and stable."""
    codes = np.zeros(len(inside[0]), dtype=np.int64)
    for k, (there, steady) in enumerate(zip(inside, stable)):
        codes |= there.astype(np.int64) << (2 * k)
        codes |= (there & steady).astype(np.int64) << (2 * k + 1)
    return codes


def _settled_groups(coords, entry, rows, at, codes, exact, n):
    """``(texts, M, K, omega, extras, several)`` of the rows with a stable equilibrium in
    the domain (``rows``: the equilibria's columns; ``at``: each one's ``(M, K, omega)``),
    each pattern of equilibria (``codes``) on its own: linearised about its
    first stable one, its equilibria text and JSON ``extra`` (``extras(keep)``: ``keep``
    rows of one pattern, as the block's ``groups`` split them); ``several``: more than one
    pattern among the ``exact`` rows."""
    from .eom_results import _equilibria_text

    texts = np.empty(n, dtype=object)
    M, K = np.full((n, 2, 2), np.nan), np.full((n, 2, 2), np.nan)
    omega = np.full((n, 2), np.nan)
    extras_of: dict = {}
    present = np.unique(codes[exact]).tolist()
    for code in present:
        mask = exact & (codes == code)
        kept = [j for j in range(len(rows)) if code >> (2 * j) & 1]
        marks = [bool(code >> (2 * j + 1) & 1) for j in kept]
        k = kept[marks.index(True)]
        Mk, Kk, wk = at[k]
        M[mask], K[mask], omega[mask] = Mk[mask], Kk[mask], wk[mask]
        if entry["roots"] is None:
            texts[mask], extras_of[code] = _moved_texts(
                coords, [rows[j] for j in kept], marks, kept.index(k), entry, mask)
            continue
        points = [list(entry["roots"][j]) for j in kept]
        texts[mask] = _equilibria_text(list(coords), points, marks, True, {})
        extra = {"equilibria": [{**dict(zip(coords, r)), "stable": m}
                                for r, m in zip(points, marks)],
                 "about": dict(zip(coords, entry["roots"][k]))}
        extra.update(_units_extra(entry))
        extras_of[code] = lambda _keep, line=json.dumps(extra): [line]  # noqa: E731

    def extras(keep):
        return extras_of[int(codes[keep[0]])](keep)
    return texts, M, K, omega, extras, len(present) > 1


def _units_extra(entry) -> dict:
    """The one-off's ``extra.matrix_units`` (after ``about``), or nothing."""
    if not entry.get("matrix_units"):
        return {}
    return {"matrix_units": {name: [list(row) for row in units]
                             for name, units in entry["matrix_units"].items()}}


def _moved_texts(coords, roots, marks, chosen: int, entry, mask):
    """``(texts, extras)`` of the ``mask`` rows' equilibria in the domain (``roots``: each
    one's two columns, ``marks`` their stabilities, ``chosen`` the one linearised about):
    the equilibria text one format call a row (those rows only), and the JSON ``extra``
    (made for JSON only, for the rows kept). A coordinate the same on every such row
    (``pi/2``) is written once into the template, not formatted a row at a time."""
    from ..physics.eom_pairs import constant

    names = list(coords)
    columns = [col[mask] for root in roots for col in root]
    same = [constant(col) for col in columns]  # (one row: formatted as a varying one)
    words = ["stable" if m else "unstable" for m in marks]
    template = "; ".join(", ".join(
        f"{c}={columns[2 * k + i][0]:.6g}" if same[2 * k + i] else f"{c}={{:.6g}}"
        for i, c in enumerate(names)) + f" ({w})" for k, w in enumerate(words))
    varying = [col.tolist() for col, fixed in zip(columns, same) if not fixed]
    texts = list(map(template.format, *varying)) if varying else template
    tail = json.dumps(_units_extra(entry))[1:-1]
    tail = "}" if not tail else ", " + tail + "}"
    first, second = json.dumps(names[0]), json.dumps(names[1])
    full = [col for root in roots for col in root]

    def extras(keep):
        cols = [repr(float(columns[i][0])) if fixed else [repr(v) for v in col[keep].tolist()]
                for i, (col, fixed) in enumerate(zip(full, same))]
        parts: list = ['{"equilibria": [']
        for k, mark in enumerate(marks):
            parts += [("" if k == 0 else ", ") + f"{{{first}: ", cols[2 * k],
                      f", {second}: ", cols[2 * k + 1], f', "stable": {json.dumps(mark)}}}']
        parts += [f'], "about": {{{first}: ', cols[2 * chosen], f", {second}: ",
                  cols[2 * chosen + 1], "}" + tail]
        return parts
    return texts, extras
