"""Tests of analysis.theory.bimaterial_stability against independent derivations and limits.

Oracles: finite differences of the potentials of a body below the interface (Hooke, boundary rows);
the 4x4 interface conditions from the potentials (singular at every root, for any k); the flutter
determinant and wedge of analysis.theory.flutter and Adams' backward wave of analysis.theory.supersonic (rigid
substrate); the frictionless pair of analysis.theory.interface_wave (identical materials, small friction);
the mirror symmetries of the problem.
"""

import math

import numpy as np
import pytest

import bimaterial_oracle
from analysis.theory import bimaterial_stability as bs
from analysis.theory import complex_roots
from analysis.theory import flutter, supersonic
from analysis.theory.interface_wave import ElasticSolid, generalized_rayleigh_speed, rayleigh_speed_ratio

E1, RHO = 1000.0, 1000.0


def _pair(nu, ratio, nu2=None):
    """Layer (E1, nu, RHO) on a substrate E2 = ratio E1 (nu2 = nu by default), equal densities."""
    return ElasticSolid(E1, nu, RHO), ElasticSolid(E1 * ratio, nu if nu2 is None else nu2, RHO)


def _d1(fun, h):
    """6th-order centred first derivative of fun(offset) at offset 0."""
    w = (-1 / 60, 3 / 20, -3 / 4, 0.0, 3 / 4, -3 / 20, 1 / 60)
    return sum(wi * fun((i - 3) * h) for i, wi in enumerate(w) if wi) / h


def _smallest_singular_ratio(matrix):
    values = np.linalg.svd(matrix, compute_uv=False)
    return values[-1] / values[0]


# --- the half-spaces: boundary rows and compliance -----------------------------------------------

@pytest.mark.parametrize("side", (1, -1))
def test_boundary_rows_from_finite_differences_of_the_potentials(side):
    solid = ElasticSolid(2.0e3, 0.3, 900.0)
    mu, lam = solid.shear_modulus, solid.shear_modulus * (1.0 / solid.gamma - 2.0)
    c, k = (0.7 + 0.3j) * solid.c_s, 1.7
    s = c / solid.c_s
    q_l = np.sqrt(1.0 - solid.gamma * s * s)   # principal roots: Re q > 0, decay away from y = 0
    q_s = np.sqrt(1.0 - s * s)
    for amplitudes in ((1.0, 0.0), (0.0, 1.0)):
        a, b = amplitudes

        def potentials(x, y):
            phase = np.exp(1j * k * x)
            return a * phase * np.exp(-side * k * q_l * y), b * phase * np.exp(-side * k * q_s * y)

        h = 1e-2 / k

        def displacement(x, y):
            phi_x = _d1(lambda e: potentials(x + e, y)[0], h)
            phi_y = _d1(lambda e: potentials(x, y + e)[0], h)
            psi_x = _d1(lambda e: potentials(x + e, y)[1], h)
            psi_y = _d1(lambda e: potentials(x, y + e)[1], h)
            return np.array([phi_x + psi_y, phi_y - psi_x])

        u = displacement(0.0, 0.0)
        du_dx = _d1(lambda e: displacement(e, 0.0), h)
        du_dy = _d1(lambda e: displacement(0.0, e), h)
        div = du_dx[0] + du_dy[1]
        sigma_xy, sigma_yy = mu * (du_dy[0] + du_dx[1]), lam * div + 2.0 * mu * du_dy[1]
        expected = np.array([u[0], u[1], sigma_xy, sigma_yy])
        rows = bimaterial_oracle.boundary_matrix(c, solid, side, k) @ np.array(amplitudes)
        np.testing.assert_allclose(rows, expected, rtol=0, atol=1e-7 * np.max(np.abs(expected)))


