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

__all__ = ["Modes", "solve_modes", "rigid_note", "SYMMETRY_RTOL", "ZERO_RTOL",
           "PROPORTIONAL_RTOL"]

#: Two mirrored entries may differ by this share of the matrix's largest entry.
SYMMETRY_RTOL = 1e-9
#: An eigenvalue ``omega^2`` within this share of the terms that sum to it
#: (``sum |psi_j| |K_jk| |psi_k|``) is a rigid-body mode (0); one below minus this share makes
#: K indefinite (the system is unstable). Also M's smallest eigenvalue against its largest.
ZERO_RTOL = 1e-10
#: The modal damping matrix ``Phi^T C Phi`` counts as diagonal (proportional damping) when
#: its off-diagonal entries are within this share of its largest entry.
PROPORTIONAL_RTOL = 1e-8
#: The note of a system whose damping is not proportional (complex modes).
NON_PROPORTIONAL_NOTE = (
    "the damping is not proportional (Phi^T C Phi is not diagonal: C M^-1 K != K M^-1 C), so "
    "the modes are complex; zeta_i and omega_d_i come from the eigenvalues s = -zeta omega +- "
    "i omega_d of the state-space form, and mode_i are the undamped mode shapes")
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
    with np.errstate(over="ignore"):
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
    """The mean of A and its transpose (halves first: no overflow near 1.8e308; an entry
    already equal to its mirror kept exactly, subnormals included)."""
    return np.where(A == A.T, A, A / 2.0 + A.T / 2.0)


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
    symmetrised). The problem is solved scaled, by powers of 2 (exactly): ``D M D`` with ``D``
    about ``diag(M)^-1/2`` has a diagonal near 1, and ``D K D`` is divided by the even power of
    2 that brings its largest entry near 1 (a change of time unit), each group of coordinates
    no entry couples on its own, so that entries from 1e-300 to 1e300 lose no digits;
    only a result beyond float64 is refused. An eigenvalue within :data:`ZERO_RTOL` of the
    terms of ``psi^T K psi`` that sum to it is a rigid-body mode (snapped to 0, with a note). With C, the damping is proportional when ``Phi^T C Phi`` is
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
    if C is not None:
        C = np.asarray(C, dtype=float)
        _check_symmetric(C, names[2])
        C = _symmetric(C)
    d = _diagonal_scale(M, names[0])
    Ms, _ = _scaled(M, d, 0)
    mass_eigs = linalg.eigvalsh(Ms) if bool(np.all(np.isfinite(Ms))) else None
    if mass_eigs is None or not mass_eigs[0] > ZERO_RTOL * abs(mass_eigs[-1]):
        _refuse_mass(M, names[0])
    if C is not None:
        _check_damping(C, d, names[2])
    parts = [_Part(index, M, K, C, d, Ms, names) for index in _components(M, K, C)]
    # every mode: (omega in SI, the part, its column there), ascending (stable: part order)
    order = sorted(((float(w), p, j) for p in parts for j, w in enumerate(p.omega)),
                   key=lambda item: item[0])
    omega = np.array([w for w, _, _ in order])
    V = np.zeros((n, n))
    rigid = np.zeros(n, dtype=bool)
    eigenvalues = np.empty(n)
    for col, (_, p, j) in enumerate(order):
        V[p.index, col] = p.V[:, j]
        rigid[col] = p.rigid[j]
        eigenvalues[col] = p.eigenvalues[j]
        p.number[j] = col
    notes: list[str] = []
    if rigid.any():
        notes.append(rigid_note(np.flatnonzero(rigid).tolist()))
    with np.errstate(over="ignore", under="ignore", divide="ignore"):
        shapes, reference = _normalised(V, normalize)
        pivot = np.abs(V[reference, np.arange(n)])
        if normalize == "mass":
            modal_mass = np.ones(n)
            modal_stiffness = omega ** 2
        else:
            modal_mass = (1.0 / pivot) ** 2       # (V/pivot)^T M (V/pivot), V^T M V = I
            modal_stiffness = (omega / pivot) ** 2
    modal_stiffness = np.where(rigid, 0.0, modal_stiffness)
    _refuse_overflow(omega, modal_mass, modal_stiffness)
    char_poly = None
    if n <= 3 and bool(np.all(np.isfinite(eigenvalues))):
        with np.errstate(all="ignore"):
            char_poly = _char_poly(M, eigenvalues)
        if not bool(np.all(np.isfinite(char_poly))):
            char_poly = None
    out = Modes(omega=omega, shapes=shapes, modal_mass=modal_mass,
                modal_stiffness=modal_stiffness, reference=reference, notes=notes,
                eigenvalues=eigenvalues, proportional=None, char_poly=char_poly)
    if C is not None:
        _damping(out, parts)
    return out


def rigid_note(indices: list[int]) -> str:
    """The note of the rigid-body modes at ``indices`` (0-based, ascending): ``omega_1 = 0: a
    rigid-body mode (...)``."""
    modes = ", ".join(f"omega_{i + 1}" for i in indices)
    return (f"{modes} = 0: {'a rigid-body mode' if len(indices) == 1 else 'rigid-body modes'}"
            f" (an eigenvalue omega^2 within {ZERO_RTOL:g} of the terms of K that sum to it is "
            f"taken as zero)")


