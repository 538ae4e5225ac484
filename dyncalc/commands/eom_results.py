"""``eom``'s computation once the input is read: dimensions, derivation, equilibria,
linearisation, frequencies, the state's accelerations, and the Result with its explanation.

sympy comes in here (through :mod:`dyncalc.physics.lagrange_equations`), and only for ``eom``.
"""
from __future__ import annotations

import math

from ..errors import InputError, PhysicsError
from ..result import Entry, Explanation, Result
from ..units import (ACCELERATION, ANGLE, ANGULAR_ACCELERATION, ANGULAR_RATE, CYCLE_RATE,
                     LENGTH, TIME, VELOCITY, Dim)
from .eom_units import LENGTH_DIM, PURE, infer_coordinates, matrix_units, unit_text

__all__ = ["build"]

_ABOUT_TOL = 1e-6


def _dim(dimension, name: str) -> Dim:
    unit = unit_text(dimension)
    return Dim(name, str(dimension), "", unit, "dimensionless" if not unit else "plain")


def _coordinate_dims(inputs):
    """``(coordinate -> Dimension or None, per_mass or None)``."""
    from ..units.expression import names_in

    if inputs.angles is not None:
        fixed = {c: (PURE if c in inputs.angles else LENGTH_DIM) for c in inputs.coords}
        cdims, per_mass = infer_coordinates(inputs.coords, inputs.trees, inputs.dims, fixed)
        return cdims, per_mass
    used = set()
    for tree in inputs.trees.values():
        used |= names_in(tree)
    params = used - set(inputs.coords) - {"t"}
    if params - set(inputs.dims):
        return {c: None for c in inputs.coords}, None
    return infer_coordinates(inputs.coords, inputs.trees, inputs.dims)


def _state(inputs, cdims):
    """The state's SI values by name (``x``, ``x_dot``, ``t``), each checked."""
    from ..units import parse_quantity
    from ..units.grammar import quantity_in_base
    from ..units.expression import Dimension

    out = {}
    for name, text in inputs.state.items():
        if name == "t":
            out[name] = parse_quantity(text, TIME, label="t=").si
            continue
        base = name[:-4] if name.endswith("_dot") else name
        kind = cdims.get(base)
        if kind is None:
            out[name] = quantity_in_base(text, label=f"{name}=")[0]
            continue
        angle = kind == PURE
        if name.endswith("_dot"):
            dim = ANGULAR_RATE if angle else VELOCITY
        else:
            dim = ANGLE if angle else LENGTH
        if kind not in (PURE, LENGTH_DIM):  # a coordinate of another dimension
            value, powers, _ = quantity_in_base(text, label=f"{name}=")
            want = kind if not name.endswith("_dot") else kind / Dimension({"[time]": 1})
            if Dimension(powers) != want:
                raise InputError(f"{name}= must be {want}; got {Dimension(powers)}")
            out[name] = value
            continue
        out[name] = parse_quantity(text, dim, label=f"{name}=").si
    return out


#: Wall-clock budget of the sympy work of one derivation (seconds); beyond it, refused.
BUDGET = 5.0


def build(inputs) -> Result:
    cdims, per_mass = _coordinate_dims(inputs)  # a refusal here costs no sympy import
    state = _state(inputs, cdims) if inputs.state else {}
    _check_powers(inputs)
    from ..physics.budget import OverBudget, time_budget

    try:
        with time_budget(BUDGET):
            return _build(inputs, cdims, per_mass, state)
    except OverBudget:
        raise PhysicsError(f"the derivation did not finish within {BUDGET:g} s; simplify "
                           "the energies (expand fewer powers, fewer nested functions)"
                           ) from None


#: Largest power of an expression in the coordinates eom derives (expansion grows as its cube).
MAX_POWER = 8


def _check_powers(inputs) -> None:
    from ..units.expression import ExpressionError, names_in

    coords = set(inputs.coords)
    for key, tree in inputs.trees.items():
        stack = [tree]
        while stack:
            node = stack.pop()
            stack.extend(node.args)
            if node.kind == "pow" and abs(node.args[1].const) > MAX_POWER and \
                    names_in(node.args[0]) & coords:
                label = f"--{key}" if ":" not in key else f"--Q {key.split(':')[1]}"
                raise ExpressionError(label, inputs.texts[key], node.pos + 1,
                                      f"eom takes powers up to {MAX_POWER} of an expression "
                                      "in the coordinates")


