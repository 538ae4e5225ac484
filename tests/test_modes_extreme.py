"""modes at extreme but valid scales (issue 19): the eigenproblem is solved with M scaled to
a diagonal near 1 (powers of 2) and each uncoupled group in its own time unit, so entries
from 1e-300 to 1e300 give the closed forms; only a result beyond float64 is refused, saying
so."""
import json
import math

import mpmath
import numpy as np
import pytest
from click.testing import CliRunner

from dyncalc.cli import cli
from dyncalc.physics.modes import solve_modes


def run(*args):
    return CliRunner().invoke(cli, ["modes", *args])


def sqrt_ratio(k, m):
    """sqrt(k/m) at 30 digits (k/m may lie far beyond float64)."""
    return float(mpmath.sqrt(mpmath.mpf(k) / mpmath.mpf(m)))


@pytest.mark.parametrize("m1, k1, m2, k2", [
    (1e300, 4e300, 1e-300, 9e-300),     # both omega ordinary, entries 1e600 apart
    (1e-300, 1e300, 1.0, 1.0),          # omega 1e300 beside omega 1
    (1e-300, 1e300, 1e300, 1e-300),     # omega 1e300 beside omega 1e-300
    (3e-310, 2e-310, 7e305, 5e307),     # subnormal mass and stiffness
])
def test_two_uncoupled_oscillators(m1, k1, m2, k2):
    out = solve_modes(np.diag([m1, m2]), np.diag([k1, k2]))
    expected = sorted([(sqrt_ratio(k1, m1), 0), (sqrt_ratio(k2, m2), 1)])
    assert out.omega.tolist() == pytest.approx([w for w, _ in expected], rel=1e-14)
    for col, (_, coordinate) in enumerate(expected):
        shape = [0.0, 0.0]
        shape[coordinate] = 1.0
        assert out.shapes[:, col].tolist() == shape
        assert out.modal_mass[col] == pytest.approx((m1, m2)[coordinate], rel=1e-14)
        assert out.modal_stiffness[col] == pytest.approx((k1, k2)[coordinate], rel=1e-14)
    assert out.notes == []


@pytest.mark.parametrize("mass_scale, stiffness_scale", [
    (1e-200, 1e200), (1e200, 1e200), (1e200, 1e-200), (1e-150, 1e150)])
def test_chain_scaled(mass_scale, stiffness_scale):
    """A fixed-fixed chain of n masses with M and K scaled: omega_j = 2 sqrt(k/m)
    sin(j pi / (2 (n + 1))) with k/m scaled by stiffness_scale / mass_scale."""
    n, m, k = 40, 2.0, 300.0
    K = (2 * np.eye(n) - np.eye(n, k=1) - np.eye(n, k=-1)) * (k * stiffness_scale)
    out = solve_modes(np.eye(n) * (m * mass_scale), K)
    ratio = sqrt_ratio(k * stiffness_scale, m * mass_scale)
    j = np.arange(1, n + 1)
    expected = 2 * ratio * np.sin(j * np.pi / (2 * (n + 1)))
    assert np.allclose(out.omega, expected, rtol=1e-11, atol=0)
    assert np.allclose(out.modal_mass, m * mass_scale * np.sum(out.shapes ** 2, axis=0),
                       rtol=1e-11, atol=0)


def test_graded_coordinates_keep_the_frequencies():
    """Two masses m between walls through three springs k, with the coordinates rescaled by
    T = diag(1e150, 1e-150) (M' = T M T, K' = T K T): the frequencies sqrt(k/m) and
    sqrt(3 k/m) do not change, and the shapes become T^-1 phi."""
    m, k, t = 2.0, 300.0, 1e150
    T = np.diag([t, 1 / t])
    M = T @ (m * np.eye(2)) @ T
    K = T @ np.array([[2 * k, -k], [-k, 2 * k]]) @ T
    out = solve_modes(M, K)
    assert out.omega.tolist() == pytest.approx([math.sqrt(k / m), math.sqrt(3 * k / m)],
                                               rel=1e-13)
    assert out.shapes[:, 0].tolist() == pytest.approx([1 / t ** 2, 1.0], rel=1e-13)
    assert out.shapes[:, 1].tolist() == pytest.approx([-1 / t ** 2, 1.0], rel=1e-13)


def test_extreme_system_through_the_cli():
    result = run("--M", "1e-300, 0; 0, 1 kg", "--K", "1e300, 0; 0, 1 N/m", "--json")
    assert result.exit_code == 0, result.stderr
    got = json.loads(result.stdout)["results"]
    assert got["omega_1"]["value"] == 1.0
    assert got["omega_2"]["value"] == pytest.approx(1e300, rel=1e-15)
    assert got["mode_2"]["value"] == [1.0, 0.0]


def test_damping_at_extreme_scales():
    """Each uncoupled oscillator keeps its own damping ratio c / (2 sqrt(k m))."""
    m, k, c = np.array([1e-300, 1e200]), np.array([1e300, 4e200]), np.array([1e-1, 2e199])
    out = solve_modes(np.diag(m), np.diag(k), np.diag(c))
    zeta = c / (2 * np.sqrt(k) * np.sqrt(m))
    omega = np.sqrt(k) / np.sqrt(m)
    order = np.argsort(omega)
    assert out.omega.tolist() == pytest.approx(omega[order].tolist(), rel=1e-14)
    assert out.zeta.tolist() == pytest.approx(zeta[order].tolist(), rel=1e-13)
    assert out.omega_d.tolist() == pytest.approx(
        (omega * np.sqrt(1 - zeta ** 2))[order].tolist(), rel=1e-13)
    assert out.proportional


def test_what_truly_overflows_is_refused_saying_so():
    """sqrt(1e308 / 5e-324) ~ 4.5e315 rad/s: beyond float64."""
    result = run("--M", "1, 0; 0, 5e-324 kg", "--K", "1, 0; 0, 1e308 N/m")
    assert result.exit_code == 2
    assert result.stderr == ("Error: omega_2 overflows float64 (it exceeds 1.79769e+308 in "
                             "SI): the matrices' scales are too far apart for this result to "
                             "be represented\n")


def test_a_singular_mass_matrix_is_still_refused():
    result = run("--M", "1, 1; 1, 1 kg", "--K", "1, 0; 0, 1 N/m")
    assert result.exit_code == 2
    assert result.stderr == ("Error: --M is not positive definite (its smallest eigenvalue is "
                             "0 in SI, its largest 2): every motion of the coordinates must "
                             "carry kinetic energy\n")


def test_uncoupled_groups_are_scipys_connected_components():
    """The groups solved apart are the connected components of the entries' pattern
    (scipy.sparse.csgraph, an independent implementation), on random patterns."""
    from scipy.sparse.csgraph import connected_components

    from dyncalc.physics.modes import _components

    rng = np.random.default_rng(19)
    for _ in range(300):
        n = int(rng.integers(1, 40))
        A = rng.random((n, n)) < rng.random() * 0.15
        A = A | A.T
        np.fill_diagonal(A, True)
        count, labels = connected_components(A, directed=False)
        expected = sorted(tuple(np.flatnonzero(labels == k)) for k in range(count))
        assert sorted(tuple(g) for g in _components(A * 1.0, np.zeros((n, n)), None)) \
            == expected
