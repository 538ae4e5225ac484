"""The modes command (SPEC v2 "modes"): the matrix grammar, the eigen solver against closed
forms, the scenes against natural-frequency, damping, and the refusals."""
import json
import math

import numpy as np
import pytest
from click.testing import CliRunner

from dyncalc.cli import cli
from dyncalc.commands.modes import modes
from dyncalc.errors import InputError
from dyncalc.physics.modes import solve_modes
from dyncalc.units import STIFFNESS
from dyncalc.units.matrix import parse_matrix


def run(*args):
    return CliRunner().invoke(cli, ["modes", *args])


def data(*args):
    result = run(*args, "--json")
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def chain(n, k=1e4, m=2.0):
    K = (2 * np.eye(n) - np.eye(n, k=1) - np.eye(n, k=-1)) * k
    return np.eye(n) * m, K


@pytest.mark.parametrize("n", [1, 2, 3, 10, 57, 200, 500])
def test_fixed_fixed_chain(n):
    """omega_j = 2 sqrt(k/m) sin(j pi / (2 (n + 1))) for n equal masses between walls."""
    M, K = chain(n)
    out = solve_modes(M, K)
    j = np.arange(1, n + 1)
    expected = 2 * math.sqrt(1e4 / 2.0) * np.sin(j * np.pi / (2 * (n + 1)))
    assert np.allclose(out.omega, expected, rtol=1e-9, atol=0)
    # the mode shapes are sin(i j pi / (n + 1)), scaled to a largest component of 1
    i = np.arange(1, n + 1)
    for col in (0, n - 1):
        shape = np.sin(i * (col + 1) * np.pi / (n + 1))
        reference = int(np.flatnonzero(out.shapes[:, col] == 1.0)[0])  # its +1 component
        assert abs(shape[reference]) == pytest.approx(np.max(np.abs(shape)), rel=1e-9)
        assert np.allclose(out.shapes[:, col], shape / shape[reference], atol=1e-8)


def test_chain_from_a_csv_file(tmp_path):
    M, K = chain(40, k=250.0, m=0.5)
    (tmp_path / "k.csv").write_text("\n".join(",".join(repr(float(v)) for v in row) for row in K))
    (tmp_path / "m.csv").write_text("\n".join(",".join(repr(float(v)) for v in row) for row in M))
    got = data("--M", f"@{tmp_path / 'm.csv'}", "--K", f"@{tmp_path / 'k.csv'}")
    assert got["results"]["omega_40"]["value"] == pytest.approx(
        2 * math.sqrt(500.0) * math.sin(40 * math.pi / 82), rel=1e-12)


def test_two_rotor_shaft_rigid_and_elastic_mode():
    J1, J2, kt = 1.2, 0.8, 4e4
    got = data("--M", f"[[{J1}, 0], [0, {J2}]] kg*m^2", "--K", "40, -40; -40, 40 kN*m/rad")
    r = got["results"]
    assert r["omega_1"]["value"] == 0.0
    assert r["omega_2"]["value"] == pytest.approx(math.sqrt(kt * (J1 + J2) / (J1 * J2)),
                                                  rel=1e-13)
    assert r["mode_1"]["value"] == pytest.approx([1.0, 1.0], rel=1e-14)
    assert r["mode_2"]["value"] == pytest.approx([-J2 / J1, 1.0], rel=1e-13)
    assert r["modal_mass_1"] == {"value": pytest.approx(J1 + J2), "unit": "kg*m^2"}
    assert got["warnings"] == ["omega_1 = 0: a rigid-body mode (an eigenvalue omega^2 within "
                               "1e-10 of the terms of K that sum to it is taken as zero)"]


def test_unit_invariance():
    si = data("--M", "2, 0; 0, 1 kg", "--K", "300, -100; -100, 100 N/m")["results"]
    lb = 0.45359237
    lbf_in = 4.4482216152605 / 0.0254
    other = data("--M", f"{2 / lb!r}, 0; 0, {1 / lb!r} lb",
                 "--K", f"[[{300 / lbf_in!r}, {-100 / lbf_in!r}], "
                        f"[{-100 / lbf_in!r}, {100 / lbf_in!r}]] lbf/in")["results"]
    for name in ("omega_1", "omega_2", "modal_mass_1", "modal_stiffness_2"):
        assert other[name]["value"] == pytest.approx(si[name]["value"], rel=1e-12)
    assert si["omega_1"]["value"] == pytest.approx(math.sqrt(50.0), rel=1e-14)
    assert si["omega_2"]["value"] == pytest.approx(math.sqrt(200.0), rel=1e-14)


