"""eom's time budget (SIGALRM) leaves the caller's interval timer and handler as it found
them (issue 19): the remaining time and interval are restored, and a timer that came due
during the derivation still fires once it ends."""
import signal
import time

import pytest

import dyncalc

pytestmark = pytest.mark.skipif(not hasattr(signal, "setitimer"), reason="POSIX timers only")

WORDS = dict(m="2 kg", k="200 N/m")


def _eom():
    return dyncalc.eom(coords="x", T="m*x'^2/2", V="k*x^2/2", **WORDS)


@pytest.fixture
def caller_timer():
    fired = []

    def handler(signum, frame):
        fired.append(time.monotonic())
    previous = signal.signal(signal.SIGALRM, handler)
    yield fired, handler
    signal.setitimer(signal.ITIMER_REAL, 0)
    signal.signal(signal.SIGALRM, previous)


def test_a_callers_itimer_survives_eom(caller_timer):
    fired, handler = caller_timer
    signal.setitimer(signal.ITIMER_REAL, 100.0, 50.0)
    started = time.monotonic()
    r = _eom()
    elapsed = time.monotonic() - started
    assert r["eom_1"] == "x'' = -k*x/m"
    delay, interval = signal.getitimer(signal.ITIMER_REAL)
    assert interval == pytest.approx(50.0, abs=1e-3)
    assert 100.0 - elapsed - 0.05 <= delay <= 100.0 - elapsed + 1e-3
    assert signal.getsignal(signal.SIGALRM) is handler
    assert fired == []


def test_a_callers_timer_due_during_eom_still_fires(caller_timer, monkeypatch):
    from dyncalc.commands import eom_results

    fired, handler = caller_timer
    _eom()  # sympy imported: what comes before the budget now takes milliseconds
    build = eom_results._build

    def slow_build(*args):  # a derivation that outlasts the caller's timer
        out = build(*args)
        time.sleep(0.3)
        return out
    monkeypatch.setattr(eom_results, "_build", slow_build)
    started = time.monotonic()
    signal.setitimer(signal.ITIMER_REAL, 0.1)
    r = _eom()
    deadline = time.monotonic() + 2.0
    while not fired and time.monotonic() < deadline:
        time.sleep(0.001)
    assert len(fired) == 1
    assert fired[0] - started >= 0.3  # after the derivation, not during it
    assert r["eom_1"] == "x'' = -k*x/m"
    assert signal.getsignal(signal.SIGALRM) is handler
    assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)


def test_no_timer_stays_no_timer():
    assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)
    before = signal.getsignal(signal.SIGALRM)
    _eom()
    assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)
    assert signal.getsignal(signal.SIGALRM) is before
