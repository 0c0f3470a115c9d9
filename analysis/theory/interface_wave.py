r"""Generalized Rayleigh wave: interface wave of two elastic half-spaces in frictionless contact.

Problem (Achenbach & Epstein 1967; derivation in docs/bimaterial-elastic.md, section 2)
------------------------------------------------------------------------------------
Plane strain. Body 1 (the layer) fills ``y > 0``, body 2 (the substrate) ``y < 0``; each is
isotropic, linear elastic: shear modulus ``mu_j``, density ``rho_j``, wave speeds ``c_sj < c_lj``,
``gamma_j = c_sj^2 / c_lj^2 = (1 - 2 nu_j) / (2 (1 - nu_j))``. The interface ``y = 0`` is in
frictionless, non-opening contact:

    u_y(1) = u_y(2),   sigma_yy(1) = sigma_yy(2),   sigma_xy(1) = sigma_xy(2) = 0.          (1)

With ``u = grad phi + curl(psi e_z)`` and ``phi, psi ~ exp(i k (x - c t) -+ k q y)`` (``-`` in body 1,
``+`` in body 2, ``k > 0``), ``q_l = sqrt(1 - c^2/c_l^2)``, ``q_s = sqrt(1 - c^2/c_s^2)``, each
half-space with ``sigma_xy = 0`` on its face has the normal surface stiffness

    sigma_yy / u_y = +- mu k R(s) / (q_l s^2),   R(s) = (2 - s^2)^2 - 4 q_l q_s,   s = c / c_s,

(``+`` body 1, ``-`` body 2; ``R`` is the Rayleigh function). Conditions (1) then give the secular
equation

    F(c) = rho_1 c_s1^4 q_l2 R_1 + rho_2 c_s2^4 q_l1 R_2 = 0,                               (2)

or, divided by ``mu_1 q_l1 q_l2 s_1^2`` (no trivial double zero at ``c = 0``),

    g(c) = r_1(s_1) / q_l1 + (mu_2 / mu_1) r_2(s_2) / q_l2 = 0,    r(s) = R(s) / s^2.          (3)

A trapped wave needs real ``0 < c < min(c_s1, c_s2)`` (all four ``q`` real and positive).

Existence (analysis behind ``generalized_rayleigh_speed``)
---------------------------------------------------------
``r(s) = (s^6 - 8 s^4 + (24 - 16 gamma) s^2 - 16 (1 - gamma)) / ((2 - s^2)^2 + 4 q_l q_s)``, so
``g(0) = -2 (1 - gamma_1) - 2 (1 - gamma_2) mu_2 / mu_1 < 0``; each term of ``g`` is negative below
its own Rayleigh speed and positive above it. A root therefore exists iff ``g(c_min) > 0`` at
``c_min = min(c_s1, c_s2)``, and lies between the two Rayleigh speeds. For identical solids ``g = 2 r
/ q_l`` and ``c = c_R``. For a very stiff substrate (``mu_2 -> inf`` at fixed ``rho_2``) the second
term tends to ``-2 (1 - gamma_2) mu_2 / mu_1``: no root. There ``F / (mu_2 c_s1^2)`` tends to
``-2 (1 - gamma_2) s_1^2 q_l1``, the determinant of a half-space on a frictionless rigid base
(``u_y = 0``, ``sigma_xy = 0``; ``analysis.theory.flutter.secular_determinant`` at ``f = 0``), which has no
zero below ``c_l``: the limit has no interface wave, and the generalized Rayleigh wave disappears at a
finite contrast. With ``kappa = c_s2 / c_s1`` the wave exists for ``kappa_low < kappa < kappa_high``
(``existence_interval``); ``kappa = 1`` is always inside.

Speeds are in m/s; ``ElasticSolid`` carries ``E`` (Pa), ``nu`` and ``rho`` (kg/m^3).

References
----------
J.D. Achenbach, H.I. Epstein (1967), Dynamic interaction of a layer and a half-space, J. Eng. Mech.
Div. ASCE 93 (EM5), 27-42 (the "smooth contact" interface wave).
K. Ranjith, J.R. Rice (2001), Slip dynamics at an interface between dissimilar materials, J. Mech.
Phys. Solids 49, 341-361 (the generalized Rayleigh wave in the stability of Coulomb sliding).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from analysis.theory import elastic
from analysis.theory.flutter import _vertical_wavenumber

__all__ = [
    "ElasticSolid",
    "rayleigh_function",
    "reduced_rayleigh_function",
    "rayleigh_speed_ratio",
    "secular_function",
    "reduced_secular_function",
    "generalized_rayleigh_speed",
    "existence_interval",
]

#: Below this |s| the reduced functions use their rationalised forms (no cancellation near s = 0).
_SMALL_S = 0.5
#: Sign changes of g are bracketed on this many points of (0, c_min].
_N_SCAN = 400


@dataclass(frozen=True)
class ElasticSolid:
    """An isotropic linear elastic solid in plane strain.

    Attributes
    ----------
    E : float     Young's modulus (Pa), finite and > 0
    nu : float    Poisson's ratio, [0, 0.5)
    rho : float   density (kg/m^3), finite and > 0
    """

    E: float
    nu: float
    rho: float

    def __post_init__(self) -> None:
        for name, value in (("E", self.E), ("rho", self.rho)):
            if not (math.isfinite(value) and value > 0.0):
                raise ValueError(f"{name} = {value!r} outside the allowed range (0, inf)")
        if not (math.isfinite(self.nu) and 0.0 <= self.nu < 0.5):
            raise ValueError(f"nu = {self.nu!r} outside the allowed range [0, 0.5)")

    @property
    def shear_modulus(self) -> float:
        """mu = E / (2 (1 + nu)) (Pa)."""
        return elastic.shear_modulus(self.E, self.nu)

    @property
    def c_s(self) -> float:
        """Shear wave speed (m/s)."""
        return elastic.shear_wave_speed(self.E, self.nu, self.rho)

    @property
    def c_l(self) -> float:
        """Plane-strain longitudinal wave speed (m/s)."""
        return elastic.longitudinal_wave_speed(self.E, self.nu, self.rho)

    @property
    def gamma(self) -> float:
        """c_s^2 / c_l^2 = (1 - 2 nu) / (2 (1 - nu))."""
        return (1.0 - 2.0 * self.nu) / (2.0 * (1.0 - self.nu))


def _as_solid(solid) -> ElasticSolid:
    if isinstance(solid, ElasticSolid):
        return solid
    return ElasticSolid(*solid)


def _q(s, gamma: float):
    """(q_l, q_s) at s = c / c_s on the physical sheet (Re q >= 0; real axis: limit from above)."""
    return _vertical_wavenumber(s, 1.0 / math.sqrt(gamma)), _vertical_wavenumber(s, 1.0)


def rayleigh_function(s, nu: float):
    """R(s) = (2 - s^2)^2 - 4 q_l q_s, s = c / c_s (dimensionless; complex s allowed)."""
    gamma = ElasticSolid(1.0, nu, 1.0).gamma
    s = np.asarray(s, dtype=complex)
    q_l, q_s = _q(s, gamma)
    return (2.0 - s * s) ** 2 - 4.0 * q_l * q_s


def reduced_rayleigh_function(s, gamma: float, q=None):
    """r(s) = R(s) / s^2, regular at s = 0 (r(0) = -2 (1 - gamma)).

    For |s| < 0.5 the rationalised form (s^6 - 8 s^4 + (24 - 16 gamma) s^2 - 16 (1 - gamma)) /
    ((2 - s^2)^2 + 4 q_l q_s) is used (its denominator is near 8 there), else R / s^2.
    q: (q_l, q_s) = _q(s, gamma) if the caller has them already (the root finders evaluate r and n at
    the same s: computing q once per s is most of their time saved, with the same numbers).
    """
    s = np.asarray(s, dtype=complex)
    q_l, q_s = _q(s, gamma) if q is None else q
    z = s * s
    small = np.abs(s) < _SMALL_S
    with np.errstate(divide="ignore", invalid="ignore"):
        direct = ((2.0 - z) ** 2 - 4.0 * q_l * q_s) / z
        rational = (((z - 8.0) * z + 24.0 - 16.0 * gamma) * z - 16.0 * (1.0 - gamma)) / (
            (2.0 - z) ** 2 + 4.0 * q_l * q_s)
    return np.where(small, rational, direct)


def rayleigh_speed_ratio(nu: float) -> float:
    """c_R / c_s of a half-space with a free surface: the root in (0, 1) of the Rayleigh cubic
    x^3 - 8 x^2 + (24 - 16 gamma) x - 16 (1 - gamma) = 0, x = (c/c_s)^2 (dimensionless)."""
    gamma = ElasticSolid(1.0, nu, 1.0).gamma
    roots = np.roots([1.0, -8.0, 24.0 - 16.0 * gamma, -16.0 * (1.0 - gamma)])
    inside = [x.real for x in roots if abs(x.imag) < 1e-12 and 0.0 < x.real < 1.0]
    if len(inside) != 1:  # the cubic has exactly one root in (0, 1) for 0 <= nu < 1/2
        raise RuntimeError(f"Rayleigh cubic: {len(inside)} roots in (0, 1) at nu = {nu}")
    x = brentq(lambda v: ((v - 8.0) * v + 24.0 - 16.0 * gamma) * v - 16.0 * (1.0 - gamma),
               0.5 * inside[0], min(1.0, 1.5 * inside[0]), xtol=1e-16, rtol=1e-15)
    return math.sqrt(x)


def secular_function(c, upper, lower):
    """F(c) / (rho_1 c_s1^4) of eq. (2): q_l2 R_1 + (rho_2 c_s2^4 / (rho_1 c_s1^4)) q_l1 R_2.

    Parameters
    ----------
    c : complex or array
        Phase speed (m/s); real values are taken as limits from Im c -> 0+.
    upper, lower : ElasticSolid or (E, nu, rho)
        Body 1 (y > 0) and body 2 (y < 0).

    Returns
    -------
    Dimensionless F; it has a trivial double zero at c = 0 (``reduced_secular_function`` has not).
    """
    upper, lower = _as_solid(upper), _as_solid(lower)
    c = np.asarray(c, dtype=complex)
    s1, s2 = c / upper.c_s, c / lower.c_s
    q_l1, q_s1 = _q(s1, upper.gamma)
    q_l2, q_s2 = _q(s2, lower.gamma)
    r_1 = (2.0 - s1 * s1) ** 2 - 4.0 * q_l1 * q_s1
    r_2 = (2.0 - s2 * s2) ** 2 - 4.0 * q_l2 * q_s2
    weight = lower.rho * lower.c_s**4 / (upper.rho * upper.c_s**4)
    result = q_l2 * r_1 + weight * q_l1 * r_2
    return result if result.ndim else complex(result)


def reduced_secular_function(c, upper, lower):
    """g(c) of eq. (3): r_1(s_1) / q_l1 + (mu_2 / mu_1) r_2(s_2) / q_l2 (dimensionless).

    Regular at c = 0, g(0) = -2 (1 - gamma_1) - 2 (1 - gamma_2) mu_2 / mu_1. Real for real
    0 <= c < min(c_l1, c_l2). ``c`` in m/s.
    """
    upper, lower = _as_solid(upper), _as_solid(lower)
    c = np.asarray(c, dtype=complex)
    s1, s2 = c / upper.c_s, c / lower.c_s
    q_l1 = _q(s1, upper.gamma)[0]
    q_l2 = _q(s2, lower.gamma)[0]
    ratio = lower.shear_modulus / upper.shear_modulus
    result = (reduced_rayleigh_function(s1, upper.gamma) / q_l1
              + ratio * reduced_rayleigh_function(s2, lower.gamma) / q_l2)
    return result if result.ndim else complex(result)


def generalized_rayleigh_speed(upper, lower) -> float | None:
    """Speed (m/s) of the generalized Rayleigh wave of two solids in frictionless contact, or None.

    The root of g (eq. 3) in (0, min(c_s1, c_s2)), bracketed by a scan and refined by Brent's method
    to round-off. None when g(c_min) <= 0 (no trapped interface wave). The wave runs either way (+-c).

    Parameters
    ----------
    upper, lower : ElasticSolid or (E, nu, rho)
        Body 1 (y > 0) and body 2 (y < 0); the result is symmetric in them.
    """
    upper, lower = _as_solid(upper), _as_solid(lower)
    c_min = min(upper.c_s, lower.c_s)

    def g(c: float) -> float:
        return float(np.real(reduced_secular_function(c, upper, lower)))

    if not g(c_min) > 0.0:
        return None
    grid = np.linspace(0.0, c_min, _N_SCAN + 1)
    values = np.real(reduced_secular_function(grid, upper, lower))
    changes = np.flatnonzero((values[:-1] < 0.0) & (values[1:] >= 0.0))
    # g(0) < 0 < g(c_min): at least one upward crossing; the first is the wave (g rises through it).
    i = int(changes[0])
    if values[i + 1] == 0.0:
        return float(grid[i + 1])
    return float(brentq(g, grid[i], grid[i + 1], xtol=1e-15 * c_min, rtol=1e-15))


def existence_interval(nu_upper: float, nu_lower: float, density_ratio: float = 1.0) -> tuple[float, float]:
    """(kappa_low, kappa_high): the generalized Rayleigh wave exists iff kappa_low < c_s2/c_s1 < kappa_high.

    The edges are where the root reaches the slower shear speed, g(c_min) = 0:

        kappa > 1:  1 / q_l1(1) + rho_r kappa^2 r_2(1/kappa) / q_l2(1/kappa) = 0,
        kappa < 1:  r_1(kappa) / q_l1(kappa) + rho_r kappa^2 / q_l2(1) = 0,

    with rho_r = rho_2 / rho_1 = density_ratio (mu_2 / mu_1 = rho_r kappa^2).
    """
    if not (math.isfinite(density_ratio) and density_ratio > 0.0):
        raise ValueError(f"density_ratio = {density_ratio!r} outside the allowed range (0, inf)")
    upper, lower = ElasticSolid(1.0, nu_upper, 1.0), ElasticSolid(1.0, nu_lower, 1.0)

    def ratio(s: float, solid: ElasticSolid) -> float:
        """r(s) / q_l(s) for real 0 < s <= 1 (q_s(1) = 0 exactly: no rounding of s = 1)."""
        return float(np.real(reduced_rayleigh_function(s, solid.gamma) / _q(s, solid.gamma)[0]))

    def margin(kappa: float) -> float:
        if kappa >= 1.0:  # body 1 is the slower: g(c_s1), s_1 = 1, s_2 = 1 / kappa
            return ratio(1.0, upper) + density_ratio * kappa**2 * ratio(1.0 / kappa, lower)
        return ratio(kappa, upper) + density_ratio * kappa**2 * ratio(1.0, lower)

    high = 2.0
    while margin(high) > 0.0:
        high *= 2.0
    low = 0.5
    while margin(low) > 0.0:
        low *= 0.5
    kappa_high = brentq(margin, 1.0, high, xtol=1e-15, rtol=1e-15)
    kappa_low = brentq(margin, low, 1.0, xtol=1e-15, rtol=1e-15)
    return float(kappa_low), float(kappa_high)
