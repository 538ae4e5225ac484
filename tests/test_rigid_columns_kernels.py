"""The rigid-body column kernels (dyncalc/physics/kinetics_columns.py, kinetics_loads_columns.py)
against the one-off physics, bit for bit, on random rows including extremes; the rows a kernel
cannot certify (ties, cancellation, warnings, refusals) are left to the scalar path, which
still gives the one-off's values and warnings."""
from __future__ import annotations

import math
import random
from fractions import Fraction

import numpy as np
import pytest
from click.testing import CliRunner

from dyncalc.cli import cli
from dyncalc.commands import rigid_columns
from dyncalc.commands.rigid_columns import _by_kernel, _defaults, _kernel, scene_columns
from dyncalc.scenes import get_scene
from dyncalc.scenes.kinetics import kinetics_scene_names

EXTREMES = (0.0, -0.0, 5e-324, 2.0 ** -1022, 1e-300, 2.0 ** -100, 1e-30, 1e30, 2.0 ** 100,
            1e300, 1.7976931348623157e308, math.inf, -math.inf, math.nan, -1.0)


def _log(rng, lo, hi):
    return float(f"{10 ** rng.uniform(math.log10(lo), math.log10(hi)):.6g}")


def _signed(rng, size):
    return float(f"{rng.uniform(-size, size):.6g}")


#: scene -> one set of columns: name -> a function of a Random giving an ordinary value
ROWS = {
    "drum-two-blocks": dict(m1=(0.1, 100), m2=(0.1, 100), r1=(0.01, 1), r2=(0.01, 1),
                            J_A=(1e-3, 10)),
    "wheel-incline-block": dict(m1=(0.1, 100), m2=(0.1, 100), beta=1.5, J_A=(1e-3, 10),
                                r=(0.01, 1)),
    "two-drums-rope-drive": dict(m1=(0.1, 100), m2=(0.1, 100), r1=(0.01, 1), r2=(0.01, 1),
                                 J1=(1e-3, 10), J2=(1e-3, 10), M0=100.0),
    "direct-central-impact": dict(m1=(0.1, 100), m2=(0.1, 100), v1=10.0, v2=10.0, e=(0.01, 1)),
    "double-pendulum-impulse": dict(m=(0.1, 100), l=(0.1, 10), F_hat=(0.1, 100), d=(0.01, 10)),
    "angled-bar-on-shaft": dict(m=(0.1, 100), l=(0.1, 10), M0=10.0, omega=10.0),
    "precessing-shaft": dict(J1=(1e-3, 1), J3=(1e-2, 1), J2=(1e-2, 1), omega0=100.0,
                             Omega=10.0, alpha0=1.0, t=(0.01, 10), psi=3.0),
    "beam-spun-up": dict(m=(0.1, 100), l=(0.1, 10), M0=10.0, x=(0.01, 10), t=(0.01, 10)),
    "rotating-angled-arm": dict(m=(0.1, 100), a=(0.1, 10), b=(0.1, 10), Omega=10.0,
                                x1=(0.01, 10)),
}


def _column(rng, spec, n, extremes):
    values = [_log(rng, *spec) if isinstance(spec, tuple) else _signed(rng, spec)
              for _ in range(n)]
    if extremes:
        for i in range(0, n, 3):
            values[i] = rng.choice(EXTREMES)
    return np.array(values)


def _kernel_only(scene, columns):
    """The kernel's own answer (no row-by-row completion)."""
    n = len(next(iter(columns.values())))
    return _by_kernel(scene, _kernel(scene), columns, _defaults(scene, set(columns)), n)


def _same(a: float, b: float) -> bool:
    return np.float64(a).view(np.int64) == np.float64(b).view(np.int64)


def _one_off(scene, columns, i):
    return scene.compute(**_defaults(scene, set(columns)),
                         **{name: float(c[i]) for name, c in columns.items()})


def test_every_rigid_body_scene_has_a_kernel():
    assert set(kinetics_scene_names()) == set(ROWS)
    for name in ROWS:
        assert _kernel(get_scene(name)) is not None, name


