"""The N, V, M diagrams of ``rigid-body --plot``, built from a Result before anything is drawn
(:func:`dyncalc.cli.plot.plot_loads` draws them): the stress resultants along the bar of
``beam-spun-up`` and along both legs of ``rotating-angled-arm``.

Every point comes from the scene's own formulas (:mod:`dyncalc.physics.kinetics_loads`), so
the curves pass through the section the command reports.
"""
from __future__ import annotations

from ..errors import InputError
from ..physics.kinetics_loads import arm_leg_a, arm_leg_b, beam_loads
from ..result import Result

__all__ = ["Leg", "LoadDiagram", "load_diagram", "DIAGRAM_SCENES"]

#: The scenes whose stress resultants ``--plot`` draws.
DIAGRAM_SCENES = ("beam-spun-up", "rotating-angled-arm")


class Leg:
    """One straight part of the bar: its ``name``, the coordinate's ``label``, positions ``x``
    (m) and ``N``, ``V`` (N), ``M`` (N m) on them; ``section`` the position asked for on this
    leg (or ``None``)."""

    __slots__ = ("name", "label", "x", "N", "V", "M", "section")

    def __init__(self, name, label, x, N, V, M, section=None):
        self.name, self.label, self.x, self.N, self.V, self.M = name, label, x, N, V, M
        self.section = section


class LoadDiagram:
    """The legs of a diagram and a title."""

    __slots__ = ("legs", "title")

    def __init__(self, legs, title):
        self.legs, self.title = legs, title


def _si(result: Result, name: str, needed: bool = True):
    """A parameter's SI value, given (inputs) or solved for (results); ``None`` for an
    optional one left out. Refuses a needed one solved with several roots."""
    entry = result.inputs.get(name) or result.results.get(name)
    if entry is not None:
        return float(entry.si)
    roots = [n for n in result.results if n.startswith(name + "_") and n[len(name) + 1:].isdigit()]
    if needed and roots:
        raise InputError(f"--plot: {name} has {len(roots)} solutions ({', '.join(roots)}): give "
                         f"one of them as {name}= to draw the diagrams")
    return None


def _grid(length: float, points: int, section: float | None) -> list[float]:
    xs = [length * i / (points - 1) for i in range(points)]
    if section is not None and section not in xs:
        xs = sorted([*xs, section])
    return xs


def load_diagram(result: Result, points: int = 201) -> LoadDiagram:
    """The diagrams of a ``rigid-body`` result of :data:`DIAGRAM_SCENES` at ``points``
    positions per leg (the section asked for among them); refuses any other result with
    the reason.

    >>> from dyncalc.commands.rigid_body import rigid_body
    >>> r = rigid_body({}, ["m=6kg", "l=2m", "M0=12 N*m", "x=0.5m", "t=2s"],
    ...                scene="beam-spun-up")
    >>> leg = load_diagram(r, points=3).legs[0]
    >>> leg.x, leg.M
    ([0.0, 0.5, 1.0, 2.0], [-12.0, -7.59375, -3.75, 0.0])
    """
    scene = result.scene
    if scene not in DIAGRAM_SCENES:
        what = f"{scene} has no stress resultants along a bar" if scene else \
            "Euler's equations give one moment, not a diagram"
        raise InputError(f"--plot: the N, V, M diagrams are drawn for "
                         f"{' and '.join(DIAGRAM_SCENES)}; {what}")
    if scene == "beam-spun-up":
        m, l, M0 = (_si(result, n) for n in ("m", "l", "M0"))
        t = _si(result, "t", needed=False)
        if t is None:
            raise InputError("--plot: beam-spun-up's normal force N grows with t^2: give t= "
                             "to draw the N, V, M diagrams")
        x = _si(result, "x", needed=False)
        xs = _grid(l, points, x)
        rows = [beam_loads(m, l, M0, s, t) for s in xs]
        legs = [Leg("beam", "x from the pin A (m)", xs, *map(list, zip(*rows)), section=x)]
        return LoadDiagram(legs, f"beam-spun-up at t = {t:g} s")
    m, a, b, W = (_si(result, n) for n in ("m", "a", "b", "Omega"))
    mu_W2 = m / (a + b) * W * W
    x1, x2 = _si(result, "x1", needed=False), _si(result, "x2", needed=False)
    legs = []
    for name, label, length, section, loads in (
            ("leg b", "x1 from the free end E (m)", b, x1, arm_leg_b),
            ("leg a", "x2 from the corner K (m)", a, x2, arm_leg_a)):
        xs = _grid(length, points, section)
        rows = [loads(mu_W2, a, b, s) for s in xs]
        legs.append(Leg(name, label, xs, *map(list, zip(*rows)), section=section))
    return LoadDiagram(legs, f"rotating-angled-arm at Omega = {W:g} rad/s")
