"""Column kernel of coupled-blocks (dyncalc/physics/coupled.py) against the one-off function,
bit for bit (see tests/kernel_rows.py), including the mode shapes: ordinary and extreme rows,
rows with one spring absent, equal blocks and the textbook set-up.
"""
import math

import numpy as np

from dyncalc.physics.columns import kernel_of
from dyncalc.physics.coupled import coupled_blocks
from kernel_rows import check_kernel, log_uniform

N = 500


def _mix(rng, ordinary, scale, n=N):
    """A third of the values in the ordinary range, a third within 1e+-30 of ``scale`` (one
    per row, anywhere in 1e-250..1e250: the kernel scales by powers of two), a third over
    1e-300..1e300."""
    third = n // 3
    return np.concatenate([log_uniform(rng, *ordinary, third),
                           scale[third:2 * third] * log_uniform(rng, -30, 30, third),
                           log_uniform(rng, -300, 300, n - 2 * third)])


def test_coupled_blocks_columns():
    rng = np.random.default_rng(41)
    masses, springs = log_uniform(rng, -250, 250, N), log_uniform(rng, -250, 250, N)
    m1, m2 = _mix(rng, (-1, 2), masses), _mix(rng, (-1, 2), masses)
    k1, k2, k3 = (_mix(rng, (1, 4), springs) for _ in range(3))
    k1[:15] = 0.0
    k3[15:30] = 0.0                 # uncoupled: the modes are the unit vectors
    k2[30:35] = k3[30:35] = 0.0     # refused by the one-off
    m2[35:45], k2[35:45] = m1[35:45], k1[35:45]      # symmetric: (1, 1)/sqrt 2 and (1, -1)/sqrt 2
    rows = {"m1": np.append(m1, [1.0, 1.0]), "m2": np.append(m2, [2.0, 1.0]),
            "k1": np.append(k1, [100.0, 100.0]), "k2": np.append(k2, [200.0, 100.0]),
            "k3": np.append(k3, [50.0, 100.0])}
    ordinary = np.append(np.arange(N) < 2 * (N // 3), [True, True])
    check_kernel(coupled_blocks, rows, {n: ("kg" if n[0] == "m" else "N/m")
                                          for n in rows}, ordinary=ordinary,
                 min_share=0.97)
    out = kernel_of(coupled_blocks)(**{n: v[-2:] for n, v in rows.items()})
    assert out.exact.all()
    # E4.15 as the scene's example: omega_1 = 10, omega_2 = sqrt(175) (mpmath.eig)
    assert out.values["omega_1"][0] == 10.0
    assert abs(out.values["omega_2"][0] - 13.228756555322953) < 4e-15
    # equal blocks and springs: sqrt(k/m), sqrt(3k/m), in-phase and anti-phase modes
    assert out.values["omega_2"][1] == math.sqrt(300.0)
    assert np.allclose(out.values["mode_2"][1], [2 ** -0.5, -(2 ** -0.5)], rtol=0, atol=2e-16)


def test_coupled_blocks_refusals_are_not_exact():
    ones = np.ones(3)
    zero = np.zeros(3)
    out = kernel_of(coupled_blocks)(ones, ones, ones, zero, zero)
    assert not out.exact.any()
    out = kernel_of(coupled_blocks)(ones, ones, -ones, ones, ones)
    assert not out.exact.any()