#: The derivations of this process, by coordinates, energies and signed parameters (the
#: rows of ``eom --scene --batch`` derive one scene again and again); at most :data:`KEEP`.
_DERIVED: dict = {}
KEEP = 32


def derive_system(inputs):
    """``(symbols, expressions, System)``: Lagrange's equations of the inputs' energies,
    every parameter a symbol (the values come in later); once per process for the same
    coordinates, energies and signed parameters."""
    key = (tuple(inputs.coords), tuple(sorted(inputs.texts.items())),
           tuple(sorted(inputs.signed)))
    if key not in _DERIVED:
        if len(_DERIVED) >= KEEP:
            _DERIVED.pop(next(iter(_DERIVED)))
        _DERIVED[key] = _derive_system(inputs)
    return _DERIVED[key]


def _derive_system(inputs):
    import sympy

    from ..physics import lagrange_equations as lagrange
    from ..physics.symbolic import Symbols, to_sympy

    s = Symbols(inputs.coords, signed=inputs.signed)
    exprs = {key: to_sympy(tree, s) for key, tree in inputs.trees.items()}
    forces = None
    if any(k.startswith("Q:") for k in exprs):
        forces = [exprs.get(f"Q:{c}", sympy.Integer(0)) for c in inputs.coords]
    return s, exprs, lagrange.derive(s, exprs["T"], exprs["V"], exprs.get("D"), forces)


