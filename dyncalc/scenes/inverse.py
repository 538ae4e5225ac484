"""Inverse problems: a result given (``f=5Hz``), one parameter unknown; solve for it.

``dyncalc natural-frequency f=5Hz m=2kg`` gives ``k = 1973.92 N/m``. The unknown is the one
required parameter left out, or the one given as ``NAME=?`` (which also frees a parameter that
has a default or is optional: ``g=?``, ``amplitude=?``).

How (decided here; docs/inverse.md and docs/guide/homework.md):

1. **Closed form** when the result is a power of the unknown, ``y = C x^a`` (every scene that
   is a product of powers: ``omega^2 = k/m``, ``g/l``, ``kt/J``, ...). The exponent is read off
   the scene itself (log-slopes at three points six decades apart must agree to 1e-9 and ``a``
   must be a simple fraction p/q, q <= 4), then ``x = x1 (y / y1)^(1/a)``, the exact inversion
   of the monomial, checked by computing the scene at ``x``.
2. Otherwise a **bracketed root find** (docs/inverse.md): the scene is computed on a coarse
   grid of the unknown's whole domain (every fifth decade from 5e-324 to 1.8e308 for a positive
   parameter, both signs and zero for a signed one, 2 degree steps from 0 to 180 degrees for
   an angle); a result that takes one value there does not depend on the unknown and is
   refused at once. The grid is refined (10 points a decade, 1/4 degree) next to every sign
   change of ``y(x) - target``, turning point and edge; every **edge** of where the scene
   answers is located to adjacent floats and approached 1, 2, 4, ... floats away
   (:func:`~dyncalc.physics.numerics.float_boundary`, ``float_approach``), and every
   **extremum** is located by Brent's minimisation (``bracketed_minimum``) and added, so the
   two roots beside a peak are split. Each sign change between neighbouring samples is a
   guaranteed bracket, refined by Brent's method (:func:`_brent`) to full precision; an extremum
   within :data:`TOUCH` of the target is one double root. Every root is reported (``k_1``,
   ``k_2``, ... ascending) with a warning that there are several; none is refused with the
   range the result takes; more than :data:`MAX_ROOTS` roots are refused, and so is a result
   the scene never gives. With an expensive ``--method`` (an ODE), the scan uses the cheapest
   model good to 1e-6 and each root is then bracketed anew, close by, with the method asked
   for.

Two roots inside one refined interval with no sampled turning point between them can be
missed; the scenes of the catalog have at most two, split by a sampled extremum.

Uncertainties: the Result's ``sensitivity`` (:func:`_sensitivity`) applies the implicit
function theorem at the roots found, with the scene's partial derivatives by central
differences on the values as read: no root is searched for again.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from ..errors import InputError
from ..result.entries import Entry, entry_from_parsed
from ..units import ANGLE, parse_quantity, registry
from . import Scene
from .runner import (DEFAULT_RTOL, Prepared, check_constraints, compute_values, is_result_name,
                     make_result, read_inputs, scene_kind, set_parameter, _entry,
                     _parameter_list)

__all__ = ["solve"]

#: Positive parameters are searched from 10^LOW to 10^HIGH (in SI), every STEP decades, and at
#: the ends of the float range (TINY, HUGE below).
LOW, HIGH, STEP = -300, 300, 5
#: The ends of a positive parameter's grid: the smallest and the largest positive floats.
TINY, HUGE = 5e-324, 1.7976931348623157e308
#: Points in each coarse interval next to a sign change or a turning point (10 a decade).
FINE = 50
#: An angle's coarse grid step (degrees) and its refinement (to 1/4 degree).
ANGLE_STEP, FINE_ANGLE = 2, 8
#: More roots than this: the result hardly depends on the unknown; refused.
MAX_ROOTS = 8
#: An extremum of the result within this relative distance of the goal is a (double) root:
#: the goal and the extremum's value are each a rounding or two from the exact ones.
TOUCH = 4 * 2.0 ** -52


class _Independent(InputError):
    """The result does not depend on the unknown: final, whichever model scans."""


def solve(scene: Scene, texts: dict[str, str], *, labels: dict[str, str], method, rtol,
          strict: bool, command: str):
    """The Result of the inverse problem ``texts`` poses (see the module docstring)."""
    target, target_text, known, asked = _split(scene, texts, labels)
    prepared = read_inputs(scene, known, labels, strict, unknown=tuple(asked))
    if not asked and not prepared.missing and target != "zeta":  # zeta: its own message
        _refuse_foreign_result(scene, target, prepared, method, rtol)
    unknown = _the_unknown(scene, target, asked, prepared.missing, labels)
    kind = scene_kind(scene, target)
    parsed_goal = parse_quantity(target_text, kind.dim,
                                 label=labels.get(target, f"{target}=").rstrip("="),
                                 strict=strict)
    problem = _Problem(scene, prepared, unknown, target, method, rtol)
    roots, how = problem.roots(parsed_goal.si)
    if not roots:
        if problem.seen and target not in problem.seen:
            raise InputError(f"{scene.name} gives no result {target}; its results are "
                             f"{', '.join(sorted(problem.seen))}")
        raise InputError(problem.no_root_message(_typed(parsed_goal, kind)))

    inputs = dict(prepared.inputs)
    inputs[target] = entry_from_parsed(target, parsed_goal, kind.dim, symbol=kind.symbol,
                                       description=kind.description)
    result = _result(problem, roots, inputs, _typed(parsed_goal, kind), command)
    result.extra["inverse"] = {"unknown": unknown.name, "method": how[0], "detail": how[1]}
    if how[1]:
        note = f"{unknown.name} solved from {target}: {how[1]}"
        result.amend_explanation(lambda explanation: explanation.assumptions.append(note))
    names = [unknown.name] if len(roots) == 1 else \
        [f"{unknown.name}_{i}" for i in range(1, len(roots) + 1)]
    result.sensitivity = lambda: _sensitivity(problem, roots, names, parsed_goal, target,
                                              len(roots) == 1)
    return result


def _result(problem: _Problem, roots: list[float], inputs: dict[str, Entry], goal_text: str,
            command: str):
    """The Result of the roots found: the unknown (``k``, or ``k_1``, ``k_2``, ... for several
    roots) first, then the scene's results at a single root."""
    unknown, target = problem.param, problem.target
    unit = "deg" if unknown.dim is ANGLE else unknown.dim.si
    describe = f"{unknown.description} (solved from {target})"
    names = [unknown.name] if len(roots) == 1 else \
        [f"{unknown.name}_{i}" for i in range(1, len(roots) + 1)]
    symbols = [unknown.name] if len(roots) == 1 else \
        [f"{unknown.name}{i}" for i in range(1, len(roots) + 1)]
    solved = {name: Entry(name, x, unknown.dim, unit=unit, symbol=symbol, description=describe)
              for name, symbol, x in zip(names, symbols, roots)}
    outcome, values, warnings = problem.evaluate(roots[0])
    if len(roots) > 1:  # the other results differ from root to root: the roots alone
        values = {}
        shown = ", ".join(f"{_shown(x, unknown):.6g} {unit}" for x in roots)
        warnings.append(f"{len(roots)} values of {unknown.name} give {target} = "
                        f"{goal_text}: {shown}; each is a result")
    return make_result(problem.scene, inputs, outcome, values, warnings, command, solved)


