"""The Python API (SPEC "Python API", docs/api.md): every command as a function, the same
numbers, inputs and messages as the CLI; Quantities of any registry, strings, SI numbers;
arrays elementwise, bit for bit the one-offs (kernel rows and the rows left to the one-off);
Dask and xarray arrays; the public API type-checked by mypy."""
from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pint
import pytest

import dyncalc
from dyncalc.api import run
from tests.helpers import error_line, invoke, json_of

ROOT = Path(__file__).resolve().parents[1]
UREG = pint.UnitRegistry()  # the caller's own registry, not dyncalc's


# --- every command through the API equals the CLI's --json -----------------------------------

CASES = [
    (("natural-frequency", "--k", "2 kN/m", "--m", "4kg"),
     lambda: dyncalc.natural_frequency(k="2 kN/m", m="4kg")),
    (("natural-frequency", "--k", "100N/m", "--m", "2kg", "--zeta", "0.05"),
     lambda: dyncalc.natural_frequency(k="100N/m", m="2kg", zeta=0.05)),
    (("natural-frequency", "--length", "1m", "--amplitude", "170deg"),
     lambda: dyncalc.natural_frequency(length="1m", amplitude="170deg")),
    (("natural-frequency", "--scene", "physical-pendulum", "m=2kg", "a=0.5m",
      "J=(2/12) kg*m^2"),
     lambda: dyncalc.natural_frequency(scene="physical-pendulum", m="2kg", a="0.5m",
                                       J="(2/12) kg*m^2")),
    (("natural-frequency", "--scene", "rolling-in-track", "R=1m", "r=0.2m",
      "body=solid-sphere"),
     lambda: dyncalc.natural_frequency(scene="rolling-in-track", R="1m", r="0.2m",
                                       body="solid-sphere")),
    (("spring-series", "200 N/m", "300 N/m"),
     lambda: dyncalc.spring_series("200 N/m", "300 N/m")),
    (("spring-parallel", "cantilever(l=2m)", "cantilever(l=1m)", "5kN/m", "EI=2e4 N*m^2"),
     lambda: dyncalc.spring_parallel("cantilever(l=2m)", "cantilever(l=1m)", "5kN/m",
                                     EI="2e4 N*m^2")),
    (("damping-ratio", "--c", "1", "--k", "100", "--m", "1"),
     lambda: dyncalc.damping_ratio(c=1, k=100, m=1)),
    (("damping-ratio", "--amplitudes", "10,8,6.4"),
     lambda: dyncalc.damping_ratio(amplitudes=[10, 8, 6.4])),
    (("rolling-onset", "--v0", "2m/s", "--mu", "0.2", "--body", "hoop"),
     lambda: dyncalc.rolling_onset(v0="2m/s", mu=0.2, body="hoop")),
    (("rolling-onset", "--v0", "2m/s", "--mu", "0.2", "--method", "ode"),
     lambda: dyncalc.rolling_onset(v0="2m/s", mu=0.2, method="ode")),
    (("coriolis", "--omega", "0,0,7.292e-05", "--vr", "10,0,0", "--mass", "2kg"),
     lambda: dyncalc.coriolis(omega=[0, 0, 7.292e-5], vr=[10, 0, 0], mass="2kg")),
]


def _untimed(data: dict) -> dict:
    """The --json object without the wall-clock times of ``extra.timing`` (``--method
    ode`` times both models: never the same twice)."""
    data["extra"].pop("timing", None)
    return data


@pytest.mark.parametrize("args, api", CASES, ids=[" ".join(c[0][:5]) for c in CASES])
def test_every_command_equals_the_cli_json(args, api):
    result = api()
    assert isinstance(result, dyncalc.Result)
    cli = json_of(*args)
    assert _untimed(result.to_dict()) == _untimed(cli)
    # each value is the --json number in the canonical unit, as a Quantity of that unit
    for name, item in cli["results"].items():
        value = result[name]
        if isinstance(value, str):
            assert value == item["value"]
        else:
            assert value.units == dyncalc.registry().Unit(item["unit"]) or \
                value.to(item["unit"]).magnitude == pytest.approx(item["value"], rel=1e-15)
            assert np.array_equal(np.asarray(value.magnitude, dtype=float),
                                  np.asarray(item["value"], dtype=float))