@pytest.mark.parametrize("side", (1, -1))
def test_surface_compliance_inverts_the_boundary_rows(side):
    solid = ElasticSolid(5.0e3, 0.42, 1200.0)
    k = 0.8
    for c in np.array([0.4 + 0.2j, 1.3 + 0.05j, -2.5 + 1.0j, 4.0 + 0.3j]) * solid.c_s:
        rows = bimaterial_oracle.boundary_matrix(c, solid, side, k)
        tractions = np.array([0.3 - 0.2j, 1.1 + 0.4j])        # (sigma_xy, sigma_yy)
        amplitudes = np.linalg.solve(rows[2:], tractions)
        u = rows[:2] @ amplitudes
        np.testing.assert_allclose(solid.shear_modulus * k * u,
                                   bimaterial_oracle.surface_compliance(c, solid, side) @ tractions, rtol=1e-12)


@pytest.mark.parametrize("nu", (0.0, 0.2, 0.45, 0.49))
def test_rayleigh_function_has_no_zero_in_the_upper_half_plane(nu):
    # Psi = r_1 r_2 Delta has the zeros of Delta there only if r has none (argument principle)
    gamma = ElasticSolid(E1, nu, RHO).gamma
    features = np.array([0.0, 1.0, -1.0, 1.0 / math.sqrt(gamma), -1.0 / math.sqrt(gamma)], dtype=complex)
    count = complex_roots.winding_number(lambda s: bs.reduced_rayleigh_function(s, gamma), -50.0, 50.0, 1e-9, 50.0,
                               features)
    assert count == 0


# --- the dispersion relation and its roots -------------------------------------------------------

CASES = [(0.2, 3.0, 1.0), (0.2, 10.0, 1.5), (0.45, 3.0, 2.0), (0.45, 1 / 3, 1.0), (0.3, 1.5, 0.5),
         (0.25, 0.1, 2.0)]


@pytest.mark.parametrize("nu, ratio, f", CASES)
def test_roots_make_the_interface_conditions_singular(nu, ratio, f):
    upper, lower = _pair(nu, ratio)
    roots = bs.growing_roots(upper, lower, f)
    assert roots.size > 0
    for c in roots:
        assert c.imag > 0.0
        assert _smallest_singular_ratio(bimaterial_oracle.interface_matrix(c, upper, lower, f)) < 1e-12
        assert abs(bs.regular_dispersion_function(c, upper, lower, f)) < 1e-12 * (1.0 + abs(c / upper.c_s)) ** 3
    # the zero count does not depend on the size of the search rectangle
    default = bs._search_box(upper, lower, f, None)[1]
    assert bs.count_growing_roots(upper, lower, f, radius=2.0 * default) == roots.size


@pytest.mark.parametrize("nu, ratio, f", CASES[:3])
def test_growth_rate_is_proportional_to_the_wavenumber(nu, ratio, f):
    # The dimensional 4x4 conditions at wavenumber k: the same c makes them singular for every k,
    # so the growth rate k Im(c) doubles when k doubles (no length scale: ill-posedness).
    upper, lower = _pair(nu, ratio)
    root = bs.growing_roots(upper, lower, f)[0]
    rates = []
    for k in (1.0, 2.0, 4.0, 50.0):
        def det(c, k=k):
            return np.linalg.det(bimaterial_oracle.interface_matrix(c, upper, lower, f, k=k))

        c = root * (1.0 + 1e-3)   # start off the root; Newton on the determinant at this k
        for _ in range(50):
            h = 1e-7 * abs(c)
            step = det(c) / ((det(c + h) - det(c - h)) / (2.0 * h))
            c -= step
            if abs(step) < 1e-14 * abs(c):
                break
        assert c == pytest.approx(root, rel=1e-11)
        rates.append(k * c.imag)
    np.testing.assert_allclose(np.array(rates) / rates[0], [1.0, 2.0, 4.0, 50.0], rtol=1e-10)