def _build(inputs, cdims, per_mass, state) -> Result:

    import sympy

    from ..physics import lagrange_equations as lagrange
    from ..physics.symbolic import latex_of, text_of

    s, exprs, system = derive_system(inputs)
    warnings: list[str] = []
    inputs.warnings_out = warnings
    values = {s.param(name): v for name, v in inputs.values.items()}
    results: dict[str, Entry] = {}
    equations = []
    for i, (c, acc) in enumerate(zip(inputs.coords, system.accelerations), start=1):
        text = f"{c}'' = {text_of(acc)}"
        equations.append(text)
        results[f"eom_{i}"] = Entry(f"eom_{i}", text, None, symbol=f"eom{i}",
                                    description=f"equation of motion of {c}")
    if system.forced:
        warnings.append("terms that depend on t alone (a prescribed forcing or support "
                        "motion) are left out of the equilibria and the linearisation")
    angles = [cdims.get(c) == PURE if cdims.get(c) is not None
              else _in_trig(exprs, s.q[i]) for i, c in enumerate(inputs.coords)]
    numeric = all(not (e.free_symbols - set(s.q)) - set(values)
                  for e in system.static) if system.static else True
    plan = _plan(system, inputs) if numeric else None
    if plan is None and numeric and len(inputs.coords) == 2:
        plan = _pair_plan(inputs)
    equilibria, stabilities, numbers = _equilibria(system, values, angles, inputs, numeric,
                                                   plan)
    extra: dict = {}
    if not equilibria:
        warnings.append("no equilibrium: the system is never at rest" + (
            "" if not numeric else " at these values"))
    chosen = _choose(equilibria, stabilities, inputs, system, values, angles)
    eq_text = _equilibria_text(inputs.coords, equilibria, stabilities, numbers, cdims)
    results["equilibria"] = Entry("equilibria", eq_text, None, symbol="eq",
                                  description="the equilibria and their stability")
    extra["equilibria"] = [
        {**{c: (float(v) if numbers else text_of(v)) if v is not None else None
            for c, v in zip(inputs.coords, point)},
         "stable": stable}
        for point, stable in zip(equilibria, stabilities)]
    latex_lines = [latex_of(sympy.Eq(qdd, acc), s) for qdd, acc in
                   zip(s.qdd, system.accelerations)]
    if chosen is not None:
        point = {s.q[i]: (0 if v is None else v) for i, v in enumerate(chosen)}
        M, K = lagrange.linearise(system, point)
        M, K = M.subs(values), K.subs(values)
        if M.free_symbols & {s.t} or K.free_symbols & {s.t}:
            M, K = M.subs(s.t, 0), K.subs(s.t, 0)
            warnings.append("the linearised matrices depend on t; shown at t = 0")
        extra["about"] = {c: (float(v) if numbers else text_of(v)) if v is not None else None
                          for c, v in zip(inputs.coords, chosen)}
        known = cdims is not None and all(d is not None for d in cdims.values())
        if not M.free_symbols and not K.free_symbols:
            import numpy as np

            if len(inputs.coords) == 2 and plan is not None:  # (dyncalc.physics.eom_pairs)
                from ..physics.eom_pairs import two_frequencies

                with np.errstate(all="ignore"):
                    at = [np.array([float(point[q])]) for q in s.q]
                    Mn, Kn, dm, dk = plan.matrices(*at, _one_row(inputs.values))
                    omega, stable_rows = two_frequencies(Mn, Kn, dm, dk)
                Mn, Kn = Mn[0], Kn[0]
            elif plan is not None:  # the numbers batch gives too (dyncalc.physics.eom_columns)
                with np.errstate(all="ignore"):
                    Mn, Kn = (x.reshape(1, 1) for x in plan.matrices(
                        np.array([float(point[s.q[0]])]), _one_row(inputs.values)))
            else:
                Mn = np.array(M.tolist(), dtype=float)
                Kn = np.array(K.tolist(), dtype=float)
            _matrix(results, extra, "mass_matrix", Mn, inputs.coords, cdims, per_mass, known,
                    False)
            _matrix(results, extra, "stiffness_matrix", Kn, inputs.coords, cdims, per_mass,
                    known, True)
            if len(inputs.coords) == 2 and plan is not None:
                omegas, stable = omega[0].tolist(), bool(stable_rows[0])
            elif plan is not None:
                from ..physics.eom_columns import one_frequency

                omega, stable_rows = one_frequency(Mn[:, 0], Kn[:, 0])
                omegas, stable = [float(omega[0])], bool(stable_rows[0])
            else:
                omegas, stable = lagrange.frequencies(M, K)
            if not stable:
                warnings.append("the equilibrium linearised about is unstable: no natural "
                                "frequency (a small disturbance grows)")
            else:
                for i, w in enumerate(omegas, start=1):
                    results[f"omega_{i}"] = Entry(f"omega_{i}", w, ANGULAR_RATE, "rad/s",
                                                  symbol=f"ω{i}",
                                                  description=f"natural angular frequency {i}")
                for i, w in enumerate(omegas, start=1):
                    results[f"f_{i}"] = Entry(f"f_{i}", w / (2 * math.pi), CYCLE_RATE, "Hz",
                                              symbol=f"f{i}", description=f"natural frequency {i}")
                if "D" in inputs.trees:
                    warnings.append("omega_i are the undamped natural frequencies (D is left "
                                    "out of them)")
        else:
            results["mass_matrix"] = Entry("mass_matrix", _matrix_text(M), None, symbol="M",
                                           description="linearised mass matrix")
            results["stiffness_matrix"] = Entry("stiffness_matrix", _matrix_text(K), None,
                                                symbol="K",
                                                description="linearised stiffness matrix")
        latex_lines += [r"M = " + latex_of(M, s), r"K = " + latex_of(K, s)]
    if inputs.state:
        _accelerations(results, inputs, system, s, values, cdims, state, plan)
    return _result(inputs, results, warnings, extra, equations, latex_lines, exprs, s,
                   per_mass)


def _in_trig(exprs, q) -> bool:
    import sympy

    return any(f.has(q) for e in exprs.values()
               for f in e.atoms(sympy.sin, sympy.cos, sympy.tan))


def _plan(system, inputs):
    """The numpy functions of a one-coordinate derivation with every value known, or None
    (made once per derivation and set of parameters)."""
    from ..physics.eom_columns import plan_of

    plans = system.__dict__.setdefault("plans", {})
    key = frozenset(inputs.values)
    if key not in plans:
        plans[key] = plan_of(system, list(inputs.values))
        if plans[key] is not None and inputs.scene is not None:
            # the generated functions the batch evaluates (dyncalc.scenes.eom_tables), the
            # same source as plan_of's: both agree bit for bit by construction
            from ..physics.eom_columns import Plan
            from ..scenes.eom_tables import TABLES

            entry = TABLES.get(inputs.scene)
            if entry is not None and set(entry["names"]) <= key:
                plans[key] = Plan.of_table(entry)
    return plans[key]