@pytest.mark.parametrize("extremes", [False, True], ids=["ordinary", "extremes"])
@pytest.mark.parametrize("name", ROWS)
def test_kernel_rows_are_the_one_offs_bit_for_bit(name, extremes):
    scene = get_scene(name)
    rng = random.Random(f"{name}-{extremes}")
    n = 600
    columns = {p: _column(rng, spec, n, extremes) for p, spec in ROWS[name].items()}
    out = _kernel_only(scene, columns)
    exact = np.flatnonzero(out.exact)
    for i in exact.tolist():
        mine = _one_off(scene, columns, i)
        assert not mine.warnings
        assert list(mine.values) == list(out.values)
        for key, value in mine.values.items():
            assert _same(value, out.values[key][i]), (key, i, value, out.values[key][i])
    # the kernel takes most ordinary rows (the refused ones are the one-off's to refuse)
    refused = 0
    for i in np.flatnonzero(~out.exact).tolist():
        try:
            result = _one_off(scene, columns, i)
        except Exception:  # noqa: BLE001 (any refusal: the generic path gives its message)
            refused += 1
            continue
        values = result.values.values()
        if result.warnings or any(not math.isfinite(v) or v == 0.0 for v in values):
            refused += 1
    taken = len(exact) / max(1, n - refused)
    assert taken > (0.3 if extremes else 0.97), (len(exact), refused)


def test_the_adapter_completes_what_the_kernel_leaves():
    """A row at an exact tie (v2' = 1 + 2 e with e = 0.6) and a row of near static balance are
    left by the kernel (no certified rounding) and computed row by row, to the one-off's
    value."""
    impact = get_scene("direct-central-impact")
    cols = {"m1": np.array([2.0, 3.5]), "m2": np.array([3.0, 1.25]),
            "v1": np.array([4.0, 2.75]), "v2": np.array([-1.0, -0.5]),
            "e": np.array([0.6, 0.35])}
    assert _kernel_only(impact, cols).exact.tolist() == [False, True]
    out = scene_columns(cols, {"scene": "direct-central-impact"})
    assert out.exact.tolist() == [True, True]
    # the tie, by hand: 1 + 2 e exactly, rounded half to even
    exact = 1 + 2 * Fraction(0.6)
    assert out.values["v2_post"][0] == float(exact) == 2.2
    drum = get_scene("drum-two-blocks")
    # m2 r2 - m1 r1 = 0.30000000000000004 - 3 x 0.1: about one ulp of either product
    cols = {"m1": np.array([3.0, 20.0]), "m2": np.array([1.0, 15.0]),
            "r1": np.array([0.1, 0.2]), "r2": np.array([3 * 0.1, 0.4]),
            "J_A": np.array([0.5, 2.0])}
    kernel = _kernel_only(drum, cols)
    out = scene_columns(cols, {"scene": "drum-two-blocks"})
    one_off = _one_off(drum, cols, 0)
    assert out.exact.tolist() == [True, True]
    for key, value in one_off.values.items():
        assert _same(out.values[key][0], value)
    # the second row is the book's E4.10, alpha = 3.7717884615... rad/s^2: the float nearest
    # the fraction formed here by hand
    assert not kernel.exact[0] and kernel.exact[1]
    m1, m2, r1, r2, J, g = (Fraction(v) for v in (20.0, 15.0, 0.2, 0.4, 2.0, 9.80665))
    assert _same(out.values["alpha"][1], float((m2 * r2 - m1 * r1) * g
                                               / (J + m1 * r1 * r1 + m2 * r2 * r2)))
    assert math.isclose(out.values["alpha"][1], 3.7717884615384615385, rel_tol=1e-15)


