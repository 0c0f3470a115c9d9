r"""Linear stability of steady Coulomb sliding between two elastic half-spaces (no regularization).

Problem and conventions (derivation in docs/bimaterial-theory.md, sections 1, 2 and 4)
-------------------------------------------------------------------------------------
Plane strain. Body 1 (the layer; ``mu_1``, ``rho_1``, ``c_s1``, ``c_l1``) fills ``y > 0``, body 2 (the
substrate) ``y < 0``. Steady state: uniform contact pressure ``p0 > 0`` and body 1 slipping in
``+x`` relative to body 2 (slip rate ``V = v_x(1) - v_x(2) > 0`` on ``y = 0``; ``V`` small against
the wave speeds, so the relative motion of the bodies does not enter the linearized equations), with
constant Coulomb coefficient ``f``. Friction on body 1 acts in ``-x``: its traction ``-sigma_xy``
equals ``-f p`` with ``p = -sigma_yy``, i.e. ``sigma_xy = -f sigma_yy``, as in ``analysis.theory.flutter``.
``f < 0`` means body 1 slips in ``-x``. A perturbation that keeps contact and keeps slipping in the
same direction satisfies on ``y = 0``

    u_y(1) = u_y(2),   sigma_yy(1) = sigma_yy(2),   sigma_xy(1) = sigma_xy(2),
    sigma_xy + f sigma_yy = 0                                                                (1)

(``u_x`` jumps: that is the slip perturbation). Take ``phi, psi ~ exp(i k (x - c t) - side k q y)``
with ``side = +1`` in body 1, ``-1`` in body 2, ``k > 0``. Each half-space has the surface
compliance (``tau = (sigma_xy, sigma_yy)`` the stresses at ``y = 0``, ``s = c / c_s`` of that body)

    mu k u = (1 / r(s)) [[ side q_s,   -i n(s)      ],
                         [ i n(s),      side q_l    ]] tau,                                  (2)

    r(s) = R(s) / s^2 = ((2 - s^2)^2 - 4 q_l q_s) / s^2,   n(s) = (2 q_l q_s - 2 + s^2) / s^2,

and (1) leaves one equation, the dispersion relation (``Gamma = mu_1 / mu_2``)

    Delta(c) = q_l1 / r_1 + Gamma q_l2 / r_2  -  i f (n_1 / r_1 - Gamma n_2 / r_2) = 0.         (3)

The first two terms are the normal compliance of the frictionless pair (their zero is the
generalized Rayleigh wave, ``analysis.theory.interface_wave``); the bracket is the coupling of slip and
normal displacement (the dynamic Dundurs coupling). At ``c -> 0`` it tends to
``((1 - 2 nu_1) - Gamma (1 - 2 nu_2)) / 2``, the numerator of Dundurs' beta.

* Identical solids: the bracket vanishes identically and ``Delta = 2 q_l / r``; its only zero is the
  grazing P wave ``c = c_l`` (real): no growing mode for any ``f``.
* Rigid substrate (``mu_2 -> inf``): ``s^2 r_1 Delta -> s^2 q_l1 + i f (2 - s^2 - 2 q_l1 q_s1)``, the
  flutter determinant of ``analysis.theory.flutter``: its wedge ``1 < f < f_upper(nu)``.
* Dissimilar solids with a generalized Rayleigh wave (``c_gR``): at ``f = 0`` (3) has the real zeros
  ``+-c_gR``; for small ``f`` they move off the real axis by ``dc/df = i Q / P'`` (``P``, ``Q`` below,
  both real there), one up, one down: a growing mode for every ``f > 0`` (Ranjith & Rice 2001),
  ``Im c`` proportional to ``f``, moving near ``c_gR``.

* Away from these limits the growing roots form two families (docs/bimaterial-theory.md, section 4):
  a *forward* one near the slower shear speed, in the slip direction of the more compliant body (the
  flutter mode, Ranjith & Rice's mode), and a *backward* one at or beyond the P speed of the more
  compliant body, running the other way: Adams' radiating backward wave of the rigid flat
  (``analysis.theory.supersonic``), made growing by the substrate's compliance (growth ~ mu_1 / mu_2 on a
  stiff substrate).

Growth: ``|exp(-i k c t)| = exp(k Im(c) t)``. The relation (3) has no length scale, so a root ``c``
does not depend on ``k`` and the growth rate ``k Im(c)`` is proportional to ``k`` (ill-posedness);
``Im c`` (m/s) is the growth rate per unit wavenumber. Direction: ``Re c > 0`` runs in ``+x``, the
slip direction of body 1 (relative to body 2); ``Re c < 0`` in ``-x``, the slip direction of body 2
(relative to body 1). "The slip direction of the more compliant material" (Ranjith & Rice) is thus
``+x`` when the layer is the more compliant (here: the lower shear modulus; a stiffer substrate,
E_2 > E_1 at equal nu) and ``-x`` when the substrate is (``compliant_slip_direction``).

Root finding
------------
The poles of (3) at the Rayleigh speeds are removed by ``Psi = r_1 r_2 Delta``:

    Psi(c) = P(c) - i f Q(c),   P = q_l1 r_2 + Gamma q_l2 r_1,   Q = n_1 r_2 - Gamma n_2 r_1,     (4)

analytic in the upper half plane of the physical sheet (branches as in ``analysis.theory.flutter``:
``Re q > 0``, real-axis values from above), with no zero of ``r`` there. Its zeros with
``Im c > 0`` are counted by the argument principle on a rectangle ``[-W, W] x [eps, W]``
(``W`` beyond the asymptotic root size ``|c| ~ |f| c_l``), isolated by bisection of the rectangle
and polished by Newton's method. Roots with ``Im c < eps`` count as neutral.

References
----------
K. Ranjith, J.R. Rice (2001), Slip dynamics at an interface between dissimilar materials, J. Mech.
Phys. Solids 49, 341-361.
G.G. Adams (1995), Self-excited oscillations of two elastic half-spaces sliding with a constant
coefficient of friction, J. Appl. Mech. 62, 867-872.
J. Weertman (1980), Unstable slippage across a fault that separates elastic media of different
elastic constants, J. Geophys. Res. 85, 1455-1461.
"""

