"""One reading of NAME=QUANTITY words for every command with scene words (issue 19):
modes and eom use commands/words.py gather_texts as natural-frequency, damping-ratio and
forced-response do, so a word given twice or a word that is not NAME=VALUE gets the same
message everywhere."""
import pytest

from helpers import error_line, invoke

TWICE = [
    ("natural-frequency", "--scene", "mass-spring", "m=1kg", "k=1N/m", "k=2N/m"),
    ("damping-ratio", "--scene", "rod-in-fluid", "m=1kg", "l=1m", "beta=1N*s/m^2", "l=2m"),
    ("forced-response", "--scene", "quarter-car", "m=400kg", "k=40kN/m", "L=10m", "k=1N/m"),
    ("modes", "--scene", "coupled-blocks", "m1=1kg", "m2=1kg", "k1=1N/m", "k2=1N/m",
     "k3=1N/m", "k3=2N/m"),
    ("eom", "--scene", "coupled-blocks", "m1=1kg", "k3=1N/m", "k3=2N/m"),
    ("eom", "--coords", "x", "--T", "m*x'^2/2", "--V", "k3*x^2/2", "k3=1N/m", "k3=2N/m"),
]


@pytest.mark.parametrize("args", TWICE, ids=lambda a: " ".join(a[:2]))
def test_a_word_given_twice(args):
    name = args[-1].partition("=")[0]
    assert error_line(invoke(*args)) == f"Error: {name} is given twice ({name}= and {name}=)"


@pytest.mark.parametrize("args, what", [
    (("natural-frequency", "--scene", "mass-spring", "m=1kg", "stiff"), "a scene parameter"),
    (("modes", "--scene", "coupled-blocks", "stiff"), "a scene parameter"),
    (("eom", "--scene", "pendulum", "stiff"), "a parameter"),
])
def test_a_word_without_equals(args, what):
    assert error_line(invoke(*args)) == (f"Error: {what} takes NAME=VALUE (for example "
                                         "m=2kg); got 'stiff'")
