"""Several degrees of freedom: natural frequencies and mode shapes of ``M x'' + C x' + K x = 0``.

SI arrays in, a :class:`Modes` record out (the command ``modes`` checks units; this module
only sees numbers). scipy is imported here, inside the functions, and nowhere on the paths of
the other commands.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapter 4 (E4.14 to E4.19) and Chapter 5.
.. [2] Caughey, T. K., O'Kelly, M. E. J., "Classical normal modes in damped linear dynamic
   systems", J. Appl. Mech. 32 (1965) 583-588.
"""
from __future__ import annotations

import math

from ..errors import InputError
from ..lazy import numpy as np
from ..records import Record

__all__ = ["Modes", "solve_modes", "SYMMETRY_RTOL", "ZERO_RTOL", "PROPORTIONAL_RTOL"]

#: Two mirrored entries may differ by this share of the matrix's largest entry.
SYMMETRY_RTOL = 1e-9
#: An eigenvalue ``omega^2`` within this share of the largest one is a rigid-body mode (0);
#: one below minus this share makes K indefinite (the system is unstable).
ZERO_RTOL = 1e-10
#: The modal damping matrix ``Phi^T C Phi`` counts as diagonal (proportional damping) when
#: its off-diagonal entries are within this share of its largest entry.
PROPORTIONAL_RTOL = 1e-8
#: Mode components below this share of the largest are shown as 0 (rounding of eigh).
_COMPONENT_FLOOR = 2.0 ** -46


class Modes(Record):
    """The modes of one system (SI): ``omega`` (rad/s, ascending), ``shapes`` (one column per
    mode, normalised), ``modal_mass`` and ``modal_stiffness`` (per mode, in the unit of the
    M and K diagonal entry of the mode's reference coordinate: ``reference[i]``, the component
    that is 1 or the largest), ``zeta`` and ``omega_d`` (with C; ``nan`` where a mode has
    none), ``proportional`` (None without C), ``notes`` (sentences for the user),
    ``eigenvalues`` (``omega^2`` before snapping), ``char_poly`` the coefficients of
    ``det(K - lambda M)`` in descending powers of ``lambda = omega^2`` (n <= 3)."""

    __slots__ = ("omega", "shapes", "modal_mass", "modal_stiffness", "reference", "zeta",
                 "omega_d", "proportional", "notes", "eigenvalues", "char_poly")

    def __init__(self, **values):
        for name in self.__slots__:
            setattr(self, name, values.get(name))


def _check_symmetric(A, name: str) -> None:
    scale = float(np.max(np.abs(A))) if A.size else 0.0
    gap = np.abs(A - A.T)
    worst = float(np.max(gap)) if A.size else 0.0
    if worst > SYMMETRY_RTOL * scale:
        i, j = np.unravel_index(int(np.argmax(gap)), A.shape)
        i, j = (i, j) if i < j else (j, i)
        raise InputError(f"{name} is not symmetric: row {i + 1}, column {j + 1} is "
                         f"{A[i, j]:.6g} but row {j + 1}, column {i + 1} is {A[j, i]:.6g} (in "
                         f"SI; mirrored entries may differ by at most {SYMMETRY_RTOL:g} of the "
                         f"largest entry)")


def _symmetric(A):
    return (A + A.T) / 2.0