from __future__ import annotations

import math

import numpy as np

from analysis.theory.interface_wave import (ElasticSolid, _as_solid, _q, generalized_rayleigh_speed,
                                     reduced_rayleigh_function)
from analysis.theory.complex_roots import isolate_roots, winding_number

__all__ = [
    "dispersion_function",
    "regular_dispersion_function",
    "count_growing_roots",
    "growing_roots",
    "small_friction_slope",
    "compliant_slip_direction",
    "mode_family",
    "instability_threshold",
    "bimaterial_regime",
]

#: Roots with Im(c) / c_s1 below this are neutral (the contour's bottom edge).
IM_FLOOR = 1e-9
#: |Re c| / c_s1 below this: a standing (non-propagating) growing mode.
STANDING = 1e-9

_SMALL_S = 0.5


def _check_f(f: float) -> float:
    f = float(f)
    if not math.isfinite(f):
        raise ValueError(f"f = {f!r} outside the allowed range (-inf, inf)")
    return f


def _reduced_coupling(s, gamma: float, q=None):
    """n(s) = (2 q_l q_s - 2 + s^2) / s^2 (dimensionless), regular at s = 0 (n(0) = -gamma).

    For |s| < 0.5 the rationalised form (-4 gamma + (4 gamma - 1) s^2) / (2 - s^2 + 2 q_l q_s)
    is used (no cancellation; its denominator is near 4 there). q: (q_l, q_s) = _q(s, gamma) if known.
    """
    s = np.asarray(s, dtype=complex)
    q_l, q_s = _q(s, gamma) if q is None else q
    z = s * s
    with np.errstate(divide="ignore", invalid="ignore"):
        direct = (2.0 * q_l * q_s - 2.0 + z) / z
        rational = (-4.0 * gamma + (4.0 * gamma - 1.0) * z) / (2.0 - z + 2.0 * q_l * q_s)
    return np.where(np.abs(s) < _SMALL_S, rational, direct)


def _parts(s, upper: ElasticSolid, lower: ElasticSolid):
    """(q_l1, r_1, n_1, q_l2, r_2, n_2, Gamma) at s = c / c_s1."""
    s = np.asarray(s, dtype=complex)
    s2 = s * (upper.c_s / lower.c_s)
    q1, q2 = _q(s, upper.gamma), _q(s2, lower.gamma)  # once per s: r and n take them
    return (q1[0], reduced_rayleigh_function(s, upper.gamma, q1), _reduced_coupling(s, upper.gamma, q1),
            q2[0], reduced_rayleigh_function(s2, lower.gamma, q2), _reduced_coupling(s2, lower.gamma, q2),
            upper.shear_modulus / lower.shear_modulus)


