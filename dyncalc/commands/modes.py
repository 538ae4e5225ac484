"""``modes``: natural frequencies and mode shapes of a linear system with several degrees of
freedom (../shared/SPEC.md v2, "modes").

:func:`read` turns the texts into SI matrices: ``--M``, ``--K`` (and ``--C``) through the
matrix grammar (:mod:`dyncalc.units.matrix`), each coordinate's kind inferred from the
diagonal of M (``kg``: a translation, ``kg*m^2``: a rotation; a bare diagonal entry takes its
kind from K's diagonal, else it is a translation) and every entry checked against the
dimension its pair of coordinates implies; or, with ``--scene``, the scene's own linearised
matrices (:attr:`dyncalc.scenes.Scene.matrices`). :func:`compute` solves them
(:func:`dyncalc.physics.modes.solve_modes`) into a Result.
"""
from __future__ import annotations

from ..errors import InputError
from ..result import Entry, Explanation, Result
from ..units import (ANGULAR_RATE, COUPLING_DAMPING, COUPLING_MASS, COUPLING_STIFFNESS,
                     CYCLE_RATE, DAMPING, DIMENSIONLESS, INERTIA, MASS, STIFFNESS,
                     TORSIONAL_DAMPING, TORSIONAL_STIFFNESS)
from .record import Command, Parameter, ResultName
from .words import gather_texts

__all__ = ["COMMAND", "ModesInputs", "read", "compute", "modes", "matrix_dims"]

#: The dimension of an entry of M, K, C by the kinds of its two coordinates.
_DIMS = {
    "M": {("length", "length"): MASS, ("angle", "angle"): INERTIA, "mixed": COUPLING_MASS},
    "K": {("length", "length"): STIFFNESS, ("angle", "angle"): TORSIONAL_STIFFNESS,
          "mixed": COUPLING_STIFFNESS},
    "C": {("length", "length"): DAMPING, ("angle", "angle"): TORSIONAL_DAMPING,
          "mixed": COUPLING_DAMPING},
}
_WORD = {"length": "a translation", "angle": "a rotation"}


def matrix_dims(which: str, kinds: list[str]):
    """``dim_of(i, j) -> (Dim, why)`` for matrix ``which`` (``M``, ``K``, ``C``) of
    coordinates of ``kinds``."""
    table = _DIMS[which]
    mixed = len(set(kinds)) > 1

    def dim_of(i: int, j: int):
        a, b = kinds[i], kinds[j]
        dim = table[(a, b)] if a == b else table["mixed"]
        if not mixed:
            return dim, ""
        if i == j:
            why = f"coordinate {i + 1} is {_WORD[a]}, from the diagonal of --M"
        else:
            why = (f"coordinate {i + 1} is {_WORD[a]} and coordinate {j + 1} {_WORD[b]}, "
                   "from the diagonal of --M")
        return dim, why
    return dim_of


class ModesInputs:
    """What :func:`read` checked: the SI matrices (``C`` may be None), the coordinates'
    names and kinds, the input entries, the scene (or None) and its equilibrium, the
    normalisation, and results the scene adds (``phi2_0``)."""

    __slots__ = ("M", "K", "C", "names", "kinds", "inputs", "scene", "equilibrium",
                 "normalize", "extra", "assumed")

    def __init__(self, **values):
        for name in self.__slots__:
            setattr(self, name, values.get(name))


def _kind_of_diagonal(Mtext, Ktext, i: int) -> str:
    from ..units.grammar import format_quantity

    q = Mtext.quantity_of(i, i)
    if q is None:
        q = Ktext.quantity_of(i, i) if Ktext is not None else None
        if q is not None and q.check("[force]*[length]"):
            return "angle"
        return "length"
    if q.check("[mass]"):
        return "length"
    if q.check("[mass]*[length]**2"):
        return "angle"
    if Mtext.cells[i][i].mag is not None:
        q = q * Mtext.cells[i][i].mag
    raise InputError(f"--M row {i + 1}, column {i + 1} must be a mass (kg: coordinate "
                     f"{i + 1} a translation) or a moment of inertia (kg*m^2: a rotation); "
                     f"got {format_quantity(q)}")