@pytest.mark.parametrize("nu, ratio, f", [(0.2, 3.0, 1.0), (0.45, 10.0, 1.5), (0.3, 0.5, 0.8)])
def test_mirror_symmetries(nu, ratio, f):
    upper, lower = _pair(nu, ratio)
    roots = bs.growing_roots(upper, lower, f)
    # body 1 slipping in -x: the mirror image x -> -x, c -> -conj(c)
    np.testing.assert_allclose(np.sort_complex(bs.growing_roots(upper, lower, -f)),
                               np.sort_complex(-np.conj(roots)), rtol=1e-10)
    # bodies swapped (the mirror y -> -y: the upper body now slips in -x relative to the lower)
    np.testing.assert_allclose(np.sort_complex(bs.growing_roots(lower, upper, f)),
                               np.sort_complex(-np.conj(roots)), rtol=1e-10)


# --- identical materials -------------------------------------------------------------------------

@pytest.mark.parametrize("nu", (0.0, 0.2, 0.45))
def test_identical_materials_have_no_coupling_and_no_growing_mode(nu):
    solid = ElasticSolid(E1, nu, RHO)
    s = np.array([0.3 + 0.1j, 0.9 + 0.01j, 1.7 + 0.4j, -2.5 + 3.0j, 8.0 + 0.2j])
    p, q = bs._psi_parts(s, solid, solid)
    assert np.max(np.abs(q)) < 1e-13 * np.max(np.abs(p))
    for f in (0.1, 0.5, 1.0, 1.5, 2.0, 5.0):
        assert bs.growing_roots(solid, solid, f).size == 0
        regime = bs.bimaterial_regime(E1, nu, RHO, E1, nu, RHO, f)
        assert not regime["unstable"] and regime["growth_rate_per_k"] == 0.0 and regime["direction"] is None
        assert regime["c_gR"] == pytest.approx(rayleigh_speed_ratio(nu) * solid.c_s, rel=1e-13)
    speed, rate = bs.small_friction_slope(solid, solid)
    assert abs(rate) < 1e-13 * solid.c_s
    assert bs.instability_threshold(solid, solid, f_max=5.0, n_grid=10) == math.inf


# --- rigid substrate: the flutter analysis -------------------------------------------------------

@pytest.mark.parametrize("nu", (0.2, 0.45))
def test_rigid_substrate_limit_of_the_dispersion_function_is_the_flutter_determinant(nu):
    s = np.array([0.5 + 0.2j, 1.4 + 0.1j, -1.2 + 0.6j, 3.0 + 1.0j, 0.9 + 2.0j])
    f = 1.3
    errors = []
    for ratio in (1e5, 1e6):
        upper, lower = _pair(nu, ratio)
        r_1 = bs.reduced_rayleigh_function(s, upper.gamma)
        scaled = s**2 * r_1 * bs.dispersion_function(s * upper.c_s, upper, lower, f)
        exact = flutter.secular_determinant(s, nu, f)
        errors.append(np.max(np.abs(scaled - exact) / np.abs(exact)))
    assert errors[0] < 1e-3
    assert errors[1] / errors[0] == pytest.approx(0.1, rel=0.05)   # O(mu_1 / mu_2)


@pytest.mark.parametrize("nu, f", [(0.2, 1.5), (0.45, 3.0)])
def test_stiff_substrate_roots_tend_to_the_flutter_root_and_adams_backward_wave(nu, f):
    (flutter_root,) = flutter.growing_roots(nu, f)
    adams = -supersonic.supersonic_trace_speed(nu, f)     # neutral on the rigid flat, runs in -x
    forward_errors, backward_growth = [], []
    for ratio in (1e4, 1e5):
        upper, lower = _pair(nu, ratio)
        roots = bs.growing_roots(upper, lower, f) / upper.c_s
        assert roots.size == 2
        forward = roots[np.argmin(np.abs(roots - flutter_root))]
        backward = roots[np.argmin(np.abs(roots - adams))]
        assert bs.mode_family(forward * upper.c_s, upper, lower) == "forward"
        assert bs.mode_family(backward * upper.c_s, upper, lower) == "backward"
        forward_errors.append(abs(forward - flutter_root))
        assert abs(backward.real - adams) < 1e-3
        backward_growth.append(backward.imag)
    assert forward_errors[0] < 1e-3
    assert forward_errors[1] / forward_errors[0] == pytest.approx(0.1, rel=0.1)
    # Adams' radiating wave becomes a growing one, with a growth that vanishes like mu_1 / mu_2
    assert 0.0 < backward_growth[1] < backward_growth[0]
    assert backward_growth[1] / backward_growth[0] == pytest.approx(0.1, rel=0.2)


