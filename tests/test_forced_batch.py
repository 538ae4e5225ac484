"""forced-response in batch: the column adapter (commands/forced_response.columns) gives the
one-off's numbers to the bit, and a block whose rows have different results (isolation above
Omega_iso only, the bandwidth where it exists) is split by them, each part on the fast path.
Also the extreme damping ratios that the batch fuzz found raising in the one-off."""
import math

import numpy as np
import pytest

from dyncalc import batch
from dyncalc.batch.fast_commands import _command_fast
from dyncalc.commands.forced_response import columns
from helpers import invoke


def test_adapter_values_are_the_one_off_values():
    given = {"k": np.array([4e4, 1e3, 5e2]), "m": np.array([40.0, 2.0, 1.0]),
             "zeta": np.array([0.05, 0.1, 0.2]), "F0": np.array([100.0, 1.0, 3.0]),
             "Omega": np.array([157.07963267948966, 10.0, 40.0])}
    out = columns(given, {"scene": None})
    assert out.exact.tolist() == [True, True, True]
    for i in range(3):
        k, m, z, F0, W = (float(given[n][i]) for n in ("k", "m", "zeta", "F0", "Omega"))
        omega = math.sqrt(k / m)
        eta = W / omega
        D = math.hypot(1 - eta * eta, 2 * z * eta)
        assert out.values["X"][i] == pytest.approx(F0 / k / D, rel=1e-13)
        assert out.values["TR"][i] == pytest.approx(math.hypot(1, 2 * z * eta) / D, rel=1e-13)
        has_iso = math.hypot(1, 2 * z * eta) / D < 1
        assert math.isnan(out.values["isolation"][i]) != has_iso


def test_adapter_refuses_what_it_does_not_handle():
    ones = np.ones(2)
    assert columns({"k": ones, "m": ones, "F0": ones, "Omega": ones}, {"scene": "quarter-car"}) is None
    assert columns({"k": ones, "m": ones, "F0": ones, "base": ones, "Omega": ones},
                   {"scene": None}) is None          # two excitations: the one-off refuses
    assert columns({"k": ones, "m": ones, "TR": ones, "Omega": ones}, {"scene": None}) is None
    out = columns({"k": np.array([1.0, -1.0]), "m": ones, "zeta": ones * 0.1,
                   "F0": ones, "Omega": ones * 3}, {"scene": None})
    assert out.exact.tolist() == [True, False]     # a negative stiffness: the one-off's to say


def test_block_with_different_results_is_split_and_stays_fast(tmp_path):
    """eta = 0.5 (no isolation) and eta = 3 (isolation): two blocks, every row fast."""
    header = "k,m,zeta,F0,Omega"
    rows = ["100,1,0.05,1,5", "100,1,0.05,1,30", "100,1,0.1,2,4", "100,1,0.1,2,25"]
    spec = batch.ForcedRows()
    cols = batch.read_header(1, header.split(","), spec)
    parsed = [r.split(",") for r in rows]
    table = [[row[c.index] for row in parsed] for c in cols]
    blocks = _command_fast(spec, cols, table, True, {})
    assert len(blocks) == 2
    assert sorted(i for b in blocks for i in b.rows.tolist()) == [0, 1, 2, 3]
    names = sorted(tuple(b.values) for b in blocks)
    assert ("isolation" in names[0]) != ("isolation" in names[1])


@pytest.mark.parametrize("zeta", ["1e300", "1e200"])
def test_huge_damping_ratio_is_answered(zeta):
    """2 zeta^2 beyond float64 used to raise OverflowError: now no peak, said so."""
    result = invoke("forced-response", "--k", "1N/m", "--m", "1kg", "--zeta", zeta, "--F0",
                    "1N", "--Omega", "2rad/s")
    assert result.exit_code == 0, result.stderr
    assert (f"warning: zeta = {float(zeta):.6g} >= 1/sqrt(2): the amplitude has no resonance "
            "peak; it is largest at Omega = 0") in result.stdout