def _matrix_entry(name: str, si, kinds: list[str], text: str, assumed: bool) -> Entry:
    unit = _DIMS[name][(kinds[0], kinds[0])].si if len(set(kinds)) == 1 else ""
    return Entry(name, si, None, unit=unit, text=text, assumed_si=assumed,
                 description={"M": "mass matrix", "K": "stiffness matrix",
                              "C": "damping matrix"}[name])


def read(options: dict[str, str | None], words=(), *, scene: str | None = None,
         normalize: str | None = None, strict: bool = False) -> ModesInputs:
    """The options as typed (``M``, ``K``, ``C``) and, with a scene, its ``NAME=QUANTITY``
    words -> :class:`ModesInputs`."""
    normalize = normalize or "max"
    if normalize not in ("max", "mass"):
        raise InputError(f"--normalize must be max or mass; got {normalize[:40]!r}")
    if scene is not None:
        return _read_scene(options, words, scene, normalize, strict)
    if words:
        raise InputError(f"modes takes NAME=QUANTITY words only with --scene; got "
                         f"{str(words[0])[:60]!r}")
    for name in ("M", "K"):
        if options.get(name) is None:
            raise InputError(f"modes needs --M and --K (matrices, e.g. --M '2, 0; 0, 1 kg' "
                             f"--K '300, -100; -100, 100 N/m') or --scene NAME; --{name} is "
                             "missing")
    from ..units.matrix import parse_matrix

    texts = {name: options[name] for name in ("M", "K", "C") if options.get(name) is not None}
    read_ = {name: parse_matrix(text, label=f"--{name}") for name, text in texts.items()}
    n = read_["M"].order
    for name in ("K", "C"):
        if name in read_ and read_[name].order != n:
            raise InputError(f"--{name} is {read_[name].order}x{read_[name].order} but --M is "
                             f"{n}x{n}: they need the same size (one row per coordinate)")
    kinds = [_kind_of_diagonal(read_["M"], read_["K"], i) for i in range(n)]
    inputs = {}
    arrays = {}
    assumed = False
    for name, matrix in read_.items():
        si, bare = matrix.si(matrix_dims(name, kinds), strict=strict)
        arrays[name] = si
        assumed = assumed or bare
        inputs[name] = _matrix_entry(name, si, kinds, texts[name], bare)
    names = [f"q{i + 1}" for i in range(n)]
    return ModesInputs(M=arrays["M"], K=arrays["K"], C=arrays.get("C"), names=names,
                       kinds=kinds, inputs=inputs, scene=None, equilibrium="",
                       normalize=normalize, extra={}, assumed=assumed)


def _read_scene(options, words, name: str, normalize: str, strict: bool) -> ModesInputs:
    from ..lazy import numpy as np
    from ..scenes import get_scene
    from ..scenes.runner import check_constraints, read_inputs

    scene = get_scene(name)
    if scene.matrices is None:
        from ..scenes import refuse_kinetics

        refuse_kinetics(scene.name, "modes")
        raise InputError(f"modes takes a scene with several degrees of freedom; {scene.name} "
                         f"has one: use dyncalc natural-frequency --scene {scene.name}")
    for option in ("M", "K", "C"):
        if options.get(option) is not None:
            raise InputError(f"--{option} does not go with --scene {scene.name}: the scene "
                             "gives its own matrices")
    texts, labels = gather_texts({}, words, "a scene parameter")
    prepared = read_inputs(scene, texts, labels, strict)
    if prepared.missing:
        raise InputError(f"{scene.name} needs {', '.join(prepared.missing)}; the parameters "
                         f"of {scene.name} are: {scene.signature()}")
    check_constraints(scene, prepared.si)
    lin = scene.matrices(prepared.si)
    return ModesInputs(M=np.array(lin.M, dtype=float), K=np.array(lin.K, dtype=float), C=None,
                       names=list(lin.coordinates), kinds=list(lin.kinds),
                       inputs=prepared.inputs, scene=scene, equilibrium=lin.equilibrium,
                       normalize=normalize, extra=lin.extra, assumed=False)