def test_value_of_a_mode_reads_back_as_a_matrix_row():
    got = run("--M", "1.0,0.0;0.0,2.0", "--K", "3,-1;-1,1", "--value", "omega_2")
    assert got.exit_code == 0
    again = data("--M", "1.0,0.0;0.0,2.0 kg", "--K", "[[3, -1], [-1, 1]] N/m")
    assert float(got.stdout) == again["results"]["omega_2"]["value"]


def test_normalize_mass():
    r = data("--M", "2, 0; 0, 1 kg", "--K", "300, -100; -100, 100 N/m", "--normalize",
             "mass")["results"]
    v = np.array(r["mode_1"]["value"])
    assert v @ np.diag([2.0, 1.0]) @ v == pytest.approx(1.0, rel=1e-14)
    assert r["modal_stiffness_1"]["value"] == pytest.approx(50.0, rel=1e-13)


# --- scenes -------------------------------------------------------------------------------

def nf(*words):
    result = CliRunner().invoke(cli, ["natural-frequency", *words, "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)["results"]


@pytest.mark.parametrize("scene, words", [
    ("coupled-blocks", ["m1=1kg", "m2=2kg", "k1=100N/m", "k2=200N/m", "k3=50N/m"]),
    ("block-disk-springs", ["M=2kg", "m=1kg", "r=0.1m", "k=100N/m"]),
    ("block-disk-springs", ["M=0.3kg", "m=5kg", "r=2cm", "k=3kN/m"]),
    ("spring-coupled-pendulums", ["m=1kg", "l=1m", "k=100N/m", "b=0.5m"]),
    ("spring-coupled-pendulums", ["m=0.2kg", "l=0.4m", "k=30N/m", "b=0m"]),
])
def test_scene_modes_equal_natural_frequency(scene, words):
    """The hand-linearised matrices (modes) against the closed forms (natural-frequency)."""
    a = data("--scene", scene, *words)["results"]
    b = nf("--scene", scene, *words)
    for name in ("omega_1", "omega_2"):
        assert a[name]["value"] == pytest.approx(b[name]["value"], rel=1e-12)


def test_block_disk_springs_closed_form_and_mode_ratio():
    M, m, r, k = 2.0, 1.0, 0.1, 100.0
    got = data("--scene", "block-disk-springs", f"M={M}kg", f"m={m}kg", f"r={r}m",
               f"k={k}N/m")["results"]
    for i, sign in ((1, -1), (2, 1)):
        lam = k * ((2 * M + 5 * m) + sign * math.sqrt(4 * M * M - 4 * M * m + 17 * m * m)) \
            / (2 * m * (3 * M + m))
        assert got[f"omega_{i}"]["value"] == pytest.approx(math.sqrt(lam), rel=1e-13)
        x, phi = got[f"mode_{i}"]["value"]
        assert r * phi / x == pytest.approx((lam * (M + m) - k) / (lam * m), rel=1e-12)


def test_block_disk_springs_needs_r_for_modes_only():
    assert nf("--scene", "block-disk-springs", "M=2kg", "m=1kg", "k=100N/m")["omega_2"][
        "value"] == pytest.approx(10.0, rel=1e-15)
    result = run("--scene", "block-disk-springs", "M=2kg", "m=1kg", "k=100N/m")
    assert result.exit_code == 2
    assert result.stderr == ("Error: modes --scene block-disk-springs needs r= (the disk's "
                             "radius): it cancels from the frequencies but not from the mode "
                             "shapes\n")


def test_pendulum_on_sliding_block_drift_and_swing():
    m1, m2, l, g = 3.0, 1.0, 0.5, 9.80665
    got = data("--scene", "pendulum-on-sliding-block", f"m1={m1}kg", f"m2={m2}kg", f"l={l}m")
    assert got["results"]["omega_1"]["value"] == 0.0
    assert got["results"]["omega_2"]["value"] == pytest.approx(
        math.sqrt((m1 + m2) * g / (m1 * l)), rel=1e-13)
    assert got["results"]["omega_2"]["value"] == pytest.approx(
        nf("--scene", "pendulum-on-sliding-block", f"m1={m1}kg", f"m2={m2}kg",
           f"l={l}m")["omega"]["value"], rel=1e-13)


def test_spring_coupled_pendulums_equilibrium_from_b_zero():
    got = data("--scene", "spring-coupled-pendulums", "m=1kg", "l=2m", "k=10N/m", "b=0m",
               "g=9.81m/s^2")["results"]
    assert got["phi2_0"]["value"] == 0.0
    assert got["omega_1"]["value"] == pytest.approx(math.sqrt(9.81 / 2), rel=1e-14)
    assert got["omega_2"]["value"] == pytest.approx(math.sqrt(9.81 / 2 + 20), rel=1e-14)


# --- damping ------------------------------------------------------------------------------

def test_rayleigh_damping_is_proportional():
    """C = a M + b K: zeta_i = a / (2 omega_i) + b omega_i / 2 (Rayleigh)."""
    M = np.diag([2.0, 1.0])
    K = np.array([[300.0, -100.0], [-100.0, 100.0]])
    a, b = 0.4, 0.002
    C = a * M + b * K
    out = solve_modes(M, K, C)
    assert out.proportional is True
    expected = a / (2 * out.omega) + b * out.omega / 2
    assert np.allclose(out.zeta, expected, rtol=1e-12)
    assert np.allclose(out.omega_d, out.omega * np.sqrt(1 - expected ** 2), rtol=1e-12)


def test_non_proportional_damping_against_the_characteristic_polynomial():
    """The state-space eigenvalues against the roots of det(M s^2 + C s + K) = 0, expanded
    by hand for two degrees of freedom."""
    M = np.array([[1.0, 0.0], [0.0, 2.0]])
    K = np.array([[2000.0, -1000.0], [-1000.0, 1500.0]])
    C = np.array([[6.0, -1.0], [-1.0, 1.0]])
    out = solve_modes(M, K, C)
    assert out.proportional is False
    p11 = np.array([M[0, 0], C[0, 0], K[0, 0]])
    p22 = np.array([M[1, 1], C[1, 1], K[1, 1]])
    p12 = np.array([M[0, 1], C[0, 1], K[0, 1]])
    roots = np.roots(np.polysub(np.polymul(p11, p22), np.polymul(p12, p12)))
    upper = sorted((z for z in roots if z.imag > 0), key=abs)
    assert np.allclose(out.zeta, [-z.real / abs(z) for z in upper], rtol=1e-10)
    assert np.allclose(out.omega_d, [z.imag for z in upper], rtol=1e-10)
    assert any("not proportional" in note for note in out.notes)


def test_one_dof_damping_against_the_closed_form():
    out = solve_modes(np.array([[2.0]]), np.array([[800.0]]), np.array([[8.0]]))
    assert out.zeta[0] == pytest.approx(8.0 / (2 * math.sqrt(800.0 * 2.0)), rel=1e-14)


def test_non_proportional_damping_against_a_time_integration():
    """The decay of the free response's energy over the slow mode's damped period matches
    exp(-2 zeta omega T_d) when only the slow mode is excited lightly damped: checked with an
    independent integration (scipy's solve_ivp) of M x'' + C x' + K x = 0."""
    from scipy.integrate import solve_ivp

    M = np.eye(2)
    K = np.array([[2.0, -1.0], [-1.0, 2.0]]) * 100.0
    C = np.array([[0.2, 0.0], [0.0, 0.0]])
    out = solve_modes(M, K, C)
    Minv = np.linalg.inv(M)

    def rhs(t, z):
        x, v = z[:2], z[2:]
        return np.concatenate([v, -Minv @ (C @ v + K @ x)])

    t_end = 40.0
    sol = solve_ivp(rhs, (0, t_end), [1.0, 1.0, 0.0, 0.0], rtol=1e-11, atol=1e-13,
                    dense_output=True)
    # the slow mode (x1 = x2) carries the start; fit the envelope's decay of x1 + x2
    t = np.linspace(0, t_end, 40001)
    s = sol.sol(t)[0] + sol.sol(t)[1]
    peaks = [i for i in range(1, len(t) - 1) if s[i] > s[i - 1] and s[i] > s[i + 1]]
    rate = -np.polyfit(t[peaks], np.log(s[peaks]), 1)[0]
    assert rate == pytest.approx(out.zeta[0] * out.omega[0], rel=2e-3)


# --- the matrix grammar and the refusals ---------------------------------------------------

def test_grammar_forms_agree():
    forms = ["2, -1; -1, 2 kN/m", "[[2, -1], [-1, 2]] kN/m", "[[2 kN/m, -1 kN/m], "
             "[-1 kN/m, 2000 N/m]]", "2000,-1000;-1000,2000", "[2, -1; -1, 2] kN/m"]
    values = [parse_matrix(f, label="--K").si(lambda i, j: (STIFFNESS, ""))[0] for f in forms]
    for v in values:
        assert v.tolist() == [[2000.0, -1000.0], [-1000.0, 2000.0]]


@pytest.mark.parametrize("args, message", [
    (["--M", "1, 0; 0, 1 kg", "--K", "2, -1; -1.5, 2 kN/m"],
     "Error: --K is not symmetric: row 1, column 2 is -1000 but row 2, column 1 is -1500 (in "
     "SI; mirrored entries may differ by at most 1e-09 of the largest entry)"),
    (["--M", "1, 0; 0, 1 kg", "--K", "[[2, -1], [-1 kg, 2]] kN/m"],
     "Error: --K row 2, column 1 must be a stiffness [force]/[length]; got -1 kilogram "
     "([mass])"),
    (["--M", "[[3 kg, 0.2 kg*m], [0.2 kg*m, 0.05 kg*m^2]]", "--K",
      "[[2000 N/m, 0], [0, 50 N/m]]"],
     "Error: --K row 2, column 2 must be a torsional stiffness [force]*[length]/[angle]; got "
     "50 newton / meter ([mass] / [time] ** 2) (coordinate 2 is a rotation, from the "
     "diagonal of --M)"),
    (["--M", "[[3 kg, 0.2 kg], [0.2 kg, 0.05 kg*m^2]]", "--K", "1, 0; 0, 1"],
     "Error: --M row 1, column 2 must be a translation-rotation mass coupling [mass]*[length]; "
     "got 0.2 kilogram ([mass]) (coordinate 1 is a translation and coordinate 2 a rotation, "
     "from the diagonal of --M)"),
    (["--M", "[[3 N, 0], [0, 1 kg]]", "--K", "1, 0; 0, 1"],
     "Error: --M row 1, column 1 must be a mass (kg: coordinate 1 a translation) or a moment "
     "of inertia (kg*m^2: a rotation); got 3 newton"),
    (["--M", "1, 0; 0, -1 kg", "--K", "2, -1; -1, 2 kN/m"],
     "Error: --M is not positive definite (its smallest eigenvalue is -1 in SI, its largest "
     "1): every motion of the coordinates must carry kinetic energy"),
    (["--M", "1, 0; 0, 1 kg", "--K", "-2, 1; 1, -2 kN/m"],
     "Error: --K is not positive semi-definite: K v = omega^2 M v has the eigenvalue "
     "omega^2 = -3000 1/s^2 < 0, so the system is unstable about this position (no "
     "oscillation)"),
    (["--M", "1, 0; 0 kg", "--K", "1"],
     "Error: --M: row 2 has 1 entry but row 1 has 2; every row needs the same number"),
    (["--M", "1, 0 kg", "--K", "1"], "Error: --M must be square: it has 1 row of 2 entries"),
    (["--M", " ", "--K", "1"],
     "Error: --M is empty; give a square matrix, e.g. '2, -1; -1, 2 kN/m'"),
    (["--M", "1 kg", "--K", "1, 0; 0, 1"],
     "Error: --K is 2x2 but --M is 1x1: they need the same size (one row per coordinate)"),
    (["--M", "1, 0; 0, 1 kg"],
     "Error: modes needs --M and --K (matrices, e.g. --M '2, 0; 0, 1 kg' --K '300, -100; "
     "-100, 100 N/m') or --scene NAME; --K is missing"),
    (["--M", "1, ; 0, 1 kg", "--K", "1, 0; 0, 1"], "Error: --M row 1, column 2 is empty"),
    (["--scene", "mass-spring", "k=1N/m", "m=1kg"],
     "Error: modes takes a scene with several degrees of freedom; mass-spring has one: use "
     "dyncalc natural-frequency --scene mass-spring"),
    (["--scene", "coupled-blocks", "--M", "1", "m1=1kg"],
     "Error: --M does not go with --scene coupled-blocks: the scene gives its own matrices"),
    (["--M", "1, 0; 0, 1 kg", "--K", "1, 0; 0, 1", "--C", "1, 0; 0, -1"],
     "Error: --C is not positive semi-definite (its smallest eigenvalue is -1 in SI): "
     "negative damping feeds energy in"),
])
def test_refusals(args, message):
    result = run(*args)
    assert result.exit_code == 2
    assert result.stderr.splitlines() == [message]


def test_too_large(tmp_path):
    path = tmp_path / "big.csv"
    path.write_text("\n".join(",".join(["0"] * 501) for _ in range(501)))
    result = run("--M", f"@{path}", "--K", f"@{path}")
    assert result.exit_code == 2
    assert result.stderr == ("Error: --M has 501 rows; dyncalc takes at most 500 degrees of "
                             "freedom\n")


def test_api_function_takes_texts():
    import dyncalc

    r = dyncalc.modes(M="2, 0; 0, 1 kg", K="300, -100; -100, 100 N/m")
    assert r["omega_1"].to("rad/s").magnitude == pytest.approx(math.sqrt(50.0), rel=1e-14)


def test_batch_one_system_per_row(tmp_path):
    path = tmp_path / "rows.csv"
    path.write_text('M,K\n"2, 0; 0, 1 kg","300, -100; -100, 100 N/m"\n'
                    '"1, 0; 0, 1 kg","200, -100; -100, 200 N/m"\n')
    result = run("--batch", str(path), "--json")
    assert result.exit_code == 0, result.output
    lines = [json.loads(line) for line in result.stdout.splitlines()]
    assert [l["results"]["omega_2"]["value"] for l in lines] == pytest.approx(
        [math.sqrt(200.0), math.sqrt(300.0)], rel=1e-14)


def test_library_refuses_strict_bare_entries():
    with pytest.raises(InputError, match=r"--K row 1, column 1: '2' has no unit"):
        modes({"M": "1, 0; 0, 1 kg", "K": "2, 0; 0, 2"}, strict=True)


def test_large_systems_shorten_the_human_table(tmp_path):
    """n = 20: a mode shape shows its ends and its size, a matrix file its name; --json and
    --value keep every component (the chain's first mode is sin(j pi / 21), largest 1)."""
    n = 20
    M, K = chain(n)
    paths = []
    for name, matrix in (("M", M), ("K", K)):
        path = tmp_path / f"{name}.csv"
        path.write_text("\n".join(",".join(repr(float(v)) for v in row) for row in matrix))
        paths.append(str(path))
    out = run("--M", f"@{paths[0]}", "--K", f"@{paths[1]}")
    assert out.exit_code == 0
    shape = np.sin(np.arange(1, n + 1) * np.pi / (n + 1))
    shape /= shape.max()
    row = next(line for line in out.stdout.splitlines() if line.startswith("mode_1 "))
    ends = [f"{v:.6g}" for v in (*shape[:3], *shape[-3:])]
    assert row.split(None, 3)[3].rstrip() == (
        f"({', '.join(ends[:3])}, ..., {', '.join(ends[3:])}) [20 components; --json for all]")
    assert out.stdout.splitlines()[-1] == f"inputs: M = @{paths[0]}, K = @{paths[1]}"
    value = run("--M", f"@{paths[0]}", "--K", f"@{paths[1]}", "--value", "mode_1")
    assert [float(v) for v in value.stdout.split(",")] == pytest.approx(shape.tolist(),
                                                                       rel=1e-10)