def _sensitivity(problem: _Problem, roots: list[float], names: list[str], parsed_goal,
                 target: str, with_values: bool):
    """Derivatives of the solved unknown (and, with one root, of the other results) with
    respect to the uncertain inputs, by the implicit function theorem at each root ``x``:
    ``y(x, p) = goal`` gives ``dx/dgoal = 1 / y_x`` and ``dx/dp = -y_p / y_x``, and another
    result ``z(x, p)`` moves by ``z_p + z_x dx/dp``. The partial derivatives are central
    differences of the forward scene on the parameters as read (two scene computations per
    uncertain input and per root, plus two for ``y_x``): no root is searched for again and
    nothing is parsed again."""
    from ..result.propagate import (RELATIVE_STEP, Sensitivity, UncertainInput,
                                    central_differences)
    from .runner import _nudged

    scene, prepared = problem.scene, problem.prepared
    params = [n for n, e in prepared.inputs.items()
              if e.uncertainty is not None and n in prepared.si]
    inputs = [UncertainInput(n, float(prepared.si[n]), float(prepared.inputs[n].uncertainty))
              for n in params]
    goal_index = None
    if parsed_goal.uncertainty is not None:
        goal_index = len(inputs)
        inputs.append(UncertainInput(target, float(parsed_goal.si),
                                     float(parsed_goal.uncertainty)))
    slopes: dict[str, dict[int, object]] = {}
    if goal_index is not None:  # the result solved from is the goal, whatever the root
        slopes[target] = {goal_index: 1.0}
    failed: set[str] = set()

    def numbers(at: _Problem, x: float) -> dict[str, object] | None:
        try:
            with np.errstate(all="ignore"):
                _outcome, values, _warnings = at.evaluate(x)
        except (InputError, ArithmeticError, ValueError):
            return None
        out = {}
        for name, value in values.items():
            entry = _entry(name, value, at.scene)
            if not isinstance(entry.si, str):
                out[name] = np.asarray(entry.si, dtype=float)
        return out

    for name, x in zip(names, roots):
        base = numbers(problem, x) or {}
        # a root whose derivative cannot be worked out leaves every result it sets without one
        unknowable = {name, *(base if with_values else ())} - {target}
        hx = RELATIVE_STEP * (abs(x) if x != 0 else 1.0)
        up, down = numbers(problem, x + hx), numbers(problem, x - hx)
        if up is None or down is None or target not in up or target not in down:
            failed.update(unknowable)
            continue
        z_x = {k: (up[k] - down[k]) / (2 * hx) for k in up if k in down}
        y_x = float(z_x[target])
        if y_x == 0 or not math.isfinite(y_x):
            failed.update(unknowable)
            continue

        def rerun(index: int, offset: float, x=x):
            nudged = _nudged(scene, prepared, params[index], offset)
            return None if nudged is None else numbers(
                _Problem(scene, nudged, problem.param, target, problem.method, problem.rtol), x)

        # the scene's partial derivatives in each parameter at this root (central, or
        # one-sided where a nudge is refused), as for a forward scene
        partials = central_differences(inputs[:len(params)], base, rerun)
        by_target = partials.slopes.get(target, {})
        for index, item in enumerate(inputs[:len(params)]):
            if item.sigma == 0:
                continue
            if index not in by_target:
                failed.update(unknowable)
                continue
            dx = -float(by_target[index]) / y_x
            slopes.setdefault(name, {})[index] = dx
            if not with_values:
                continue
            for k in z_x:  # the result solved from stays at its goal: 0
                if k in partials.failed:
                    failed.add(k)
                elif index in partials.slopes.get(k, {}):
                    slopes.setdefault(k, {})[index] = (
                        0.0 if k == target else partials.slopes[k][index] + z_x[k] * dx)
        if goal_index is not None and inputs[goal_index].sigma != 0:
            dx = 1.0 / y_x
            slopes.setdefault(name, {})[goal_index] = dx
            if with_values:  # the result solved from moves with its goal, 1 for 1
                for k, slope in z_x.items():
                    slopes.setdefault(k, {})[goal_index] = 1.0 if k == target else slope * dx
    return Sensitivity(inputs, slopes, failed)