def dispersion_function(c, upper, lower, f: float):
    """Delta(c) of eq. (3) (dimensionless; c in m/s, vectorised). Poles at the Rayleigh speeds."""
    upper, lower = _as_solid(upper), _as_solid(lower)
    f = _check_f(f)
    q_l1, r_1, n_1, q_l2, r_2, n_2, gam = _parts(np.asarray(c, dtype=complex) / upper.c_s, upper, lower)
    result = q_l1 / r_1 + gam * q_l2 / r_2 - 1j * f * (n_1 / r_1 - gam * n_2 / r_2)
    return result if np.ndim(result) else complex(result)


def _psi(s, upper: ElasticSolid, lower: ElasticSolid, f: float):
    q_l1, r_1, n_1, q_l2, r_2, n_2, gam = _parts(s, upper, lower)
    return q_l1 * r_2 + gam * q_l2 * r_1 - 1j * f * (n_1 * r_2 - gam * n_2 * r_1)


def _psi_parts(s, upper: ElasticSolid, lower: ElasticSolid):
    """(P, Q) of eq. (4) at s = c / c_s1."""
    q_l1, r_1, n_1, q_l2, r_2, n_2, gam = _parts(s, upper, lower)
    return q_l1 * r_2 + gam * q_l2 * r_1, n_1 * r_2 - gam * n_2 * r_1


def regular_dispersion_function(c, upper, lower, f: float):
    """Psi(c) = r_1 r_2 Delta of eq. (4) (dimensionless; c in m/s, vectorised). No poles."""
    upper, lower = _as_solid(upper), _as_solid(lower)
    f = _check_f(f)
    result = _psi(np.asarray(c, dtype=complex) / upper.c_s, upper, lower, f)
    return result if np.ndim(result) else complex(result)


def _search_box(upper: ElasticSolid, lower: ElasticSolid, f: float, radius: float | None,
                bottom: float = IM_FLOOR):
    """(x0, x1, y0, y1) in s = c / c_s1: half-width W = 4 (1 + |f|) max(c_l1, c_l2) / c_s1 + 4,
    beyond the asymptotic size |c| ~ |f| c_l of a root of (4); bottom at IM_FLOOR."""
    if radius is None:
        radius = 4.0 * (1.0 + abs(f)) * max(upper.c_l, lower.c_l) / upper.c_s + 4.0
    return (-radius, radius, bottom, radius)


def _count_in_search_box(fun, upper, lower, f, radius, features):
    """(box, count) for the search rectangle; if a zero lies on its bottom edge (a root crossing
    Im c = IM_FLOOR c_s1), the edge is moved by a factor of a few."""
    for bottom in (IM_FLOOR, 3.7 * IM_FLOOR, 0.27 * IM_FLOOR):
        box = _search_box(upper, lower, f, radius, bottom)
        try:
            return box, winding_number(fun, *box, features)
        except ArithmeticError:
            continue
    raise ArithmeticError("argument principle: zeros on every bottom edge tried")


def _features(upper: ElasticSolid, lower: ElasticSolid) -> np.ndarray:
    """The origin and the branch points +-c_s, +-c_l of both solids, in s = c / c_s1."""
    speeds = np.array([upper.c_s, upper.c_l, lower.c_s, lower.c_l]) / upper.c_s
    return np.concatenate([[0.0], speeds, -speeds]).astype(complex)


def count_growing_roots(upper, lower, f: float, radius: float | None = None) -> int:
    """Number of zeros of Psi with IM_FLOOR < Im(c)/c_s1 < W and |Re c|/c_s1 < W (argument principle).

    radius: W (dimensionless, in units of c_s1); default as in ``growing_roots``.
    """
    upper, lower = _as_solid(upper), _as_solid(lower)
    f = _check_f(f)
    return _count_in_search_box(lambda s: _psi(s, upper, lower, f), upper, lower, f, radius,
                                _features(upper, lower))[1]