def test_every_command_has_its_function():
    """One function per command record, and the CLI's computing commands are those."""
    from dyncalc.api import function_names
    from dyncalc.cli import COMMAND_MODULES

    names = function_names()
    assert names == sorted(dyncalc.COMMAND_FUNCTIONS)
    assert sorted(n.replace("_", "-") for n in names) == sorted(
        c for c in COMMAND_MODULES if c != "scenes")
    for name in names:
        function = getattr(dyncalc, name)
        assert function.__name__ == name and function.record.name == name.replace("_", "-")


def test_explain_is_the_cli_explanation():
    r = dyncalc.natural_frequency(k="2 kN/m", m="4kg")
    printed = invoke("natural-frequency", "--k", "2 kN/m", "--m", "4kg", "--explain")
    assert printed.exit_code == 0
    assert r.explain().startswith("formula:")
    assert printed.stdout.endswith(r.explain() + "\n")
    md = invoke("natural-frequency", "--k", "2 kN/m", "--m", "4kg", "--explain=markdown")
    assert md.stdout.rstrip("\n").endswith(r.explain("markdown").rstrip("\n"))
    assert r.to_dict(explain=True) == json_of("natural-frequency", "--k", "2 kN/m", "--m",
                                              "4kg", "--explain")


# --- quantities of any registry, strings, plain numbers ---------------------------------------

def test_quantities_of_a_foreign_registry():
    r = dyncalc.natural_frequency(k=UREG.Quantity(2, "kN/m"), m=UREG.Quantity(4000, "g"))
    omega = r["omega"]
    assert omega._REGISTRY is UREG  # the caller's registry: mixes with their quantities
    assert omega.magnitude == math.sqrt(2000 / 4)  # sqrt(k/m) in SI, correctly rounded
    assert (omega + UREG.Quantity(1, "rad/s")).magnitude == math.sqrt(500) + 1
    assert str(r["T"].units) == "second"
    # read as its magnitude and unit text: the CLI given that text
    assert r.to_dict() == json_of("natural-frequency", "--k", "2 kN / m", "--m", "4000 g")
    assert r.to_dict()["inputs"]["k"] == {"value": 2.0, "unit": "kN / m", "text": "2 kN / m"}


def test_application_registry_and_dyncalc_registry_quantities():
    app = pint.get_application_registry()
    r1 = dyncalc.spring_series(app.Quantity(200, "N/m"), app.Quantity(300, "N/m"))
    r2 = dyncalc.spring_series(dyncalc.Q_(200, "N/m"), dyncalc.Q_(300, "N/m"))
    assert r1["k_eq"].magnitude == r2["k_eq"].magnitude == 1 / (1 / 200 + 1 / 300)
    assert r2["k_eq"]._REGISTRY is dyncalc.registry()


def test_plain_numbers_are_si_and_strings_as_typed():
    plain = dyncalc.natural_frequency(k=2000, m=4.0)
    assert plain.to_dict() == json_of("natural-frequency", "--k", "2000", "--m", "4.0")
    assert plain.to_dict()["inputs"]["k"]["assumed_si"] is True
    assert plain["omega"].magnitude == math.sqrt(500)
    assert plain["omega"]._REGISTRY is dyncalc.registry()  # no Quantity given: dyncalc's
    typed = dyncalc.natural_frequency(k="2 kN/m", m="4 kg")
    assert typed["omega"].magnitude == math.sqrt(500)
    # an angle as a plain number is in radians, as on the command line
    rad = dyncalc.natural_frequency(length=1, amplitude=math.pi / 2)
    deg = dyncalc.natural_frequency(length=1, amplitude=UREG.Quantity(90, "degree"))
    assert rad["T"].magnitude == pytest.approx(deg["T"].magnitude, rel=1e-15)