def test_vanishing_damping_base_bandwidth():
    """zeta = 1e-300 on base motion (4 zeta^2 underflows): bandwidth 2 zeta omega to the
    last digit (4 zeta sqrt(1 - zeta^2)/(eta+ + eta-), eta+- = 1)."""
    result = invoke("forced-response", "--omega", "3rad/s", "--zeta", "1e-300", "--base", "1m",
                    "--Omega", "6rad/s", "--value", "bandwidth")
    assert result.exit_code == 0, result.stderr
    assert float(result.stdout) == pytest.approx(6e-300, rel=1e-15)


def test_unbalance_far_above_resonance_keeps_its_limits():
    """eta = 1e308 (eta^2 beyond float64): V -> 1, TR and F_T from mpmath at 50 digits (they
    were 0 and NaN when the squares overflowed)."""
    import json

    import mpmath

    with mpmath.workdps(50):
        eta, z = mpmath.mpf("1e308"), mpmath.mpf("0.3")
        D = mpmath.sqrt((1 - eta ** 2) ** 2 + (2 * z * eta) ** 2)
        TR = mpmath.sqrt(1 + (2 * z * eta) ** 2) / D
        V, F_T = eta ** 2 / D, 1 * eta ** 2 * TR          # m_u e = 1 kg m, omega = 1 rad/s
    result = invoke("forced-response", "--omega", "1rad/s", "--zeta", "0.3", "--unbalance",
                    "1kg*m", "--m", "1kg", "--Omega", "1e308rad/s", "--json")
    assert result.exit_code == 0, result.stderr
    data = json.loads(result.stdout)
    got = {k: v["value"] for k, v in data["results"].items()}
    assert data["warnings"] == []
    assert got["V"] == pytest.approx(float(V), rel=1e-15)
    assert got["TR"] == pytest.approx(float(TR), rel=1e-12)   # a subnormal: ~50 bits
    assert got["F_T"] == pytest.approx(float(F_T), rel=1e-15)


def test_unbalance_at_rest_is_no_motion():
    """Omega = 0 with an unbalance: no unbalance force (m_u e Omega^2 = 0), so X = V = F_T = 0
    and TR = 1; it used to end in an internal error (ZeroDivisionError in V = eta/(D/eta))."""
    result = invoke("forced-response", "--omega", "10rad/s", "--m", "1kg", "--zeta", "0.1",
                    "--unbalance", "1kg*m", "--Omega", "0rad/s", "--json")
    assert result.exit_code == 0, result.stderr
    import json
    got = json.loads(result.stdout)["results"]
    assert [got[n]["value"] for n in ("X", "V", "F_T", "TR")] == [0.0, 0.0, 0.0, 1.0]
    assert got["V_res"]["value"] == pytest.approx(1 / (2 * 0.1), rel=1e-15)


def test_heavily_overdamped_transient_keeps_its_slow_rate():
    """zeta = 1e10: the slow rate zeta omega - omega sqrt(zeta^2 - 1) cancelled to 0 (and at
    zeta about 1e303 went negative and exp overflowed: an internal error); now
    omega/(zeta + sqrt(zeta^2 - 1)). Against mpmath at 50 digits."""
    import mpmath

    from dyncalc.physics.forced import transient

    mpmath.mp.dps = 50
    z, w, x0, t = mpmath.mpf(10) ** 10, mpmath.mpf(1), mpmath.mpf(1), mpmath.mpf(10) ** 10
    ws = w * mpmath.sqrt(z * z - 1)
    slow, fast = mpmath.exp(-(z * w - ws) * t), mpmath.exp(-(z * w + ws) * t)
    b = z * w * x0
    ref = x0 * (slow + fast) / 2 + b * (slow - fast) / (2 * ws)
    assert transient(1.0, 1e10, 1.0, 0.0, 1e10) == pytest.approx(float(ref), rel=1e-9)
    result = invoke("forced-response", "--omega", "16.4rpm", "--m", "1e-300kg", "--c",
                    "40N*s/m", "--unbalance", "13.9kg*m", "--Omega", "3.08rad/s", "--v0",
                    "0.18m/s", "--t", "1.8ms", "--value", "x")
    assert result.exit_code == 0, result.stderr
    assert math.isfinite(float(result.stdout))


@pytest.mark.parametrize("header", ["k,m,F0,Omega", "omega [rpm],m,base,f_exc",
                                    "k [kN/m],m,unbalance,Omega,x0,v0,t",
                                    "omega,m,base_accel,Omega [rpm],t [ms]"])
