"""Tests of analysis.theory.flutter against closed forms and independent oracles.

Oracles: the exact threshold (f = 1, c = sqrt(2) c_s, slope i sqrt(nu / (2 (1 - nu)))), the
frictionless determinant s^2 q_l, the argument principle (counts zeros without the polynomial used
by growing_roots), finite differences of the reconstructed field (Navier, Hooke, interface).
"""

import math

import numpy as np
import pytest

from analysis.theory import flutter, flutter_mode

NUS_UNSTABLE = (0.1, 0.25, 0.4)


# --- helpers -------------------------------------------------------------------------------------

def _q_principal(s, a):
    return np.sqrt(1.0 - (s / a) ** 2 + 0j)


def _count_zeros_argument_principle(nu, f, half_width=12.0, bottom=0.01, n=200_000):
    """Zeros of D/s^2 inside [-W, W] x [bottom, W] (counter-clockwise winding number).

    Uses the principal square roots directly (Im s > 0 on the whole contour), not the module's
    branch code nor its polynomial.
    """
    a_l = 1.0 / math.sqrt(flutter.speed_ratio_squared(nu))
    w = half_width
    corners = [complex(-w, bottom), complex(w, bottom), complex(w, w), complex(-w, w), complex(-w, bottom)]
    path = np.concatenate([np.linspace(p, q, n, endpoint=False) for p, q in zip(corners[:-1], corners[1:])])
    path = np.append(path, corners[0])
    q_l, q_s = _q_principal(path, a_l), _q_principal(path, 1.0)
    d = (path**2 * q_l + 1j * f * (2.0 - path**2 - 2.0 * q_l * q_s)) / path**2
    dphase = np.diff(np.unwrap(np.angle(d)))
    assert np.max(np.abs(dphase)) < 0.3, "contour under-resolved"
    return int(round(np.sum(dphase) / (2.0 * math.pi)))


def _d1(fun, h):
    """6th-order centred first derivative of fun(offset) at offset 0."""
    w = (-1 / 60, 3 / 20, -3 / 4, 0.0, 3 / 4, -3 / 20, 1 / 60)
    return sum(wi * fun((i - 3) * h) for i, wi in enumerate(w) if wi) / h


def _d2(fun, h):
    """6th-order centred second derivative of fun(offset) at offset 0."""
    w = (1 / 90, -3 / 20, 3 / 2, -49 / 18, 3 / 2, -3 / 20, 1 / 90)
    return sum(wi * fun((i - 3) * h) for i, wi in enumerate(w)) / h**2


# --- (1) Renardy's threshold f = 1 ---------------------------------------------------------------

@pytest.mark.parametrize("nu", NUS_UNSTABLE)
def test_no_growing_root_below_threshold_one_above(nu):
    for f in (0.3, 0.9, 1.0 - 1e-4):
        assert flutter.growing_roots(nu, f).size == 0, f
    roots = flutter.growing_roots(nu, 1.0 + 1e-4)
    assert roots.size == 1
    assert roots[0].imag > 0.0


def test_no_instability_at_nu_zero():
    # c_l = sqrt(2) c_s: the crossing point of the threshold is the P branch point.
    for f in (0.5, 1.0 + 1e-4, 1.01, 1.1, 1.5, 2.0, 5.0):
        assert flutter.growing_roots(0.0, f).size == 0, f
    assert all(math.isnan(v) for v in flutter.flutter_boundary(0.0))


# --- (2) root speed at the threshold ------------------------------------------------------------

@pytest.mark.parametrize("nu", NUS_UNSTABLE)
def test_root_tends_to_sqrt2_cs_with_exact_slope(nu):
    # D(sqrt 2) = 0 at f = 1 (real-axis value taken from above); ds/df = i sqrt(nu / (2 (1 - nu))).
    assert abs(flutter.secular_determinant(math.sqrt(2.0), nu, 1.0)) < 1e-14
    slope = math.sqrt(nu / (2.0 * (1.0 - nu)))
    for eps in (1e-3, 1e-4):
        (root,) = flutter.growing_roots(nu, 1.0 + eps)
        assert abs(root.real - math.sqrt(2.0)) < 10.0 * eps**2   # no first-order drift in Re
        assert root.imag / eps == pytest.approx(slope, rel=20.0 * eps)
    # propagates in the sliding direction (+x), between c_s and c_l
    assert 1.0 < root.real < 1.0 / math.sqrt(flutter.speed_ratio_squared(nu))


def test_reversed_sliding_mirrors_the_wave():
    # f -> -f (sliding in -x) maps c -> -conj(c): same growth, opposite propagation.
    for nu, f in ((0.2, 1.5), (0.45, 3.0)):
        plus, minus = flutter.growing_roots(nu, f), flutter.growing_roots(nu, -f)
        np.testing.assert_allclose(minus, -np.conj(plus), rtol=1e-10)


# --- (3) reconstructed field: Navier equations and interface conditions --------------------------

