"""The ``--json`` object of SPEC version 2 against the JSON Schema shipped in the package
(``dyncalc/result/schema/dyncalc-2.schema.json``): every computing command, every scene's
example, with and without ``--explain``, ``--check`` and an uncertain input; results in their
canonical unit, also for ``--value``. The schema itself must reject what is not the object."""
from __future__ import annotations

import copy
import fnmatch
import json
import math
import re
import shlex
import tomllib
from pathlib import Path

import jsonschema
import pytest

from dyncalc.result import encode
from dyncalc.scenes import catalog
from dyncalc.scenes.sdof import COORDINATES, forced_example
from dyncalc.units import registry
from helpers import invoke

ROOT = Path(__file__).resolve().parents[1]
VALIDATOR = jsonschema.Draft202012Validator(encode.json_schema())

#: Every computing command in the forms its object differs (scenes: their examples, below).
COMMANDS = {
    "spring-series": "spring-series 200N/m 300N/m",
    "spring-series-kN": "spring-series 2kN/m 3kN/m",
    "spring-parallel": 'spring-parallel 2kN/m "12 lbf/in"',
    "spring-parallel-rigid": 'spring-parallel "1 N/m" inf',
    "spring-network": 'spring-series "parallel(cantilever(l=2m), cantilever(l=1m))" 5kN/m '
                      'EI="2e4 N*m^2"',
    "spring-torsional": 'spring-series "3 kN*m/rad" "torsion-bar(l=0.5m, G=80GPa, J_t=1e-8m^4)"',
    "natural-frequency-inverse": "natural-frequency f=5Hz m=2kg",
    "natural-frequency-ode": "natural-frequency --length 1m --amplitude 30deg --method ode",
    "damping-c": "damping-ratio --c 0.7lbf*s/in --k 2.4kN/m --m 1.5kg",
    "damping-decrement": "damping-ratio --decrement 0.5 --omega 10rad/s",
    "damping-ratio": "damping-ratio --ratio 2 --cycles 3 --k 100N/m --m 1kg",
    "damping-amplitudes": 'damping-ratio --amplitudes "12.1, 9.0, 6.8, 5.1, 3.8 mV"',
    "damping-scene": 'damping-ratio --scene rod-in-fluid m=1.5kg l=0.8m "beta=2 N*s/m^2"',
    "rolling-onset": 'rolling-onset --v0 "5 m/s" --mu 0.3',
    "rolling-onset-incline": 'rolling-onset --v0 "2 m/s" --mu 0.2 --radius 28.5mm '
                             '--omega0 "-300 rad/s" --incline 5deg --body hoop',
    "rolling-onset-ode": 'rolling-onset --v0 "5 m/s" --mu 0.3 --method ode',
    "coriolis-scalar": "coriolis --omega 2rad/s --vr 3m/s --r 1m --alpha 1rad/s^2 --mass 2kg",
    "coriolis-vector": 'coriolis --omega "0,0,30 rpm" --vr "0.5,0,0 m/s" --r "0.2,0,0 m"',
    "coriolis-earth": 'coriolis --latitude 45deg --speed "180 km/h" --heading 0deg',
    "coriolis-time": 'coriolis --mass 2kg --r "s0 - b*t^2/2, 0, 0 m" s0=4m b=0.5m/s^2 '
                     '--omega "0, 0, k*t" k=0.3rad/s^2 --t 2s --basis fixed',
    "inertia": 'inertia "rod(m=2kg, l=1m, along=x, at=(0.5, 0, 0) m)" "-point(m=0.1kg)" '
               '--axis "z through (0, 0.1, 0) m"',
    "inertia-density": 'inertia "plate(rho=7.8 kg/m^2, a=40cm, b=20cm)" '
                       '"-disk(rho=7.8 kg/m^2, r=5cm, at=(0.1, 0, 0) m)"',
    "eom-typed": "eom --coords x --T \"m*x'^2/2\" --V \"k*x^2/2\" m=2kg k=200N/m x=1cm",
    "eom-symbolic": "eom --coords phi --T \"m*l^2*phi'^2/2\" --V \"m*g*l*(1 - cos(phi))\" "
                    "m=1kg",
    "eom-scene": "eom --scene block-disk-springs M=3kg m=1kg r=10cm k=100N/m x=1cm phi=0",
    "rigid-body-euler": 'rigid-body --inertia-tensor "1, 0, 0; 0, 1, 0; 0, 0, 2 kg*m^2" '
                        '--omega "2, 0, 3 rad/s" --alpha "0, 0, 1 rad/s^2"',
    "rigid-body-inverse": "rigid-body --scene E4.10 m1=20kg m2=15kg r1=0.2m r2=0.4m "
                          "alpha=3rad/s^2 J_A=?",
}
#: Cases whose quantities sit inside words (inertia's bodies): the uncertain form as typed.
UNCERTAIN_FORMS = {
    "inertia": 'inertia "rod(m=2kg ± 1%, l=1m, along=x, at=(0.5, 0, 0) m)" "-point(m=0.1kg)" '
               '--axis z',
    "inertia-density": 'inertia "plate(rho=7.8 kg/m^2 ± 1%, a=40cm, b=20cm)"',
}
CASES = {**{f"scene-{name}": scene.example.removeprefix("dyncalc ")
            for name, scene in catalog().items()},
         **{f"driven-{name}": forced_example(name).removeprefix("dyncalc ")
            for name in COORDINATES}, **COMMANDS}