def test_undamped_rows_vectorised_write_the_one_off_bytes(tmp_path, header):
    """Undamped files through the vectorised path: the same CSV, JSON lines, warning lines
    on stderr (one a row) and exit status as row by row, edges (zero, negative, 1e300, a
    resonance, units, empty cells) included; most rows vectorised."""
    import random
    import sys

    sys.path.insert(0, str(__import__("pathlib").Path(__file__).parent))
    from test_batch_kernels import _command_cell, _same_both_ways

    rng = random.Random(header)
    names = [h.split("[")[0].strip() for h in header.split(",")]
    rows = [",".join(_command_cell(rng, "forced-response", n) for n in names)
            for _ in range(120)]
    rows += ["100,1,2,10" + ",0" * (len(names) - 4)] * 2   # Omega = omega (k, m): refused
    path = tmp_path / "rows.csv"
    path.write_text(header + "\n" + "\n".join(rows) + "\n")
    spec = batch.ForcedRows()
    code, _out, err = _same_both_ways(spec, path)
    assert code == 2                        # the refused and bad rows: exit 2, as row by row
    assert err.count("warning: line") > 60
    cols = batch.read_header(1, header.split(","), spec)
    import csv
    import io
    parsed = list(csv.reader(io.StringIO("\n".join(rows))))
    table = [[row[c.index] for row in parsed] for c in cols]
    covered = {i for b in _command_fast(spec, cols, table, True, {}) for i in b.rows.tolist()}
    from dyncalc.physics.forced import UNDAMPED_WARNING
    clean = set()
    for i, row in enumerate(parsed):
        texts = {c.key: batch.with_header_unit(row[c.index].strip(), c.unit)
                 for c in cols if row[c.index].strip()}
        try:
            if spec.compute(texts, {}).warnings == [UNDAMPED_WARNING]:
                clean.add(i)
        except Exception:
            pass
    assert covered <= clean and len(covered) > 40
    # what is left to the one-off: rows with a cell beyond the kernel's domain
    assert all({"0", "1e300", "1e-300"} & set(parsed[i]) for i in clean - covered)


def test_a_whole_undamped_chunk_writes_its_warnings(tmp_path):
    """Every row of the chunk vectorised (one block): the warning lines still come, one a
    row, after the chunk's lines, as row by row."""
    from test_batch_kernels import _same_both_ways

    path = tmp_path / "u.csv"
    path.write_text("k,m,F0,Omega\n" + "".join(f"{100 + i},1,1,{3 + i % 7}\n"
                                               for i in range(30)))
    spec = batch.ForcedRows()
    code, _out, err = _same_both_ways(spec, path)
    assert code == 0
    assert err.splitlines() == [f"warning: line {n}: undamped: X_res, the peak and the "
                                "bandwidth are unbounded; not given" for n in range(2, 32)]


def test_each_kind_of_block_is_probed_once_a_run_not_once_a_chunk(tmp_path):
    """Undamped rows below and above Omega_iso (two blocks a chunk: isolation or not) over
    seven chunks: two one-offs in all, and the lines are the row-by-row run's."""
    import io

    rows = [f"{100 + i},1,1,{3 + (i % 2) * 20}" for i in range(56)]   # omega ~ 10: eta .3, 2.2
    path = tmp_path / "u.csv"
    path.write_text("k,m,F0,Omega\n" + "\n".join(rows) + "\n")
    spec = batch.ForcedRows()
    spec.csv_rows = 8
    calls = []
    compute = spec.compute
    spec.compute = lambda texts, labels: calls.append(texts) or compute(texts, labels)
    out, err = io.StringIO(), io.StringIO()
    assert batch.run_batch(spec, str(path), out=out, err=err) == 0
    assert len(calls) == 2   # one probe per kind (with and without isolation), seven chunks
    generic, generic_err = io.StringIO(), io.StringIO()
    assert batch.run_batch(batch.ForcedRows(), str(path), out=generic, err=generic_err,
                           fast=False) == 0
    assert out.getvalue() == generic.getvalue() and err.getvalue() == generic_err.getvalue()
    assert out.getvalue().count("\n") == 57