def compute(inputs: ModesInputs, digits: int = 6) -> Result:
    """Solve the eigenproblem and build the Result."""
    import math

    from ..physics.modes import solve_modes

    out = solve_modes(inputs.M, inputs.K, inputs.C, normalize=inputs.normalize)
    n = len(out.omega)
    results: dict[str, Entry] = {}
    coordinates = _coords(inputs)
    for i in range(n):
        results[f"omega_{i + 1}"] = Entry(f"omega_{i + 1}", float(out.omega[i]), ANGULAR_RATE,
                                          "rad/s", f"ω{i + 1}", f"angular frequency of mode "
                                                                 f"{i + 1}")
    for i in range(n):
        results[f"f_{i + 1}"] = Entry(f"f_{i + 1}", float(out.omega[i]) / (2.0 * math.pi),
                                      CYCLE_RATE, "Hz", f"f{i + 1}", f"frequency of mode {i + 1}")
    for i in range(n):
        ref = inputs.kinds[int(out.reference[i])]
        mass_dim = MASS if ref == "length" else INERTIA
        stiff_dim = STIFFNESS if ref == "length" else TORSIONAL_STIFFNESS
        results[f"mode_{i + 1}"] = Entry(f"mode_{i + 1}", out.shapes[:, i].copy(),
                                         DIMENSIONLESS, "", f"mode {i + 1}",
                                         f"shape of mode {i + 1} ({coordinates})")
        results[f"modal_mass_{i + 1}"] = Entry(
            f"modal_mass_{i + 1}", float(out.modal_mass[i]), mass_dim, mass_dim.si,
            f"m{i + 1}", f"modal mass of mode {i + 1}")
        results[f"modal_stiffness_{i + 1}"] = Entry(
            f"modal_stiffness_{i + 1}", float(out.modal_stiffness[i]), stiff_dim, stiff_dim.si,
            f"k{i + 1}", f"modal stiffness of mode {i + 1}")
    if out.zeta is not None:
        for i in range(n):
            if not math.isnan(out.zeta[i]):
                results[f"zeta_{i + 1}"] = Entry(f"zeta_{i + 1}", float(out.zeta[i]),
                                                 DIMENSIONLESS, "", f"ζ{i + 1}",
                                                 f"damping ratio of mode {i + 1}")
        for i in range(n):
            if not math.isnan(out.omega_d[i]):
                results[f"omega_d_{i + 1}"] = Entry(
                    f"omega_d_{i + 1}", float(out.omega_d[i]), ANGULAR_RATE, "rad/s",
                    f"ωd{i + 1}", f"damped angular frequency of mode {i + 1}")
    if "phi2_0" in inputs.extra:
        from ..result.kinds import result_kind

        kind = result_kind("phi2_0")
        results["phi2_0"] = Entry("phi2_0", inputs.extra["phi2_0"], kind.dim, kind.unit,
                                  kind.symbol, kind.description)
    method = "eigh" if inputs.C is None or out.proportional else "eigh+state-space"
    model = "linear" if inputs.C is None else ("proportional damping" if out.proportional
                                               else "non-proportional damping")
    result = Result("modes", results, inputs=inputs.inputs,
                    scene=inputs.scene.name if inputs.scene is not None else None,
                    model=model, method=method, warnings=list(out.notes),
                    explanation=lambda: _explain(inputs, out))
    result.extra["coordinates"] = [{"name": name, "kind": "translation" if kind == "length"
                                    else "rotation", "unit": "m" if kind == "length" else "rad"}
                                   for name, kind in zip(inputs.names, inputs.kinds)]
    result.extra["normalize"] = inputs.normalize
    if inputs.equilibrium:
        result.extra["equilibrium"] = inputs.equilibrium
    return result


def _coords(inputs: ModesInputs) -> str:
    shown = ", ".join(f"{n} [{'m' if k == 'length' else 'rad'}]"
                      for n, k in zip(inputs.names, inputs.kinds))
    return shown if len(shown) <= 60 else f"{len(inputs.names)} coordinates"