def _split(scene: Scene, texts: dict[str, str], labels: dict[str, str]):
    """``(target, its text, the parameters' texts, the names asked for as NAME=?)``."""
    targets = {n: t for n, t in texts.items()
               if scene.param(n) is None and is_result_name(n, scene)}
    asked = [n for n, t in texts.items() if scene.param(n) is not None and t.strip() == "?"]
    known = {n: t for n, t in texts.items() if n not in targets and n not in asked}
    for name, text in targets.items():
        if text.strip() == "?":
            raise InputError(f"{name} is a result of {scene.name}, not one of its parameters: "
                             f"give every parameter to compute it ({_parameter_list(scene)})")
    if len(targets) > 1:
        raise InputError(f"give one result to solve from, not {len(targets)} "
                         f"({', '.join(targets)}); compare the others with --check")
    if len(asked) > 1:
        raise InputError(f"give one unknown (NAME=?), not {len(asked)} ({', '.join(asked)})")
    (target, target_text), = targets.items()
    for group in scene.one_of:
        if not any(n in known or n in asked or scene.param(n).default is not None
                   for n in group):
            raise InputError(f"{target}= leaves {' or '.join(group)} unknown: give one of "
                             f"them, or one as NAME=? to solve for it")
    return target, target_text, known, asked


