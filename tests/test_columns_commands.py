"""The commands' column adapters (``columns(given, settings)``) against the one-off commands.

Every row is also computed the one-off way, through the command's own ``compute`` with the
texts a batch row hands it, and its ``--json`` results are compared with the adapter's values
JSON-encoded the same way (so a -0.0, an ulp or a name out of order fails). Rows where the
one-off refuses or warns must not be exact; ordinary rows must mostly be exact.
"""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

from dyncalc.errors import InputError, PhysicsError
from dyncalc.result.encode import _json_value, json_data
from dyncalc.units import parse_quantity, parse_vector

RNG_SEED = 20240611


def _one_off(compute):
    """(JSON text of the results' values, warnings, model, method), or None if it raises."""
    try:
        result = compute()
    except (InputError, PhysicsError):
        return None
    data = json_data(result, {}, [], False)
    values = [(name, item["value"]) for name, item in data["results"].items()]
    return json.dumps(values), data["warnings"], data["model"], data["method"]


def _columns_row(cols, i: int) -> str:
    return json.dumps([(name, _json_value(value[i])) for name, value in cols.values.items()])


def _compare(cols, rows, ordinary=None, share=0.9):
    """Check the adapter's Columns against the one-off per row (``rows``: a list of
    functions computing the one-off); returns the exact mask."""
    exact = np.asarray(cols.exact, dtype=bool)
    assert exact.shape == (len(rows),)
    for i, compute in enumerate(rows):
        got = _one_off(compute)
        if got is None or got[1]:
            assert not exact[i], (i, got)
            continue
        if exact[i]:
            text, _warnings, model, method = got
            assert _columns_row(cols, i) == text, i
            assert (cols.model, cols.method) == (model, method)
    if ordinary is not None:
        assert exact[ordinary].mean() >= share, exact[ordinary].mean()
    return exact


def _si(texts, dim):
    return np.array([parse_quantity(t, dim).si for t in texts])


def _log_uniform(rng, low, high, n):
    return 10.0 ** rng.uniform(low, high, n)


# --- springs -------------------------------------------------------------------------------

@pytest.mark.parametrize("how", ["series", "parallel"])
def test_springs_columns_match_the_one_off(how):
    from dyncalc.commands.springs import columns, network_stiffness
    from dyncalc.units import STIFFNESS

    rng = np.random.default_rng(RNG_SEED)
    n, elements = 240, 3
    k = _log_uniform(rng, -3, 6, (n, elements))
    k[:20] = _log_uniform(rng, -300, 300, (20, elements))      # extremes
    k[20:24] = [[1e-320, 1.0, 2.0], [1e308, 1e308, 1.0], [5e-324, 5e-324, 5e-324],
                [1.7e308, 1.7e308, 1.7e308]]                    # underflow, overflow
    k[24] = [200.0, 300.0, 600.0]                                # 1/(1/200+1/300+1/600) = 100
    texts = [[f"{float(x)!r} N/m" for x in row] for row in k]
    given = {f"k{j + 1}": _si([t[j] for t in texts], STIFFNESS) for j in range(elements)}
    assert columns(given, {"how": how}) is None       # the unit typed is not known
    cols = columns(given, {"how": how, "units": {"k1": "N/m", "k2": "N/m", "k3": "N/m"}})
    rows = [lambda t=t: network_stiffness(how, t) for t in texts]
    exact = _compare(cols, rows, ordinary=np.arange(25, n))
    assert not exact[22 if how == "series" else 23]      # k_eq underflows / overflows
    assert exact[20] and cols.values["k_eq"][20] == (1e-320 if how == "series" else 3.0)
    expected = 100.0 if how == "series" else 1100.0
    assert exact[24] and cols.values["k_eq"][24] == expected


def test_springs_columns_torsional_and_refusals():
    from dyncalc.commands.springs import columns, network_stiffness
    from dyncalc.units import TORSIONAL_STIFFNESS

    texts = [["0.1 N*m/rad", "0.2 N*m/rad"], ["3 N*m/rad", "6 N*m/rad"]]
    given = {f"k{j + 1}": _si([t[j] for t in texts], TORSIONAL_STIFFNESS) for j in range(2)}
    for how in ("series", "parallel"):
        cols = columns(given, {"how": how, "units": {"k1": "N*m/rad"}})
        exact = _compare(cols, [lambda t=t: network_stiffness(how, t) for t in texts])
        assert exact.all()
    assert cols.values["k_eq"].tolist() == [math.fsum([0.1, 0.2]), 9.0]
    # the one-off adds in the first element's unit: not the SI sum
    assert columns(given, {"how": "series", "units": {"k1": "lbf/in"}}) is None
    assert columns({"k1": given["k1"], "EI": given["k2"]},
                   {"how": "series", "units": {"k1": ""}}) is None
    assert columns(given, {"how": "sideways", "units": {"k1": ""}}) is None


