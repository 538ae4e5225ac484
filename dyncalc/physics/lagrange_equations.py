"""Lagrange's equations with sympy: equations of motion, equilibria, linearisation.

For coordinates ``q`` with kinetic energy ``T(q, q', t)``, potential ``V(q, t)``, Rayleigh
dissipation ``D(q, q')`` and generalized forces ``Q``::

    E_i = d/dt(dT/dq_i') - dT/dq_i + dV/dq_i + dD/dq_i' - Q_i = 0

The total time derivative is taken term by term (``d/dt f = sum f_q q' + f_q' q'' + f_t``),
``E`` is linear in the accelerations, ``E = A q'' + b``, and solved ``q'' = -A^-1 b``
(Goldstein, *Classical Mechanics*, 3rd ed., 1.4; Gross et al., *Engineering Mechanics 3*,
2nd ed., 4.3). Equilibria solve ``E(q, 0, 0) = 0`` with the terms that depend on ``t`` alone
(a prescribed forcing) left out; the linearisation about one is ``M = A``, ``K = dE/dq``
there, and ``omega^2`` the eigenvalues of ``M^-1 K``.

Only ``eom`` imports this module (sympy is heavy).
"""
from __future__ import annotations

import math

import sympy

from ..errors import PhysicsError
from ..lazy import numpy as np
from .symbolic import Symbols

__all__ = ["System", "derive", "linearise", "numeric_equilibria", "symbolic_equilibria",
           "frequencies", "stability_of", "solvable", "free_coordinates"]

#: Size (sympy's count_ops) above which an acceleration is only cancelled, not simplified.
SIMPLIFY_LIMIT = 400


class System:
    """The derived equations: ``equations`` (``E_i``, each = 0), ``mass`` (``A``),
    ``accelerations`` (``q_i''`` solved), ``static`` (``E`` at rest, forcing in ``t``
    dropped), ``forced`` (whether terms in ``t`` were dropped)."""

    def __init__(self, symbols: Symbols, equations, mass, accelerations, static, forced):
        self.symbols, self.equations, self.mass = symbols, equations, mass
        self.accelerations, self.static, self.forced = accelerations, static, forced


def _ddt(expr, s: Symbols):
    out = sympy.diff(expr, s.t)
    for q, qd, qdd in zip(s.q, s.qd, s.qdd):
        out += sympy.diff(expr, q) * qd + sympy.diff(expr, qd) * qdd
    return out


def _tidy(expr):
    """The shortest of the expression, its simplified and its factored forms (only
    cancelled when it is large: simplify's cost grows fast with size)."""
    if sympy.count_ops(expr) > SIMPLIFY_LIMIT:
        return sympy.cancel(expr)
    forms = [expr, sympy.simplify(expr)]
    forms.append(sympy.factor(forms[1]))
    return min(forms, key=lambda f: (sympy.count_ops(f), len(str(f))))


def solvable(equations, unknowns) -> bool:
    """Whether sympy's ``solve`` is worth asking (it can run for minutes otherwise): one
    unknown that appears only algebraically or only inside sin/cos/tan of itself, or
    polynomial equations in two unknowns."""
    if len(unknowns) == 1:
        q = unknowns[0]
        for e in equations:
            plain = e.replace(sympy.sin, lambda a: sympy.Dummy() if a == q else sympy.sin(a))
            plain = plain.replace(sympy.cos, lambda a: sympy.Dummy() if a == q else sympy.cos(a))
            plain = plain.replace(sympy.tan, lambda a: sympy.Dummy() if a == q else sympy.tan(a))
            if plain.has(q) and not e.is_polynomial(q):
                return False
        return True
    return len(unknowns) == 2 and all(e.is_polynomial(*unknowns) for e in equations)


def derive(s: Symbols, T, V, D=None, Q=None) -> System:
    """Lagrange's equations of ``T``, ``V`` (``D``, ``Q``: a list per coordinate, or None)."""
    n = len(s.q)
    D = sympy.Integer(0) if D is None else D
    Q = [sympy.Integer(0)] * n if Q is None else Q
    equations = []
    for i in range(n):
        e = (_ddt(sympy.diff(T, s.qd[i]), s) - sympy.diff(T, s.q[i]) + sympy.diff(V, s.q[i])
             + sympy.diff(D, s.qd[i]) - Q[i])
        equations.append(e)
    mass = sympy.Matrix(n, n, lambda i, j: sympy.diff(equations[i], s.qdd[j]))
    if any(sympy.diff(mass[i, j], x) != 0 for i in range(n) for j in range(n)
           for x in s.qdd):
        raise PhysicsError("the equations are not linear in the accelerations: T must be "
                           "quadratic in the rates")
    if mass.det() == 0:
        raise PhysicsError("the mass matrix d2T/dq'dq' is singular: some coordinate carries "
                           "no kinetic energy (check --T and --coords)")
    zero = {x: 0 for x in s.qdd}
    rest = sympy.Matrix([-e.subs(zero) for e in equations])
    if n == 1:
        solved = [rest[0] / mass[0, 0]]
    else:
        solved = list(mass.LUsolve(rest))
    accelerations = [_tidy(a) for a in solved]
    at_rest = {**zero, **{x: 0 for x in s.qd}}
    static, forced = [], False
    for e in equations:
        e = e.subs(at_rest)
        if e.has(s.t):
            terms = sympy.Add.make_args(sympy.expand(e))
            kept = [term for term in terms if not term.has(s.t)]
            if len(kept) != len(terms):
                forced = True
            e = sympy.Add(*kept)
        static.append(e)
    return System(s, equations, mass, accelerations, static, forced)