def test_a_slack_rope_row_keeps_the_one_offs_warning(tmp_path):
    """two-drums-rope-drive with a driving moment that throws block 2 faster than g: the kernel
    leaves the row (the one-off warns), the batch writes the one-off's warning."""
    scene = get_scene("two-drums-rope-drive")
    cols = {k: np.array([v]) for k, v in dict(m1=10.0, m2=20.0, r1=0.3, r2=0.2, J1=0.0, J2=0.0,
                                               M0=500.0).items()}
    assert not _kernel_only(scene, cols).exact[0]
    rows = tmp_path / "rows.csv"
    rows.write_text("m1,m2,r1,r2,J1,J2,M0 [N*m]\n10,20,0.3,0.2,1.5,0.8,50\n"
                    "10,20,0.3,0.2,0,0,500\n")
    out = CliRunner().invoke(cli, ["rigid-body", "--scene", "two-drums-rope-drive", "--batch",
                                   str(rows)])
    assert out.exit_code == 0
    one_off = CliRunner().invoke(cli, ["rigid-body", "--scene", "two-drums-rope-drive",
                                       "m1=10kg", "m2=20kg", "r1=0.3m", "r2=0.2m",
                                       "J1=0kg*m^2", "J2=0kg*m^2", "M0=500N*m", "--json"])
    import json

    warning = json.loads(one_off.stdout)["warnings"][0]
    assert warning.startswith("the rope of block 2 goes slack: a2 = ")
    assert warning in out.stderr
    assert len(out.stdout.splitlines()) == 3
    generic = CliRunner(env={"DYNCALC_BATCH_GENERIC": "1"}).invoke(
        cli, ["rigid-body", "--scene", "two-drums-rope-drive", "--batch", str(rows)])
    assert (generic.stdout, generic.stderr) == (out.stdout, out.stderr)


def test_the_kernel_answers_the_batch(tmp_path, monkeypatch):
    """A 2,000-row file of drum-two-blocks runs through the kernel, no row taken row by
    row."""
    calls = []
    monkeypatch.setattr(rigid_columns, "_admissible", lambda *a: calls.append(1) or True)
    rng = random.Random(7)
    lines = ["m1 [kg],m2 [kg],r1 [m],r2 [m],J_A [kg*m^2]"]
    lines += [",".join(f"{rng.uniform(0.5, 5):.6g}" for _ in range(5)) for _ in range(2000)]
    rows = tmp_path / "rows.csv"
    rows.write_text("\n".join(lines) + "\n")
    seen = []
    adapter = rigid_columns.scene_columns

    def watching(given, settings):
        out = adapter(given, settings)
        seen.append(int(out.exact.sum()))
        return out

    monkeypatch.setattr(rigid_columns, "scene_columns", watching)
    out = CliRunner().invoke(cli, ["rigid-body", "--scene", "drum-two-blocks", "--batch",
                                   str(rows)])
    assert out.exit_code == 0, out.stderr
    assert sum(seen) == 2000
    assert len(out.stdout.splitlines()) == 2001
    assert calls == []


@pytest.mark.parametrize("as_json", [False, True], ids=["csv", "json"])
def test_a_body_column_goes_through_the_kernel(tmp_path, monkeypatch, as_json):
    """wheel-incline-block with a body word a row: each word's rows through the kernel (its
    kappa), the same bytes as the generic path; a word the scene has not is refused as the
    one-off refuses it."""
    rows = tmp_path / "rows.csv"
    rows.write_text("m1 [kg],m2 [kg],beta [deg],body\n20,15,30,solid-cylinder\n"
                    "5,1,60, hoop\n3,8,-10,solid-sphere\n3,8,-10,banana\n4,2,15,hoop\n")
    seen = []
    adapter = rigid_columns.scene_columns

    def watching(given, settings):
        out = adapter(given, settings)
        seen.append(0 if out is None else int(out.exact.sum()))
        return out

    monkeypatch.setattr(rigid_columns, "scene_columns", watching)
    args = ["rigid-body", "--scene", "wheel-incline-block", "--batch", str(rows), "--on-error",
            "skip", *(["--json"] if as_json else [])]
    fast = CliRunner().invoke(cli, args)
    assert sum(seen) == 4, seen
    generic = CliRunner(env={"DYNCALC_BATCH_GENERIC": "1"}).invoke(cli, args)
    assert (fast.exit_code, fast.stdout, fast.stderr) == (
        generic.exit_code, generic.stdout, generic.stderr)
    assert fast.stderr == ("Error: line 5: body must be one of solid-sphere, hollow-sphere, "
                           "solid-cylinder, hollow-cylinder, hoop; got 'banana'\n")
