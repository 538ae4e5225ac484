"""Column kernels of dyncalc.physics.springs against the one-off functions, bit for bit."""
from __future__ import annotations

import numpy as np
import pytest

from dyncalc.physics.columns import kernel_of
from dyncalc.physics.springs import parallel_stiffness, series_stiffness
from dyncalc.units import Q_


@pytest.mark.parametrize("function", [series_stiffness, parallel_stiffness])
def test_stiffness_kernels_match_the_one_off(function):
    rng = np.random.default_rng(11)
    n, e = 600, 4
    k = 10.0 ** rng.uniform(-3, 6, (n, e))
    k[:60] = 10.0 ** rng.uniform(-300, 300, (60, e))
    k[60] = [200.0, 300.0, np.inf, 600.0]         # a rigid link
    k[61] = [0.1, 0.2, 0.3, 0.4]
    out = kernel_of(function)(k)
    assert out.model == function.__name__.split("_")[0]
    one_off = np.array([function([Q_(x, "N/m") for x in row]).to("N/m").magnitude
                        for row in k.tolist()])
    exact = out.exact
    assert exact[60:].all() and exact.mean() > 0.95
    assert np.array_equal(out.values["k_eq"][exact].view(np.int64),
                          one_off[exact].view(np.int64))
    assert out.values["k_eq"][60] == (100.0 if function is series_stiffness else np.inf)


def test_stiffness_kernels_refuse_non_positive_rows():
    out = kernel_of(series_stiffness)(np.array([[1.0, -2.0], [0.0, 1.0], [3.0, 6.0]]))
    assert out.exact.tolist() == [False, False, True] and out.values["k_eq"][2] == 2.0
    with pytest.raises(ValueError):
        kernel_of(parallel_stiffness)(np.array([1.0, 2.0]))
