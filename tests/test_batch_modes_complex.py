"""``modes --batch`` rows whose damping is not proportional, on the stack
(dyncalc/physics/modes_columns._complex_damping: the state-space eigenvalues of the Cholesky-
reduced system with numpy's ``eig``) against the one-off row by row (``scipy.linalg.eig`` of
the scaled pencil, LAPACK's ggev): the same rows, models, notes and refusals, the numbers
within 1e-12 relative (the documented difference: two eigensolvers round otherwise); and
against the closed form of a single degree of freedom's eigenvalues."""
from __future__ import annotations

import io
import json
import math
import random

import numpy as np
import pytest

from dyncalc.batch import run_batch
from dyncalc.batch.rows import ModesRows
from dyncalc.physics.modes import NON_PROPORTIONAL_NOTE
from dyncalc.physics.modes_columns import stacked_modes

from tests.test_batch_modes import _cells, _close


def _text(A) -> str:
    return "[" + ", ".join("[" + ", ".join(repr(float(x)) for x in r) + "]" for r in A) + "]"


def _spd(rng, n: int, scale: float):
    a = np.array([[rng.uniform(-1, 1) for _ in range(n)] for _ in range(n)])
    A = (a @ a.T + n * np.eye(n)) * scale
    return (A + A.T) / 2.0


def _file(tmp_path, seed: int, count: int = 100):
    """Rows with a C that is not proportional (a random positive semi-definite matrix, a
    dashpot on one coordinate), sizes 2 to 4, scales 1e-100 to 1e90; then rows the kernel
    leaves to the one-off: an overdamped mode (real eigenvalues), zeta below 1e-3, and
    proportional ones it takes on the other path."""
    rng = random.Random(seed)
    lines = ["M,K,C"]
    for _ in range(count):
        n = rng.choice((2, 3, 4))
        scale_m, scale_k = rng.choice([1.0, 1e-100, 3.5]), rng.choice([1.0, 1e90, 250.0])
        M, K = _spd(rng, n, scale_m), _spd(rng, n, scale_k)
        rate = math.sqrt(scale_k / scale_m) * scale_m
        if rng.random() < 0.5:
            b = np.array([[rng.uniform(-1, 1) for _ in range(n)] for _ in range(n - 1)])
            C = b.T @ b  # rank n - 1: positive semi-definite
        else:
            C = np.zeros((n, n))
            C[rng.randrange(n), rng.randrange(n)] = 0.0
            i = rng.randrange(n)
            C[i, i] = 1.0
        C = (C + C.T) / 2.0 * rate * rng.uniform(0.05, 0.6)
        lines.append(f'"{_text(M)}","{_text(K)}","{_text(C)}"')
    lines += ['"[[1,0],[0,1]]","[[2,-1],[-1,2]]","[[9,0],[0,0]]"',      # real eigenvalues
              '"[[1,0],[0,1]]","[[2,-1],[-1,2]]","[[0.0001,0],[0,0]]"',  # zeta below 1e-3
              '"[[1,0],[0,1]]","[[2,-1],[-1,2]]","[[0.2,0],[0,0.2]]"']   # proportional
    path = tmp_path / "complex.csv"
    path.write_text("\n".join(lines) + "\n")
    return path, count


def _run(path, as_json: bool, fast: bool, normalize=None):
    out, err = io.StringIO(), io.StringIO()
    status = run_batch(ModesRows(normalize=normalize), str(path), as_json=as_json,
                       on_error="skip", out=out, err=err, fast=fast)
    return status, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("normalize", [None, "mass"])
@pytest.mark.parametrize("seed", [1, 2])
def test_complex_damping_rows_are_the_one_off_within_1e_12(tmp_path, seed, normalize):
    path, count = _file(tmp_path, seed)
    for as_json in (False, True):
        fast, generic = _run(path, as_json, True, normalize), _run(path, as_json, False,
                                                                    normalize)
        assert (fast[0], fast[2]) == (generic[0], generic[2]) and fast[0] == 0
        if as_json:
            lines_f, lines_g = fast[1].splitlines(), generic[1].splitlines()
            assert len(lines_f) == len(lines_g) == count + 3
            models = [json.loads(line)["model"] for line in lines_g]
            assert models.count("non-proportional damping") >= count
            for a, b in zip(lines_f, lines_g):
                assert _close(json.loads(a), json.loads(b))
        else:
            assert fast[2].count(NON_PROPORTIONAL_NOTE) >= count
            mine, theirs = _cells(fast[1]), _cells(generic[1])
            assert len(mine) == len(theirs)
            for a, b in zip(mine, theirs):
                assert len(a) == len(b) and all(_close(x, y) for x, y in zip(a, b)), (a, b)