@pytest.mark.parametrize("nu,f", [(0.25, 1.5), (0.4, 3.0), (0.1, 2.0)])
def test_reconstructed_field_solves_navier_and_interface(nu, f):
    (root,) = flutter.growing_roots(nu, f)
    k, mu, c_s = 2.0, 3.0, 1.5
    mode = flutter_mode.reconstruct_field(root, nu, f, wavenumber=k, shear_modulus=mu, shear_speed=c_s,
                                     slip_amplitude=0.7)
    rho, lam = mode.density, mode.lame_lambda
    assert rho == pytest.approx(mu / c_s**2)
    assert lam == pytest.approx(mu * (1.0 / flutter.speed_ratio_squared(nu) - 2.0))
    assert mode.q_l.real > 0.0 and mode.q_s.real > 0.0
    h = 2e-2 / k
    for x, y, t in ((0.3, 0.2, 0.1), (-1.1, 0.9, 0.7), (2.0, 2.5, 1.3)):
        u = lambda dx=0.0, dy=0.0, dt=0.0: mode.displacement(x + dx, y + dy, t + dt)
        sig = lambda dx=0.0, dy=0.0: mode.stress(x + dx, y + dy, t)
        # Hooke: stresses from finite-difference strains
        u_x = _d1(lambda e: u(dx=e), h)
        u_y = _d1(lambda e: u(dy=e), h)
        div = u_x[0] + u_y[1]
        hooke = np.array([lam * div + 2 * mu * u_x[0], lam * div + 2 * mu * u_y[1], mu * (u_y[0] + u_x[1])])
        scale = np.max(np.abs(hooke))
        np.testing.assert_allclose(sig(), hooke, rtol=0, atol=1e-8 * scale)
        # Navier: rho u_tt = div sigma
        acc = rho * _d2(lambda e: u(dt=e), h / c_s)
        sx = _d1(lambda e: sig(dx=e), h)
        sy = _d1(lambda e: sig(dy=e), h)
        div_sig = np.array([sx[0] + sy[2], sx[2] + sy[1]])
        scale = max(np.max(np.abs(acc)), np.max(np.abs(sx)))
        np.testing.assert_allclose(div_sig, acc, rtol=0, atol=1e-8 * scale)
        vel = _d1(lambda e: u(dt=e), h / c_s)
        np.testing.assert_allclose(mode.velocity(x, y, t), vel, rtol=0, atol=1e-8 * np.max(np.abs(vel)))
    # interface conditions (1) at y = 0, complex field and its real part
    xs, ts = np.linspace(-3.0, 3.0, 13), 0.4
    u0, s0 = mode.displacement(xs, 0.0, ts), mode.stress(xs, 0.0, ts)
    scale_u, scale_s = np.max(np.abs(u0)), np.max(np.abs(s0))
    assert np.max(np.abs(u0[1])) < 1e-13 * scale_u
    assert np.max(np.abs(s0[2] + f * s0[1])) < 1e-12 * scale_s
    assert np.max(np.abs(s0[2].real + f * s0[1].real)) < 1e-12 * scale_s
    # normalisation, growth in time, decay into the body
    assert mode.displacement(0.0, 0.0, 0.0)[0] == pytest.approx(0.7)
    ratio = np.abs(mode.displacement(0.3, 0.5, 2.0)) / np.abs(mode.displacement(0.3, 0.5, 0.0))
    np.testing.assert_allclose(ratio, math.exp(2.0 * mode.growth_rate))
    assert mode.growth_rate == pytest.approx(k * c_s * root.imag)
    decay = min(mode.q_l.real, mode.q_s.real)   # slowest decay rate / k
    depth = 15.0 / (k * decay)
    bound = k * (abs(mode.amplitude_p) * (1 + abs(mode.q_l)) + abs(mode.amplitude_s) * (1 + abs(mode.q_s)))
    assert np.max(np.abs(mode.displacement(0.0, depth, 0.0))) <= bound * math.exp(-15.0) * (1 + 1e-12)


def test_reconstruct_field_rejects_non_roots():
    with pytest.raises(ValueError):
        flutter_mode.reconstruct_field(1.3 + 0.2j, 0.25, 1.5)
    with pytest.raises(ValueError):
        flutter_mode.reconstruct_field(0.0, 0.25, 1.5)


# --- (4) frictionless: no surface wave -----------------------------------------------------------

@pytest.mark.parametrize("nu", (0.0, 0.2, 0.45))
def test_frictionless_determinant_is_s2_ql(nu):
    a_l = 1.0 / math.sqrt(flutter.speed_ratio_squared(nu))
    s = np.array([0.3 + 0.1j, 1.2 + 0.5j, -2.0 + 0.01j, 0.5 + 3.0j, 5.0 + 2.0j])
    np.testing.assert_allclose(flutter.secular_determinant(s, nu, 0.0), s**2 * _q_principal(s, a_l), rtol=1e-13)
    assert flutter.growing_roots(nu, 0.0).size == 0
    assert flutter.growing_roots(nu, 1e-3).size == 0


