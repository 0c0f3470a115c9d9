"""Tests of analysis.theory.supersonic: the steady supersonic slip wave (Adams 2000).

The oracle is built here from scratch: two plane waves u = d F(n . x - v t) in the paper's frame
(sliding in +x), Lame constants from (E, nu), stresses from Hooke's law. Nothing below uses the
reduced ratio R(s) of the module; the speeds it returns must make this field satisfy the interface
conditions, and the 2x2 determinant of those conditions must vanish there.
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from analysis.theory import flutter, supersonic

E, RHO = 1000.0, 1000.0
NU_BACKWARD = [0.05, 0.2, 0.3, 1.0 / 3.0, 0.4, 0.45, 0.49]
F_VALUES = [0.1, 0.5, 0.8, 1.0, 1.5, 3.0]


def _elastic(nu):
    """(lambda, mu, c_s, c_l) from E, nu, rho (plane strain)."""
    mu = E / (2.0 * (1.0 + nu))
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    return lam, mu, math.sqrt(mu / RHO), math.sqrt((lam + 2.0 * mu) / RHO)


def _waves(nu, celerity, outgoing=True):
    """Wave vectors n and polarisations d of the P and S plane waves with trace velocity `celerity`.

    n = (1, p): fronts move along sign(celerity) n, so p_y has the sign of the celerity for waves
    leaving the interface (outgoing) and the opposite one for waves coming in.
    P: d = n (u = grad phi); S: d = (p, -1) (u = curl psi e_z), orthogonal to n.
    """
    _, _, c_s, c_l = _elastic(nu)
    alpha = math.sqrt(celerity**2 / c_l**2 - 1.0)
    beta = math.sqrt(celerity**2 / c_s**2 - 1.0)
    sign = math.copysign(1.0, celerity) * (1.0 if outgoing else -1.0)
    n_p, n_s = np.array([1.0, sign * alpha]), np.array([1.0, sign * beta])
    return (n_p, n_p.copy()), (n_s, np.array([sign * beta, -1.0]))


def _stress(nu, grad_u):
    lam, mu, _, _ = _elastic(nu)
    strain = 0.5 * (grad_u + grad_u.T)
    return lam * np.trace(strain) * np.eye(2) + 2.0 * mu * strain


def _interface_rows(nu, celerity, f, outgoing=True):
    """2x2 matrix on (A, B): [u_y / F', (sigma_xy + f sigma_yy) / F''] at y = 0 (sliding in +x)."""
    rows = np.zeros((2, 2))
    for j, (n, d) in enumerate(_waves(nu, celerity, outgoing)):
        sigma = _stress(nu, np.outer(d, n))  # grad u = d (x) n F''
        rows[0, j] = d[1]
        rows[1, j] = sigma[0, 1] + f * sigma[1, 1]
    return rows


def _field_at_interface(nu, celerity, f, outgoing=True):
    """(u_y, v, sigma) at y = 0 per unit F' and F'', amplitudes chosen so that u_y = 0 and the slip
    rate v_x is positive (the pulse slips in +x, the sliding direction)."""
    (n_p, d_p), (n_s, d_s) = _waves(nu, celerity, outgoing)
    amp_p = 1.0
    amp_s = -amp_p * d_p[1] / d_s[1]  # u_y = A d_p,y + B d_s,y = 0
    u_y = amp_p * d_p[1] + amp_s * d_s[1]
    velocity = -celerity * (amp_p * d_p + amp_s * d_s)  # d/dt F'(x - v t) = -v F''
    if velocity[0] < 0.0:
        amp_p, amp_s, velocity = -amp_p, -amp_s, -velocity
    grad_u = amp_p * np.outer(d_p, n_p) + amp_s * np.outer(d_s, n_s)
    return u_y, velocity, _stress(nu, grad_u)


# --- the root makes the plane-wave field satisfy every equation ---------------------------------

@pytest.mark.parametrize("nu", [0.2, 0.45, 0.49])
def test_each_plane_wave_solves_navier_at_the_root(nu):
    lam, mu, c_s, _ = _elastic(nu)
    c = supersonic.supersonic_trace_speed(nu, 1.0, c_s)
    for n, d in _waves(nu, -c):
        # (lambda + mu) (d . n) n + mu |n|^2 d = rho v^2 d  for u = d F(n . x - v t)
        lhs = (lam + mu) * np.dot(d, n) * n + mu * np.dot(n, n) * d
        np.testing.assert_allclose(lhs, RHO * c * c * d, rtol=1e-13)


@pytest.mark.parametrize("nu", NU_BACKWARD)
@pytest.mark.parametrize("f", F_VALUES)
def test_backward_root_keeps_contact_and_slides_on_the_friction_cone(nu, f):
    _, mu, c_s, c_l = _elastic(nu)
    c = supersonic.supersonic_trace_speed(nu, f, c_s)
    assert c > c_l
    u_y, velocity, sigma = _field_at_interface(nu, -c, f)  # celerity -c: against the sliding
    assert abs(u_y) <= 1e-15
    assert velocity[0] > 0.0 and abs(velocity[1]) <= 1e-14 * abs(velocity[0])
    scale = mu * (1.0 + c * c / c_s**2)
    assert abs(sigma[0, 1] + f * sigma[1, 1]) <= 1e-12 * scale  # sigma_xy = -f sigma_yy: slip +x


@pytest.mark.parametrize("nu", NU_BACKWARD)
def test_backward_pulse_releases_pressure_and_radiates_into_the_body(nu):
    _, _, c_s, _ = _elastic(nu)
    c = supersonic.supersonic_trace_speed(nu, 0.8, c_s)
    _, velocity, sigma = _field_at_interface(nu, -c, 0.8)
    assert sigma[1, 1] > 0.0  # tension increment: the contact pressure drops where it slips
    assert -(sigma[0, 1] * velocity[0] + sigma[1, 1] * velocity[1]) > 0.0  # flux -sigma.v into y > 0
    for n, d in _waves(nu, -c):  # and each wave alone carries energy away from the interface
        sigma_w, v_w = _stress(nu, np.outer(d, n)), c * d
        assert -(sigma_w[1] @ v_w) > 0.0


@pytest.mark.parametrize("nu", [0.2, 0.45, 0.49])
def test_incoming_partner_needs_the_opposite_slip(nu):
    """Reversing both vertical slownesses flips the sign of sigma_xy / sigma_yy: at the backward
    speed, the field coming in from the body satisfies the friction law of sliding in -x."""
    _, mu, c_s, _ = _elastic(nu)
    f = 0.8
    c = supersonic.supersonic_trace_speed(nu, f, c_s)
    u_y, _, sigma = _field_at_interface(nu, -c, f, outgoing=False)
    assert abs(u_y) <= 1e-15
    scale = mu * (1.0 + c * c / c_s**2)
    assert abs(sigma[0, 1] - f * sigma[1, 1]) <= 1e-12 * scale
    assert abs(sigma[0, 1] + f * sigma[1, 1]) > 1e-3 * scale


# --- independent root finding -------------------------------------------------------------------

@pytest.mark.parametrize("nu", NU_BACKWARD)
@pytest.mark.parametrize("f", [0.5, 1.0, 1.5])
def test_root_of_the_unreduced_determinant(nu, f):
    _, _, c_s, c_l = _elastic(nu)
    expected = supersonic.supersonic_trace_speed(nu, f, c_s)

    def det(c):
        return np.linalg.det(_interface_rows(nu, -c, f))

    hi = supersonic.backward_speed_limit(nu, c_s)
    hi = min(hi, 200.0 * c_l) * (1.0 - 1e-9)
    # det changes sign once between c_l and the limit: bracket on a grid, refine with Brent
    grid = c_l * (1.0 + 1e-9) + (hi - c_l * (1.0 + 1e-9)) * np.linspace(0.0, 1.0, 801) ** 3
    values = np.array([det(c) for c in grid])
    changes = np.flatnonzero(np.sign(values[:-1]) != np.sign(values[1:]))
    assert changes.size == 1
    i = int(changes[0])
    root = brentq(det, grid[i], grid[i + 1], xtol=1e-15, rtol=1e-15)
    assert root == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("nu", NU_BACKWARD)
def test_agrees_with_the_flutter_determinant_on_its_real_supersonic_axis(nu):
    """analysis.theory.flutter's D(s; nu, f) (f < 0: sliding in -x, wave in +x) vanishes at the root."""
    for f in (0.5, 1.0, 2.0):
        s = supersonic.supersonic_trace_speed(nu, f)
        scale = 1.0 + f * (1.0 + s * s) + s**3
        assert abs(flutter.secular_determinant(s, nu, -f)) <= 1e-12 * scale
        assert abs(flutter.secular_determinant(s * (1.0 + 1e-6), nu, -f)) > 1e-9 * scale


# --- limits, monotonicity, existence ------------------------------------------------------------

@pytest.mark.parametrize("nu", [0.1, 0.45, 0.49])
def test_small_friction_limit_is_grazing_p_wave_at_first_order(nu):
    """c -> c_l with alpha = sqrt(c^2/c_l^2 - 1) = f nu / (1 - nu) + O(f^2): the error of alpha / f
    halves with f (order 1)."""
    a = supersonic.speed_ratio(nu)
    fs = [1e-2, 5e-3, 2.5e-3]
    errors = [math.sqrt((supersonic.supersonic_trace_speed(nu, f) / a) ** 2 - 1.0) / f - nu / (1.0 - nu)
              for f in fs]
    rates = [math.log2(errors[i] / errors[i + 1]) for i in range(2)]
    assert all(abs(r - 1.0) < 0.05 for r in rates)


@pytest.mark.parametrize("nu", [0.4, 0.45, 0.49])
def test_large_friction_speed_grows_like_f_times_cl_minus_2cs(nu):
    """c / (f (c_l - 2 c_s)) - 1 = O(1 / f^2) for nu > 1/3."""
    _, _, c_s, c_l = _elastic(nu)
    fs = [100.0, 200.0, 400.0]
    errors = [supersonic.supersonic_trace_speed(nu, f, c_s) / (f * (c_l - 2.0 * c_s)) - 1.0 for f in fs]
    rates = [math.log2(errors[i] / errors[i + 1]) for i in range(2)]
    assert all(abs(r - 2.0) < 0.05 for r in rates)


def test_large_friction_at_one_third_grows_like_cube_root():
    fs = [200.0, 400.0, 800.0]
    errors = [supersonic.supersonic_trace_speed(1.0 / 3.0, f) / f ** (1.0 / 3.0) - 1.0 for f in fs]
    rates = [math.log2(errors[i] / errors[i + 1]) for i in range(2)]
    assert all(abs(r - 2.0 / 3.0) < 0.02 for r in rates)


@pytest.mark.parametrize("nu", [0.1, 0.2])
def test_large_friction_below_one_third_tends_to_zero_normal_stress_speed(nu):
    """c -> s_* c_s, s_*^2 = 4 gamma / (4 gamma - 1), where the pair with u_y = 0 has sigma_yy = 0."""
    _, _, c_s, c_l = _elastic(nu)
    gamma = c_s**2 / c_l**2
    s_star = math.sqrt(4.0 * gamma / (4.0 * gamma - 1.0))
    assert supersonic.backward_speed_limit(nu) == pytest.approx(s_star, rel=1e-14)
    _, _, sigma = _field_at_interface(nu, -s_star * c_s * (1.0 + 1e-12), 1.0)
    assert abs(sigma[1, 1]) < 1e-8 * abs(sigma[0, 1])
    fs = [200.0, 400.0, 800.0]
    gaps = [s_star - supersonic.supersonic_trace_speed(nu, f) for f in fs]
    rates = [math.log2(gaps[i] / gaps[i + 1]) for i in range(2)]
    assert all(g > 0.0 for g in gaps) and all(abs(r - 1.0) < 0.05 for r in rates)


@pytest.mark.parametrize("nu", NU_BACKWARD)
def test_speed_rises_strictly_with_friction_between_its_bounds(nu):
    _, _, c_s, c_l = _elastic(nu)
    fs = np.geomspace(1e-3, 1e3, 121)
    speeds = np.array([supersonic.supersonic_trace_speed(nu, f, c_s) for f in fs])
    assert np.all(np.diff(speeds) > 0.0)
    assert speeds[0] > c_l
    assert speeds[-1] < supersonic.backward_speed_limit(nu, c_s)


def test_no_backward_wave_at_nu_zero():
    assert supersonic.supersonic_trace_speed(0.0, 1.0) is None
    assert supersonic.backward_speed_limit(0.0) == pytest.approx(supersonic.speed_ratio(0.0), rel=1e-15)


def test_nu_zero_forward_root_is_exact_and_needs_f_above_one():
    """At nu = 0, -R = alpha + beta: one forward root for f > 1, none for f <= 1."""
    assert supersonic.forward_trace_speeds(0.0, 1.0) == ()
    _, mu, c_s, c_l = _elastic(0.0)
    for f in (1.2, 2.0, 5.0):
        (c,) = supersonic.forward_trace_speeds(0.0, f, c_s)
        u_y, velocity, sigma = _field_at_interface(0.0, c, f)
        assert c > c_l and abs(u_y) <= 1e-15 and velocity[0] > 0.0
        assert abs(sigma[0, 1] + f * sigma[1, 1]) <= 1e-12 * mu * (1.0 + c * c / c_s**2)


@pytest.mark.parametrize("nu", [0.1, 0.2, 0.3])
def test_forward_roots_exist_above_the_flutter_edge_only(nu):
    f_upper = flutter.flutter_boundary(nu)[1]
    assert supersonic.forward_trace_speeds(nu, 0.99 * f_upper) == ()
    _, mu, c_s, _ = _elastic(nu)
    f = 1.5 * f_upper
    roots = supersonic.forward_trace_speeds(nu, f, c_s)
    assert len(roots) == 2 and roots[0] < roots[1]
    for c in roots:
        u_y, velocity, sigma = _field_at_interface(nu, c, f)  # celerity +c: with the sliding
        assert abs(u_y) <= 1e-15 and velocity[0] > 0.0
        assert abs(sigma[0, 1] + f * sigma[1, 1]) <= 1e-11 * mu * (1.0 + c * c / c_s**2)
        assert abs(flutter.secular_determinant(c / c_s, nu, f)) <= 1e-10 * (1.0 + f) * (c / c_s) ** 3
    merged = supersonic.forward_trace_speeds(nu, f_upper * (1.0 + 1e-10))
    s_upper = flutter.boundary_speeds(nu)[1]
    assert merged[0] == pytest.approx(s_upper, rel=1e-4) and merged[1] == pytest.approx(s_upper, rel=1e-4)


@pytest.mark.parametrize("nu", [1.0 / 3.0, 0.45, 0.49])
def test_no_forward_wave_from_one_third_on(nu):
    assert supersonic.forward_trace_speeds(nu, 50.0) == ()


def test_traction_ratio_is_nan_below_cl_and_zero_at_cl():
    a = supersonic.speed_ratio(0.45)
    assert math.isnan(supersonic.traction_ratio(0.99 * a, 0.45))
    assert supersonic.traction_ratio(a, 0.45) == 0.0


@pytest.mark.parametrize(
    "call, key",
    [
        (lambda: supersonic.supersonic_trace_speed(0.5, 1.0), "nu"),
        (lambda: supersonic.supersonic_trace_speed(-0.1, 1.0), "nu"),
        (lambda: supersonic.supersonic_trace_speed(0.45, 0.0), "f"),
        (lambda: supersonic.supersonic_trace_speed(0.45, math.nan), "f"),
        (lambda: supersonic.supersonic_trace_speed(0.45, 1.0, c_s=-1.0), "c_s"),
        (lambda: supersonic.forward_trace_speeds(0.2, -1.0), "f"),
    ],
)
def test_bad_input_names_the_key_and_range(call, key):
    with pytest.raises(ValueError, match=rf"^{key} = .* outside the allowed range"):
        call()