def _refuse_foreign_result(scene: Scene, target: str, prepared: Prepared, method, rtol) -> None:
    """Every parameter given and ``target`` a name this scene never gives (``x=`` to
    mass-spring; ``x`` is forced-response's result): refused as a parameter the scene does
    not have, as when no scene gave that result."""
    try:
        check_constraints(scene, prepared.si)
        _outcome, values, _warnings = compute_values(scene, prepared.kwargs, prepared.zeta,
                                                     method, rtol)
    except InputError:
        return
    if target not in values:
        raise InputError(f"{scene.name} has no parameter {target!r}; {_parameter_list(scene)}")


def _the_unknown(scene: Scene, target: str, asked: list[str], missing: list[str],
                 labels: dict[str, str]):
    """The one parameter to solve for: asked as ``NAME=?`` or the one required left out."""
    unknowns = asked + [n for n in missing if n not in asked]
    typed = labels.get(target, "")
    if not unknowns:
        if target == "zeta" and not scene.accepts_zeta and "(from" not in typed:
            raise InputError(f"{scene.name} takes no zeta: {scene.no_zeta_because}; "
                             f"{_parameter_list(scene)}")
        # delta= or Q= of damping-ratio --scene arrive as zeta (from delta)=
        shown = typed.split(" (from ")[-1].rstrip(")=") if "(from" in typed else target
        raise InputError(f"{shown}= is a result of {scene.name} and every parameter is "
                         f"given: leave out the one to solve for (or give it as NAME=?), or "
                         f"compare with --check {shown}=...")
    if len(unknowns) > 1:
        raise InputError(f"{scene.name}: {target}= leaves {len(unknowns)} parameters unknown "
                         f"({', '.join(unknowns)}); give all but one")
    unknown = scene.param(unknowns[0])
    if unknown.dim is None:
        raise InputError(f"{unknown.name} is a choice, not a number to solve for; give "
                         f"kappa=? for the shape factor")
    return unknown




def _typed(parsed, kind) -> str:
    """The target as typed, ``-5 Hz``, for messages (SI when no unit was typed)."""
    from ..units import convert

    unit = parsed.unit_text or kind.dim.si
    try:
        value = convert(parsed.si, kind.dim, unit) if unit != kind.dim.si else parsed.si
    except InputError:
        value, unit = parsed.si, kind.dim.si
    return f"{float(value):.6g} {unit}".rstrip()


def _shown(x: float, param) -> float:
    return math.degrees(x) if param.dim is ANGLE else x


def _si_where_typed_in_si(scene: Scene, prepared: Prepared) -> dict:
    """The physics' keyword arguments with each quantity typed in its SI unit replaced by its
    plain SI number, which the physics takes as it is (converting a quantity to the unit it
    is in gives its magnitude unchanged, so the results are the same to the bit; a solve
    calls the physics hundreds or thousands of times, and pint's conversion was most of each
    call). Angles and quantities typed in other units stay as they are."""
    ureg = registry()
    kwargs = dict(prepared.kwargs)
    for name, value in prepared.kwargs.items():
        param = scene.param(name)
        if (param is None or param.dim is None or param.dim is ANGLE or not param.dim.si
                or not hasattr(value, "units")):
            continue
        si_unit = ureg.Unit(param.dim.si.replace("^", "**"))
        if value.units == si_unit and float(value.magnitude) == prepared.si.get(name):
            kwargs[name] = float(value.magnitude)
    return kwargs