def solve_modes(M, K, C=None, *, normalize: str = "max", names=("--M", "--K", "--C")) -> Modes:
    """Natural frequencies and mode shapes of ``M x'' + K x = 0`` (and, with ``C``, the modal
    damping of ``M x'' + C x' + K x = 0``).

    .. math:: K \\phi_i = \\omega_i^2 M \\phi_i, \\qquad
              m_i = \\phi_i^T M \\phi_i, \\quad k_i = \\phi_i^T K \\phi_i = \\omega_i^2 m_i

    solved as a generalized symmetric eigenproblem (``scipy.linalg.eigh``, LAPACK's
    ``sygvd``: Cholesky of M, then a symmetric tridiagonal solve).

    Parameters
    ----------
    M : array (n, n)
        Mass matrix in SI (kg, kg*m, kg*m^2 by coordinate pair): symmetric, positive definite.
    K : array (n, n)
        Stiffness matrix in SI (N/m, N/rad, N*m/rad): symmetric, positive semi-definite (a
        zero eigenvalue is a rigid-body mode, ``omega_i = 0``).
    C : array (n, n), optional
        Viscous damping matrix in SI: symmetric, positive semi-definite.
    normalize : {"max", "mass"}
        ``max``: the largest component of each mode is +1; ``mass``: unit modal mass
        (``phi^T M phi = 1``, largest component positive).
    names : the options the matrices came from, for the messages.

    Returns
    -------
    Modes

    Notes
    -----
    Symmetry is checked to :data:`SYMMETRY_RTOL` of the largest entry (then the matrices are
    symmetrised); eigenvalues within :data:`ZERO_RTOL` of the largest are rigid-body modes
    (snapped to 0, with a note). With C, the damping is proportional when ``Phi^T C Phi`` is
    diagonal (Caughey's condition ``C M^-1 K = K M^-1 C`` [2], checked on the modes, to
    :data:`PROPORTIONAL_RTOL`): then ``zeta_i = c_i / (2 omega_i m_i)`` and
    ``omega_d_i = omega_i sqrt(1 - zeta_i^2)``. Otherwise the modes are complex: the
    eigenvalues ``s = -zeta omega +- i omega_d`` of the first-order (state-space) form
    ``[[0, I], [-K, -C]] z = s [[I, 0], [0, M]] z`` give zeta_i and omega_d_i (``scipy.linalg.eig``),
    matched to the undamped modes by nearest frequency.

    Examples
    --------
    Three equal masses between two walls, four equal springs (a fixed-fixed chain):
    ``omega_j = 2 sqrt(k/m) sin(j pi / 8)``.

    >>> K = np.array([[2., -1, 0], [-1, 2, -1], [0, -1, 2]]) * 100.0
    >>> out = solve_modes(np.eye(3), K)
    >>> [round(float(w), 9) for w in out.omega]
    [7.653668647, 14.142135624, 18.47759065]
    >>> out.shapes[:, 1].tolist()
    [1.0, 0.0, -1.0]
    """
    from scipy import linalg

    M = np.asarray(M, dtype=float)
    K = np.asarray(K, dtype=float)
    n = M.shape[0]
    _check_symmetric(M, names[0])
    _check_symmetric(K, names[1])
    M, K = _symmetric(M), _symmetric(K)
    mass_eigs = linalg.eigvalsh(M)
    if not mass_eigs[0] > ZERO_RTOL * abs(mass_eigs[-1]):
        raise InputError(f"{names[0]} is not positive definite (its smallest eigenvalue is "
                         f"{mass_eigs[0]:.6g} in SI, its largest {mass_eigs[-1]:.6g}): every "
                         f"motion of the coordinates must carry kinetic energy")
    lam, V = linalg.eigh(K, M)
    top = max(abs(float(lam[-1])), abs(float(lam[0])))
    notes: list[str] = []
    if lam[0] < -ZERO_RTOL * top:
        raise InputError(f"{names[1]} is not positive semi-definite: K v = omega^2 M v has the "
                         f"eigenvalue omega^2 = {lam[0]:.6g} 1/s^2 < 0, so the system is "
                         f"unstable about this position (no oscillation)")
    rigid = np.abs(lam) <= ZERO_RTOL * top
    if top == 0.0:
        rigid[:] = True
    count = int(np.sum(rigid))
    if count:
        modes = ", ".join(f"omega_{i + 1}" for i in np.flatnonzero(rigid))
        notes.append(f"{modes} = 0: {'a rigid-body mode' if count == 1 else 'rigid-body modes'}"
                     f" (an eigenvalue omega^2 within {ZERO_RTOL:g} of the largest is taken "
                     f"as zero)")
    lam_clean = np.where(rigid, 0.0, lam)
    omega = np.sqrt(lam_clean)
    shapes, reference = _normalised(V, normalize)
    modal_mass = np.sum(shapes * (M @ shapes), axis=0)
    modal_stiffness = np.sum(shapes * (K @ shapes), axis=0)
    if normalize == "mass":
        modal_mass = np.ones(n)
        modal_stiffness = lam_clean.copy()
    modal_stiffness = np.where(rigid, 0.0, modal_stiffness)
    out = Modes(omega=omega, shapes=shapes, modal_mass=modal_mass,
                modal_stiffness=modal_stiffness, reference=reference, notes=notes,
                eigenvalues=lam, proportional=None,
                char_poly=_char_poly(M, lam) if n <= 3 else None)
    if C is not None:
        _damping(out, M, K, np.asarray(C, dtype=float), V, lam_clean, rigid, names[2])
    return out


