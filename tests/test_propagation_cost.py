"""The cost of uncertainty propagation grows at most linearly with the number of uncertain
inputs (SPEC, "Uncertainty"; issue 15 asks for a test that holds it).

Cost is counted, not timed: every Python function call into ``dyncalc/physics/`` during a run
(``sys.setprofile``), so the work inside the careful kernels (one ``two_product`` per spring of
a series sum, ...) counts too, and a propagation that recomputed the whole network once per
uncertain input (n inputs x n springs) would show as quadratic. For a scene the count is of
its physics function's calls. Linear growth ``a + b n`` with ``a >= 0`` satisfies
``calls(2n) <= 2 calls(n)``; anything faster than linear eventually breaks it.
"""
import sys

import pytest

from dyncalc.commands.natural_frequency import compute_scene
from dyncalc.result.propagate import propagate
from dyncalc.scenes import get_scene
from helpers import invoke


def physics_calls(*args) -> int:
    """Calls into dyncalc/physics/ while ``dyncalc ARGS --json`` runs (asserting exit 0)."""
    count = 0

    def profile(frame, event, _arg):
        nonlocal count
        if event == "call" and "/dyncalc/physics/" in frame.f_code.co_filename.replace("\\", "/"):
            count += 1

    sys.setprofile(profile)
    try:
        result = invoke(*args, "--json")
    finally:
        sys.setprofile(None)
    assert result.exit_code == 0, result.stderr
    assert '"uncertainty"' in result.stdout
    return count


def springs(n: int) -> list[str]:
    return [f"{100 + i} N/m ± 1%" for i in range(n)]


def test_spring_series_propagation_is_linear_in_the_springs():
    """10, 20 and 40 uncertain springs in series."""
    physics_calls("spring-series", *springs(3))        # the lazy imports, not counted below
    calls = {n: physics_calls("spring-series", *springs(n)) for n in (10, 20, 40)}
    assert calls[10] < calls[20] < calls[40], calls   # the counter sees the physics
    assert calls[20] <= 2 * calls[10], calls
    assert calls[40] <= 2 * calls[20], calls


CLOCK = {"m": ("0.5", "kg"), "l": ("1", "m"), "M": ("2", "kg"), "r": ("0.1", "m"),
         "a": ("0.9", "m"), "g": ("9.81", "m/s^2")}


def clock_words(uncertain: int, leave_out: str = "") -> list[str]:
    """The clock pendulum's parameters, the first ``uncertain`` of them with ± 1 %."""
    names = [n for n in CLOCK if n != leave_out]
    return [f"{n}={CLOCK[n][0]} {CLOCK[n][1]} ± 1%" if i < uncertain
            else f"{n}={CLOCK[n][0]} {CLOCK[n][1]}" for i, n in enumerate(names)]


def test_scene_propagation_is_linear_in_its_uncertain_parameters():
    """clock-pendulum with 1, 2, 3 and 6 of its parameters uncertain."""
    physics_calls("natural-frequency", "--scene", "clock-pendulum", *clock_words(1))
    calls = {k: physics_calls("natural-frequency", "--scene", "clock-pendulum",
                              *clock_words(k)) for k in (1, 2, 3, 6)}
    assert calls[1] < calls[2] < calls[3] < calls[6], calls
    assert calls[2] <= 2 * calls[1], calls
    assert calls[6] <= 2 * calls[3], calls


def test_scene_propagation_calls_its_physics_twice_per_uncertain_input():
    """The same scene, its physics function counted: one forward run and two nudged runs (a
    central difference) per uncertain input, exactly."""
    scene = get_scene("clock-pendulum")
    calls = []
    counted = scene.replace(compute=lambda **kw: calls.append(1) or scene.compute(**kw))
    for k in range(7):
        calls.clear()
        texts = dict(w.split("=", 1) for w in clock_words(k))
        propagate(lambda: compute_scene(counted, texts))
        assert len(calls) == 1 + 2 * k, (k, len(calls))


@pytest.mark.parametrize("n", [1, 2])
def test_inverse_propagation_is_linear_in_its_uncertain_inputs(n):
    """clock-pendulum solved for a from omega = 4.5 rad/s (two roots) with n, 2n of the other
    parameters uncertain: the search costs the same whatever the uncertainties, and the
    propagation on top of it (the implicit function theorem at each root: two scene runs per
    uncertain input and per root, plus two for the slope in a) at most doubles."""
    scene = get_scene("clock-pendulum")
    calls = []
    counted = scene.replace(compute=lambda **kw: calls.append(1) or scene.compute(**kw))

    def cost(k: int) -> int:
        calls.clear()
        texts = dict(w.split("=", 1) for w in clock_words(k, leave_out="a"))
        texts["omega"] = "4.5 rad/s"
        result = propagate(lambda: compute_scene(counted, texts))
        assert {"a_1", "a_2"} <= set(result.results)
        return len(calls)

    search = cost(0)
    extra = {k: cost(k) - search for k in (n, 2 * n)}
    assert 0 < extra[n] < extra[2 * n] <= 2 * extra[n], (search, extra)