class _Problem:
    """The scene as a function of the unknown alone: ``y(x)`` in SI, NaN where refused."""

    def __init__(self, scene: Scene, prepared: Prepared, param, target: str, method, rtol):
        self.scene, self.prepared, self.param, self.target = scene, prepared, param, target
        self.method, self.rtol = method, rtol
        self.unit = param.dim.si.replace("^", "**") if param.dim.si else ""
        self.kind_unit = scene_kind(scene, target).dim.si
        self.seen: set[str] = set()  # every result name the scene gave at some x
        # changes of y below this (relative) are rounding or model error, not a turning point
        self.noise = 8 * max(rtol if rtol else DEFAULT_RTOL, 2.0 ** -52)
        self.samples: list[float] = []
        self.kwargs = _si_where_typed_in_si(scene, prepared)

    def evaluate(self, x: float):
        """``(outcome, values, warnings)`` of the scene at ``x``; InputError when refused."""
        prepared = Prepared()
        prepared.kwargs = dict(self.kwargs)
        prepared.si = dict(self.prepared.si)
        prepared.zeta = self.prepared.zeta
        # x is SI: the physics takes a plain number as SI (an angle keeps its unit: the physics
        # works in the unit an angle is given in)
        quantity = registry().Quantity(x, self.unit) if self.param.dim is ANGLE else x
        set_parameter(self.scene, prepared, self.param.name, x, quantity)
        check_constraints(self.scene, prepared.si)
        return compute_values(self.scene, prepared.kwargs, prepared.zeta, self.method,
                              self.rtol)

    def y(self, x: float) -> float:
        """The target result at ``x`` in SI; NaN where the scene refuses ``x`` or has no such
        result (a bead below its bifurcation has no ``theta_eq``)."""
        if not self._admissible(x):
            return math.nan
        try:
            with np.errstate(all="ignore"):
                _outcome, values, _warnings = self.evaluate(x)
        except (InputError, ArithmeticError, ValueError):
            return math.nan
        self.seen.update(values)
        value = values.get(self.target)
        if value is None:
            return math.nan
        entry = _entry(self.target, value, self.scene)
        return float(entry.si) if isinstance(entry.si, float) else math.nan

    def _admissible(self, x: float) -> bool:
        constraint = self.param.constraint
        return not (constraint == "positive" and x <= 0 or constraint == "nonnegative" and x < 0
                    or constraint == "nonzero" and x == 0)

    # -- the grid ------------------------------------------------------------------------

    def grid(self) -> list[float]:
        """The coarse grid: every STEP decades (both signs for a signed parameter), or every
        ANGLE_STEP degrees of an angle up to 180."""
        if self.param.dim is ANGLE:  # and a tail toward 180 degrees, where periods diverge
            tail = [180 - 10.0 ** -k for k in range(0, 8)]
            return [math.radians(d) for d in [*range(0, 180, ANGLE_STEP), *tail]] + [math.pi]
        # the domain's own ends: the smallest subnormal and the largest float
        decades = [TINY, *(10.0 ** e for e in range(LOW, HIGH + 1, STEP)), HUGE]
        if self.param.constraint == "positive":
            return decades
        if self.param.constraint == "nonnegative":
            return [0.0, *decades]
        return [-d for d in reversed(decades)] + [0.0] + decades

    # -- solving ---------------------------------------------------------------------------

    def _root_between(self, lo: float, hi: float, goal: float) -> float | None:
        """The root of ``y - goal`` in ``[lo, hi]`` if the ends bracket one, else ``None``."""
        g_lo, g_hi = self.y(lo) - goal, self.y(hi) - goal
        if not (math.isfinite(g_lo) and math.isfinite(g_hi)):
            return None
        if g_lo == 0 or g_hi == 0:
            return lo if g_lo == 0 else hi
        if (g_lo > 0) == (g_hi > 0):  # by the signs: a product of two tiny ones underflows
            return None
        return _brent(lambda x: self.y(x) - goal, lo, hi)

    def roots(self, goal: float) -> tuple[list[float], tuple[str, str]]:
        """Every ``x`` with ``y(x) = goal``, ascending, and how they were found."""
        if not math.isfinite(goal):
            return [], ("none", "")
        power = self._power_law() if self.param.constraint in ("positive", "nonnegative") \
            and self.param.dim is not ANGLE else None
        if power is not None:
            x1, y1, a = power
            if goal > 0 and y1 > 0:
                try:  # x = x1 (goal / y1)^(1/a), in logarithms (the ratio may not be a float)
                    x = x1 * math.exp((math.log(goal) - math.log(y1)) / float(a))
                except OverflowError:
                    x = math.inf
                if math.isfinite(x) and x > 0 and self._close(self.y(x), goal):
                    return [x], ("closed-form", f"{self.target} is proportional to "
                                                f"{self.param.name}^({a}): inverted exactly")
            # not a power law after all (one only where the probes were): search
        how = ("bracketed-root", f"a sign change on a grid of {self.param.name}, refined by "
                                 "Brent's method")
        if self.method not in (None, "auto") and self.scene.methods:
            near = self._from_scout(goal)
            if near is not None:
                return near, how
        return self._bracketed(goal), how

    def _from_scout(self, goal: float) -> list[float] | None:
        """The roots of a method chosen with ``--method`` (an ODE, say), found by scanning
        with the cheapest model good to 1e-6 and bracketing each root anew, within 1e-6 to
        1e-2 of it, with the chosen method; ``None`` when that does not find them all (the
        whole scan is then made with the chosen method)."""
        scout = _Problem(self.scene, self.prepared, self.param, self.target, None, 1e-6)
        try:
            near = scout._bracketed(goal)
        except _Independent:
            raise  # whatever the model: no need to scan again with the expensive one
        except InputError:
            return None
        roots = []
        for r in near:
            for width in (1e-6, 1e-4, 1e-2):
                step = width * abs(r) if r != 0 else width
                root = self._root_between(r - step, r + step, goal)
                if root is not None:
                    roots.append(root)
                    break
            else:
                return None
        if not roots:
            return None
        self.seen |= scout.seen
        self.samples = scout.samples
        return _distinct(roots)

    @staticmethod
    def _close(y: float, goal: float) -> bool:
        return math.isfinite(y) and abs(y - goal) <= 1e-12 * abs(goal)

    def _power_law(self):
        """``(x1, y1, a)`` when ``y = C x^a`` with a simple fraction ``a``, else ``None``."""
        xs = (1e-3, 1.0, 1e3)
        ys = [self.y(x) for x in xs]
        if not all(math.isfinite(y) and y > 0 for y in ys):
            return None
        slopes = [(math.log(ys[i + 1]) - math.log(ys[i])) / math.log(xs[i + 1] / xs[i])
                  for i in (0, 1)]
        if abs(slopes[0] - slopes[1]) > 1e-9 or abs(slopes[0]) < 1e-9:
            return None
        a = Fraction(slopes[0]).limit_denominator(4)
        if abs(float(a) - slopes[0]) > 1e-9:
            return None
        return xs[1], ys[1], a

    def _bracketed(self, goal: float) -> list[float]:
        """Every root of ``y - goal``: the coarse grid, refined next to sign changes, turning
        points and edges (:meth:`_refine`), every edge of where the scene answers approached
        to the last float (:meth:`_edges`), every extremum located (:meth:`_extrema`); then
        each sign change between neighbours is a bracket, and an extremum that reaches the
        goal to rounding is a (double) root."""
        xs = self.grid()
        ys = [self.y(x) for x in xs]
        self.samples = [y for y in ys if math.isfinite(y)]
        if self.target not in self.seen:
            return []
        self._refuse_flat()  # on the coarse grid: every interval would be refined otherwise
        xs, ys = self._refine(xs, ys, goal)
        xs, ys = self._edges(xs, ys)
        xs, ys, touching = self._extrema(xs, ys, goal)
        self.samples = [y for y in ys if math.isfinite(y)]
        gs = [y - goal for y in ys]
        roots = list(touching)
        for (x0, g0), (x1, g1) in zip(zip(xs, gs), zip(xs[1:], gs[1:])):
            if not (math.isfinite(g0) and math.isfinite(g1)):
                continue
            if g0 == 0:
                roots.append(x0)
            elif (g0 > 0) != (g1 > 0) and g1 != 0:  # signs, not a product that underflows
                try:
                    roots.append(_brent(lambda x: self.y(x) - goal, x0, x1))
                except (ValueError, RuntimeError):
                    continue
        if gs and math.isfinite(gs[-1]) and gs[-1] == 0:
            roots.append(xs[-1])
        roots = _distinct(_touched(roots, touching, xs, gs, TOUCH * abs(goal)))
        if len(roots) > MAX_ROOTS:
            raise InputError(f"{len(roots)} values of {self.param.name} give {self.target} = "
                             f"{goal:.6g} {self.kind_unit} in {self.scene.name}; give "
                             f"{self.param.name} and solve for another parameter")
        return roots

    def _refuse_flat(self) -> None:
        """Refuse a target that takes one value on the whole grid: it does not depend on the
        unknown."""
        if len(self.samples) > 1 and max(self.samples) - min(self.samples) <= \
                1e-12 * max(abs(v) for v in self.samples):
            raise _Independent(f"{self.target} does not depend on {self.param.name} in "
                               f"{self.scene.name} (it is {self.samples[0]:.6g} whatever "
                               f"{self.param.name} is): {self.param.name} cannot be solved "
                               f"for from {self.target}")

    def _edges(self, xs: list[float], ys: list[float]):
        """The samples with every edge of where the scene answers (a finite result next to a
        refused or infinite one) located to adjacent floats (:func:`float_boundary`) and
        approached from the answering side 1, 2, 4, ... floats away (:func:`float_approach`):
        a result that diverges or ends there (``R -> r``, an amplitude -> 90 degrees) is then
        sampled evenly in its own scale, down to the last float."""
        from ..physics.numerics import float_approach, float_boundary

        added: dict[float, float] = {}
        for i in range(len(xs) - 1):
            fine = [math.isfinite(ys[i]), math.isfinite(ys[i + 1])]
            if fine[0] == fine[1]:
                continue
            good, bad = (xs[i], xs[i + 1]) if fine[0] else (xs[i + 1], xs[i])
            known: dict[float, float] = {}

            def answers(x: float, known=known) -> bool:
                known[x] = self.y(x)
                return math.isfinite(known[x])

            edge, _tried = float_boundary(answers, good, bad)
            added.update(known)
            at_edge = known[edge] if edge in known else self.y(edge)
            added[edge] = at_edge
            # from afar inward, until the values are those of the edge itself (a result that
            # is smooth up to the edge: the edge brackets the rest; one that diverges or
            # ends there: down to the last float)
            for x in reversed(float_approach(edge, good)):
                added[x] = y = self.y(x)
                if math.isfinite(y) and abs(y - at_edge) <= self.noise * abs(at_edge):
                    break
        return _merged(xs, ys, added)

    def _extrema(self, xs: list[float], ys: list[float], goal: float):
        """The samples with the extremum inside every turning point of the samples (where the
        sign of the slope changes, flat steps skipped) located by a bracketed minimisation
        (:func:`bracketed_minimum`, in ``log |x|`` where the bracket keeps one sign): two roots
        on either side of a peak are then split by it. Also the extrema that meet the goal to
        rounding (a double root at the peak itself)."""
        from ..physics.numerics import bracketed_minimum

        added: dict[float, float] = {}
        touching = []
        for lo, mid, hi in _turning_points(xs, ys, self.noise):
            sense = -1.0 if ys[mid] > ys[lo] else 1.0   # a maximum is the minimum of -y
            a, b, c = xs[lo], xs[mid], xs[hi]
            if a > 0 or c < 0:
                sign = 1.0 if a > 0 else -1.0
                to_x = (lambda u, sign=sign: sign * math.exp(u))
                bracket = [math.log(abs(v)) for v in (a, b, c)]
                xtol, rtol = 1.5e-8, 0.0   # sqrt(eps) relative in x: y to rounding
            else:
                to_x = (lambda u: u)
                bracket, xtol, rtol = [a, b, c], 1e-300, 1.5e-8
            seen: dict[float, float] = {}

            def objective(u: float, to_x=to_x, seen=seen, sense=sense) -> float:
                x = to_x(u)
                seen[x] = self.y(x)
                return sense * seen[x]

            best = bracketed_minimum(objective, *bracket, xtol=xtol, rtol=rtol, max_iter=60)
            added.update(seen)
            x_best = to_x(best.x)
            y_best = seen.get(x_best, math.nan)
            if math.isfinite(y_best) and abs(y_best - goal) <= TOUCH * abs(goal):
                touching.append(x_best)
        xs, ys = _merged(xs, ys, added)
        return xs, ys, touching
    def _refine(self, xs: list[float], ys: list[float], goal: float):
        """Add FINE points to every coarse interval next to a sign change of ``y - goal``,
        a turning point or the edge of where the scene answers, so that two roots close
        together are both bracketed."""
        fine = FINE_ANGLE if self.param.dim is ANGLE else FINE
        gs = [y - goal for y in ys]
        marked = set()
        for i in range(len(xs) - 1):
            a, b = gs[i], gs[i + 1]
            if math.isfinite(a) != math.isfinite(b) or (math.isfinite(a) and a * b <= 0):
                marked.add(i)
        for lo, mid, hi in _turning_points(xs, ys, self.noise):
            # the steps into and out of it and the extreme sample's neighbours (not a long
            # flat stretch between them: an even function's trough at 0 is flat for decades)
            marked.update(i for i in (lo, mid - 1, mid, hi - 1) if 0 <= i < len(xs) - 1)
        out_x, out_y = [], []
        for i, x in enumerate(xs):
            out_x.append(x)
            out_y.append(ys[i])
            if i not in marked:
                continue
            nxt = xs[i + 1]
            geometric = x * nxt > 0 and self.param.dim is not ANGLE
            for j in range(1, fine):
                xj = x * (nxt / x) ** (j / fine) if geometric else x + (nxt - x) * j / fine
                out_x.append(xj)
                out_y.append(self.y(xj))
        return out_x, out_y

    def no_root_message(self, goal_text: str) -> str:
        span = "; the scene refused every value of it tried" if not self.seen else ""
        if self.samples:
            span = (f"; over the values of {self.param.name} tried it ranges from "
                    f"{min(self.samples):.6g} to {max(self.samples):.6g} "
                    f"{self.kind_unit}".rstrip())
        return (f"no value of {self.param.name} gives {self.target} = {goal_text} in "
                f"{self.scene.name} with the other parameters given{span}")