def _normalised(V, normalize: str):
    """The columns of ``V`` (mass-normalised by eigh) scaled: largest component +1 (``max``)
    or kept at unit modal mass with the largest component positive (``mass``); tiny
    components set to 0. Returns ``(shapes, reference)``: the index of each mode's largest
    component."""
    reference = np.argmax(np.abs(V), axis=0)
    cols = np.arange(V.shape[1])
    pivot = V[reference, cols]
    if normalize == "max":
        shapes = V / pivot
    else:
        shapes = V * np.sign(pivot)
    largest = np.abs(shapes[reference, cols])
    shapes = np.where(np.abs(shapes) < _COMPONENT_FLOOR * largest, 0.0, shapes) + 0.0
    if normalize == "max":
        shapes[reference, cols] = 1.0
    return shapes, reference


def _char_poly(M, lam):
    """Coefficients of ``det(K - lambda M)`` in descending powers of ``lambda``:
    ``(-1)^n det(M) prod(lambda - lambda_i)``."""
    n = M.shape[0]
    return (-1.0) ** n * float(np.linalg.det(M)) * np.poly(lam)


def _damping(out: Modes, M, K, C, V, lam, rigid, name: str) -> None:
    """Fill ``zeta``, ``omega_d`` and ``proportional`` of ``out``."""
    from scipy import linalg

    n = M.shape[0]
    _check_symmetric(C, name)
    C = _symmetric(C)
    c_eigs = linalg.eigvalsh(C)
    if c_eigs[0] < -ZERO_RTOL * max(abs(c_eigs[-1]), abs(c_eigs[0])):
        raise InputError(f"{name} is not positive semi-definite (its smallest eigenvalue is "
                         f"{c_eigs[0]:.6g} in SI): negative damping feeds energy in")
    modal = V.T @ C @ V          # mass-normalised modes: c_i / m_i on the diagonal
    off = modal - np.diag(np.diag(modal))
    scale = float(np.max(np.abs(modal))) if n else 0.0
    zeta = np.full(n, math.nan)
    omega_d = np.full(n, math.nan)
    omega = out.omega
    if float(np.max(np.abs(off))) <= PROPORTIONAL_RTOL * scale or scale == 0.0:
        out.proportional = True
        for i in range(n):
            c = float(modal[i, i])
            if rigid[i]:
                if c > 0.0:
                    out.notes.append(f"mode {i + 1} is a rigid-body mode: it has no damping "
                                     f"ratio (its motion decays at the rate c/m = {c:.6g} 1/s)")
                continue
            zeta[i] = c / (2.0 * omega[i])
            omega_d[i] = _damped_frequency(omega[i], zeta[i], i, out.notes)
    else:
        out.proportional = False
        out.notes.append("the damping is not proportional (Phi^T C Phi is not diagonal: "
                         "C M^-1 K != K M^-1 C), so the modes are complex; zeta_i and "
                         "omega_d_i come from the eigenvalues s = -zeta omega +- i omega_d of "
                         "the state-space form, and mode_i are the undamped mode shapes")
        Z, I = np.zeros((n, n)), np.eye(n)
        A = np.block([[Z, I], [-K, -C]])
        B = np.block([[I, Z], [Z, M]])
        s = linalg.eigvals(A, B)
        s = s[np.isfinite(s)]
        scale_s = float(np.max(np.abs(s))) if s.size else 0.0
        complex_ = sorted((z for z in s if z.imag > ZERO_RTOL * scale_s), key=abs)
        real = sorted(float(z.real) for z in s if abs(z.imag) <= ZERO_RTOL * scale_s)
        free = [i for i in range(n)]
        for z in complex_:
            if not free:
                break
            i = min(free, key=lambda k: abs(omega[k] - abs(z)))
            free.remove(i)
            zeta[i] = -z.real / abs(z)
            omega_d[i] = z.imag
        if real:
            shown = ", ".join(f"{r:.6g}" for r in real)
            out.notes.append(f"{len(real)} real eigenvalue{'s' if len(real) != 1 else ''} "
                             f"s = {shown} 1/s (overdamped or rigid-body motion): "
                             f"{'modes' if len(free) != 1 else 'mode'} "
                             f"{', '.join(str(i + 1) for i in free)} "
                             f"{'have' if len(free) != 1 else 'has'} no damped frequency")
    out.zeta, out.omega_d = zeta, omega_d


def _damped_frequency(omega: float, zeta: float, i: int, notes: list[str]) -> float:
    from .outcome import CRITICAL_BAND

    gap = (1.0 - zeta) * (1.0 + zeta)
    if abs(gap) <= CRITICAL_BAND:
        notes.append(f"mode {i + 1} is critically damped (zeta_{i + 1} = 1): no damped "
                     f"frequency")
        return math.nan
    if gap < 0.0:
        notes.append(f"mode {i + 1} is overdamped (zeta_{i + 1} = {zeta:.6g} > 1): no damped "
                     f"frequency")
        return math.nan
    return omega * math.sqrt(gap)
