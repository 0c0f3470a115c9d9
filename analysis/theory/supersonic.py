r"""Steady supersonic slip wave of an elastic half-space sliding on a rigid flat (Adams 2000).

Problem
-------
Plane strain; the body is ``y > 0`` (shear modulus ``mu``, wave speeds ``c_s < c_l``), the rigid flat
is ``y = 0``, Coulomb friction ``f``. Take a frame in which the wave runs in ``+x`` at trace speed
``c > c_l`` and superpose on a state at the friction limit a pair of plane waves of any profile F,

    phi = A F(x + alpha y - c t),    psi = B F(x + beta y - c t),
    alpha = sqrt(s^2/a^2 - 1),  beta = sqrt(s^2 - 1),  s = c / c_s,  a = c_l / c_s,

with ``u_x = phi_x + psi_y``, ``u_y = phi_y - psi_x``. With ``alpha, beta > 0`` the wave fronts move
along ``(1, alpha)`` and ``(1, beta)``: both waves leave the interface (radiation condition). Hooke's
law (``lambda = mu (a^2 - 2)``) gives on ``y = 0``, with ``' = d/dx``,

    u_y = (alpha A - B) F',                  u_x = (A + beta B) F',
    sigma_yy = mu ((beta^2 - 1) A - 2 beta B) F'',    sigma_xy = mu (2 alpha A + (beta^2 - 1) B) F''.

Contact kept, ``u_y = 0``, gives ``B = alpha A``, and then

    sigma_xy / sigma_yy = R(s) = alpha (1 + beta^2) / (beta^2 - 1 - 2 alpha beta)
                        = alpha (s^2 - 2 + 2 alpha beta) / ((1 - 4 gamma) s^2 + 4 gamma),      (1)

``gamma = c_s^2 / c_l^2`` (the second form multiplies by ``s^2 - 2 + 2 alpha beta > 0`` and has no
cancellation). Sliding of the body in ``-x`` (friction on it in ``+x``) means
``sigma_xy = +f sigma_yy``; sliding in ``+x`` means ``sigma_xy = -f sigma_yy``. So

    R(s) = +f   the wave runs against the sliding direction ("backward", the paper's c_p < 0),  (2)
    R(s) = -f   the wave runs with it ("forward").                                              (3)

Results (proofs in docs/supersonic-backward.md)
-----------------------------------------------
* Where the denominator of (1) is positive, R increases strictly with ``s``; ``R(a) = 0`` for
  ``nu > 0``. Hence (2) has
  exactly one root for every ``f > 0`` and ``0 < nu < 1/2``, with ``c -> c_l`` as ``f -> 0``
  (``alpha = f nu / (1 - nu) + O(f^2)``) and, as ``f -> inf``, ``c ~ f (c_l - 2 c_s)`` for
  ``nu > 1/3``, ``c ~ f^(1/3) c_s`` at ``nu = 1/3``, ``c -> s_* c_s`` for ``nu < 1/3`` with
  ``s_*^2 = 4 gamma / (4 gamma - 1) = 2 (1 - 2 nu) / (1 - 3 nu)`` (where ``sigma_yy`` of the pair
  vanishes). No root at ``nu = 0``.
* (3) needs ``R < 0``, i.e. ``nu < 1/3`` and ``s > s_*``; ``-R`` is there the flutter edge function
  of ``analysis.theory.flutter``: two roots for ``f > f_upper(nu)``, one at ``f = f_upper`` (for
  ``nu = 0``: one root for every ``f > 1``). For ``nu >= 1/3`` only the backward wave exists.
* Changing ``alpha, beta`` to ``-alpha, -beta`` (waves coming in from the body) changes the sign of
  R: the forward partner of a backward root at the same speed is the incoming field, excluded by the
  radiation condition. Inside a backward pulse on a stuck interface at the friction limit the slip
  rate has the sign of the sliding and the contact pressure drops: the energy flux into the body on
  ``y = 0``, ``-sigma_xy v_x = f d(sigma_yy) v_x`` for sliding in ``+x``, is positive exactly then.

Speeds are returned in the units of ``c_s`` (``c_s = 1``: normalised; pass
``analysis.theory.elastic.wave_speeds(nu)[0]`` for m/s at the paper's E and rho).

Reference
---------
G.G. Adams (2000), Radiation of body waves induced by the sliding of an elastic half-space against a
rigid surface, J. Appl. Mech. 67, 1-5.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from analysis.theory import elastic, flutter

__all__ = [
    "speed_ratio",
    "vertical_slownesses",
    "traction_ratio",
    "backward_speed_limit",
    "supersonic_trace_speed",
    "forward_trace_speeds",
]

NU_OPEN = 1.0 / 3.0  # for nu >= 1/3 the backward speed is unbounded in f and no forward wave exists


def _check_nu(nu: float) -> float:
    nu = float(nu)
    if not 0.0 <= nu < 0.5:
        raise ValueError(f"nu = {nu!r} outside the allowed range [0, 0.5)")
    return nu


def _check_f(f: float) -> float:
    f = float(f)
    if not (math.isfinite(f) and f > 0.0):
        raise ValueError(f"f = {f!r} outside the allowed range (0, inf)")
    return f


def _check_c_s(c_s: float) -> float:
    c_s = float(c_s)
    if not (math.isfinite(c_s) and c_s > 0.0):
        raise ValueError(f"c_s = {c_s!r} outside the allowed range (0, inf)")
    return c_s


def speed_ratio(nu: float) -> float:
    """a = c_l / c_s = sqrt(2 (1 - nu) / (1 - 2 nu)) (plane strain), from `analysis.theory.elastic`."""
    nu = _check_nu(nu)
    return elastic.longitudinal_wave_speed(1.0, nu, 1.0) / elastic.shear_wave_speed(1.0, nu, 1.0)


def vertical_slownesses(s, nu: float):
    """(alpha, beta) = (sqrt(s^2/a^2 - 1), sqrt(s^2 - 1)) for s = c / c_s >= a (dimensionless).

    ``(1, alpha)`` and ``(1, beta)`` are the P and S wave vectors divided by their x component.
    nan for s < a (the P wave would not radiate).
    """
    a = speed_ratio(nu)
    s = np.asarray(s, dtype=float)
    with np.errstate(invalid="ignore"):
        alpha = np.where(s >= a, np.sqrt(np.maximum(s * s / (a * a) - 1.0, 0.0)), np.nan)
        beta = np.where(s >= a, np.sqrt(s * s - 1.0), np.nan)
    return alpha, beta


def traction_ratio(s, nu: float):
    """R(s) = sigma_xy / sigma_yy on y = 0 of the outgoing P + S pair with u_y = 0, eq. (1).

    Vectorised over ``s = c / c_s >= c_l / c_s`` (nan below); +-inf where sigma_yy = 0 (s = s_*).
    """
    nu = _check_nu(nu)
    gamma = 1.0 / speed_ratio(nu) ** 2
    alpha, beta = vertical_slownesses(s, nu)
    t = np.asarray(s, dtype=float) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        result = alpha * (t - 2.0 + 2.0 * alpha * beta) / ((1.0 - 4.0 * gamma) * t + 4.0 * gamma)
    return result if result.ndim else float(result)


def backward_speed_limit(nu: float, c_s: float = 1.0) -> float:
    """Upper bound of the backward trace speed, reached as f -> inf (units of c_s).

    s_* c_s with s_*^2 = 2 (1 - 2 nu) / (1 - 3 nu) for 0 <= nu < 1/3 (sigma_yy of the pair vanishes
    there; at nu = 0, s_* = c_l / c_s and the range is empty); math.inf for nu >= 1/3.
    """
    nu, c_s = _check_nu(nu), _check_c_s(c_s)
    if nu >= NU_OPEN:
        return math.inf
    return c_s * math.sqrt(2.0 * (1.0 - 2.0 * nu) / (1.0 - 3.0 * nu))


def _excess(alpha: float, nu: float, signed_f: float) -> float:
    """alpha (t - 2 + 2 alpha beta) - signed_f ((1 - 4 gamma) t + 4 gamma), t = a^2 (1 + alpha^2).

    Zero iff R = signed_f: eq. (1) multiplied by its denominator, so it has no pole at s_*.
    """
    a = speed_ratio(nu)
    gamma = 1.0 / (a * a)
    t = a * a * (1.0 + alpha * alpha)
    beta = math.sqrt(t - 1.0)
    return alpha * (t - 2.0 + 2.0 * alpha * beta) - signed_f * ((1.0 - 4.0 * gamma) * t + 4.0 * gamma)


def _speed_from_alpha(alpha: float, nu: float) -> float:
    return speed_ratio(nu) * math.sqrt(1.0 + alpha * alpha)


def _solve_alpha(nu: float, signed_f: float, lo: float, hi: float) -> float:
    return brentq(_excess, lo, hi, args=(nu, signed_f), xtol=1e-300, rtol=4.0 * np.finfo(float).eps,
                  maxiter=500)


def supersonic_trace_speed(nu: float, f: float, c_s: float = 1.0) -> float | None:
    """Trace speed of the steady supersonic slip wave that runs against the sliding direction.

    The root c > c_l of ``R(c / c_s) = f``, eq. (2) of the module docstring:

        alpha (1 + beta^2) = f (beta^2 - 1 - 2 alpha beta),
        alpha = sqrt(c^2/c_l^2 - 1),  beta = sqrt(c^2/c_s^2 - 1).

    In the paper's convention (sliding in +x) the celerity is ``-c``.

    Parameters
    ----------
    nu : float
        Poisson's ratio, [0, 0.5).
    f : float
        Coulomb coefficient, > 0.
    c_s : float
        Shear wave speed; the result is in its units (default 1: c / c_s).

    Returns
    -------
    float or None
        c (> c_l, < `backward_speed_limit`), unique; None at nu = 0, where no such wave exists.

    References
    ----------
    G.G. Adams (2000), J. Appl. Mech. 67, 1-5.
    """
    nu, f, c_s = _check_nu(nu), _check_f(f), _check_c_s(c_s)
    if nu == 0.0:
        return None
    if nu < NU_OPEN:
        # alpha at s_*, written without cancellation: R -> +inf there, so the excess is positive.
        hi = nu / math.sqrt((1.0 - nu) * (1.0 - 3.0 * nu))
    else:
        hi = 1.0
        while _excess(hi, nu, f) <= 0.0:
            hi *= 2.0
    return c_s * _speed_from_alpha(_solve_alpha(nu, f, 0.0, hi), nu)


def forward_trace_speeds(nu: float, f: float, c_s: float = 1.0) -> tuple[float, ...]:
    """Trace speeds of the steady supersonic slip waves that run in the sliding direction, eq. (3).

    Roots of ``R(c / c_s) = -f``, ascending (units of c_s). Empty for nu >= 1/3 and for
    f < f_upper(nu) (`analysis.theory.flutter.flutter_boundary`, the double root at
    `analysis.theory.flutter.boundary_speeds`); two roots above it. At nu = 0 one root for every f > 1.
    """
    nu, f, c_s = _check_nu(nu), _check_f(f), _check_c_s(c_s)
    if nu >= NU_OPEN:
        return ()
    alpha_star = nu / math.sqrt((1.0 - nu) * (1.0 - 3.0 * nu))

    def upper_bracket(lo: float) -> float:
        hi = max(2.0 * lo, 1.0)
        while _excess(hi, nu, -f) <= 0.0:
            hi *= 2.0
        return hi

    if nu == 0.0:
        # -R = alpha + beta (exact at nu = 0), rising from 1 at s = sqrt(2): alpha + beta = f with
        # beta^2 = 1 + 2 alpha^2 gives alpha = sqrt(2 f^2 - 1) - f.
        if f <= 1.0:
            return ()
        return (c_s * _speed_from_alpha(math.sqrt(2.0 * f * f - 1.0) - f, nu),)
    f_upper = flutter.flutter_boundary(nu)[1]
    s_upper = flutter.boundary_speeds(nu)[1]
    alpha_upper = math.sqrt(s_upper**2 / speed_ratio(nu) ** 2 - 1.0)
    if f < f_upper:
        return ()
    if f == f_upper:
        return (c_s * s_upper,)
    # -R = +inf at alpha_star (the excess is alpha N > 0 there), minimum f_upper < f at alpha_upper
    # (excess < 0), +inf as alpha -> inf: one root on each side.
    slow = _solve_alpha(nu, -f, alpha_star, alpha_upper)
    fast = _solve_alpha(nu, -f, alpha_upper, upper_bracket(alpha_upper))
    return (c_s * _speed_from_alpha(slow, nu), c_s * _speed_from_alpha(fast, nu))