def test_stiff_substrate_follows_the_flutter_wedge():
    nu = 0.2
    lower_f, upper_f = flutter.flutter_boundary(nu)
    upper, lower = _pair(nu, 1e4)
    # Near the wedge's edges a neutral root of the rigid case grows weakly on a deformable substrate
    # (Im c of order sqrt(mu_1 / mu_2) c_s1 at a double root): away from them the forward mode is
    # strong (Im c > 0.05 c_s1) inside the wedge and weak (< 0.01 c_s1) or absent outside.
    for f in (0.9, 0.5 * (lower_f + upper_f), upper_f + 0.3):
        roots = bs.growing_roots(upper, lower, f) / upper.c_s
        forward = [r.imag for r in roots if r.real > 0.0]
        inside = flutter.inside_wedge(nu, f)
        assert (max(forward, default=0.0) > 0.05) == inside, f
        assert max(forward, default=0.0) > 0.05 or max(forward, default=0.0) < 0.01, f
        assert all(r.imag < 1e-3 for r in roots if r.real < 0.0)   # only the weak backward mode


# --- dissimilar pairs ----------------------------------------------------------------------------

@pytest.mark.parametrize("nu, ratio, direction", [(0.2, 1.5, 1.0), (0.2, 1 / 1.5, -1.0), (0.45, 1.2, 1.0),
                                                  (0.3, 0.8, -1.0)])
def test_generalized_rayleigh_pair_is_unstable_for_every_friction(nu, ratio, direction):
    # Ranjith & Rice (2001): growth ~ f, near c_gR, in the slip direction of the more compliant body
    # (E2 > E1: the layer, +x; E2 < E1: the substrate, -x).
    upper, lower = _pair(nu, ratio)
    c_gr = generalized_rayleigh_speed(upper, lower)
    assert c_gr is not None
    speed, rate = bs.small_friction_slope(upper, lower)
    assert speed == pytest.approx(direction * c_gr, rel=1e-15) and rate > 0.0
    errors = []
    for f in (1e-2, 5e-3):
        root = bs.growing_roots(upper, lower, f)[0]
        errors.append(abs(root - (speed + 1j * f * rate)))
    assert errors[0] < 1e-3 * upper.c_s
    assert errors[0] / errors[1] == pytest.approx(4.0, rel=0.1)   # second order in f
    tiny = bs.growing_roots(upper, lower, 1e-5)
    assert tiny.size >= 1 and tiny[0].imag > 0.0
    assert bs.instability_threshold(upper, lower) == 0.0
    assert bs.mode_family(tiny[0], upper, lower) == "forward"
    assert bs.compliant_slip_direction(upper, lower) == direction


@pytest.mark.parametrize("nu, ratio", [(0.2, 3.0), (0.2, 1 / 3), (0.45, 3.0)])
def test_pair_without_generalized_rayleigh_wave_needs_friction_above_a_threshold(nu, ratio):
    upper, lower = _pair(nu, ratio)
    assert generalized_rayleigh_speed(upper, lower) is None
    threshold = bs.instability_threshold(upper, lower)
    assert 0.0 < threshold < math.inf
    assert bs.growing_roots(upper, lower, threshold * (1.0 - 1e-3)).size == 0
    above = bs.growing_roots(upper, lower, threshold * (1.0 + 1e-3))
    assert above.size >= 1 and above[0].imag < 1e-2 * upper.c_s    # the root has just left the axis
    # the swapped pair (mirror) has the same threshold
    assert bs.instability_threshold(lower, upper) == pytest.approx(threshold, rel=1e-5)