def _explain(inputs: ModesInputs, out) -> Explanation:
    from ..result import format_number

    n = len(out.omega)
    damped = inputs.C is not None
    formula = ["M q'' + C q' + K q = 0" if damped else "M q'' + K q = 0",
               "K phi_i = omega_i^2 M phi_i: the generalized symmetric eigenproblem "
               "(scipy.linalg.eigh), omega_1 <= ... <= omega_n"]
    if n <= 3:
        formula.append("det(K - omega^2 M) = 0")
    formula += ["f_i = omega_i / (2 pi)",
                "modal mass m_i = phi_i^T M phi_i, modal stiffness k_i = phi_i^T K phi_i "
                "= omega_i^2 m_i"]
    if damped and out.proportional:
        formula.append("proportional damping (Phi^T C Phi diagonal): zeta_i = phi_i^T C phi_i "
                       "/ (2 omega_i m_i), omega_d_i = omega_i sqrt(1 - zeta_i^2)")
    elif damped:
        formula.append("non-proportional damping: [[0, I], [-K, -C]] z = s [[I, 0], [0, M]] z "
                       "(scipy.linalg.eig), s = -zeta omega +- i omega_d")
    substituted = []
    if n <= 8:
        substituted += [f"M = {format_number(inputs.M, 6)}", f"K = {format_number(inputs.K, 6)}"]
        if damped:
            substituted.append(f"C = {format_number(inputs.C, 6)}")
    if out.char_poly is not None:
        terms = []
        for power, coefficient in zip(range(n, -1, -1), out.char_poly):
            lam = "" if power == 0 else ("λ" if power == 1 else f"λ^{power}")
            terms.append(f"({coefficient:.6g}){' ' + lam if lam else ''}")
        roots = ", ".join(f"{float(v):.6g}" for v in out.eigenvalues)
        substituted.append(f"det(K - λ M) = {' + '.join(terms)} = 0, λ = omega^2 [1/s^2]: "
                           f"λ = {roots}")
    for i in range(min(n, 8)):
        substituted.append(f"omega_{i + 1} = sqrt({float(out.omega[i]) ** 2:.6g} 1/s^2) = "
                           f"{float(out.omega[i]):.6g} rad/s")
    assumptions = [
        "linear: small motions about the equilibrium" + (f" ({inputs.equilibrium})"
                                                          if inputs.equilibrium else ""),
        "coordinates: " + ", ".join(f"{name} ({'translation, m' if k == 'length' else 'rotation, rad'})"
                                    for name, k in zip(inputs.names[:12], inputs.kinds[:12]))
        + (", ..." if n > 12 else ""),
        "mode shapes: components in SI (m, rad), " + (
            "the largest component +1" if inputs.normalize == "max" else
            "unit modal mass phi^T M phi = 1 (largest component positive)"),
        "symmetry checked to 1e-9 of the largest entry; an eigenvalue within 1e-10 of the "
        "terms of phi^T K phi that sum to it is a rigid-body mode (omega = 0); solved with "
        "M scaled to a diagonal near 1 (D M D, D = diag(M)^-1/2 rounded to powers of 2)",
    ]
    reference = inputs.scene.reference if inputs.scene is not None else ""
    return Explanation(formula, substituted, assumptions, reference)


def modes(options: dict[str, str | None], words=(), *, scene: str | None = None,
          normalize: str | None = None, strict: bool = False) -> Result:
    """The command: ``{"M": "2, 0; 0, 1 kg", "K": "...", "C": None}`` (and a scene's words)
    -> the Result (:func:`read`, then :func:`compute`).

    >>> r = modes({"M": "1, 0; 0, 1 kg", "K": "200, -100; -100, 200 N/m"})
    >>> round(r.results["omega_1"].si, 12), round(r.results["omega_2"].si ** 2, 9)
    (10.0, 300.0)
    """
    return compute(read(options, words, scene=scene, normalize=normalize, strict=strict))