def _pair_plan(inputs):
    """The generated functions of a two-coordinate scene (dyncalc.scenes.eom_tables2), the
    batch's too, so both agree bit for bit; ``None``: not in the table, a parameter
    without a value, or numbers the table cannot give at some equilibrium (an overflow:
    the symbolic path answers, as the batch leaves such rows to this one-off)."""
    from ..scenes.eom_tables2 import TABLES2

    entry = TABLES2.get(inputs.scene) if inputs.scene is not None else None
    if entry is None or not set(entry["names"]) <= set(inputs.values):
        return None
    import numpy as np

    from ..physics.eom_pairs import PairPlan, finite_rows, within

    plan, row = PairPlan(entry), _one_row(inputs.values)
    with np.errstate(all="ignore"):
        roots = [[0.0 if v is None else float(v) for v in r] for r in entry["roots"]] \
            if entry["roots"] is not None else _form_roots(plan, row)
        if roots is None:
            return None  # (values the forms do not cover: the numeric search)
        bounds = plan.bound_rows(row, 1)
        for root in roots:
            if not all(map(math.isfinite, root)):
                return None
            at = [np.array([v]) for v in root]
            if within(at, bounds)[0] and not finite_rows(*plan.matrices(*at, row))[0]:
                return None  # (an equilibrium off the scene's domain is never linearised)
    return plan


def _form_roots(plan, row: dict) -> list[list[float]] | None:
    """The equilibria of one row from the table's closed forms
    (:meth:`~dyncalc.physics.eom_pairs.PairPlan.root_rows`, the batch's too), in its order,
    each missing (NaN) or coinciding with an earlier one left out (as the numeric search
    merges them); ``None`` where the forms are not all of them (the search answers)."""
    from ..physics.eom_pairs import near

    roots, _distinct, covered = plan.root_rows(row, 1)
    if not covered[0]:
        return None
    found: list[list[float]] = []
    for root in roots:
        point = [float(q[0]) for q in root]
        if all(map(math.isnan, point)):
            continue
        if not any(all(near(a, b) for a, b in zip(other, point)) for other in found):
            found.append(point)
    return found


def constant_roots(system, angle: bool):
    """The equilibria of a one-coordinate derivation that do not depend on the values
    (:func:`dyncalc.physics.eom_columns.constant_equilibria`), once per derivation."""
    from ..physics.eom_columns import constant_equilibria

    roots = system.__dict__.setdefault("roots", {})
    if angle not in roots:
        roots[angle] = constant_equilibria(system, angle)
    return roots[angle]


def _table_roots(inputs):
    """The equilibria from the closed forms of the generated table
    (:func:`dyncalc.physics.eom_columns.equilibria_rows` on one row), or ``None``."""
    from ..scenes.eom_tables import TABLES

    entry = TABLES.get(inputs.scene) if inputs.scene is not None else None
    if entry is None or entry.get("R") is None or not set(entry["names"]) <= set(inputs.values):
        return None
    from ..physics.eom_columns import equilibria_rows, root_columns

    row = _one_row(inputs.values)
    x, count = equilibria_rows(root_columns(entry["R"], [row[n] for n in entry["names"]], 1),
                               entry["angle"])
    return [[float(v)] for v in x[0, :count[0]]]


def _one_row(values: dict) -> dict:
    """Parameter name -> a float64 array of one row (the batch's arrays, one row long)."""
    import numpy as np

    return {name: np.array([float(v)]) for name, v in values.items()}


