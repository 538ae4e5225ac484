"""The numbers of a one-coordinate ``eom`` derivation on arrays: the linearised mass and
stiffness, the natural frequency and the acceleration at a state, each a numpy function of
the parameters (``sympy.lambdify`` of the symbolic derivation, once per derivation).

The one-off (:mod:`dyncalc.commands.eom_results`) and ``eom --scene --batch`` both evaluate
these functions on float64 arrays (the one-off on arrays of one row), so they agree bit for
bit; the equations themselves (their text) do not depend on the values.

For ``q'' = a(q, q', t)`` linearised about ``q0``:

.. math:: M = \\partial^2 T / \\partial q'^2 |_{q_0}, \\quad
          K = \\partial E_{static} / \\partial q |_{q_0}, \\quad
          \\omega = \\sqrt{K / M}\\ (K / M > 0)

Reference: Gross et al., *Engineering Mechanics 3*, 2nd ed., 4.3.
"""
from __future__ import annotations

import math

from ..lazy import numpy as np

__all__ = ["Plan", "plan_of", "one_frequency", "constant_equilibria", "value_roots",
           "root_columns", "equilibria_rows"]


class Plan:
    """The numpy functions of one derivation with one coordinate: ``names`` (the parameters,
    in the order the functions take them after the coordinate), ``mass(q, *p)``,
    ``stiffness(q, *p)`` and ``acceleration(q, q', t, *p)``; ``uses_t``: whether the
    acceleration depends on ``t``."""

    __slots__ = ("names", "mass", "stiffness", "acceleration", "uses_t")

    def __init__(self, names, mass, stiffness, acceleration, uses_t):
        self.names, self.mass, self.stiffness = names, mass, stiffness
        self.acceleration, self.uses_t = acceleration, uses_t

    @classmethod
    def of_table(cls, entry: dict) -> "Plan":
        """The plan of an entry of the generated :mod:`dyncalc.scenes.eom_tables` (its
        parameters all of the scene's, sorted)."""
        return cls(list(entry["names"]), entry["M"], entry["K"], entry["a"], entry["uses_t"])

    def matrices(self, q, params: dict):
        """``(M, K)`` at ``q`` (arrays) for ``params`` (name -> array of the same length)."""
        args = [params[name] for name in self.names]
        return _array(self.mass(q, *args), q), _array(self.stiffness(q, *args), q)

    def accelerations(self, q, qd, t, params: dict):
        """``q''`` at the state (arrays)."""
        args = [params[name] for name in self.names]
        return _array(self.acceleration(q, qd, t, *args), q)


def _array(value, like):
    """A lambdified function's answer as a float64 array of ``like``'s length (a constant
    expression gives a scalar)."""
    out = np.asarray(value, dtype=float)
    return out if out.shape == np.shape(like) else np.full(np.shape(like), float(out))


def plan_of(system, names) -> Plan | None:
    """The :class:`Plan` of a derivation (``names``: the parameters given a value), or
    ``None``: more than one coordinate, a forcing in ``t``, a coordinate free of the static
    equations, or a parameter without a value in ``M`` or ``K``."""
    import sympy

    from . import lagrange_equations as lagrange
    s = system.symbols
    if len(s.q) != 1 or system.forced or lagrange.free_coordinates(system):
        return None
    q = s.q[0]
    rest = {s.qd[0]: 0, s.qdd[0]: 0}
    m = system.mass[0, 0].subs(rest)
    k = sympy.diff(system.static[0], q)
    names = sorted(names)
    params = [s.param(name) for name in names]
    if (m.free_symbols | k.free_symbols) - set(params) - {q}:
        return None
    acc = system.accelerations[0]
    return Plan(names, sympy.lambdify([q, *params], m, "numpy"),
                sympy.lambdify([q, *params], k, "numpy"),
                sympy.lambdify([q, s.qd[0], s.t, *params], acc, "numpy"), acc.has(s.t))


def one_frequency(M, K):
    """``(omega, stable)`` arrays of ``M q'' + K q = 0``: ``lam = K / M``; stable where
    ``lam >= -1e-10 |lam|`` (the rule of :func:`lagrange_equations.frequencies`),
    ``omega = sqrt(lam)`` where ``lam > 1e-10 |lam|``, else 0.

    >>> import numpy as np
    >>> one_frequency(np.array([2.0]), np.array([200.0]))
    (array([10.]), array([ True]))
    """
    with np.errstate(all="ignore"):
        lam = K / M
        tol = 1e-10 * np.abs(lam)
        stable = lam >= -tol
        omega = np.where(lam > tol, np.sqrt(np.where(lam > tol, lam, 0.0)), 0.0)
    return omega, stable


