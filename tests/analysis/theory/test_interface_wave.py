"""Tests of analysis.theory.interface_wave (generalized Rayleigh wave) against closed forms and limits.

Oracles: the Rayleigh speed of a Poisson solid (c_R^2 = (2 - 2/sqrt(3)) c_s^2) and Viktorov's
approximation; the unreduced secular function (2) and the 4x4 determinant of the interface conditions
built from the potentials (tests/analysis/theory/bimaterial_oracle.py: interface_matrix at f = 0); the frictionless
rigid base derived here from its 2x2 system; the mirror symmetry of the pair.
"""

import math

import numpy as np
import pytest

import bimaterial_oracle
from analysis.theory import flutter
from analysis.theory.interface_wave import (ElasticSolid, existence_interval, generalized_rayleigh_speed,
                                     rayleigh_function, rayleigh_speed_ratio, reduced_secular_function,
                                     secular_function)

NUS = (0.0, 0.1, 0.2, 0.25, 0.3, 0.4, 0.45, 0.49)


def _pair(nu1, nu2, kappa, density_ratio=1.0, E1=1000.0, rho1=1000.0):
    """Layer (E1, nu1, rho1) and a substrate with c_s2 = kappa c_s1, rho_2 = density_ratio rho_1."""
    upper = ElasticSolid(E1, nu1, rho1)
    mu_2 = density_ratio * kappa**2 * upper.shear_modulus
    return upper, ElasticSolid(2.0 * (1.0 + nu2) * mu_2, nu2, density_ratio * rho1)


# --- the Rayleigh speed --------------------------------------------------------------------------

def test_rayleigh_speed_of_a_poisson_solid_is_exact():
    # nu = 1/4: gamma = 1/3, the cubic factors as (x - 4)(3 x^2 - 12 x + 8): x = 2 - 2 / sqrt(3)
    assert rayleigh_speed_ratio(0.25) == pytest.approx(math.sqrt(2.0 - 2.0 / math.sqrt(3.0)), rel=1e-15)


@pytest.mark.parametrize("nu", NUS)
def test_rayleigh_speed_is_a_zero_of_the_rayleigh_function_and_near_viktorov(nu):
    s_r = rayleigh_speed_ratio(nu)
    assert abs(rayleigh_function(s_r, nu)) < 1e-14
    # Viktorov (1967): c_R / c_s ~ (0.862 + 1.14 nu) / (1 + nu): 1.4 % low at nu = 0, within 0.5 %
    # from nu = 0.2 on
    assert s_r == pytest.approx((0.862 + 1.14 * nu) / (1.0 + nu), rel=1.5e-2 if nu < 0.2 else 5e-3)


# --- identical materials -------------------------------------------------------------------------

@pytest.mark.parametrize("nu", NUS)
def test_identical_solids_carry_the_rayleigh_wave(nu):
    solid = ElasticSolid(2.5e3, nu, 800.0)
    c = generalized_rayleigh_speed(solid, solid)
    assert c == pytest.approx(rayleigh_speed_ratio(nu) * solid.c_s, rel=1e-13)


# --- the root: equation, bounds, symmetry --------------------------------------------------------

def _random_pairs(n, seed=24):
    """Pairs inside the existence domain: random nu's, density ratio, kappa inside its interval."""
    rng = np.random.default_rng(seed)
    pairs = []
    while len(pairs) < n:
        nu1, nu2 = rng.uniform(0.0, 0.49, 2)
        density_ratio = math.exp(rng.uniform(-1.0, 1.0))
        low, high = existence_interval(nu1, nu2, density_ratio)
        kappa = math.exp(rng.uniform(math.log(low), math.log(high)))
        pairs.append(_pair(nu1, nu2, kappa, density_ratio))
    return pairs


@pytest.mark.parametrize("upper, lower", _random_pairs(12))
def test_root_solves_the_secular_equation_below_both_shear_speeds(upper, lower):
    c = generalized_rayleigh_speed(upper, lower)
    assert c is not None
    assert 0.0 < c < min(upper.c_s, lower.c_s)
    # between the two Rayleigh speeds (each term of g changes sign at its own Rayleigh speed)
    c_r = sorted((rayleigh_speed_ratio(upper.nu) * upper.c_s, rayleigh_speed_ratio(lower.nu) * lower.c_s))
    assert c_r[0] * (1 - 1e-13) <= c <= c_r[1] * (1 + 1e-13)
    # the unreduced form (2): |F| relative to the size of its two terms
    s1, s2 = c / upper.c_s, c / lower.c_s
    scale = (abs(rayleigh_function(s1, upper.nu))
             + lower.rho * lower.c_s**4 / (upper.rho * upper.c_s**4) * abs(rayleigh_function(s2, lower.nu)))
    assert abs(secular_function(c, upper, lower)) < 1e-12 * scale
    # the 4x4 interface conditions (1) from the potentials of both bodies: singular at c
    matrix = bimaterial_oracle.interface_matrix(c, upper, lower, 0.0)
    singular = np.linalg.svd(matrix, compute_uv=False)
    assert singular[-1] < 1e-12 * singular[0]
    # swapping the bodies (the mirror image y -> -y) gives the same wave
    assert generalized_rayleigh_speed(lower, upper) == pytest.approx(c, rel=1e-13)