# --- damping-ratio -------------------------------------------------------------------------

def _damping_rows(texts: dict, n: int):
    from dyncalc.commands.damping_ratio import COMMAND

    names = [p.name for p in COMMAND.inputs]
    rows = []
    for i in range(n):
        values = {name: (texts[name][i] if name in texts else None) for name in names}
        values.update(scene=None, method=None)
        rows.append(lambda v=values: COMMAND.compute(v, (), rtol=None, strict=False))
    return rows


def test_damping_columns_from_coefficients():
    from dyncalc.commands.damping_ratio import columns
    from dyncalc.units import DAMPING, MASS, STIFFNESS

    rng = np.random.default_rng(RNG_SEED + 1)
    n = 300
    k, m = _log_uniform(rng, -4, 6, n), _log_uniform(rng, -4, 4, n)
    c = 2.0 * np.sqrt(k * m) * rng.uniform(0.001, 0.999, n)       # underdamped
    c[:30] = 2.0 * np.sqrt(k[:30] * m[:30]) * rng.uniform(1.001, 5.0, 30)   # overdamped
    c[30:35] = 0.0                                                  # undamped: a note
    c[35] = 2.0 * math.sqrt(k[35] * m[35])                          # critical: a note
    k[36:46], m[36:46] = _log_uniform(rng, -300, 300, 10), _log_uniform(rng, -300, 300, 10)
    c[36:46] = _log_uniform(rng, -300, 300, 10)
    c[46], k[46], m[46] = 4.0, 100.0, 1.0                           # zeta = 0.2 exactly
    texts = {"c": [f"{float(x) / 1000!r} kN*s/m" for x in c], "k": [f"{float(x)!r} N/m" for x in k],
             "m": [f"{float(x) * 1000!r} g" for x in m]}
    given = {"c": _si(texts["c"], DAMPING), "k": _si(texts["k"], STIFFNESS),
             "m": _si(texts["m"], MASS)}
    cols = columns(given, {"scene": None, "method": None})
    assert list(cols.values) == ["zeta", "delta", "regime", "Q", "c_c", "c", "omega", "xi",
                                 "omega_d", "f_d", "T_d"]
    exact = _compare(cols, _damping_rows(texts, n), ordinary=np.arange(47, n))
    assert not exact[:36].any()
    assert exact[46] and cols.values["zeta"][46] == 0.2
    assert cols.values["regime"][46] == "underdamped"


@pytest.mark.parametrize("extra", ["omega", "km", ""])
def test_damping_columns_from_a_decrement(extra):
    from dyncalc.commands.damping_ratio import columns
    from dyncalc.units import ANGULAR_RATE, DIMENSIONLESS, MASS, STIFFNESS

    rng = np.random.default_rng(RNG_SEED + 2)
    n = 200
    delta = _log_uniform(rng, -6, 2, n)
    delta[:3] = [0.0, 1e-320, 1e300]                # undamped (a note), Q overflows, huge
    delta[3] = math.log(10) / 10                    # E5.18
    texts = {"decrement": [repr(float(x)) for x in delta]}
    given = {"decrement": _si(texts["decrement"], DIMENSIONLESS)}
    if extra == "omega":
        texts["omega"] = [f"{float(x)!r} rad/s" for x in _log_uniform(rng, -3, 5, n)]
        given["omega"] = _si(texts["omega"], ANGULAR_RATE)
    elif extra == "km":
        texts["k"] = [f"{float(x)!r} N/m" for x in _log_uniform(rng, -3, 6, n)]
        texts["m"] = [f"{float(x)!r} kg" for x in _log_uniform(rng, -3, 3, n)]
        given.update(k=_si(texts["k"], STIFFNESS), m=_si(texts["m"], MASS))
    cols = columns(given, {"scene": None, "method": "closed-form"})
    exact = _compare(cols, _damping_rows(texts, n), ordinary=np.arange(4, n))
    assert not exact[:2].any() and exact[3]
    assert round(cols.values["zeta"][3], 9) == 0.036622197   # Gross et al., E5.18