def _components(M, K, C):
    """The groups of coordinates no entry of M, K or C couples to one another (index arrays,
    in order of their first coordinate): each is solved with its own time scale."""
    linked = (M != 0.0) | (K != 0.0)
    if C is not None:
        linked |= C != 0.0
    i, j = np.nonzero(linked)
    labels = np.arange(M.shape[0])
    while True:  # each coordinate takes the least label among its neighbours, to a fixed point
        new = labels.copy()
        np.minimum.at(new, i, labels[j])
        new = new[new]  # and its label's label (pointer jumping: fewer rounds on a chain)
        if np.array_equal(new, labels):
            break
        labels = new
    roots = np.unique(labels)
    if len(roots) == 1:
        return [np.arange(M.shape[0])]
    return [np.flatnonzero(labels == root) for root in roots]


class _Part:
    """One uncoupled group of coordinates (``index``), solved scaled: ``Ms = D M D`` (a
    diagonal near 1), ``Ks = D K D / 2^E`` (time in units of ``2^(-E/2)`` s, its largest entry
    ~1), ``Vs`` the eigenvectors of ``Ks v = lam Ms v``; ``omega`` (SI), ``V = D Vs`` (the
    original coordinates, ``V^T M V = I``), ``rigid``, ``eigenvalues`` (``omega^2`` in SI,
    before snapping), ``number`` (each mode's place in the whole, set by the caller)."""

    def __init__(self, index, M, K, C, d, Ms, names):
        from scipy import linalg

        self.index = index
        sub = np.ix_(index, index)
        self.Ms = Ms[sub]
        self.Ks, E = _scaled(K[sub], d[index], None)
        self.half = E // 2
        self.C = C[sub] if C is not None else None
        self.d = d[index]
        # LAPACK's divide and conquer (sygvd): at n = 500 twice as fast as scipy's default
        lam, self.Vs = linalg.eigh(self.Ks, self.Ms, driver="gvd", check_finite=False)
        # the size of the terms that sum to each eigenvalue psi^T K psi: an eigenvalue that
        # is a rounding residue of them (a rigid-body mode) is within ZERO_RTOL of it
        terms = np.sum(np.abs(self.Vs) * (np.abs(self.Ks) @ np.abs(self.Vs)), axis=0)
        if lam[0] < -ZERO_RTOL * terms[0]:
            with np.errstate(over="ignore"):
                shown = float(np.ldexp(lam[0], E))
            raise InputError(f"{names[1]} is not positive semi-definite: K v = omega^2 M v has "
                             f"the eigenvalue omega^2 = {shown:.6g} 1/s^2 < 0, so the system "
                             f"is unstable about this position (no oscillation)")
        self.rigid = (np.abs(lam) <= ZERO_RTOL * terms) | (terms == 0.0)
        self.lam = np.where(self.rigid, 0.0, lam)
        self.scaled_omega = np.sqrt(self.lam)
        with np.errstate(over="ignore", under="ignore"):
            self.omega = np.ldexp(self.scaled_omega, self.half)
            self.eigenvalues = np.ldexp(lam, E)
        self.V = self.d[:, None] * self.Vs
        self.number = [0] * len(index)


