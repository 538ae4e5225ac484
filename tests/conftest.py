"""Test settings shared by the suite: hypothesis draws the same examples on every run (no
example database), so a green run on one machine is green on another and a failure is
reproduced by running the test again, and it has no deadline nor the too-slow health check
(wall-clock assertions: a CI run on a loaded machine failed a 0.03 ms example that once
took 260 ms);
a test's mpmath precision is its own (its module's ``MPMATH_DPS``, at least 40 digits)."""
import pytest
from hypothesis import HealthCheck, settings

settings.register_profile("dyncalc", derandomize=True, database=None, deadline=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile("dyncalc")


#: mpmath's working precision at the start of every test, unless its module asks for more
#: (``MPMATH_DPS = 50``): a test's reference digits never depend on which modules were
#: collected or run before it (a module-level ``mpmath.mp.dps = ...`` is global, and the last
#: module imported used to decide it for all).
MPMATH_DPS = 40


@pytest.fixture(autouse=True)
def _mpmath_precision_kept(request):
    """Each test starts at its module's mpmath precision (``MPMATH_DPS``, 40 digits unless the
    module says more); a test that sets ``mp.dps`` itself keeps it to itself."""
    import mpmath

    dps = mpmath.mp.dps
    mpmath.mp.dps = max(MPMATH_DPS, getattr(request.module, "MPMATH_DPS", MPMATH_DPS))
    yield
    mpmath.mp.dps = dps