def test_uncertainties_are_propagated_as_on_the_cli():
    r = dyncalc.natural_frequency(k="(100 ± 5) N/m", m="2kg")
    cli = json_of("natural-frequency", "--k", "(100 ± 5) N/m", "--m", "2kg")
    assert r.to_dict() == cli
    # first order: u(omega)/omega = u(k) / (2 k)
    assert r.uncertainty("omega").magnitude == pytest.approx(
        math.sqrt(50) * 0.025, rel=1e-9)
    assert r.uncertainty("omega").magnitude == cli["results"]["omega"]["uncertainty"]


# --- arrays: elementwise, bit for bit the one-offs -------------------------------------------

def _bits(a):
    a = np.asarray(a, dtype=float)
    return a.view(np.int64)


def _same_as_one_offs(result, calls):
    """Every element of an ArrayResult is the one-off of its arguments, to the bit."""
    for flat, args in enumerate(calls):
        index = np.unravel_index(flat, result.shape)
        one = args()
        assert list(one) == [n for n in result if n in one]
        for name in result:
            got = result[name]
            got = got[index] if isinstance(got, np.ndarray) else got.magnitude[index]
            if name not in one:
                assert np.isnan(got).all(), (name, index)
            elif isinstance(one[name], str):
                assert got == one[name]
            else:
                assert np.array_equal(_bits(got), _bits(one[name].magnitude)), (name, index)


@pytest.fixture
def one_offs(monkeypatch):
    """Count the rows computed by the one-off (the others took the column kernels)."""
    calls = []
    original = run.one_off

    def counting(*args, **kwargs):
        calls.append(1)
        return original(*args, **kwargs)
    monkeypatch.setattr(run, "one_off", counting)
    return calls


def test_natural_frequency_arrays_with_extremes(one_offs):
    k = np.array([1.0, 2.5, 1e300, 5e-324, 1e-300, 7.0, 3e8, 1.0])
    m = np.array([4.0, 4.0, 1e-10, 1e300, 1e300, 0.3, 2.0, 1e-300])
    r = dyncalc.natural_frequency(k=UREG.Quantity(k, "kN/m"), m=UREG.Quantity(m, "kg"))
    assert r["omega"]._REGISTRY is UREG and r.shape == (8,)
    assert 1 < len(one_offs) < len(k)  # extremes left to the one-off, the rest the kernel's
    del one_offs[:]
    _same_as_one_offs(r, [lambda i=i: dyncalc.natural_frequency(
        k=UREG.Quantity(k[i], "kN/m"), m=UREG.Quantity(m[i], "kg")) for i in range(len(k))])
    assert r["omega"].magnitude[0] == math.sqrt(1000 / 4)


def test_arrays_broadcast_and_damped_scenes():
    k = np.array([[100.0], [400.0], [1e-3]])
    zeta = np.array([0.0, 0.05, 0.999, 1.0])
    r = dyncalc.natural_frequency(k=k, m="2 kg", zeta=zeta)
    assert r.shape == (3, 4)
    assert any("at index (0, 3)" in w for w in r.warnings)  # critical: the one-off's warning
    _same_as_one_offs(r, [lambda i=i, j=j: dyncalc.natural_frequency(
        k=float(k[i, 0]), m="2 kg", zeta=float(zeta[j])) for i in range(3) for j in range(4)])


def test_spring_arrays(one_offs):
    k1 = np.array([200.0, 1e300, 5e-324, np.inf, 3.0])
    r = dyncalc.spring_series(k1, UREG.Quantity(300.0, "N/m"))
    assert 1 < len(one_offs) < len(k1)
    _same_as_one_offs(r, [lambda v=v: dyncalc.spring_series(
        float(v), UREG.Quantity(300.0, "N/m")) for v in k1])
    assert r["k_eq"].magnitude[0] == 1 / (1 / 200 + 1 / 300)
    p = dyncalc.spring_parallel(["1 kN/m", "2 N/m"], 5)  # a list of texts, elementwise
    assert p["k_eq"].magnitude.tolist() == [
        dyncalc.spring_parallel("1 kN/m", 5)["k_eq"].magnitude, 7.0]