def _brent(g, lo: float, hi: float) -> float:
    """The root of ``g`` in ``[lo, hi]`` (a sign change) to full precision by Brent's method:
    :func:`~dyncalc.physics.brent_arrays.brent_roots` on one bracket (scipy's brentq to the
    bit, without importing scipy); ValueError where ``g`` is NaN or does not change sign,
    RuntimeError where 200 iterations do not converge (as brentq)."""
    from ..physics.brent_arrays import RTOL_MIN, brent_roots

    out = brent_roots(lambda x, _rows: np.array([g(float(x[0]))]), np.array([lo]),
                      np.array([hi]), xtol=1e-300, rtol=RTOL_MIN, maxiter=200)
    if out.nan[0]:
        raise ValueError(f"no root of the bracket [{lo!r}, {hi!r}]: a NaN or no sign change")
    if not out.converged[0]:
        raise RuntimeError("Brent's method did not converge in 200 iterations")
    return float(out.x[0])


def _merged(xs: list[float], ys: list[float], added: dict[float, float]):
    """The samples ``xs, ys`` with ``added`` (x -> y) merged in, ascending in x."""
    if not added:
        return xs, ys
    points = dict(zip(xs, ys))
    points.update(added)
    order = sorted(points)
    return order, [points[x] for x in order]