def linearise(system: System, point: dict):
    """``(M, K)`` about ``point`` (coordinate symbol -> value): sympy matrices."""
    s = system.symbols
    n = len(s.q)
    rest = {**{x: 0 for x in s.qd}, **{x: 0 for x in s.qdd}}
    M = system.mass.subs(rest).subs(point)
    K = sympy.Matrix(n, n, lambda i, j: sympy.diff(system.static[i], s.q[j])).subs(point)
    return M, K


def free_coordinates(system: System) -> list[int]:
    """Indices of coordinates absent from every static equation (a drift: any value)."""
    s = system.symbols
    return [i for i, q in enumerate(s.q) if not any(e.has(q) for e in system.static)]


def symbolic_equilibria(system: System) -> list[dict] | None:
    """The equilibria sympy's ``solve`` finds (coordinate symbol -> expression); where it
    cannot be asked (the static equations mix a coordinate with its sine), the rest position
    ``q = 0`` when it is one, else None."""
    s = system.symbols
    free = set(free_coordinates(system))
    unknowns = [q for i, q in enumerate(s.q) if i not in free]
    equations = [e for e in system.static if e != 0]
    if not unknowns:
        return [] if equations else [{}]
    if not solvable(equations, unknowns):
        zero = {q: 0 for q in unknowns}
        if all(sympy.simplify(e.subs(zero)) == 0 for e in equations):
            return [zero]
        return None
    try:
        # check=False: sympy's own check simplifies every root at length (seconds); the
        # roots of these forms (polynomials, or sines and cosines of one unknown) are exact
        found = sympy.solve(equations, unknowns, dict=True, check=False, simplify=False)
    except (NotImplementedError, ValueError, TypeError):
        return None
    return [f for f in found if all(v.is_real is not False for v in f.values())]


def numeric_equilibria(system: System, values: dict, angles: list[bool],
                       scales: list[float]) -> list[list[float]]:
    """Every equilibrium found from a grid of starts (angles over a turn, lengths over a few
    decades of ``scales``), each polished and checked, angles wrapped to (-pi, pi]; coordinates
    free of the static equations are 0. ``values`` maps parameter symbols to floats."""
    from scipy.optimize import root

    s = system.symbols
    free = set(free_coordinates(system))
    index = [i for i in range(len(s.q)) if i not in free]
    unknowns = [s.q[i] for i in index]
    equations = [e.subs(values).subs({s.q[i]: 0 for i in free}) for e in system.static]
    if not index:
        return [] if any(e != 0 for e in equations) else [[0.0] * len(s.q)]
    equations = [e for e in equations if e != 0] or [sympy.Integer(0)]
    if any(e.free_symbols - set(unknowns) for e in equations):
        missing = sorted(str(x) for e in equations for x in e.free_symbols - set(unknowns))
        raise PhysicsError(f"the equilibria need a value for {', '.join(missing)}")
    jac = sympy.Matrix(equations).jacobian(unknowns)
    f = sympy.lambdify(unknowns, equations, "math")
    J = sympy.lambdify(unknowns, jac.tolist(), "math")
    grids = []
    for i in index:
        if angles[i]:
            grids.append([-math.pi + k * math.pi / 6 for k in range(12)] + [math.pi / 2 * 0.99])
        else:
            sc = scales[i]
            grids.append([0.0] + [sg * sc * d for d in (0.01, 0.1, 1.0, 10.0) for sg in (1, -1)])
    starts = [[]]
    for g in grids:
        starts = [p + [x] for p in starts for x in g]
    found: list[list[float]] = []
    square = len(equations) == len(unknowns)

    def residual(x):
        return np.array(f(*x), dtype=float)

    def jacobian(x):
        return np.array(J(*x), dtype=float)

    periodic = [_periodic(equations, q) for q in unknowns]
    for x0 in starts:
        try:
            if square:
                sol = root(residual, x0, jac=jacobian, method="hybr", tol=1e-13)
            else:
                sol = root(residual, x0, jac=jacobian, method="lm", tol=1e-13)
        except (ValueError, ZeroDivisionError, OverflowError, FloatingPointError):
            continue
        x = list(sol.x)
        if not all(math.isfinite(v) for v in x):
            continue
        for k, i in enumerate(index):
            if angles[i] and periodic[k]:
                x[k] = math.remainder(x[k], 2 * math.pi)
                if x[k] <= -math.pi + 1e-12:
                    x[k] = math.pi
            if abs(x[k]) > 1e6 * (math.pi if angles[i] else scales[i]):
                break
        else:
            try:
                r = residual(x)
                size = float(np.max(np.abs(jacobian(x))))
            except (ValueError, ZeroDivisionError, OverflowError):
                continue
            reach = max([1.0] + [abs(x[k]) / scales[i] for k, i in enumerate(index)
                                 if not angles[i]])
            if not np.all(np.abs(r) <= 1e-9 * max(size, 1e-300) * reach):
                continue
            for k, i in enumerate(index):
                if abs(x[k]) < 1e-12 * (1.0 if angles[i] else scales[i]):
                    x[k] = 0.0
            if any(all(abs(a - b) <= 1e-7 * max(1.0, abs(a)) for a, b in zip(x, y))
                   for y in found):
                continue
            found.append(x)
    out = []
    for x in found:
        full = [0.0] * len(s.q)
        for k, i in enumerate(index):
            full[i] = x[k]
        out.append(full)
    out.sort(key=lambda p: (sum(abs(v) for v in p), [-v for v in p]))
    return out