#: Cases whose quantities are all vectors or peak lists (which take no uncertainty) get a
#: scalar option for the uncertain form.
SCALAR_ADDED = {"coriolis-vector": ["--mass", "2kg"], "damping-amplitudes": ["--omega", "25rad/s"]}
#: The first plain "NUMBER UNIT" quantity of a command line gets an uncertainty of 1 %.
_PLAIN_QUANTITY = re.compile(r"^((?:[A-Za-z_]\w*=)?[0-9]+(?:\.[0-9]+)?) ?([A-Za-z][\w*/^]*)$")


def words(case: str) -> list[str]:
    return shlex.split(CASES[case])


def json_object(*args, code: int = 0) -> dict:
    result = invoke(*args, "--json")
    assert result.exit_code == code, (result.stdout, result.stderr)
    return json.loads(result.stdout)


def assert_valid(data: dict) -> None:
    errors = [f"{'/'.join(map(str, e.absolute_path))}: {e.message}"
              for e in VALIDATOR.iter_errors(data)]
    assert errors == []
    assert tuple(data) == encode.TOP_KEYS


def with_uncertainty(args: list[str]) -> list[str]:
    """``args`` with its first plain quantity (``100N/m``, ``k=2kN/m``) given ± 1 %."""
    out = list(args)
    for i, word in enumerate(out):
        m = _PLAIN_QUANTITY.match(word)
        if m and not word.startswith("-"):
            out[i] = f"{m.group(1)} {m.group(2)} ± 1%"
            return out
    raise AssertionError(f"no plain quantity in {args}")


def answers(data: dict) -> list[tuple[str, bool]]:
    """``--check`` answers of the first single-number result and whether each passes: its own
    value and 2.5 times it; an infinite one (null, a rigid network) against 1 of its unit."""
    for name, item in data["results"].items():
        value, unit = item["value"], item["unit"]
        if value is None:
            return [(f"{name}=1 {unit}".strip(), False)]
        if isinstance(value, float):
            return [(f"{name}={value!r} {unit}".strip(), True),
                    (f"{name}={value * 2.5!r} {unit}".strip(), False)]
    raise AssertionError(f"no single-number result in {list(data['results'])}")


# --- every command's object is valid --------------------------------------------------------

@pytest.mark.parametrize("case", CASES)
def test_plain_object_is_valid_and_in_canonical_units(case):
    data = json_object(*words(case))
    assert_valid(data)
    assert data["schema"] == "dyncalc/2" and data["command"] == words(case)[0]
    ureg = registry()
    for name, item in data["results"].items():
        # SI coherent: 1 of the unit is 1 in SI base units (pint counts rad and cycles as 1)
        factor = ureg.Quantity(1.0, item["unit"]).to_base_units().magnitude
        assert factor == pytest.approx(1.0, rel=1e-12), (name, item["unit"])
    for name, item in data["inputs"].items():
        ureg.Quantity(1.0, item["unit"])  # the unit typed reads back in pint
        assert item["text"].strip(), name


@pytest.mark.parametrize("explain", ["--explain", "--explain=latex"])
@pytest.mark.parametrize("case", CASES)
def test_explained_object_is_valid(case, explain):
    data = json_object(*words(case), explain)
    assert_valid(data)
    assert data["extra"]["explanation"]["formula"]
    assert ("rendered" in data["extra"]["explanation"]) == (explain != "--explain")