def test_damping_columns_from_a_ratio():
    from dyncalc.commands.damping_ratio import columns
    from dyncalc.units import DIMENSIONLESS

    rng = np.random.default_rng(RNG_SEED + 3)
    n = 200
    ratio = 1.0 + _log_uniform(rng, -8, 3, n)
    ratio[:3] = [1.0, 0.5, 10.0]                     # no decay (a note), refused, E5.18
    cycles = rng.integers(1, 50, n).astype(str).astype(object)
    cycles[2] = "10"
    cycles[3:6] = ["1e1", "0", " 7 "]                # read by the one-off / refused / plain
    texts = {"ratio": [repr(float(x)) for x in ratio], "cycles": list(cycles)}
    given = {"ratio": _si(texts["ratio"], DIMENSIONLESS), "cycles": np.array(cycles, dtype=str)}
    cols = columns(given, {"scene": None, "method": None})
    exact = _compare(cols, _damping_rows(texts, n), ordinary=np.arange(6, n))
    assert not exact[:2].any() and not exact[3:5].any() and exact[2] and exact[5]
    assert round(cols.values["zeta"][2], 9) == 0.036622197   # Gross et al., E5.18
    # a numeric cycles column works the same
    numeric = columns({"ratio": given["ratio"], "cycles": np.where(
        exact, np.array([float(str(c)) if str(c).strip().isdigit() else 1.0 for c in cycles]),
        1.0)}, {})
    assert np.array_equal(numeric.values["zeta"][exact], cols.values["zeta"][exact])


def test_damping_columns_refuse_what_they_do_not_vectorise():
    from dyncalc.commands.damping_ratio import columns

    one = np.ones(2)
    assert columns({"c": one, "k": one, "m": one}, {"scene": "rod-in-fluid"}) is None
    assert columns({"decrement": one}, {"method": "nonlinear"}) is None
    assert columns({"amplitudes": np.array(["1,0.5", "2,1"])}, {}) is None
    assert columns({"decrement": one, "ratio": one}, {}) is None       # two forms
    assert columns({"decrement": one, "k": one}, {}) is None           # k without m
    assert columns({"decrement": one, "omega": one, "k": one, "m": one}, {}) is None
    assert columns({"c": one, "k": one}, {}) is None
    assert columns({"cycles": one}, {}) is None


# --- coriolis ------------------------------------------------------------------------------

_VECTOR_UNITS = {"omega": "rad/s", "vr": "m/s", "r": "m", "alpha": "rad/s^2", "a0": "m/s^2",
                 "ar": "m/s^2"}


def _coriolis_rows(texts: dict, n: int):
    from dyncalc.commands.coriolis import COMMAND

    names = [p.name for p in COMMAND.inputs]
    rows = []
    for i in range(n):
        values = {name: (texts[name][i] if name in texts else None) for name in names}
        rows.append(lambda v=values: COMMAND.compute(v, (), rtol=None, strict=False))
    return rows


def _coriolis_given(texts: dict):
    from dyncalc.commands.coriolis import OPTIONS

    return {name: np.array([parse_vector(t, OPTIONS[name][0], allow_scalar=True).si
                            for t in column]) for name, column in texts.items()}


@pytest.mark.parametrize("which", [("omega", "vr"), ("omega", "vr", "mass"),
                                   ("omega", "vr", "r", "alpha", "a0", "ar", "mass"),
                                   ("omega", "vr", "a0")])
def test_coriolis_columns_vectors(which):
    from dyncalc.commands.coriolis import columns

    rng = np.random.default_rng(RNG_SEED + 4)
    n = 150
    texts = {}
    for name in which:
        if name == "mass":
            texts[name] = [f"{float(x)!r} kg" for x in _log_uniform(rng, -3, 3, n)]
            continue
        v = _log_uniform(rng, -3, 3, (n, 3)) * rng.choice([-1.0, 1.0], (n, 3))
        v *= rng.random((n, 3)) > 0.15                   # some zero components
        v[:8] = _log_uniform(rng, -300, 300, (8, 3))     # extremes: overflows, underflows
        if name == "omega":
            v[8] = [0.0, 0.0, 2.0]
        if name == "vr":
            v[8] = [3.0, 0.0, 0.0]                       # a_c = 2 Omega x v_r = (0, 12, 0)
        texts[name] = [",".join(repr(float(x)) for x in row) + " " + _VECTOR_UNITS[name]
                       for row in v]
    cols = columns(_coriolis_given(texts), {})
    exact = _compare(cols, _coriolis_rows(texts, n), ordinary=np.arange(9, n))
    assert exact[8] and cols.values["a_c"][8].tolist() == [0.0, 12.0, 0.0]
    assert cols.values["a_c_mag"][8] == 12.0
    assert not exact[:8].all()


@pytest.mark.parametrize("which", [("omega", "vr"), ("omega", "vr", "r", "mass"),
                                   ("omega", "vr", "alpha"), ("omega", "vr", "r", "alpha")])
