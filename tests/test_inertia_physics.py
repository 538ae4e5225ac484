"""The physics of ``inertia`` (dyncalc/physics/inertia.py, inertia_tensor.py).

Every body against its closed form (Table 3.1 of Gross et al.) and against an independent
Monte Carlo integration over its volume, surface or line (fixed seed; the tolerance is five
standard errors of the sample mean, estimated from the sample itself); the tensor invariants
under random rotations; the parallel-axis theorem against a translated composite; composites
against sums; the book's bent bar (E3.41) and a disk with a hole against hand derivations.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from dyncalc.errors import InputError
from dyncalc.physics.inertia import (BODY_DIMENSIONS, mass_from_density, principal_local,
                                     reference_offset)
from dyncalc.physics.inertia_tensor import (body_frame, composite, moment_about, placed,
                                            principal, steiner)

N = 400_000
DIMS = {"rod": {"l": 1.3}, "disk": {"r": 0.7}, "ring": {"r": 0.7},
        "solid-sphere": {"r": 0.6}, "hollow-sphere": {"r": 0.6},
        "solid-cylinder": {"r": 0.4, "h": 1.1}, "hollow-cylinder": {"ri": 0.3, "ro": 0.5, "h": 0.9},
        "plate": {"a": 0.8, "b": 0.3}, "half-cylinder-shell": {"r": 0.5, "h": 0.7},
        "point": {}}


def _sample(kind: str, d: dict, rng) -> np.ndarray:
    """N points spread uniformly over the body in its own axes (rejection sampling from a box,
    or normalised Gaussian vectors for a circle or sphere): no formula of the code used."""
    def box(*half):
        return rng.uniform(-1.0, 1.0, size=(4 * N, len(half))) * np.array(half)

    z = np.zeros(N)
    if kind == "point":
        return np.zeros((N, 3))
    if kind == "rod":
        return np.column_stack([z, z, rng.uniform(-d["l"] / 2, d["l"] / 2, N)])
    if kind == "plate":
        return np.column_stack([rng.uniform(-d["a"] / 2, d["a"] / 2, N),
                                rng.uniform(-d["b"] / 2, d["b"] / 2, N), z])
    if kind in ("ring", "half-cylinder-shell"):
        g = rng.normal(size=(N, 2))
        g = d["r"] * g / np.linalg.norm(g, axis=1)[:, None]
        if kind == "ring":
            return np.column_stack([g, z])
        g[:, 0] = np.abs(g[:, 0])
        return np.column_stack([g, rng.uniform(-d["h"] / 2, d["h"] / 2, N)])
    if kind == "hollow-sphere":
        g = rng.normal(size=(N, 3))
        return d["r"] * g / np.linalg.norm(g, axis=1)[:, None]
    if kind == "solid-sphere":
        p = box(d["r"], d["r"], d["r"])
        return p[np.linalg.norm(p, axis=1) <= d["r"]][:N]
    if kind == "disk":
        p = box(d["r"], d["r"])
        p = p[np.linalg.norm(p, axis=1) <= d["r"]][:N]
        return np.column_stack([p, np.zeros(len(p))])
    ro = d["r"] if kind == "solid-cylinder" else d["ro"]
    ri = 0.0 if kind == "solid-cylinder" else d["ri"]
    p = box(ro, ro, d["h"] / 2)
    radius = np.linalg.norm(p[:, :2], axis=1)
    return p[(radius <= ro) & (radius >= ri)][:N]


def _monte_carlo(points: np.ndarray, m: float):
    """Centre of mass, the tensor about it (J_xy = -int x y dm) and the standard error of
    each entry."""
    centre = points.mean(axis=0)
    p = points - centre
    r2 = np.einsum("ij,ij->i", p, p)
    samples = m * (r2[:, None, None] * np.eye(3) - p[:, :, None] * p[:, None, :])
    return centre, samples.mean(axis=0), samples.std(axis=0) / math.sqrt(len(points))


@pytest.mark.parametrize("kind", list(BODY_DIMENSIONS))
def test_every_body_against_monte_carlo(kind):
    m, d = 2.5, DIMS[kind]
    rng = np.random.default_rng(20261124)
    points = _sample(kind, d, rng)
    assert len(points) == N
    centre, J_mc, error = _monte_carlo(points, m)
    body = placed(kind, m, d)
    assert np.all(np.abs(body.c - centre) <= 5 * points.std(axis=0) / math.sqrt(N) + 1e-15)
    assert np.all(np.abs(body.J_C - J_mc) <= 5 * error + 1e-15), (body.J_C, J_mc)
    assert np.array_equal(np.diag(np.diag(body.J_C)), body.J_C)  # own axes are principal


CLOSED = {  # J_xx, J_yy, J_zz / m, textbook table with the dimensions of DIMS
    "rod": (1.3 ** 2 / 12, 1.3 ** 2 / 12, 0.0),
    "disk": (0.7 ** 2 / 4, 0.7 ** 2 / 4, 0.7 ** 2 / 2),
    "ring": (0.7 ** 2 / 2, 0.7 ** 2 / 2, 0.7 ** 2),
    "solid-sphere": (0.4 * 0.36, 0.4 * 0.36, 0.4 * 0.36),
    "hollow-sphere": (0.36 * 2 / 3, 0.36 * 2 / 3, 0.36 * 2 / 3),
    "solid-cylinder": ((3 * 0.16 + 1.21) / 12, (3 * 0.16 + 1.21) / 12, 0.08),
    "hollow-cylinder": ((3 * 0.34 + 0.81) / 12, (3 * 0.34 + 0.81) / 12, 0.17),
    "plate": (0.09 / 12, 0.64 / 12, 0.73 / 12),
    "half-cylinder-shell": (0.125 + 0.49 / 12, 0.125 + 0.49 / 12 - 1 / math.pi ** 2,
                            0.25 - 1 / math.pi ** 2),
    "point": (0.0, 0.0, 0.0),
}


@pytest.mark.parametrize("kind", list(BODY_DIMENSIONS))
def test_every_body_against_its_closed_form(kind):
    m = 2.5
    got = principal_local(kind, m, DIMS[kind])
    assert got == pytest.approx([m * c for c in CLOSED[kind]], rel=1e-14, abs=1e-16)


def test_half_cylinder_shell_centre_is_two_r_over_pi_off_its_axis():
    assert reference_offset("half-cylinder-shell", {"r": 0.5, "h": 1.0}) == (1 / math.pi, 0, 0)
    body = placed("half-cylinder-shell", 1.0, {"r": 0.5, "h": 1.0}, at=(1.0, 2.0, 3.0),
                  along=(1.0, 0.0, 0.0))  # own x -> world y (the cycle y, z, x)
    assert body.c.tolist() == pytest.approx([1.0, 2.0 + 1 / math.pi, 3.0], rel=1e-15)
    # about its own axis through the reference point: all the mass at r (m r^2)
    assert moment_about(body.J_C, 1.0, body.c, (1.0, 0, 0), (1.0, 2.0, 3.0)) == \
        pytest.approx(0.25, rel=1e-14)


@pytest.mark.parametrize("kind,density,factor", [
    ("rod", 3.0, 1.3), ("ring", 3.0, 2 * math.pi * 0.7), ("disk", 3.0, math.pi * 0.49),
    ("plate", 3.0, 0.24), ("hollow-sphere", 3.0, 4 * math.pi * 0.36),
    ("half-cylinder-shell", 3.0, math.pi * 0.5 * 0.7), ("solid-sphere", 3.0, 4 * math.pi * 0.216 / 3),
    ("solid-cylinder", 3.0, math.pi * 0.16 * 1.1), ("hollow-cylinder", 3.0, math.pi * 0.16 * 0.9)])
def test_mass_from_density(kind, density, factor):
    assert mass_from_density(kind, density, DIMS[kind]) == pytest.approx(density * factor,
                                                                         rel=1e-14)


def _rotation(rng) -> np.ndarray:
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    return q if np.linalg.det(q) > 0 else -q


@pytest.mark.parametrize("seed", range(8))
def test_invariants_under_random_rotations(seed):
    """Turning every body's axis and position by one rotation Q turns J_O into Q J_O Q^T:
    the same trace and eigenvalues; axially symmetric bodies only (a plate's in-plane sides
    follow body_frame's rule, not Q)."""
    rng = np.random.default_rng(seed)
    kinds = ["rod", "disk", "ring", "solid-cylinder", "hollow-cylinder", "solid-sphere", "point"]
    bodies = []
    for kind in rng.choice(kinds, size=4):
        bodies.append((kind, float(rng.uniform(0.5, 3)), DIMS[kind], rng.normal(size=3),
                       rng.normal(size=3)))
    Q = _rotation(rng)
    plain = composite([placed(k, m, d, at=a, along=u) for k, m, d, a, u in bodies])
    turned = composite([placed(k, m, d, at=Q @ a, along=Q @ u) for k, m, d, a, u in bodies])
    assert turned.J_O == pytest.approx(Q @ plain.J_O @ Q.T, rel=1e-12, abs=1e-12)
    assert np.trace(turned.J_C) == pytest.approx(np.trace(plain.J_C), rel=1e-13)
    assert np.linalg.eigvalsh(turned.J_C) == pytest.approx(np.linalg.eigvalsh(plain.J_C),
                                                           rel=1e-12)
    assert turned.r_c == pytest.approx(Q @ plain.r_c, rel=1e-12, abs=1e-13)


@pytest.mark.parametrize("kind", ["plate", "half-cylinder-shell", "solid-cylinder", "rod"])
def test_any_along_keeps_the_principal_moments_and_the_axis(kind):
    rng = np.random.default_rng(7)
    u = rng.normal(size=3)
    body = placed(kind, 2.0, DIMS[kind], along=u)
    local = sorted(principal_local(kind, 2.0, DIMS[kind]))
    assert np.linalg.eigvalsh(body.J_C) == pytest.approx(local, rel=1e-12, abs=1e-14)
    n = u / np.linalg.norm(u)
    J_zz = principal_local(kind, 2.0, DIMS[kind])[2]
    assert body.J_C @ n == pytest.approx(J_zz * n, rel=1e-12, abs=1e-13)  # along= is principal


def test_body_frame_is_a_rotation_with_z_along_and_the_stated_x():
    assert body_frame([0, 0, 1]).tolist() == np.eye(3).tolist()
    assert body_frame([0, 1, 0]).tolist() == [[0, 1, 0], [0, 0, 1], [1, 0, 0]]
    R = body_frame([1.0, 2.0, -2.0])
    assert R.T @ R == pytest.approx(np.eye(3), abs=1e-15) and np.linalg.det(R) == \
        pytest.approx(1.0)
    assert R[:, 2] == pytest.approx([1 / 3, 2 / 3, -2 / 3])
    # largest component y -> x is the projection of z onto the plane
    z = np.array([0, 0, 1.0]) - (-2 / 3) * R[:, 2]
    assert R[:, 0] == pytest.approx(z / np.linalg.norm(z))


def test_parallel_axis_theorem_against_the_translated_composite():
    rng = np.random.default_rng(3)
    parts = [("rod", 2.0, DIMS["rod"], rng.normal(size=3), rng.normal(size=3)),
             ("plate", 1.0, DIMS["plate"], rng.normal(size=3), rng.normal(size=3)),
             ("solid-sphere", 3.0, DIMS["solid-sphere"], rng.normal(size=3), (0, 0, 1))]
    whole = composite([placed(k, m, d, at=a, along=u) for k, m, d, a, u in parts])
    p, n = rng.normal(size=3), rng.normal(size=3)
    moved = composite([placed(k, m, d, at=np.asarray(a) - p, along=u)
                       for k, m, d, a, u in parts])
    unit = n / np.linalg.norm(n)
    assert moment_about(whole.J_C, whole.m, whole.r_c, n, p) == pytest.approx(
        unit @ moved.J_O @ unit, rel=1e-12)
    # and J_O = J_C + m (|r_c|^2 I - r_c r_c^T)
    assert whole.J_O == pytest.approx(whole.J_C + steiner(whole.m, whole.r_c), rel=1e-13)


def test_composite_is_the_sum_of_its_bodies():
    a = placed("disk", 4.0, {"r": 0.3}, at=(0.1, 0.2, 0.0), along=(1, 1, 0))
    b = placed("rod", 1.0, {"l": 2.0}, at=(-1.0, 0.0, 0.5))
    c = placed("point", 0.5, {}, at=(0.0, 0.0, -2.0))
    total = composite([a, b, c])
    assert total.m == 5.5
    assert total.J_O == pytest.approx(a.J_O + b.J_O + c.J_O, rel=1e-15)
    assert total.r_c == pytest.approx((4.0 * a.c + 1.0 * b.c + 0.5 * c.c) / 5.5, rel=1e-15)


def test_bent_bar_of_example_3_41():
    """Gross et al. E3.41: leg 2l (mass 2m/3) along xi from O, then leg l (mass m/3) parallel
    to the shaft zeta: J_zeta = 20 m l^2/9, J_xi_zeta = -m l^2/3, xi_C = 4l/3, zeta_C = l/6."""
    m, l = 3.0, 0.4
    bar = composite([placed("rod", 2 * m / 3, {"l": 2 * l}, at=(l, 0, 0), along=(1, 0, 0)),
                     placed("rod", m / 3, {"l": l}, at=(2 * l, 0, l / 2))])
    assert bar.J_O[2, 2] == pytest.approx(20 * m * l * l / 9, rel=1e-14)
    assert bar.J_O[0, 2] == bar.J_O[2, 0] == pytest.approx(-m * l * l / 3, rel=1e-14)
    assert bar.r_c == pytest.approx([4 * l / 3, 0, l / 6], rel=1e-14)


def test_disk_with_an_off_centre_hole():
    """Same areal density rho: M = rho pi R^2, m = rho pi r^2; about the big disk's centre
    J_z = M R^2/2 - (m r^2/2 + m d^2), the centre of mass at -m d/(M - m)."""
    rho, R, r, d = 7.8, 0.2, 0.05, 0.1
    M, m = rho * math.pi * R * R, rho * math.pi * r * r
    plate = composite([placed("disk", mass_from_density("disk", rho, {"r": R}), {"r": R}),
                       placed("disk", mass_from_density("disk", rho, {"r": r}), {"r": r},
                              at=(d, 0, 0), sign=-1)])
    assert plate.m == pytest.approx(M - m, rel=1e-14)
    assert plate.J_O[2, 2] == pytest.approx(M * R * R / 2 - (m * r * r / 2 + m * d * d),
                                            rel=1e-14)
    assert plate.r_c[0] == pytest.approx(-m * d / (M - m), rel=1e-13)


def test_principal_axes_convention():
    moments, axes = principal(np.diag([3.0, 1.0, 2.0]))
    assert moments.tolist() == [1.0, 2.0, 3.0]
    assert axes.tolist() == [[0, 1, 0], [0, 0, 1], [1, 0, 0]]
    # a disk turned about z: the degenerate pair comes back as x, y
    disk = placed("disk", 1.0, {"r": 1.0}, along=(0, 0, -1))
    moments, axes = principal(disk.J_C)
    assert axes == pytest.approx(np.eye(3), abs=1e-15)
    # a general tensor: eigenvectors, unit, largest component positive
    J = np.array([[2.0, -0.5, 0.1], [-0.5, 1.0, -0.3], [0.1, -0.3, 1.5]])
    moments, axes = principal(J)
    for value, axis in zip(moments, axes):
        assert J @ axis == pytest.approx(value * axis, abs=1e-14)
        assert np.linalg.norm(axis) == pytest.approx(1.0)
        assert axis[np.argmax(np.abs(axis))] > 0


def test_refusals():
    disk = placed("disk", 1.0, {"r": 1.0})
    with pytest.raises(InputError) as e:
        composite([disk, placed("disk", 2.0, {"r": 1.0}, sign=-1)])
    assert str(e.value) == ("the negative bodies weigh as much as the others or more: the total "
                            "mass is -1 kg; a hole cannot be larger than what it cuts")
    with pytest.raises(InputError) as e:
        composite([disk, placed("ring", 0.9, {"r": 1.0}, sign=-1)])
    assert str(e.value) == ("the negative bodies cut more than there is: the inertia tensor "
                            "about the centre of mass is not positive semi-definite (smallest "
                            "principal moment -0.4 kg*m^2)")
    with pytest.raises(InputError) as e:  # a hole that keeps the tensor semi-definite
        composite([placed("solid-sphere", 1.0, {"r": 1.0}),
                   placed("rod", 0.5, {"l": 3.0}, sign=-1)])
    assert str(e.value).startswith("the negative bodies cut more than there is: the principal "
                                   "moments ")
    assert str(e.value).endswith(" kg*m^2 break J_1 + J_2 >= J_3, which every body keeps")
    with pytest.raises(InputError, match="^--axis: the axis direction has zero length$"):
        moment_about(disk.J_C, 1.0, disk.c, (0, 0, 0))
    with pytest.raises(InputError, match="^along= has zero length$"):
        body_frame((0.0, 0.0, 0.0))