#: eom does not propagate uncertainties (it refuses them: tests/test_eom.py); its symbolic
#: form has no number to check. rigid-body's Euler mode reads a matrix and vectors only,
#: which take no uncertainty.
NUMERIC_CASES = [case for case in CASES if not case.startswith("eom")] + ["eom-typed",
                                                                          "eom-scene"]
PROPAGATING_CASES = [case for case in CASES
                     if not CASES[case].startswith("eom") and case != "rigid-body-euler"]


@pytest.mark.parametrize("case", NUMERIC_CASES)
def test_object_with_checks_is_valid(case):
    checks = answers(json_object(*words(case)))
    options = [word for text, _passes in checks for word in ("--check", text)]
    data = json_object(*words(case), *options, code=1)
    assert_valid(data)
    assert [c["pass"] for c in data["extra"]["checks"]] == [passes for _text, passes in checks]
    assert [f"{c['name']}=" for c in data["extra"]["checks"]] == [
        text[:text.index("=") + 1] for text, _passes in checks]


@pytest.mark.parametrize("case", PROPAGATING_CASES)
def test_object_with_an_uncertain_input_is_valid(case):
    if case in UNCERTAIN_FORMS:
        args = shlex.split(UNCERTAIN_FORMS[case])
    else:
        args = with_uncertainty(words(case) + SCALAR_ADDED.get(case, []))
    data = json_object(*args)
    assert_valid(data)
    uncertain = [n for n, item in data["inputs"].items() if "uncertainty" in item]
    assert len(uncertain) == 1, data["inputs"]
    explained = json_object(*args, "--explain")
    assert_valid(explained)
    finite = [item for item in data["results"].values() if item["value"] is not None]
    if finite:  # else every result is infinite (a rigid network) and carries no uncertainty
        assert any("uncertainty" in item for item in finite)
        assert explained["extra"]["explanation"]["variance"]
    else:
        assert case == "spring-parallel-rigid"


def test_unit_option_names_the_unit_of_json_and_value():
    args = ("natural-frequency", "--k", "100N/m", "--m", "2kg", "--unit", "f=rpm")
    data = json_object(*args)
    assert_valid(data)
    assert data["results"]["f"]["unit"] == "rpm"
    assert data["results"]["f"]["value"] == pytest.approx(60 * math.sqrt(50) / (2 * math.pi),
                                                          rel=1e-15)
    assert invoke(*args, "--value", "f").stdout == f"{data['results']['f']['value']!r}\n"


# --- canonical units in --json and --value ----------------------------------------------------

@pytest.mark.parametrize("elements", [("2kN/m", "3kN/m"), ("2kN/m", "3000N/m"),
                                      ("2000 N/m", "3 kN/m")])
def test_value_is_in_the_canonical_unit_whatever_the_inputs(elements):
    result = invoke("spring-series", *elements, "--value", "k_eq")
    assert (result.exit_code, result.stdout, result.stderr) == (0, "1200.0\n", "")
    data = json_object("spring-series", *elements)
    assert data["results"]["k_eq"] == {"value": 1200.0, "unit": "N/m"}
    result = invoke("spring-series", *elements, "--unit", "k_eq=kN/m", "--value", "k_eq")
    assert float(result.stdout) == pytest.approx(1.2, rel=1e-15)


def test_inputs_keep_the_unit_typed_and_the_text():
    data = json_object("natural-frequency", "--k", "100 N/m", "--m", "2 kg")
    assert data["inputs"] == {"k": {"value": 100.0, "unit": "N/m", "text": "100 N/m"},
                              "m": {"value": 2.0, "unit": "kg", "text": "2 kg"}}
    data = json_object("spring-series", "2kN/m", "3000N/m")
    assert data["inputs"] == {"k1": {"value": 2.0, "unit": "kN/m", "text": "2kN/m"},
                              "k2": {"value": 3000.0, "unit": "N/m", "text": "3000N/m"}}


def test_uncertainty_is_in_the_unit_of_its_value():
    """k_eq = 1.2 kN/m; d k_eq / d k1 = (k_eq / k1)^2 = 0.36, u(k1) = 100 N/m: 36 N/m."""
    args = ("spring-series", "2 kN/m ± 5%", "3 kN/m")
    item = json_object(*args)["results"]["k_eq"]
    assert item["unit"] == "N/m" and item["value"] == 1200.0
    assert item["uncertainty"] == pytest.approx(36.0, rel=1e-8)
    assert float(invoke(*args, "--value", "u(k_eq)").stdout) == item["uncertainty"]
    in_kn = invoke(*args, "--unit", "k_eq=kN/m", "--value", "u(k_eq)")
    assert float(in_kn.stdout) == pytest.approx(0.036, rel=1e-8)