def constant_equilibria(system, angle: bool) -> list[float] | None:
    """The equilibria of a one-coordinate derivation when they do not depend on the values
    (sympy's roots are numbers), as the numeric search gives them (angles wrapped to
    (-pi, pi], sorted by size, the positive first); ``None`` otherwise."""
    import sympy

    from . import lagrange_equations as lagrange
    q = system.symbols.q[0]
    equations = [e for e in system.static if e != 0]
    if not equations or not lagrange.solvable(equations, [q]):
        return None  # (sympy would list the rest position only: the search finds the rest)
    found = lagrange.symbolic_equilibria(system)
    if not found:
        return None
    points = []
    for f in found:
        value = sympy.sympify(f.get(q, 0))
        if value.free_symbols:
            return None
        x = float(value)
        if not math.isfinite(x):
            return None
        if angle:
            x = math.remainder(x, 2 * math.pi)
            if x <= -math.pi + 1e-12:
                x = math.pi
        if abs(x) < 1e-12:
            x = 0.0
        if any(abs(x - y) <= 1e-7 * max(1.0, abs(x)) for y in points):
            continue
        points.append(x)
    points.sort(key=lambda v: (abs(v), -v))
    return points


def value_roots(system, angle: bool):
    """The closed-form equilibria of a one-angle derivation whose static equation factors
    into terms in ``sin(q)`` alone or ``cos(q)`` alone (``sin(q) (Omega^2 r cos(q) - g)``):
    ``sin(q) = s`` gives ``asin(s)`` and ``pi - asin(s)``, ``cos(q) = c`` gives ``+-acos(c)``
    (sympy's ``solve`` on ``q`` misses ``pi``); a list of sympy expressions in the
    parameters (a root that does not exist at some values is ``nan`` there), or ``None``."""
    import sympy

    from . import lagrange_equations as lagrange
    q = system.symbols.q[0]
    equations = [e for e in system.static if e != 0]
    if not angle or len(equations) != 1 or lagrange.free_coordinates(system):
        return None
    S, C = sympy.Dummy("S"), sympy.Dummy("C")
    roots = []
    for factor, _power in sympy.factor_list(sympy.factor(equations[0]))[1]:
        if not factor.has(q):
            continue
        f = factor.subs({sympy.sin(q): S, sympy.cos(q): C})
        if f.has(q) or (f.has(S) and f.has(C)):
            return None
        x = S if f.has(S) else C
        try:
            found = sympy.solve(f, x, check=False, simplify=False)
        except (NotImplementedError, ValueError, TypeError):
            return None
        if not found or any(v.has(q) for v in found):
            return None
        for v in found:
            roots += [sympy.asin(v), sympy.pi - sympy.asin(v)] if x is S else \
                [sympy.acos(v), -sympy.acos(v)]
    return roots or None


def root_columns(rootf, args, n: int):
    """The ``(n, k)`` candidates of ``rootf(*args)`` (a generated list of closed forms, a
    constant one a scalar)."""
    with np.errstate(all="ignore"):
        found = rootf(*args)
    return np.column_stack([np.broadcast_to(np.asarray(c, dtype=float), (n,)) for c in found])


def equilibria_rows(candidates, angle: bool):
    """The equilibria of each row from the columns ``candidates`` (``(n, k)``; ``nan``: no
    root there), as the numeric search gives them: angles wrapped to (-pi, pi], ``|q| <
    1e-12`` made 0, a root within ``1e-7 max(1, |q|)`` of an earlier one dropped, sorted by
    size, the positive first; ``(roots, count)``: ``(n, k)`` with ``nan`` after each row's
    ``count`` roots.

    >>> import numpy as np
    >>> equilibria_rows(np.array([[0.0, -np.pi, 1.0, -1.0]]), True)
    (array([[ 0.        ,  1.        , -1.        ,  3.14159265]]), array([4]))
    """
    x = np.array(candidates, dtype=float)
    with np.errstate(all="ignore"):
        x[~np.isfinite(x)] = np.nan
        if angle:
            turn = 2 * math.pi
            x = np.where(np.abs(x) > math.pi, x - turn * np.round(x / turn), x)
            x = np.where(x <= -math.pi + 1e-12, math.pi, x)
        x = np.where(np.abs(x) < 1e-12, 0.0, x)
        for j in range(1, x.shape[1]):
            near = np.zeros(x.shape[0], dtype=bool)
            for i in range(j):
                near |= np.abs(x[:, j] - x[:, i]) <= 1e-7 * np.maximum(1.0, np.abs(x[:, j]))
            x[near, j] = np.nan
        missing = np.isnan(x)
        order = np.lexsort((np.where(missing, np.inf, -x), np.where(missing, np.inf, np.abs(x))),
                           axis=-1)
    x = np.take_along_axis(x, order, axis=-1)
    return x, (~missing).sum(axis=1)