def _equilibria(system, values, angles, inputs, numeric, plan=None):
    """``(points, stabilities, numbers)``: each point a list (None for a free coordinate)."""
    import sympy

    from ..physics import lagrange_equations as lagrange

    s = system.symbols
    free = set(lagrange.free_coordinates(system))
    points, stabilities = [], []
    if numeric:
        lengths = [abs(v) for name, v in inputs.values.items()
                   if inputs.dims.get(name) == LENGTH_DIM and v != 0]
        scale = max(lengths) if lengths else 1.0
        pair = plan if len(s.q) == 2 else None
        if pair is not None:
            plan = None
        roots = constant_roots(system, angles[0]) if plan is not None else None
        closed = _table_roots(inputs) if plan is not None and roots is None else None
        if pair is not None and pair.roots is None:  # the table's closed forms, as batch
            found = _form_roots(pair, _one_row(inputs.values))
        elif pair is not None:  # the generated table's roots, as batch takes them: no search
            found = [[0.0 if v is None else v for v in r] for r in pair.roots]
        elif roots is not None:  # sympy's roots, as batch takes them: no search
            found = [[r] for r in roots]
        elif closed is not None:  # the table's closed forms, as batch takes them
            found = closed
        else:
            found = lagrange.numeric_equilibria(system, values, angles,
                                                 [scale] * len(s.q))
        bounds = _bounds(inputs, values) if pair is None or not pair.domain else {
            i: (float(lo[0]), float(hi[0]))  # (the table's, as batch takes them)
            for i, (lo, hi) in pair.bound_rows(_one_row(inputs.values), 1).items()}
        for p in found:
            if any(not lo - 1e-9 <= p[i] <= hi + 1e-9 for i, (lo, hi) in bounds.items()):
                continue
            point = [None if i in free else v for i, v in enumerate(p)]
            if pair is not None:
                import numpy as np

                from ..physics.eom_pairs import two_frequencies

                with np.errstate(all="ignore"):
                    Mp, Kp, dm, dk = pair.matrices(np.array([float(p[0])]),
                                                   np.array([float(p[1])]),
                                                   _one_row(inputs.values))
                points.append(point)
                stabilities.append(bool(two_frequencies(Mp, Kp, dm, dk)[1][0]))
                continue
            if plan is not None:
                import numpy as np

                from ..physics.eom_columns import one_frequency

                with np.errstate(all="ignore"):
                    Mp, Kp = plan.matrices(np.array([float(p[0])]), _one_row(inputs.values))
                points.append(point)
                stabilities.append(bool(one_frequency(Mp, Kp)[1][0]))
                continue
            M, K = lagrange.linearise(system, {s.q[i]: v for i, v in enumerate(p)})
            M, K = M.subs(values), K.subs(values)
            if M.free_symbols or K.free_symbols:
                M, K = M.subs(s.t, 0), K.subs(s.t, 0)
            if M.free_symbols or K.free_symbols:  # parameters without a value remain
                stable = lagrange.stability_of(M, K)
            else:
                stable = lagrange.frequencies(M, K)[1]
            points.append(point)
            stabilities.append(stable)
        return points, stabilities, True
    found = lagrange.symbolic_equilibria(system)
    if found is None:
        return [], [], False
    if not lagrange.solvable([e for e in system.static if e != 0],
                              [q for i, q in enumerate(s.q) if i not in free]):
        inputs.warnings_out.append("the static equations have no closed-form solution: only "
                                   "the rest position is listed; give every parameter a "
                                   "value for the numeric search")
    for f in found:
        point = [None if i in free else f.get(q, sympy.Integer(0)) for i, q in enumerate(s.q)]
        subs = {q: (0 if v is None else v) for q, v in zip(s.q, point)}
        M, K = lagrange.linearise(system, subs)
        points.append(point)
        stabilities.append(lagrange.stability_of(M, K))
    return points, stabilities, False


def _bounds(inputs, values) -> dict:
    """{coordinate index: (lowest, highest)} of the scene's domain at these values."""
    from ..physics.symbolic import Symbols, to_sympy
    from ..units.expression import parse_expression

    out = {}
    s = Symbols(inputs.coords)
    by_name = {str(k): v for k, v in values.items()}
    for c, pair in (inputs.domain or {}).items():
        ends = []
        for text in pair:
            tree = parse_expression(text, names=set(by_name), free_names=False)
            ends.append(float(to_sympy(tree, s).subs({s.param(n): v
                                                       for n, v in by_name.items()})))
        out[inputs.coords.index(c)] = tuple(ends)
    return out


def _parse_about(inputs, system, values):
    """``--about "phi=0, x=0"`` -> {coordinate index: value} (constant expressions)."""
    import re

    from ..units.expression import parse_expression

    out = {}
    for part in re.split(r"[,;]", inputs.about):
        if not part.strip():
            continue
        name, sep, text = part.partition("=")
        name = name.strip()
        if not sep or name not in inputs.coords:
            raise InputError(f"--about takes COORDINATE=VALUE, e.g. \"phi=0\" (the "
                             f"coordinates are {', '.join(inputs.coords)}); got "
                             f"{part.strip()[:60]!r}")
        tree = parse_expression(text, label=f"--about {name}", free_names=False)
        if tree.const is None:
            raise InputError(f"--about {name}: give a number (with its unit), e.g. pi or "
                             "30deg")
        out[inputs.coords.index(name)] = tree.const
    return out