def test_a_result_shown_in_the_unit_typed_is_canonical_in_json_and_value():
    """damping-ratio echoes c, shown in lbf*s/in on the table; JSON and --value give N*s/m."""
    args = ("damping-ratio", "--c", "0.7 lbf*s/in", "--k", "2.4 kN/m", "--m", "1.5 kg")
    human = invoke(*args)
    assert re.search(r"^c\s+c\s+0\.7\s+lbf\*s/in$", human.stdout, re.M), human.stdout
    c_si = 0.7 * 4.4482216152605 / 0.0254
    data = json_object(*args)
    assert data["results"]["c"]["unit"] == "N*s/m"
    assert data["results"]["c"]["value"] == pytest.approx(c_si, rel=1e-15)
    assert float(invoke(*args, "--value", "c").stdout) == data["results"]["c"]["value"]


def test_an_angle_result_is_in_radians():
    args = ("natural-frequency", "--scene", "pendulum-accelerating-support", "l=1m",
            "a0=-3m/s^2")
    phi = json_object(*args)["results"]["phi_0"]
    assert phi["unit"] == "rad"
    assert phi["value"] == pytest.approx(math.atan(3 / 9.80665), rel=1e-15)
    assert float(invoke(*args, "--value", "phi_0").stdout) == phi["value"]
    degrees = invoke(*args, "--unit", "phi_0=deg", "--value", "phi_0")
    assert float(degrees.stdout) == pytest.approx(math.degrees(phi["value"]), rel=1e-15)


# --- the schema rejects what is not the object -------------------------------------------------

def _good() -> dict:
    return json_object("natural-frequency", "--k", "100 N/m", "--m", "2 kg", "--explain")


def _errors(data) -> list[str]:
    return [e.message for e in VALIDATOR.iter_errors(data)]


def test_the_schema_is_draft_2020_12_and_accepts_the_real_object():
    schema = encode.json_schema()
    assert schema["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    jsonschema.Draft202012Validator.check_schema(schema)
    assert set(schema["required"]) == set(encode.TOP_KEYS) == set(schema["properties"])
    assert _errors(_good()) == []


def test_an_object_without_schema_is_rejected():
    data = _good()
    del data["schema"]
    assert _errors(data) == ["'schema' is a required property"]


def test_an_extra_top_level_key_is_rejected():
    data = _good()
    data["explanation"] = data["extra"].pop("explanation")
    errors = _errors(data)
    assert len(errors) == 1 and "'explanation' was unexpected" in errors[0]


@pytest.mark.parametrize("change, words", [
    (lambda d: d.update(schema="dyncalc/1"), "'dyncalc/2' was expected"),
    (lambda d: d["results"]["omega"].pop("unit"), "'unit' is a required property"),
    (lambda d: d["inputs"]["k"].pop("text"), "'text' is a required property"),
    (lambda d: d["inputs"]["m"].update(assumed_si=False), "True was expected"),
    (lambda d: d["results"]["f"].update(value={"x": 1}), "is not valid under any"),
    (lambda d: d["results"]["T"].update(symbol="T"), "'symbol' was unexpected"),
    (lambda d: d["extra"]["explanation"].pop("formula"), "'formula' is a required property"),
    (lambda d: d.update(command="natural_frequency"), "is not one of"),
    (lambda d: d.update(warnings=[1]), "1 is not of type 'string'"),
])
def test_the_schema_rejects_a_changed_object(change, words):
    data = copy.deepcopy(_good())
    change(data)
    errors = _errors(data)
    assert len(errors) == 1 and words in errors[0], errors


# --- the schema ships in the package ---------------------------------------------------------

def test_the_schema_file_is_package_data():
    """``pip install .`` copies what pyproject.toml's package-data names: the schema is in it,
    and json_schema() reads the file next to the code (importlib.resources)."""
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    patterns = pyproject["tool"]["setuptools"]["package-data"]["dyncalc.result"]
    assert any(fnmatch.fnmatch(encode.SCHEMA_FILE, p) for p in patterns), patterns
    on_disk = ROOT / "dyncalc" / "result" / encode.SCHEMA_FILE
    assert encode.json_schema() == json.loads(on_disk.read_text(encoding="utf-8"))