def test_regime_places_a_point():
    regime = bs.bimaterial_regime(E1, 0.2, RHO, 3 * E1, 0.2, RHO, 1.5)
    roots = bs.growing_roots(*_pair(0.2, 3.0), 1.5)
    assert regime["unstable"] and regime["c_gR"] is None and regime["n_growing"] == roots.size
    assert regime["growth_rate_per_k"] == pytest.approx(roots[0].imag, rel=1e-12)
    assert regime["phase_speed"] == pytest.approx(roots[0].real, rel=1e-12)
    assert regime["direction"] == ("+x" if roots[0].real > 0 else "-x")
    assert regime["modes"][0] == (regime["phase_speed"], regime["growth_rate_per_k"])
    assert regime["growth_rate_per_k_over_cs1"] * ElasticSolid(E1, 0.2, RHO).c_s == pytest.approx(
        regime["growth_rate_per_k"], rel=1e-14)
    assert not bs.bimaterial_regime(E1, 0.2, RHO, 3 * E1, 0.2, RHO, 0.3)["unstable"]
    # families: the layer on a stiffer substrate is the more compliant body, forward = +x
    assert regime["compliant_body"] == "layer" and regime["family"] == "forward"
    assert regime["forward_growth_rate_per_k"] == regime["growth_rate_per_k"]
    assert regime["backward_growth_rate_per_k"] == 0.0 and regime["backward_phase_speed"] is None
    # the mirror pair: the substrate is the more compliant, both families keep their growth rates
    soft = bs.bimaterial_regime(E1, 0.45, RHO, E1 / 3, 0.45, RHO, 1.0)
    stiff = bs.bimaterial_regime(E1 / 3, 0.45, RHO, E1, 0.45, RHO, 1.0)
    assert soft["compliant_body"] == "substrate" and stiff["compliant_body"] == "layer"
    for name in ("forward", "backward"):
        assert soft[f"{name}_growth_rate_per_k"] == pytest.approx(stiff[f"{name}_growth_rate_per_k"], rel=1e-10)
        assert soft[f"{name}_phase_speed"] == pytest.approx(-stiff[f"{name}_phase_speed"], rel=1e-10)
    assert soft["family"] == "backward" and soft["direction"] == "+x"


def test_bad_input_names_the_key_and_range():
    with pytest.raises(ValueError, match=r"^f = .* outside the allowed range"):
        bs.growing_roots(*_pair(0.2, 3.0), math.nan)
    with pytest.raises(ValueError, match=r"^E = .* outside the allowed range"):
        bs.bimaterial_regime(E1, 0.2, RHO, -1.0, 0.2, RHO, 1.0)
    with pytest.raises(ValueError, match=r"^family = .* outside the allowed range"):
        bs.instability_threshold(*_pair(0.2, 3.0), family="sideways")
    with pytest.raises(ValueError, match=r"^side = "):
        bimaterial_oracle.surface_compliance(1.0, ElasticSolid(E1, 0.2, RHO), 0)


def test_forward_onset_on_a_stiff_substrate_tends_to_renardys_threshold():
    # the flutter wedge starts at f = 1 (analysis.theory.flutter); on a substrate mu_2 / mu_1 times stiffer
    # the forward family starts below it by O(mu_1 / mu_2)
    nu = 0.45
    gaps = []
    for ratio in (1e2, 1e3):
        upper, lower = _pair(nu, ratio)
        onset = bs.instability_threshold(upper, lower, f_max=1.2, n_grid=3, family="forward")
        gaps.append(flutter.flutter_boundary(nu)[0] - onset)
    assert 0.0 < gaps[1] < gaps[0] < 2e-2
    assert gaps[1] / gaps[0] == pytest.approx(0.1, rel=0.1)