def test_determinant_matches_matrix_and_branches_decay():
    for s in (0.4 + 0.2j, 1.3 + 0.1j, 1.9 + 0.05j, -1.6 + 0.3j, 3.0 + 2.0j, 1.5 - 0.2j):
        m = flutter.secular_matrix(s, 0.3, 1.7)
        assert np.linalg.det(m) == pytest.approx(flutter.secular_determinant(s, 0.3, 1.7), rel=1e-12)
        q_l, q_s = flutter._wavenumbers(s, 0.3)
        assert q_l.real > 0.0 and q_s.real > 0.0
    # real axis: limit from Im s -> 0+
    q_l, q_s = flutter._wavenumbers(np.array([1.5, -1.5, 3.0]), 0.3)
    np.testing.assert_allclose(q_s, [-1j * math.sqrt(1.25), 1j * math.sqrt(1.25), -1j * math.sqrt(8.0)])
    np.testing.assert_allclose(q_s, flutter._wavenumbers(np.array([1.5, -1.5, 3.0]) + 1e-12j, 0.3)[1], atol=1e-10)


# --- argument principle: an oracle independent of the polynomial ---------------------------------

@pytest.mark.parametrize("nu,f", [(0.2, 1.5), (0.2, 10.0), (0.1, 0.5), (0.4, 3.0), (0.45, 10.0), (0.0, 1.3)])
def test_growing_roots_agree_with_argument_principle(nu, f):
    roots = flutter.growing_roots(nu, f)
    assert all(r.imag > 0.01 and abs(r) < 12.0 for r in roots)
    assert _count_zeros_argument_principle(nu, f) == roots.size


# --- (5) the wedge: boundary values --------------------------------------------------------------

def test_boundary_table_monotone_and_limits():
    nus = (0.0, 0.1, 0.2, 0.3, 0.4)
    table = [flutter.flutter_boundary(nu) for nu in nus]
    assert all(math.isnan(v) for v in table[0])
    assert all(lower == 1.0 for lower, _ in table[1:])
    uppers = [upper for _, upper in table[1:]]
    assert all(math.isfinite(u) for u in uppers[:3]) and uppers[3] == math.inf
    assert all(b > a > 1.0 for a, b in zip(uppers[:-1], uppers[1:]))
    # tip of the wedge at (0, 1): f_upper = 1 + 2 sqrt(nu) + O(nu); continuity; divergence at 1/3
    for nu in (1e-10, 1e-8, 1e-6):
        assert (flutter.flutter_boundary(nu)[1] - 1.0) / (2.0 * math.sqrt(nu)) == pytest.approx(1.0, abs=3 * math.sqrt(nu))
    assert flutter.flutter_boundary(0.1 + 1e-6)[1] == pytest.approx(uppers[0], rel=1e-4)
    assert flutter.flutter_boundary(1.0 / 3.0 - 1e-3)[1] > 10.0 * uppers[2]
    assert flutter.flutter_boundary(1.0 / 3.0) == (1.0, math.inf)


@pytest.mark.parametrize("nu", (1e-3, 0.05, 0.1, 0.2, 0.3))
def test_upper_boundary_agrees_with_root_finding(nu):
    f_upper = flutter.flutter_boundary(nu)[1]
    (root,) = flutter.growing_roots(nu, f_upper * (1.0 - 1e-6))
    assert flutter.growing_roots(nu, f_upper * (1.0 + 1e-6)).size == 0
    # the root leaves through a supersonic double root at boundary_speeds(nu)[1]
    s_upper = flutter.boundary_speeds(nu)[1]
    assert s_upper > 1.0 / math.sqrt(flutter.speed_ratio_squared(nu))
    assert root.real == pytest.approx(s_upper, rel=1e-5)
    assert root.imag < 1e-2


@pytest.mark.parametrize("nu", (0.4, 0.45, 0.49))
def test_open_wedge_root_tends_to_standing_growing_mode(nu):
    gamma = flutter.speed_ratio_squared(nu)
    limit = 1j * math.sqrt(4.0 * gamma / (1.0 - 4.0 * gamma))
    (root,) = flutter.growing_roots(nu, 1e4)
    assert abs(root - limit) < 1e-2 * abs(limit)


def test_invalid_poisson_ratio_rejected():
    for nu in (-0.1, 0.5, 0.7):
        with pytest.raises(ValueError):
            flutter.flutter_boundary(nu)


def test_inside_wedge_is_strict_and_follows_the_boundary():
    lower, upper = flutter.flutter_boundary(0.2)
    assert flutter.inside_wedge(0.2, 1.5) and flutter.inside_wedge(0.2, 0.5 * (lower + upper))
    assert not flutter.inside_wedge(0.2, lower) and not flutter.inside_wedge(0.2, upper)
    assert not flutter.inside_wedge(0.2, 0.9) and not flutter.inside_wedge(0.2, upper + 0.1)
    assert flutter.inside_wedge(0.4, 1e6)            # open wedge for nu >= 1/3
    assert not flutter.inside_wedge(0.0, 1.5)        # no instability at nu = 0