def growing_roots(upper, lower, f: float, radius: float | None = None) -> np.ndarray:
    """Phase speeds c (m/s, complex) of the growing modes of steady sliding, Im c > 0.

    Zeros of Psi (eq. 4) in the upper half plane, counted by the argument principle, isolated by
    bisection and polished by Newton's method to round-off; sorted by decreasing Im c. The growth rate
    of wavenumber k is k Im(c) (1/s); Re c > 0 runs in +x (body 1's slip direction).

    Parameters
    ----------
    upper, lower : ElasticSolid or (E, nu, rho)
        Body 1 (y > 0, slipping in +x for f > 0) and body 2 (y < 0).
    f : float
        Coulomb coefficient (f < 0: body 1 slips in -x).
    radius : float, optional
        Half-width W of the search rectangle in units of c_s1 (default 4 (1 + |f|) c_l,max / c_s1 + 4).

    Raises
    ------
    ArithmeticError
        when the zero count cannot be made consistent (a root on every contour tried).
    """
    upper, lower = _as_solid(upper), _as_solid(lower)
    f = _check_f(f)
    if f == 0.0:
        return np.empty(0, dtype=complex)  # frictionless contact conserves energy: nothing grows

    def fun(s):
        return _psi(s, upper, lower, f)

    features = _features(upper, lower)
    box, n_roots = _count_in_search_box(fun, upper, lower, f, radius, features)
    roots = isolate_roots(fun, box, n_roots, size_floor=1e-10 * (box[1] - box[0]), features=features)
    roots = [r for r in roots if r.imag > box[2]]
    return np.array(sorted((r * upper.c_s for r in roots), key=lambda r: -r.imag), dtype=complex)


def small_friction_slope(upper, lower) -> tuple[float, float] | None:
    """The growing root born at the generalized Rayleigh speed, to first order in f (Ranjith & Rice).

    Psi = P - i f Q with P(+-c_gR) = 0 and P, Q real on the real axis below both shear speeds, so
    dc/df = i Q / P' (P' = dP/dc) is imaginary, of opposite signs at +c_gR and -c_gR: for f > 0 the
    root at c_gR sign(Q / P') grows, c = c_gR sign(Q / P') + i f |Q / P'| + O(f^2).

    Returns
    -------
    (phase_speed, growth_per_k_per_f) : (float, float)
        signed speed of the growing root at f -> 0+ (m/s; + = +x, the layer's slip direction) and
        d(Im c)/df > 0 (m/s); None without a generalized Rayleigh wave.
    """
    upper, lower = _as_solid(upper), _as_solid(lower)
    c_gr = generalized_rayleigh_speed(upper, lower)
    if c_gr is None:
        return None
    s = c_gr / upper.c_s
    h = 1e-6 * s
    p_plus = _psi_parts(np.array([s + h]), upper, lower)[0][0]
    p_minus = _psi_parts(np.array([s - h]), upper, lower)[0][0]
    dp_ds = complex(p_plus - p_minus) / (2.0 * h)
    q = complex(_psi_parts(np.array([s]), upper, lower)[1][0])
    rate = (1j * q / dp_ds).imag * upper.c_s  # d(Im c)/df of the root at +c_gR
    return (c_gr, rate) if rate > 0.0 else (-c_gr, -rate)


def compliant_slip_direction(upper, lower) -> int:
    """+1 if the layer (body 1) is the more compliant (mu_1 < mu_2): its slip direction, +x, is the
    "slip direction of the more compliant material"; -1 if the substrate is (its slip direction
    relative to the layer is -x); 0 for equal shear moduli."""
    upper, lower = _as_solid(upper), _as_solid(lower)
    return int(np.sign(lower.shear_modulus - upper.shear_modulus))


def mode_family(c: complex, upper, lower) -> str:
    """"forward" if the mode runs in the slip direction of the more compliant body, "backward" if
    against it, "standing" for |Re c| < STANDING c_s1, "equal_moduli" if mu_1 = mu_2. c in m/s."""
    upper, lower = _as_solid(upper), _as_solid(lower)
    direction = compliant_slip_direction(upper, lower)
    if abs(complex(c).real) < STANDING * upper.c_s:
        return "standing"
    if direction == 0:
        return "equal_moduli"
    return "forward" if np.sign(complex(c).real) == direction else "backward"


