"""rigid-body --batch Euler rows (inertia_tensor, omega, alpha) on columns
(dyncalc/physics/euler_columns.py): the same bytes as the one-off row by row, on random rows
including extremes, refusals and cells the columns do not read."""
from __future__ import annotations

import random

import numpy as np
import pytest
from click.testing import CliRunner

from dyncalc.batch import GENERIC_ENV
from dyncalc.cli import cli
from dyncalc.commands import rigid_columns
from dyncalc.errors import InputError, PhysicsError
from dyncalc.physics.euler import check_tensor, euler_moment
from dyncalc.physics.euler_columns import euler_columns, tensor_rows_ok


def _tensor(rng: random.Random) -> list[float]:
    """A physical tensor: J = tr(S) I - S for a random second moment S = A A^T."""
    a = np.array([[rng.gauss(0, 1) for _ in range(3)] for _ in range(3)]) * 10 ** rng.uniform(-3, 3)
    s = a @ a.T
    return (np.trace(s) * np.eye(3) - s).ravel().tolist()


def _cell(values) -> str:
    return '"' + "; ".join(", ".join(repr(v) for v in values[r:r + 3]) for r in (0, 3, 6)) + '"'


def _vector(rng: random.Random) -> str:
    scale = 10 ** rng.uniform(-4, 4)
    return '"' + ", ".join(repr(rng.gauss(0, scale)) for _ in range(3)) + '"'


def _rows(rng: random.Random, n: int) -> list[str]:
    odd = ['"1, 2, 0; 0, 1, 0; 0, 0, 1"',          # not symmetric
           '"1, 0, 0; 0, 1, 0; 0, 0, 3"',          # triangle inequality
           '"1, 0, 0; 0, -0, 0; 0, 0, 1"',         # a typed -0 (the generic path reads it)
           '"1, 0, 0; 0, 1, 0; 0, 0, 2 kg*m^2"',   # a unit in the cell
           '"1e300, 0, 0; 0, 1e300, 0; 0, 0, 1e300"']
    lines = []
    for i in range(n):
        tensor = _cell(_tensor(rng)) if i % 9 else rng.choice(odd)
        omega = _vector(rng) if i % 17 else '"1e200, 1e200, 0"'
        lines.append(f"{tensor},{omega},{_vector(rng)}")
    return lines


@pytest.mark.parametrize("as_json", [False, True], ids=["csv", "json"])
def test_euler_rows_on_columns_are_the_one_offs_bytes(tmp_path, monkeypatch, as_json):
    rng = random.Random(11)
    path = tmp_path / "euler.csv"
    path.write_text("inertia_tensor,omega,alpha\n" + "\n".join(_rows(rng, 300)) + "\n")
    exact = []
    adapter = rigid_columns.euler_columns_of

    def watching(given, settings):
        out = adapter(given, settings)
        exact.append(0 if out is None else int(out.exact.sum()))
        return out

    monkeypatch.setattr(rigid_columns, "euler_columns_of", watching)
    args = ["rigid-body", "--batch", str(path), "--on-error", "skip",
            *(["--json"] if as_json else [])]
    fast = CliRunner().invoke(cli, args)
    assert sum(exact) >= 240, exact
    monkeypatch.setenv(GENERIC_ENV, "1")
    generic = CliRunner().invoke(cli, args)
    assert (fast.exit_code, fast.stdout, fast.stderr) == (
        generic.exit_code, generic.stdout, generic.stderr)
    assert "is not symmetric" in fast.stderr and "triangle inequality" in fast.stderr


def test_a_vector_left_out_is_zero(tmp_path):
    path = tmp_path / "euler.csv"
    path.write_text('inertia_tensor,omega\n"1,0,0;0,1,0;0,0,2","2,0,3"\n'
                    '"2,0.1,0;0.1,3,0;0,0,4","1,2,3"\n')
    fast = CliRunner().invoke(cli, ["rigid-body", "--batch", str(path)])
    generic = CliRunner(env={GENERIC_ENV: "1"}).invoke(cli, ["rigid-body", "--batch", str(path)])
    assert fast.stdout == generic.stdout
    # omega x (J omega) by hand: J omega = (2, 0, 6), (2, 0, 3) x (2, 0, 6) = (0, -6, 0)
    assert fast.stdout.splitlines()[1].endswith(',"0.0,-6.0,0.0",6.0,"2.0,0.0,6.0",11.0')


def test_the_column_kernel_against_euler_moment_with_extremes():
    rng = np.random.default_rng(5)
    n = 3000
    a = rng.standard_normal((n, 3, 3)) * np.exp(rng.uniform(-300, 300, (n, 1, 1)) / 10)
    s = a @ np.transpose(a, (0, 2, 1))
    J = np.trace(s, axis1=1, axis2=2)[:, None, None] * np.eye(3) - s
    J[::5] = rng.standard_normal((len(J[::5]), 3, 3))
    w = rng.standard_normal((n, 3)) * np.exp(rng.uniform(-300, 300, (n, 1)))
    al = rng.standard_normal((n, 3)) * np.exp(rng.uniform(-300, 300, (n, 1)))
    w[::7, 1] = 0.0
    out = euler_columns(J, w, al)
    taken = 0
    for i in range(n):
        try:
            check_tensor(J[i])
            want = euler_moment(J[i], w[i], al[i])
        except (InputError, PhysicsError):
            assert not out.exact[i]
            continue
        assert tensor_rows_ok(J[i:i + 1])[0]
        if not out.exact[i]:
            continue
        taken += 1
        for key in ("M", "H"):
            assert np.array_equal(np.asarray(want[key]).view(np.int64),
                                  out.values[key][i].view(np.int64)), (key, i)
        for key in ("M_mag", "T"):
            assert np.float64(want[key]).view(np.int64) == np.float64(
                out.values[key][i]).view(np.int64), (key, i)
    assert taken > 1000