def _run(values: dict[str, str | None], words=(), *, rtol=None, strict=False) -> Result:
    return modes({name: values.get(name) for name in ("M", "K", "C")}, words,
                 scene=values.get("scene"), normalize=values.get("normalize"), strict=strict)


def scene_names() -> list[str]:
    """The scenes ``modes --scene`` takes: those with several degrees of freedom."""
    from ..scenes import catalog

    return [s.name for s in catalog().values() if s.matrices is not None]


COMMAND = Command(
    "modes",
    "Natural frequencies and mode shapes of several degrees of freedom (M, K, C matrices).",
    """Natural frequencies omega_i (ascending), f_i, mode shapes mode_i, modal masses and
    stiffnesses of M q'' + K q = 0, from mass and stiffness matrices with units, or from a
    scene with several degrees of freedom linearised about its equilibrium. With --C also
    the modal damping ratios zeta_i and damped frequencies omega_d_i (proportional damping
    from the modes; otherwise from the complex eigenvalues, with a note).

    A matrix: rows by ';' or nested brackets, one trailing unit or a unit on each entry, or
    @FILE.csv. Each coordinate is a translation (M diagonal in kg) or a rotation (kg*m^2);
    a mixed entry is in kg*m (M), N/rad (K), N*s/rad (C). A zero eigenvalue is a rigid-body
    mode, reported as omega_i = 0. Mode shapes have their largest component +1
    (--normalize mass: unit modal mass).

    \b
    Examples:
      dyncalc modes --M "2, 0; 0, 1 kg" --K "300, -100; -100, 100 N/m"
      dyncalc modes --M "[[1.2, 0], [0, 0.8]] kg*m^2" --K "40, -40; -40, 40 kN*m/rad"
      dyncalc modes --M "1, 0; 0, 1 kg" --K "2, -1; -1, 2 kN/m" --C "4, 0; 0, 4 N*s/m"
      dyncalc modes --M @mass.csv --K @stiffness.csv --normalize mass
      dyncalc modes --scene block-disk-springs M=2kg m=1kg r=0.1m k=100N/m
    """,
    (
        Parameter("scene", None, "A scene with several degrees of freedom, linearised about "
                  "its equilibrium; its parameters as NAME=QUANTITY words.", "NAME",
                  kind="setting", choices=scene_names),
        Parameter("M", None, "Mass matrix, e.g. '2, 0; 0, 1 kg' (symmetric, positive "
                  "definite).", "MATRIX", kind="text"),
        Parameter("K", None, "Stiffness matrix, e.g. '300, -100; -100, 100 N/m' (symmetric, "
                  "positive semi-definite).", "MATRIX", kind="text"),
        Parameter("C", None, "Viscous damping matrix, e.g. '4, 0; 0, 4 N*s/m' (optional).",
                  "MATRIX", kind="text"),
        Parameter("normalize", None, "Mode shapes: largest component +1 (max) or unit modal "
                  "mass (mass).", "max|mass", default="max", kind="setting",
                  choices=("max", "mass")),
    ),
    (
        ResultName("omega_<i>", "ω", ANGULAR_RATE.si, "natural angular frequency of mode i "
                                                       "(ascending; 0 for a rigid-body mode)"),
        ResultName("f_<i>", "f", CYCLE_RATE.si, "natural frequency of mode i"),
        ResultName("mode_<i>", "mode", "", "shape of mode i (components in m or rad)"),
        ResultName("modal_mass_<i>", "m", MASS.si, "modal mass phi^T M phi (kg*m^2 when the "
                                                   "mode's largest component is a rotation)"),
        ResultName("modal_stiffness_<i>", "k", STIFFNESS.si, "modal stiffness phi^T K phi "
                                                             "(N*m/rad for a rotation)"),
        ResultName("zeta_<i>", "ζ", "", "damping ratio of mode i (with --C)"),
        ResultName("omega_d_<i>", "ω_d", ANGULAR_RATE.si, "damped angular frequency of mode "
                                                          "i (with --C)"),
    ),
    _run,
    words="[NAME=QUANTITY]...",
)
