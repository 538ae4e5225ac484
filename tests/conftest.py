"""Test settings shared by the suite: hypothesis draws the same examples on every run (no
example database), so a green run on one machine is green on another and a failure is
reproduced by running the test again."""
from hypothesis import settings

settings.register_profile("dyncalc", derandomize=True, database=None)
settings.load_profile("dyncalc")