def _choose(equilibria, stabilities, inputs, system, values, angles):
    """The equilibrium to linearise about: --about's, else the first stable, else the
    first; None when there is none."""
    if inputs.about is None:
        for point, stable in zip(equilibria, stabilities):
            if stable:
                return point
        return equilibria[0] if equilibria else None
    wanted = _parse_about(inputs, system, values)
    for point in equilibria:
        if all(_close(point[i], v, angles[i]) for i, v in wanted.items()):
            return point
    shown = ", ".join(f"{inputs.coords[i]}={v:g}" for i, v in wanted.items())
    raise PhysicsError(f"--about {shown}: not an equilibrium found; the equilibria are "
                       f"{_equilibria_text(inputs.coords, equilibria, stabilities, True, {}) if equilibria else 'none'}")


def _close(a, b, angle) -> bool:
    if a is None:
        return True
    try:
        a = float(a)
    except TypeError:
        return False
    d = a - b
    if angle:
        d = math.remainder(d, 2 * math.pi)
    return abs(d) <= _ABOUT_TOL * max(1.0, abs(b))


def _number_text(v, angle: bool) -> str:
    v = float(v)
    text = f"{v:.6g}"
    return text


def _equilibria_text(coords, points, stabilities, numbers, cdims) -> str:
    if not points:
        return "none"
    parts = []
    for point, stable in zip(points, stabilities):
        items = []
        for c, v in zip(coords, point):
            if v is None:
                items.append(f"{c}=any")
            elif numbers:
                items.append(f"{c}={_number_text(v, False)}")
            else:  # (sympy only here: the batch's numbers do not load it)
                from ..physics.symbolic import text_of

                items.append(f"{c}={text_of(v)}")
        word = {True: "stable", False: "unstable", None: "stability open"}[stable]
        parts.append(", ".join(items) + f" ({word})")
    return "; ".join(parts)


def _matrix_text(m) -> str:
    from ..physics.symbolic import text_of

    return "[" + ", ".join("[" + ", ".join(text_of(m[i, j]) for j in range(m.shape[1])) + "]"
                           for i in range(m.shape[0])) + "]"


def _matrix(results, extra, name, array, coords, cdims, per_mass, known, stiffness):
    units = matrix_units(coords, cdims, per_mass, stiffness) if known else None
    flat = {u for row in units for u in row} if units else {""}
    description = "linearised " + ("stiffness" if stiffness else "mass") + " matrix"
    if len(flat) == 1:
        unit = flat.pop()
        dim = Dim(description, unit or "dimensionless", "", unit,
                  "plain" if unit else "dimensionless")
        results[name] = Entry(name, array, dim, unit, symbol="K" if stiffness else "M",
                              description=description)
    else:
        results[name] = Entry(name, array, None, "", symbol="K" if stiffness else "M",
                              description=description + " (a unit on each entry; JSON: "
                              "extra.matrix_units)", units=units)
        extra.setdefault("matrix_units", {})[name] = units