def _turning_points(xs: list[float], ys: list[float], noise: float):
    """``(lo, mid, hi)`` indices around every turning point of the finite samples: the
    direction of the steps changes between ``lo -> ...`` and ``... -> hi``, counting only
    steps larger than ``noise`` relative (the rounding or model error of a result that is flat
    to it, an asymptote, is no extremum), and ``ys[mid]`` is the largest (smallest) sample
    between them, beyond both ends."""
    out = []
    run: list[int] = []
    for i in range(len(xs) + 1):
        if i < len(xs) and math.isfinite(ys[i]):
            run.append(i)
            continue
        steps = [(a, b) for a, b in zip(run, run[1:])
                 if abs(ys[b] - ys[a]) > noise * max(abs(ys[a]), abs(ys[b]))]
        for (a, b), (c, d) in zip(steps, steps[1:]):
            rising = ys[b] > ys[a]
            if rising != (ys[d] > ys[c]):
                inner = range(b, c + 1)
                mid = max(inner, key=ys.__getitem__) if rising else \
                    min(inner, key=ys.__getitem__)
                out.append((a, mid, d))
        run = []
    return out


def _touched(roots: list[float], touching: list[float], xs: list[float], gs: list[float],
             band: float) -> list[float]:
    """``roots`` with those that an extremum touching the goal absorbs: the roots from which
    ``y - goal`` stays within rounding (``band``) of zero all the way to the extremum. They
    are the one double root there, split by rounding noise (the values near a peak are flat to
    about ``sqrt(eps)`` of ``x``)."""
    if not touching:
        return roots
    kept = []
    for r in roots:
        absorbed = False
        for t in touching:
            lo, hi = min(r, t), max(r, t)
            between = [g for x, g in zip(xs, gs) if lo <= x <= hi]
            if all(math.isfinite(g) and abs(g) <= band for g in between):
                absorbed = True
                break
        if not absorbed:
            kept.append(r)
    return kept + list(touching)


def _distinct(roots: list[float]) -> list[float]:
    out: list[float] = []
    for r in sorted(roots):
        if not out or abs(r - out[-1]) > 1e-9 * max(abs(r), abs(out[-1])):
            out.append(r)
    return out