def test_rolling_coriolis_and_damping_arrays():
    v0 = np.array([0.5, 2.0, 1e-200, 40.0])
    body = np.array(["solid-sphere", "hoop", "solid-cylinder", "hollow-sphere"])
    r = dyncalc.rolling_onset(v0=v0, mu=0.2, body=body)
    _same_as_one_offs(r, [lambda i=i: dyncalc.rolling_onset(v0=float(v0[i]), mu=0.2,
                                                            body=str(body[i]))
                          for i in range(4)])
    # the sphere's rolling speed: 5/7 v0 (Gross et al., the rolling-onset example)
    assert r["v_roll"].magnitude[0] == pytest.approx(5 / 7 * 0.5, rel=1e-15)
    vr = np.array([[10.0, 0, 0], [0, 3.0, 0], [1e-300, 0, 0]])
    c = dyncalc.coriolis(omega=UREG.Quantity([0, 0, 2.0], "rad/s"), vr=vr, mass="2kg")
    assert c["a_c"].shape == (3, 3)
    _same_as_one_offs(c, [lambda i=i: dyncalc.coriolis(
        omega=UREG.Quantity([0, 0, 2.0], "rad/s"), vr=vr[i], mass="2kg") for i in range(3)])
    assert c["a_c"].magnitude[0].tolist() == [0.0, 40.0, 0.0]  # 2 Omega x v_r
    cs = np.array([1.0, 20.0, 100.0, 1e-9])  # under-, critically, over-damped (c_c = 20)
    d = dyncalc.damping_ratio(c=cs, k=100, m=1)
    assert d["regime"].tolist()[:3] == ["underdamped", "critically damped", "overdamped"]
    _same_as_one_offs(d, [lambda v=v: dyncalc.damping_ratio(c=float(v), k=100, m=1)
                          for v in cs])


def test_array_elements_and_their_json():
    k = np.array([100.0, 400.0])
    r = dyncalc.natural_frequency(k=k, m=UREG.Quantity(2, "kg"))
    lines = r.to_dict()
    assert lines[1] == json_of("natural-frequency", "--k", "400.0", "--m", "2 kg")
    assert r.element(1).explain() == dyncalc.natural_frequency(k=400.0, m="2 kg").explain()
    with pytest.raises(TypeError, match="r.element"):
        r.explain()


# --- errors: the CLI's message, nothing printed -----------------------------------------------

ERRORS = [
    (("natural-frequency", "--k", "-2 N/m", "--m", "1"),
     lambda: dyncalc.natural_frequency(k="-2 N/m", m=1)),
    (("natural-frequency", "--k", "2 kg", "--m", "1"),
     lambda: dyncalc.natural_frequency(k=UREG.Quantity(2, "kg"), m=1)),
    (("natural-frequency", "--k", "2", "--m", "1", "--scene", "nope"),
     lambda: dyncalc.natural_frequency(k=2, m=1, scene="nope")),
    (("natural-frequency", "--length", "1m", "l=2m"),
     lambda: dyncalc.natural_frequency(length="1m", l="2m")),
    (("rolling-onset", "--v0", "2", "--mu", "0.2", "--method", "foo"),
     lambda: dyncalc.rolling_onset(v0=2, mu=0.2, method="foo")),
    (("rolling-onset", "--v0", "2", "--mu", "0.2", "--body", "foo"),
     lambda: dyncalc.rolling_onset(v0=2, mu=0.2, body="foo")),
    (("spring-series",), lambda: dyncalc.spring_series()),
    (("damping-ratio", "--c", "1", "--k", "100", "--m", "1", "--strict-units"),
     lambda: dyncalc.damping_ratio(c=1, k=100, m=1, strict_units=True)),
]


@pytest.mark.parametrize("args, api", ERRORS, ids=[" ".join(e[0][:3]) for e in ERRORS])
def test_errors_are_the_cli_messages(args, api, capsys):
    line = error_line(invoke(*args))
    capsys.readouterr()
    with pytest.raises(dyncalc.InputError) as caught:
        api()
    assert "Error: " + str(caught.value) == line
    assert capsys.readouterr() == ("", "")