def test_coriolis_columns_magnitudes(which):
    from dyncalc.commands.coriolis import columns

    rng = np.random.default_rng(RNG_SEED + 5)
    n = 150
    units = {**_VECTOR_UNITS, "mass": "kg"}
    values = {name: _log_uniform(rng, -3, 3, n) for name in which}
    for name in which:
        values[name][:6] = _log_uniform(rng, -300, 300, 6)
        values[name][6] = 0.0 if name == "r" else 1.5
    if "vr" in values:
        values["vr"][7] = -1.0                           # a magnitude must not be negative
        values["omega"][8], values["vr"][8] = 2.0, 3.0   # a_c = 2 Omega v_r = 12
    texts = {name: [f"{float(x)!r} {units[name]}" for x in column]
             for name, column in values.items()}
    cols = columns(_coriolis_given(texts), {})
    exact = _compare(cols, _coriolis_rows(texts, n), ordinary=np.arange(9, n))
    assert not exact[7] and exact[8] and cols.values["a_c"][8] == 12.0


def test_coriolis_columns_refuse_what_they_do_not_vectorise():
    from dyncalc.commands.coriolis import columns

    one, vec = np.ones(2), np.ones((2, 3))
    assert columns({"latitude": one, "vr": vec}, {}) is None          # the Earth form
    assert columns({"omega": vec}, {}) is None                         # no v_r
    assert columns({"omega": vec, "vr": one}, {}) is None              # mixed forms
    assert columns({"omega": one, "vr": one, "a0": one}, {}) is None   # a0 needs a direction


# --- rolling-onset ---------------------------------------------------------------------------

def _rolling_rows(texts: dict, n: int):
    from dyncalc.commands.rolling_onset import COMMAND

    names = [p.name for p in COMMAND.inputs]
    rows = []
    for i in range(n):
        values = {name: (texts[name][i] if name in texts else None) for name in names}
        values["method"] = None
        rows.append(lambda v=values: COMMAND.compute(v, (), rtol=None, strict=False))
    return rows


@pytest.mark.parametrize("which", [("v0", "mu"), ("v0", "mu", "body", "radius", "omega0"),
                                   ("v0", "mu", "kappa", "g", "incline"),
                                   ("v0", "mu", "radius", "omega0", "incline")])
def test_rolling_columns_match_the_one_off(which):
    from dyncalc.commands.rolling_onset import columns
    from dyncalc.units import ACCELERATION, ANGLE, ANGULAR_RATE, DIMENSIONLESS, LENGTH, VELOCITY

    rng = np.random.default_rng(RNG_SEED + 6)
    n = 80
    columns_of = {
        "v0": (VELOCITY, "m/s", _log_uniform(rng, -2, 2, n)),
        "mu": (DIMENSIONLESS, "", rng.uniform(0.05, 1.0, n)),
        "kappa": (DIMENSIONLESS, "", rng.uniform(0.0, 1.0, n)),
        "g": (ACCELERATION, "m/s^2", rng.uniform(1.0, 30.0, n)),
        "radius": (LENGTH, "mm", _log_uniform(rng, 0, 3, n)),
        "omega0": (ANGULAR_RATE, "rad/s", rng.uniform(-50, 50, n)),
        "incline": (ANGLE, "rad", rng.uniform(-0.3, 0.3, n)),
    }
    texts, given = {}, {}
    for name in which:
        if name == "body":
            words = rng.choice(["solid-sphere", "hoop", "hollow-sphere", "solid-cylinder"], n)
            texts[name], given[name] = list(words), words
            continue
        dim, unit, values = columns_of[name]
        values[0] = {"v0": 5.0, "mu": 0.3, "radius": 110.0, "omega0": 0.0, "g": 9.80665,
                     "kappa": 0.4, "incline": 0.0}[name]           # Example 3.45
        texts[name] = [f"{float(x)!r} {unit}".strip() for x in values]
        given[name] = _si(texts[name], dim)
    cols = columns(given, {"method": None, "units": {"incline": "rad"}})
    exact = _compare(cols, _rolling_rows(texts, n), ordinary=np.arange(1, n), share=0.5)
    if "body" not in which or texts["body"][0] == "solid-sphere":
        assert exact[0] and cols.values["v_roll"][0] == 25 / 7    # 5/7 v0, Gross et al. E3.45
        assert round(cols.values["t_roll"][0], 5) == 0.48558


def test_rolling_columns_refuse_what_they_do_not_vectorise():
    from dyncalc.commands.rolling_onset import columns

    one = np.ones(2)
    assert columns({"v0": one, "mu": one}, {"method": "ode"}) is None
    assert columns({"v0": one}, {}) is None
    assert columns({"v0": one, "mu": one, "body": np.array(["hoop", "hoop"]), "kappa": one},
                   {}) is None
    assert columns({"v0": one, "mu": one, "incline": one}, {"units": {"incline": "deg"}}) is None
    cols = columns({"v0": np.array([5.0, -1.0]), "mu": np.array([0.3, 0.3])}, {})
    assert cols.exact.tolist() == [True, False]                   # v0 < 0 is refused