def instability_threshold(upper, lower, f_max: float = 10.0, n_grid: int = 40,
                          family: str | None = None) -> float:
    """The smallest f > 0 with a growing mode (the body 1 slipping in +x), or inf below f_max.

    0 when a generalized Rayleigh wave exists and the coupling does not vanish there (unstable for
    every f > 0, ``small_friction_slope``). Otherwise a scan of (0, f_max] on n_grid points and a
    bisection (to 1e-6 relative) of the first stable-unstable transition. Only the onset: for a
    near-rigid substrate and nu < 1/3 the unstable range is bounded above too (the flutter wedge).
    A growth rate below IM_FLOOR c_s1 per unit k counts as neutral, so a mode whose growth vanishes
    only as f -> 0 (the backward mode on a very stiff substrate) gives a threshold near 1e-5.
    family: None (any growing mode), "forward" or "backward" (``mode_family``): the onset of that
    family only (the generalized Rayleigh mode is forward).
    """
    upper, lower = _as_solid(upper), _as_solid(lower)
    if family not in (None, "forward", "backward"):
        raise ValueError(f"family = {family!r} outside the allowed range {{None, 'forward', 'backward'}}")
    slope = small_friction_slope(upper, lower)
    if family != "backward" and slope is not None and slope[1] > IM_FLOOR * upper.c_s:
        return 0.0

    def unstable(f: float) -> bool:
        if family is None:
            return count_growing_roots(upper, lower, f) > 0
        return any(mode_family(c, upper, lower) == family for c in growing_roots(upper, lower, f))

    grid = np.linspace(f_max / n_grid, f_max, n_grid)
    previous = 0.0
    for f in grid:
        if unstable(f):
            low, high = previous, float(f)
            while high - low > 1e-6 * high:
                middle = 0.5 * (low + high)
                if unstable(middle):
                    high = middle
                else:
                    low = middle
            return high
        previous = float(f)
    return math.inf


def bimaterial_regime(E1: float, nu1: float, rho1: float, E2: float, nu2: float, rho2: float,
                      f: float) -> dict:
    """Place a point (layer E1, nu1, rho1 on substrate E2, nu2, rho2; Coulomb f) against the theory.

    Returns
    -------
    dict with
        c_gR : float or None           generalized Rayleigh speed (m/s), None if it does not exist
        c_gR_over_cs1 : float or None
        unstable : bool                 a growing mode exists (steady sliding is ill-posed)
        growth_rate_per_k : float       Im c of the most unstable mode (m/s; 0 if stable);
                                        the growth rate of wavenumber k is k times this (1/s)
        growth_rate_per_k_over_cs1 : float
        phase_speed : float or None     Re c of that mode (m/s, signed; + = +x = the layer's slip)
        phase_speed_over_cs1 : float or None
        direction : str or None         "+x" (the layer's slip direction), "-x" (the substrate's),
                                        "standing", None if stable
        n_growing : int                 number of growing modes
        modes : list of (float, float)  (phase speed, growth rate per k) of every growing mode (m/s),
                                        most unstable first
        compliant_body : str or None    "layer" or "substrate" (lower shear modulus), None if equal
        family : str or None            ``mode_family`` of the most unstable mode
        forward_growth_rate_per_k, backward_growth_rate_per_k : float
                                        Im c of the most unstable mode of each family (m/s; 0 if none)
        forward_phase_speed, backward_phase_speed : float or None   their Re c (m/s)
    """
    upper, lower = ElasticSolid(E1, nu1, rho1), ElasticSolid(E2, nu2, rho2)
    c_gr = generalized_rayleigh_speed(upper, lower)
    roots = growing_roots(upper, lower, f)
    unstable = roots.size > 0
    top = roots[0] if unstable else None
    if top is None:
        direction = None
    elif abs(top.real) < STANDING * upper.c_s:
        direction = "standing"
    else:
        direction = "+x" if top.real > 0.0 else "-x"
    result = {
        "c_gR": c_gr,
        "c_gR_over_cs1": None if c_gr is None else c_gr / upper.c_s,
        "unstable": bool(unstable),
        "growth_rate_per_k": float(top.imag) if unstable else 0.0,
        "growth_rate_per_k_over_cs1": float(top.imag) / upper.c_s if unstable else 0.0,
        "phase_speed": float(top.real) if unstable else None,
        "phase_speed_over_cs1": float(top.real) / upper.c_s if unstable else None,
        "direction": direction,
        "n_growing": int(roots.size),
        "modes": [(float(r.real), float(r.imag)) for r in roots],
        "compliant_body": {1: "layer", -1: "substrate", 0: None}[compliant_slip_direction(upper, lower)],
        "family": mode_family(top, upper, lower) if unstable else None,
    }
    for name in ("forward", "backward"):
        members = [r for r in roots if mode_family(r, upper, lower) == name]  # sorted: strongest first
        result[f"{name}_growth_rate_per_k"] = float(members[0].imag) if members else 0.0
        result[f"{name}_phase_speed"] = float(members[0].real) if members else None
    return result