def test_physics_errors_and_array_errors():
    args = ("damping-ratio", "--amplitudes", "1,2,4")
    with pytest.raises(dyncalc.PhysicsError) as caught:
        dyncalc.damping_ratio(amplitudes=[1, 2, 4])  # peaks that grow
    assert "Error: " + str(caught.value) == error_line(invoke(*args))
    with pytest.raises(dyncalc.InputError) as caught:
        dyncalc.natural_frequency(k=np.array([1.0, 2.0, -3.0]), m=1)
    single = error_line(invoke("natural-frequency", "--k", "-3.0", "--m", "1"))
    assert str(caught.value) == "at index 2: " + single.removeprefix("Error: ")
    with pytest.raises(dyncalc.InputError, match=r"^at index \(1, 0\): "):
        dyncalc.natural_frequency(k=np.array([[1.0], [np.inf]]), m=[1, 2])


def test_wrong_keywords_are_type_errors():
    with pytest.raises(TypeError, match="unexpected keyword argument 'foo'"):
        dyncalc.rolling_onset(foo=1)
    with pytest.raises(dyncalc.InputError, match="^foo= is used by no vector component"):
        dyncalc.coriolis(foo=1)  # coriolis takes NAME= parameters of its components
    with pytest.raises(TypeError, match="keyword arguments only"):
        dyncalc.natural_frequency(2, 1)
    with pytest.raises(TypeError, match="does not take plot="):
        dyncalc.damping_ratio(c=1, k=100, m=1, plot="x.png")
    with pytest.raises(TypeError, match="a vector has 3 components"):
        dyncalc.coriolis(omega=[0, 2], vr=[1, 0, 0])