def _diagonal_scale(M, name: str):
    """``d_i``, the power of 2 nearest ``1/sqrt(M_ii)``: the diagonal scaling that gives
    ``D M D`` a diagonal between 1/2 and 2 (``D = diag(d)``), so that masses of 1e-300 and
    1e300 kg side by side lose no digits. Powers of 2 scale exactly: a system of ordinary
    scale gives the same bits as unscaled. A diagonal entry that is not positive refuses M
    (not positive definite)."""
    diagonal = np.diag(M).copy()
    if not bool(np.all(diagonal > 0.0)):
        _refuse_mass(M, name)
    _, exponent = np.frexp(diagonal)
    return np.ldexp(1.0, -(exponent // 2))


def _scaled(A, d, shift):
    """``D A D / 2^shift`` without an intermediate overflow (mantissas and exponents apart);
    ``shift`` None: the even power of 2 that brings the largest entry near 1, returned."""
    fa, ea = np.frexp(A)
    fd, ed = np.frexp(d)
    mantissa = fa * fd[:, None] * fd[None, :]
    exponent = ea + ed[:, None] + ed[None, :]
    if shift is None:
        nonzero = mantissa != 0.0
        top = int(np.max(exponent[nonzero])) if bool(np.any(nonzero)) else 0
        shift = top + (top % 2)
    with np.errstate(over="ignore", under="ignore"):
        return np.ldexp(mantissa, exponent - shift), shift


def _refuse_mass(M, name: str):
    from scipy import linalg

    with np.errstate(all="ignore"):
        eigs = linalg.eigvalsh(M)
    raise InputError(f"{name} is not positive definite (its smallest eigenvalue is "
                     f"{eigs[0]:.6g} in SI, its largest {eigs[-1]:.6g}): every motion of the "
                     f"coordinates must carry kinetic energy")


def _refuse_overflow(omega, modal_mass, modal_stiffness) -> None:
    """A frequency, modal mass or modal stiffness beyond float64 (above 1.8e308 in SI): the
    only extreme input refused."""
    for name, values in (("omega", omega), ("modal_mass", modal_mass),
                         ("modal_stiffness", modal_stiffness)):
        bad = np.flatnonzero(~np.isfinite(values))
        if len(bad):
            raise InputError(f"{name}_{int(bad[0]) + 1} overflows float64 (it exceeds "
                             f"{np.finfo(float).max:.6g} in SI): the matrices' scales are too "
                             "far apart for this result to be represented")


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


def _check_damping(C, d, name: str) -> None:
    """C positive semi-definite, checked on ``D C D`` (the same inertia, entries near 1)."""
    from scipy import linalg

    Cs, _ = _scaled(C, d, None)
    c_eigs = linalg.eigvalsh(Cs)
    if c_eigs[0] < -ZERO_RTOL * max(abs(c_eigs[-1]), abs(c_eigs[0])):
        raise InputError(f"{name} is not positive semi-definite (its smallest eigenvalue is "
                         f"{linalg.eigvalsh(C)[0]:.6g} in SI): negative damping feeds "
                         "energy in")


def _damping(out: Modes, parts: list) -> None:
    """Fill ``zeta``, ``omega_d`` and ``proportional`` of ``out``, part by part (each in its
    own time unit ``2^-half`` s)."""
    n = len(out.omega)
    out.zeta, out.omega_d = np.full(n, math.nan), np.full(n, math.nan)
    out.proportional = True
    complex_notes: list[str] = []
    for p in parts:
        Cs, _ = _scaled(p.C, p.d, p.half)
        if not bool(np.all(np.isfinite(Cs))):
            raise InputError("--C is too large against --M and --K: the damping rates "
                             "overflow float64")
        if not _damp_part(out, p, Cs, complex_notes):
            out.proportional = False
    if not out.proportional:
        out.notes.append(NON_PROPORTIONAL_NOTE)
    out.notes += complex_notes


def _damp_part(out: Modes, p: _Part, C, complex_notes: list[str]) -> bool:
    """One part's zeta and omega_d into ``out`` (at the modes' places ``p.number``); whether
    its damping is proportional."""
    from scipy import linalg

    n = len(p.index)
    omega = p.scaled_omega

    def rate(value: float) -> float:  # a scaled rate in 1/s
        with np.errstate(over="ignore", under="ignore"):
            return float(np.ldexp(value, p.half))
    modal = p.Vs.T @ C @ p.Vs          # mass-normalised modes: c_i / m_i on the diagonal
    off = modal - np.diag(np.diag(modal))
    scale = float(np.max(np.abs(modal))) if n else 0.0
    if float(np.max(np.abs(off))) <= PROPORTIONAL_RTOL * scale or scale == 0.0:
        for i in range(n):
            c, k = float(modal[i, i]), p.number[i]
            if p.rigid[i]:
                if c > 0.0:
                    out.notes.append(f"mode {k + 1} is a rigid-body mode: it has no damping "
                                     f"ratio (its motion decays at the rate c/m = "
                                     f"{rate(c):.6g} 1/s)")
                continue
            out.zeta[k] = c / (2.0 * omega[i])
            out.omega_d[k] = rate(_damped_frequency(omega[i], out.zeta[k], k, out.notes))
        return True
    Z, I = np.zeros((n, n)), np.eye(n)
    A = np.block([[Z, I], [-p.Ks, -C]])
    B = np.block([[I, Z], [Z, p.Ms]])
    s = linalg.eigvals(A, B)
    s = s[np.isfinite(s)]
    scale_s = float(np.max(np.abs(s))) if s.size else 0.0
    complex_ = sorted((z for z in s if z.imag > ZERO_RTOL * scale_s), key=abs)
    real = sorted(float(z.real) for z in s if abs(z.imag) <= ZERO_RTOL * scale_s)
    free = list(range(n))
    for z in complex_:
        if not free:
            break
        i = min(free, key=lambda k: abs(omega[k] - abs(z)))
        free.remove(i)
        out.zeta[p.number[i]] = -z.real / abs(z)
        out.omega_d[p.number[i]] = rate(z.imag)
    if real:
        shown = ", ".join(f"{rate(r):.6g}" for r in real)
        numbers = sorted(p.number[i] + 1 for i in free)
        complex_notes.append(f"{len(real)} real eigenvalue{'s' if len(real) != 1 else ''} "
                             f"s = {shown} 1/s (overdamped or rigid-body motion): "
                             f"{'modes' if len(numbers) != 1 else 'mode'} "
                             f"{', '.join(str(i) for i in numbers)} "
                             f"{'have' if len(numbers) != 1 else 'has'} no damped frequency")
    return False


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