def _periodic(equations, q) -> bool:
    """Whether the equations repeat when ``q`` turns once (a spring wound up does not)."""
    shifted = [e.subs(q, q + 2 * sympy.pi) for e in equations]
    return all(sympy.simplify(sympy.expand_trig(a - b)) == 0 for a, b in zip(shifted, equations))


def frequencies(M, K) -> tuple[list[float], bool]:
    """The natural angular frequencies (ascending) of numeric ``M``, ``K``, and whether the
    equilibrium is stable (no negative eigenvalue of ``M^-1 K``).

    Both matrices are first scaled by ``D = diag(M_ii^-1/2)`` (``D K D``, ``D M D``: the
    same eigenvalues, a unit diagonal of ``M``), so entries far apart in size (a mass of
    1e300 kg beside one of 1e5) do not overflow the eigenvalue solver; an eigenvalue that is
    still not finite is refused rather than read as stable."""
    from scipy.linalg import eigvals

    Mn = np.array(M.tolist(), dtype=float)
    Kn = np.array(K.tolist(), dtype=float)
    if not (np.isfinite(Mn).all() and np.isfinite(Kn).all()):
        raise PhysicsError("the linearised mass or stiffness matrix overflows at these values "
                           "(an entry beyond 1.8e308 in SI units)")
    diagonal = np.diag(Mn)
    if (diagonal > 0).all():
        with np.errstate(all="ignore"):
            d = 1 / np.sqrt(diagonal)
            Ms, Ks = Mn * d[:, None] * d[None, :], Kn * d[:, None] * d[None, :]
        if np.isfinite(Ms).all() and np.isfinite(Ks).all():  # (else as given)
            Mn, Kn = Ms, Ks
    with np.errstate(all="ignore"):  # (an overflow is refused just below)
        lam = eigvals(Kn, Mn)
    if not np.isfinite(lam).all():
        raise PhysicsError("the natural frequencies overflow at these values (an eigenvalue "
                           "of M^-1 K beyond 1.8e308 in SI units)")
    lam = np.sort(lam.real)
    scale = float(np.max(np.abs(lam))) if lam.size else 0.0
    tol = 1e-10 * scale
    stable = bool(np.all(lam >= -tol))
    return [math.sqrt(v) if v > tol else 0.0 for v in lam], stable


def stability_of(M, K):
    """True, False or None (undecided) for symbolic ``M``, ``K`` with positive parameters:
    stable when ``M^-1 K`` is positive definite (Sylvester's criterion on ``K`` and ``M``)."""
    n = M.shape[0]

    def sign(expr):  # the assumptions first; simplify only what stays small
        known = expr.is_nonnegative if n == 1 else expr.is_positive
        if known is None and sympy.count_ops(expr) <= 40:
            expr = sympy.simplify(expr)
            known = expr.is_nonnegative if n == 1 else expr.is_positive
        return known, expr
    try:
        if n == 1:
            return sign(K[0, 0] / M[0, 0])[0]
        minors = [sign(K[:k, :k].det())[1] for k in range(1, n + 1)]
        if all(m.is_positive for m in minors):
            return True
        if any(m.is_negative for m in minors):  # interlacing: K has a negative eigenvalue
            return False
    except (TypeError, ValueError):
        return None
    return None