@pytest.mark.parametrize("upper, lower", _random_pairs(6, seed=7))
def test_root_is_the_only_sign_change_below_the_slower_shear_speed(upper, lower):
    c_min = min(upper.c_s, lower.c_s)
    g = np.real(reduced_secular_function(np.linspace(0.0, c_min, 20001), upper, lower))
    assert g[0] < 0.0 < g[-1]
    assert np.count_nonzero(np.diff(np.sign(g))) == 1
    # g(0) in closed form: -2 (1 - gamma_1) - 2 (1 - gamma_2) mu_2 / mu_1
    expected = -2.0 * (1.0 - upper.gamma) - 2.0 * (1.0 - lower.gamma) * lower.shear_modulus / upper.shear_modulus
    assert g[0] == pytest.approx(expected, rel=1e-14)


# --- existence domain ----------------------------------------------------------------------------

@pytest.mark.parametrize("nu", (0.0, 0.2, 0.25, 0.45))
def test_existence_interval_of_equal_poisson_and_density_is_symmetric(nu):
    low, high = existence_interval(nu, nu)
    # the mirror pair (kappa -> 1/kappa, bodies swapped) has the same wave
    assert low * high == pytest.approx(1.0, rel=1e-12)
    assert 1.0 < high < 2.0


@pytest.mark.parametrize("nu1, nu2, density_ratio", [(0.2, 0.2, 1.0), (0.45, 0.45, 1.0), (0.1, 0.4, 2.0),
                                                      (0.3, 0.05, 0.5)])
def test_existence_interval_edges(nu1, nu2, density_ratio):
    low, high = existence_interval(nu1, nu2, density_ratio)
    for kappa in np.geomspace(low / 3.0, high * 3.0, 41):
        exists = generalized_rayleigh_speed(*_pair(nu1, nu2, kappa, density_ratio)) is not None
        assert exists == (low < kappa < high), kappa
    # at the edges the root reaches the slower shear speed
    for edge, inside in ((high, high * (1 - 1e-6)), (low, low * (1 + 1e-6))):
        upper, lower = _pair(nu1, nu2, edge, density_ratio)
        c_min = min(upper.c_s, lower.c_s)
        assert abs(reduced_secular_function(c_min, upper, lower)) < 1e-11
        upper, lower = _pair(nu1, nu2, inside, density_ratio)
        assert generalized_rayleigh_speed(upper, lower) / min(upper.c_s, lower.c_s) > 1.0 - 1e-3


def test_no_wave_at_large_shear_speed_contrast():
    # E_2 / E_1 = 10 at equal nu and rho: c_s2 / c_s1 = sqrt(10) > kappa_high (about 1.40 at nu = 0.2)
    upper, lower = ElasticSolid(1000.0, 0.2, 1000.0), ElasticSolid(1e4, 0.2, 1000.0)
    assert generalized_rayleigh_speed(upper, lower) is None
    assert generalized_rayleigh_speed(lower, upper) is None
    g = np.real(reduced_secular_function(np.linspace(0.0, upper.c_s, 20001), upper, lower))
    assert np.all(g < 0.0)


# --- rigid substrate -----------------------------------------------------------------------------

def _rigid_base_determinant(s, nu):
    """Half-space y > 0 on a frictionless rigid base, derived here: u_y = -k (q_l A + i B) = 0 and
    sigma_xy = mu k^2 (-2 i q_l A + (2 - s^2) B) = 0, det [[q_l, i], [-2 i q_l, 2 - s^2]] = -s^2 q_l."""
    gamma = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))
    q_l = np.sqrt(1.0 - gamma * s * s + 0j)
    matrix = np.array([[q_l, 1j], [-2j * q_l, 2.0 - s * s]])
    return np.linalg.det(matrix)


@pytest.mark.parametrize("nu1, nu2", [(0.2, 0.2), (0.45, 0.3), (0.0, 0.49)])
def test_rigid_substrate_limit_is_the_frictionless_rigid_base(nu1, nu2):
    s = np.array([0.2, 0.5, 0.8, 0.95, 1.3])  # c / c_s1, real (the rigid base has no root there)
    errors = []
    for ratio in (1e6, 1e7):
        upper = ElasticSolid(1000.0, nu1, 1000.0)
        lower = ElasticSolid(1000.0 * ratio, nu2, 1000.0)
        scaled = (secular_function(s * upper.c_s, upper, lower) * upper.shear_modulus / lower.shear_modulus
                  / (2.0 * (1.0 - lower.gamma)))
        rigid = np.array([_rigid_base_determinant(v, nu1) for v in s])
        np.testing.assert_allclose(rigid, -flutter.secular_determinant(s, nu1, 0.0), rtol=1e-14)
        errors.append(np.max(np.abs(scaled - rigid)))
        assert generalized_rayleigh_speed(upper, lower) is None
    # the difference is O(mu_1 / mu_2): ten times stiffer, ten times closer (first order)
    assert errors[0] < 1e-5
    assert errors[1] / errors[0] == pytest.approx(0.1, rel=0.05)


def test_bad_solid_names_the_key_and_range():
    for args, key in (((0.0, 0.2, 1.0), "E"), ((1.0, 0.5, 1.0), "nu"), ((1.0, -0.1, 1.0), "nu"),
                      ((1.0, 0.2, math.nan), "rho"), ((math.inf, 0.2, 1.0), "E")):
        with pytest.raises(ValueError, match=rf"^{key} = .* outside the allowed range"):
            ElasticSolid(*args)
    with pytest.raises(ValueError, match="^density_ratio"):
        existence_interval(0.2, 0.2, -1.0)