def test_import_dyncalc_stays_cheap():
    """`import dyncalc` loads no API machinery, numpy or pint until a function is used."""
    code = ("import sys, dyncalc; heavy = [m for m in ('numpy', 'pint', 'dyncalc.api') "
            "if m in sys.modules]; print(heavy)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "[]"


# --- Dask and xarray (the optional `array` extra) ---------------------------------------------

def test_dask_arrays_block_by_block():
    dask = pytest.importorskip("dask", reason="dask is not installed (pip install "
                                              "'dyncalc[array]')")
    da = pytest.importorskip("dask.array")
    k = np.array([100.0, 1e300, 400.0, 5e-324, 9.0, 16.0, 25.0])
    with dask.config.set(scheduler="synchronous"):
        r = dyncalc.natural_frequency(k=UREG.Quantity(da.from_array(k, chunks=3), "N/m"),
                                      m=2.0)
        assert isinstance(r["omega"].magnitude, da.Array)  # lazy until computed
        omega = r["omega"].compute()
        plain = dyncalc.natural_frequency(k=UREG.Quantity(k, "N/m"), m=2.0)
        assert omega._REGISTRY is UREG
        assert np.array_equal(_bits(omega.magnitude), _bits(plain["omega"].magnitude))
        bad = dyncalc.natural_frequency(k=da.from_array(np.array([1.0, 2, 3, -4]), chunks=2),
                                        m=1)
        with pytest.raises(dyncalc.InputError, match=r"^at index 3: --k must be positive"):
            bad["f"].compute()


def test_xarray_dataarrays_keep_their_coordinates():
    xr = pytest.importorskip("xarray", reason="xarray is not installed (pip install "
                                              "'dyncalc[array]')")
    k = xr.DataArray([100.0, 400.0, 900.0], dims="k", coords={"k": [1, 2, 3]},
                     attrs={"units": "N/m"})
    m = xr.DataArray(UREG.Quantity([1.0, 4.0], "kg"), dims="m", coords={"m": [10, 20]})
    r = dyncalc.natural_frequency(k=k, m=m)
    omega = r["omega"]
    assert isinstance(omega, xr.DataArray) and omega.dims == ("k", "m")
    assert omega.coords["m"].values.tolist() == [10, 20]
    assert omega.data._REGISTRY is UREG
    expected = np.sqrt(np.array([100.0, 400.0, 900.0])[:, None] / np.array([1.0, 4.0]))
    assert np.array_equal(omega.data.magnitude, expected)  # sqrt(k/m): exact squares


# --- types: py.typed and mypy on the public API -----------------------------------------------

USAGE = '''
import numpy as np
import pint
import dyncalc
from dyncalc import ArrayResult, InputError, Result

ureg: pint.UnitRegistry = pint.UnitRegistry()
r = dyncalc.natural_frequency(k=ureg.Quantity(2, "kN/m"), m="4 kg")
omega = r["omega"]
if isinstance(r, Result):
    data: dict[str, object] = r.to_dict()
    text: str = r.explain("markdown")
    warnings: list[str] = r.warnings
arrays = dyncalc.spring_series(np.array([1.0, 2.0]), 3.0, rtol=1e-9)
if isinstance(arrays, ArrayResult):
    shape: tuple[int, ...] = arrays.shape
try:
    dyncalc.coriolis(omega=[0, 0, 2], vr=[1, 0, 0])
except InputError as exc:
    message: str = str(exc)
'''


def _mypy(tmp_path, source: str):
    usage = tmp_path / "usage.py"
    usage.write_text(source)
    return subprocess.run([sys.executable, "-m", "mypy", "--follow-imports=silent",
                           "--ignore-missing-imports", "--cache-dir", str(tmp_path / "cache"),
                           str(usage), str(ROOT / "dyncalc" / "api")],
                          capture_output=True, text=True, cwd=tmp_path, timeout=300)


def test_the_public_api_type_checks(tmp_path):
    assert (ROOT / "dyncalc" / "py.typed").exists()
    done = _mypy(tmp_path, USAGE)
    assert done.returncode == 0, done.stdout + done.stderr
    wrong = _mypy(tmp_path, USAGE + 'dyncalc.natural_frequency(k=1, rtol="tight")\n'
                  'dyncalc.natural_frequency(k=1).explain(3)\n')
    assert wrong.returncode == 1
    assert 'Argument "rtol"' in wrong.stdout and 'Argument 1 to "explain"' in wrong.stdout


# --- the docs page's tour runs as doctests ----------------------------------------------------

def test_docs_api_page_runs():
    import doctest

    for module in ("dask", "xarray"):  # the tour shows them too
        pytest.importorskip(module, reason=f"{module} is not installed (pip install "
                                           "'dyncalc[array]')")

    failures, tried = doctest.testfile(str(ROOT / "docs" / "api.md"), module_relative=False,
                                       optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert tried > 20 and failures == 0


def test_results_round_trip_to_json():
    r = dyncalc.coriolis(omega=[0, 0, 2], vr=[1, 0, 0])
    assert json.loads(json.dumps(r.to_dict())) == r.to_dict()


# --- modes: matrices as arrays, Quantity arrays and nested lists of Quantities ----------------

def _modes_closed_form(M, K):
    """omega_i by scipy's own generalized eigenproblem of the SI matrices (an independent
    solver of the same problem: numpy's eigvals of M^-1 K)."""
    return np.sqrt(np.sort(np.linalg.eigvals(np.linalg.solve(M, K)).real))


def test_modes_takes_a_bare_numpy_array_in_si():
    r = dyncalc.modes(M=np.eye(2), K=np.array([[200.0, -100.0], [-100.0, 200.0]]))
    # two equal masses, three equal springs: omega = sqrt(k/m), sqrt(3 k/m)
    assert r["omega_1"].to("rad/s").magnitude == pytest.approx(10.0, rel=1e-14)
    assert r["omega_2"].to("rad/s").magnitude == pytest.approx(math.sqrt(300.0), rel=1e-14)
    assert r.to_dict()["inputs"]["K"]["text"] == "200.0, -100.0; -100.0, 200.0"


def test_modes_takes_quantity_arrays_of_the_callers_registry():
    M = np.diag([2.0, 1.0]) * UREG.lb
    K = np.array([[3.0, -1.0], [-1.0, 1.0]]) * UREG("lbf/in")
    r = dyncalc.modes(M=M, K=K)
    expected = _modes_closed_form(M.to("kg").magnitude, K.to("N/m").magnitude)
    got = [r[f"omega_{i}"].to("rad/s").magnitude for i in (1, 2)]
    assert got == pytest.approx(expected.tolist(), rel=1e-12)
    assert r["omega_1"]._REGISTRY is UREG
    same = dyncalc.modes(M="2, 0; 0, 1 lb", K="3, -1; -1, 1 lbf/in")
    assert got == [same[f"omega_{i}"].to("rad/s").magnitude for i in (1, 2)]


def test_modes_takes_nested_lists_of_quantities_with_mixed_units():
    """A translation and a rotation: M's mixed entry in kg*m, K's in N/rad."""
    M = [[2 * UREG.kg, 0.1 * UREG("kg*m")], [0.1 * UREG("kg*m"), 0.05 * UREG("kg*m^2")]]
    K = [[300 * UREG("N/m"), 0 * UREG("N/rad")], [0 * UREG("N/rad"), 40 * UREG("N*m/rad")]]
    r = dyncalc.modes(M=M, K=K)
    expected = _modes_closed_form(np.array([[2.0, 0.1], [0.1, 0.05]]),
                                  np.array([[300.0, 0.0], [0.0, 40.0]]))
    got = [r[f"omega_{i}"].to("rad/s").magnitude for i in (1, 2)]
    assert got == pytest.approx(expected.tolist(), rel=1e-12)
    cli = json_of("modes", "--M", "[[2 kg, 0.1 kg*m], [0.1 kg*m, 0.05 kg*m^2]]",
                  "--K", "[[300 N/m, 0 N/rad], [0 N/rad, 40 N*m/rad]]")
    assert got == [cli["results"][f"omega_{i}"]["value"] for i in (1, 2)]


def test_modes_array_refusals_are_the_clis():
    with pytest.raises(dyncalc.InputError) as info:
        dyncalc.modes(M=np.eye(2) * UREG.kg, K=np.eye(2) * UREG.s)
    assert str(info.value) == ("--K row 1, column 1 must be a stiffness [force]/[length]; "
                               "got 1 second ([time])")
    assert error_line(invoke("modes", "--M", "1, 0; 0, 1 kg", "--K", "1, 0; 0, 1 s")) == \
        f"Error: {info.value}"
    with pytest.raises(dyncalc.InputError) as info:
        dyncalc.modes(M=np.eye(2), K=np.ones((2, 3)))
    assert str(info.value) == "--K must be square: it has shape (2, 3)"
    with pytest.raises(dyncalc.InputError) as info:
        dyncalc.modes(M=np.array([[1.0, 0.0], [0.0, np.nan]]), K=np.eye(2))
    assert str(info.value) == "--M row 2, column 2 must be finite; got nan"
    with pytest.raises(TypeError, match=r"^K: a matrix is a 2-D array; got shape \(3,\)$"):
        dyncalc.modes(M=np.eye(3) * UREG.kg, K=np.ones(3) * UREG("N/m"))


def test_modes_takes_a_500_degree_chain_as_an_array():
    """Past the 20,000 characters a typed matrix may have: the uniform fixed-fixed chain,
    omega_j = 2 sqrt(k/m) sin(j pi / (2 (n + 1)))."""
    n, m, k = 500, 2.0, 300.0
    K = k * (2 * np.eye(n) - np.eye(n, k=1) - np.eye(n, k=-1))
    r = dyncalc.modes(M=m * np.eye(n) * UREG.kg, K=K * UREG("N/m"))
    for j in (1, 250, 500):
        expected = 2 * math.sqrt(k / m) * math.sin(j * math.pi / (2 * (n + 1)))
        assert r[f"omega_{j}"].to("rad/s").magnitude == pytest.approx(expected, rel=1e-10)
    assert r.to_dict()["inputs"]["M"]["text"] == "[500x500 array] kg"


def test_api_md_matrices_section_runs(tmp_path):
    """docs/api.md's matrix examples (the page's full doctest needs dask and xarray)."""
    import doctest

    text = (ROOT / "docs" / "api.md").read_text(encoding="utf-8")
    section = text[text.index("## Matrices"):text.index("## Errors")]
    page = tmp_path / "matrices.md"
    page.write_text("```python\n>>> import numpy as np, pint, dyncalc\n"
                    ">>> ureg = pint.UnitRegistry()\n\n```\n" + section, encoding="utf-8")
    failures, tried = doctest.testfile(str(page), module_relative=False)
    assert failures == 0 and tried >= 8