def _stacked(path):
    """The kernel on the file's rows of two coordinates: how many it takes."""
    rows = [json.loads("[" + line + "]") for line in path.read_text().splitlines()[1:]]
    rows = [[np.array(json.loads(c)) for c in r] for r in rows]
    rows = [r for r in rows if r[0].shape == (2, 2)]
    M, K, C = (np.stack([r[j] for r in rows]) for j in range(3))
    return stacked_modes(M, K, "max", C, damping="complex")


def test_most_non_proportional_rows_take_the_kernel(tmp_path):
    path, _count = _file(tmp_path, 3, count=300)
    out = _stacked(path)
    rows = len(out.exact)
    # (a dashpot on one coordinate often leaves a mode below zeta 1e-3: the one-off's)
    assert int(np.sum(out.exact)) >= 0.6 * (rows - 3)  # the last three are the one-off's
    assert not out.exact[-3:].any()


def test_one_mass_on_two_coordinates_against_the_closed_form():
    # two uncoupled-in-K masses joined only by a dashpot: M = I, K = diag(k1, k2),
    # C = c [[1, -1], [-1, 1]]; with k1 = k2 = k the modes are 1, 1 and 1, -1:
    # s^2 + 2 c s + k = 0 for the second (relative motion), s^2 + k = 0 for the first
    # (undamped: real part 0, so zeta_1 = 0 is below COMPLEX_ZETA and goes to the one-off);
    # with k2 = 4 k1 every mode is damped: compare with the roots of the quartic
    k, c = 100.0, 3.0
    M = np.eye(2)[None]
    K = np.array([[[k, 0.0], [0.0, 4.0 * k]]])
    C = np.array([[[c, -c], [-c, c]]])
    out = stacked_modes(M, K, "max", C, damping="complex")
    assert out.exact.tolist() == [True] and out.model == "non-proportional damping"
    # det(s^2 M + s C + K) = (s^2 + c s + k)(s^2 + c s + 4k) - c^2 s^2
    roots = np.roots([1.0, 2 * c, 5 * k, 5 * c * k, 4 * k * k])
    upper = sorted((z for z in roots if z.imag > 0), key=abs)
    for i, z in enumerate(upper, start=1):
        assert math.isclose(out.values[f"omega_d_{i}"][0], z.imag, rel_tol=1e-12)
        assert math.isclose(out.values[f"zeta_{i}"][0], -z.real / abs(z), rel_tol=1e-12)
    # and the undamped pair k1 = k2: zeta_1 = 0 (no damping of the in-phase mode)
    K = np.array([[[k, 0.0], [0.0, k]]])
    assert stacked_modes(M, K, "max", C, damping="complex").exact.tolist() == [False]


def test_the_modulus_is_within_two_ulp_and_the_same_at_every_place():
    """``modulus`` (the ``|s|`` of the stacked path and of the limit script) against mpmath
    at 60 digits, and the same bits for a value wherever it sits in arrays of every length
    from 1 to 40 (what ``numpy.abs`` of a complex array does not promise)."""
    import mpmath

    from dyncalc.physics.modes_columns import modulus

    rng = np.random.default_rng(7)
    size = 400
    z = (rng.standard_normal(size) * 10.0 ** rng.uniform(-300, 300, size)
         + 1j * rng.standard_normal(size) * 10.0 ** rng.uniform(-300, 300, size))
    z[:4] = [3 + 4j, -1e300j, 0j, 1e-320 + 1e-320j]
    got = modulus(z)
    with mpmath.workdps(60):
        for value, m in zip(z.tolist(), got.tolist()):
            exact = float(mpmath.sqrt(mpmath.mpf(value.real) ** 2 + mpmath.mpf(value.imag) ** 2))
            assert abs(m - exact) <= 2 * math.ulp(exact), (value, m, exact)
    for n in range(1, 41):
        for start in range(8):
            assert modulus(z[start:start + n]).tolist() == got[start:start + n].tolist()
            strided = np.stack([z, z], axis=1)[start:start + n, 0]
            assert modulus(strided).tolist() == got[start:start + n].tolist()