def _accelerations(results, inputs, system, s, values, cdims, state, plan=None):
    subs = dict(values)
    for i, c in enumerate(inputs.coords):
        if c in state:
            subs[s.q[i]] = state[c]
        if c + "_dot" in state:
            subs[s.qd[i]] = state[c + "_dot"]
    if "t" in state:
        subs[s.t] = state["t"]
    for i, (c, acc) in enumerate(zip(inputs.coords, system.accelerations)):
        value = acc.subs(subs)
        missing = sorted(str(x) for x in value.free_symbols)
        if missing:
            shown = ", ".join(m.replace("''", "_ddot").replace("'", "_dot") + "="
                              for m in missing)
            raise InputError(f"{c}_ddot at the state needs {shown} too")
        if plan is not None and len(inputs.coords) == 2:  # (dyncalc.physics.eom_pairs)
            import numpy as np

            with np.errstate(all="ignore"):
                rows = [np.array([float(state.get(k, 0.0))]) for k in
                        (*inputs.coords, *(c + "_dot" for c in inputs.coords))]
                number = complex(float(plan.accelerations(
                    *rows, np.array([float(state.get("t", 0.0))]),
                    _one_row(inputs.values))[i][0]))
            if not math.isfinite(number.real):  # an overflow: the batch leaves it here
                number = complex(value.evalf())
        elif plan is not None:  # the batch's numbers (dyncalc.physics.eom_columns)
            import numpy as np

            with np.errstate(all="ignore"):
                number = complex(float(plan.accelerations(
                    np.array([float(state.get(c, 0.0))]),
                    np.array([float(state.get(c + "_dot", 0.0))]),
                    np.array([float(state.get("t", 0.0))]), _one_row(inputs.values))[0]))
        else:
            number = complex(value.evalf())
        if abs(number.imag) > 1e-12 * max(1.0, abs(number.real)) or \
                not math.isfinite(number.real):
            raise PhysicsError(f"{c}_ddot is not a finite real number at this state")
        kind = cdims.get(c)
        if kind == PURE:
            dim = ANGULAR_ACCELERATION
        elif kind == LENGTH_DIM:
            dim = ACCELERATION
        elif kind is not None:
            from ..units.expression import Dimension

            dim = _dim(kind / Dimension({"[time]": 2}), "acceleration")
        else:
            dim = None
        results[f"{c}_ddot"] = Entry(f"{c}_ddot", number.real, dim,
                                     dim.si if dim is not None else "", symbol=f"{c}''",
                                     description=f"acceleration of {c} at the state")


def _result(inputs, results, warnings, extra, equations, latex_lines, exprs, s, per_mass):
    from ..physics.symbolic import latex_of, text_of

    from ..result import entry_from_parsed
    from .eom_units import nice_unit

    entries = {}
    for name, value in inputs.values.items():
        if name in inputs.parsed:
            parsed, pdim = inputs.parsed[name]
            entries[name] = entry_from_parsed(name, parsed, pdim)
            continue
        dimension = inputs.dims.get(name)
        unit = nice_unit(dimension) if dimension is not None else ""
        dim = Dim("quantity", str(dimension), "", unit,
                  "plain" if unit else "dimensionless")
        entries[name] = Entry(name, value, dim, unit, text=inputs.param_texts.get(name))
    energy = "per unit mass" if per_mass else ""
    formula = [f"T = {text_of(exprs['T'])}" + (f"  ({energy})" if energy else ""),
               f"V = {text_of(exprs['V'])}"]
    if "D" in exprs:
        formula.append(f"D = {text_of(exprs['D'])}")
    for c in inputs.coords:
        if f"Q:{c}" in exprs:
            formula.append(f"Q_{c} = {text_of(exprs[f'Q:{c}'])}")
    formula.append(_LAGRANGE_TEXT)
    formula += equations
    latex = [f"T = {latex_of(exprs['T'], s)}", f"V = {latex_of(exprs['V'], s)}"]
    if "D" in exprs:
        latex.append(f"D = {latex_of(exprs['D'], s)}")
    latex.append(r"\frac{d}{dt}\frac{\partial T}{\partial \dot q} - \frac{\partial T}"
                 r"{\partial q} + \frac{\partial V}{\partial q} + \frac{\partial D}"
                 r"{\partial \dot q} = Q_q")
    latex += latex_lines
    assumptions = ["parameters without a value are symbols taken positive",
                   "stability from the linearised conservative system (M^-1 K)"]
    if inputs.note:
        assumptions.insert(0, inputs.note)
    explanation = Explanation(formula, [], assumptions,
                              reference="Lagrange's equations of the second kind; Gross et al., "
                                        "Engineering Mechanics 3, 2nd ed., 4.3"
                                        + (f" ({inputs.reference})" if inputs.reference else ""),
                              latex=latex)
    numeric = any(k.startswith("omega_") for k in results)
    return Result("eom", results, entries, scene=inputs.scene, model="lagrange",
                  method="symbolic" + (" + numeric equilibria" if "equilibria" in extra and
                                       extra["equilibria"] and numeric else ""),
                  warnings=warnings, explanation=explanation, extra=extra)


_LAGRANGE_TEXT = "Lagrange: d/dt(dT/dq') - dT/dq + dV/dq + dD/dq' = Q_q"
