r"""Flutter (Hadamard) instability of steady frictional sliding: elastic half-space on a rigid flat.

Problem
-------
An isotropic linear elastic half-space ``y > 0`` (plane strain; shear modulus ``mu``, density
``rho``, wave speeds ``c_s``, ``c_l``) slides in ``+x`` over a rigid flat ``y = 0`` with Coulomb
friction ``f`` (constant). The traction on the body at ``y = 0`` is ``t = -sigma . e_y``; contact
pressure ``p = -sigma_yy > 0`` and friction on the body acts in ``-x``, so ``-sigma_xy = -f p``:

    sigma_xy = -f sigma_yy                                  (sliding in +x, continued slip)

A perturbation of the steady state that keeps contact and keeps slipping in ``+x`` satisfies

    u_y = 0,   sigma_xy + f sigma_yy = 0      at y = 0.                                   (1)

Surface solutions (as in Renardy 1992; Martins, Guimaraes & Faria 1995)
------------------------------------------------------------------------
With ``u = grad phi + curl(psi e_z)``, i.e. ``u_x = phi_x + psi_y``, ``u_y = phi_y - psi_x``, take

    phi = A exp(i k (x - c t) - k q_l y),   psi = B exp(i k (x - c t) - k q_s y),   k > 0,

    q_l^2 = 1 - s^2 gamma,   q_s^2 = 1 - s^2,   s = c / c_s,   gamma = c_s^2/c_l^2 = (1-2nu)/(2(1-nu)).

Hooke's law gives (``E_j = exp(i k (x - c t) - k q_j y)``)

    u_x      = k (i A E_l - q_s B E_s),            u_y = -k (q_l A E_l + i B E_s),
    sigma_yy = mu k^2 ((1 + q_s^2) A E_l + 2 i q_s B E_s),
    sigma_xy = mu k^2 (-2 i q_l A E_l + (1 + q_s^2) B E_s),
    sigma_xx = mu k^2 ((q_s^2 - 1 - 2 q_l^2) A E_l - 2 i q_s B E_s)

(``lambda (q_l^2 - 1) + 2 mu q_l^2 = mu (1 + q_s^2)`` was used). Conditions (1) on (A, B):

    M = [[ -q_l,                       -i                      ],
         [ -2 i q_l + f (1 + q_s^2),    1 + q_s^2 + 2 i f q_s  ]],

    D(s; nu, f) = det M = s^2 q_l + i f (2 - s^2 - 2 q_l q_s) = 0,    B = i q_l A.          (2)

``D`` has a trivial double zero at ``s = 0`` (there ``B = i A`` and the field vanishes
identically); it is not a mode. With ``2 - s^2 - 2 q_l q_s = s^2 (4 gamma + (1 - 4 gamma) s^2)
/ (2 - s^2 + 2 q_l q_s)`` the reduced function ``D / s^2`` is regular and nonzero at ``s = 0``.

Branch choices (documented because everything hinges on them)
-------------------------------------------------------------
Decay into the body needs ``Re(k q) > 0``; for ``k > 0`` that is ``Re q > 0`` for both ``q``.
A mode grows in time iff ``Im c > 0`` (``|exp(-i k c t)| = exp(k Im(c) t)``); the growth rate
``k Im c`` is proportional to ``k``, so any such root makes the problem ill-posed (flutter).
``k < 0`` adds nothing: its modes are the complex conjugates of the ``k > 0`` ones.

* ``q_j(s) = sqrt(1 - s^2/a_j^2)`` is the principal root (``Re q_j > 0``), ``a_l = c_l/c_s``,
  ``a_s = 1``. It is analytic off the cuts ``s`` real, ``|s| >= a_j``; this cut plane is the
  *physical sheet*. Growing roots live in its upper half.
* On the real axis the value is the limit from ``Im s -> 0+`` (the growing side):
  ``q_j = sqrt(1 - s^2/a_j^2) > 0`` for ``|s| < a_j``, ``q_j = -i sign(s) sqrt(s^2/a_j^2 - 1)`` for
  ``|s| > a_j``. In the code, for ``Im s >= 0``, ``q_j = -i sqrt(s/a_j - 1) sqrt(s/a_j + 1)``
  (principal square roots), which equals the principal branch there and has exactly these limits.
  For ``Im s < 0`` the principal branch is used.
* Real roots with ``|s| > c_l/c_s`` have ``Re q = 0``: they are neutral, radiating (leaky) modes, not
  surface waves, and do not count as growing.

Where the growing root comes from (analysis behind ``flutter_boundary``)
------------------------------------------------------------------------
``D`` is even in ``s`` and has no zeros near the branch points (``D(+-1) = sqrt(1-gamma) + i f``,
``D(+-c_l/c_s) = i f (2 - 1/gamma) != 0`` for ``nu > 0``) nor at infinity
(``D ~ -i sqrt(gamma) s^3``).
For ``f = 0`` it reduces to ``s^2 q_l``: no surface wave under a bilateral frictionless
constraint (the only nontrivial zero, ``c = c_l``, is a P wave grazing the surface), hence no root
for small ``f``. The number of roots with ``Im s > 0`` can therefore
change only where a root crosses the real axis (boundary values from above, ``f > 0``):

* ``|s| < 1``: ``Re D = s^2 q_l != 0``. ``-c_l/c_s < s < -1``: ``Re D = s^2 q_l + 2 f q_l beta > 0``.
* ``1 < s < c_l/c_s`` (``q_s = -i beta``, ``beta = sqrt(s^2 - 1)``):
  ``D = s^2 q_l - 2 f q_l beta + i f (2 - s^2)`` vanishes only at ``s = sqrt(2)``, ``f = 1``
  (Renardy's threshold). There ``dD/ds = -2 sqrt(2) i``, ``dD/df = -2 q_l``, so
  ``ds/df = i q_l / sqrt(2) = i sqrt(nu / (2 (1 - nu)))``: a root enters the upper half plane as
  ``f`` increases through 1, with speed ``c -> sqrt(2) c_s`` in the sliding direction (``+x``).
  At ``nu = 0`` (``c_l = sqrt(2) c_s``) the crossing point is the branch point and no root enters.
* ``|s| > c_l/c_s`` (``q_l = -+i alpha``, ``alpha = sqrt(gamma s^2 - 1)``): ``D / i`` is real,
  ``D / i = f (2 - s^2 + 2 alpha beta) - s^2 alpha`` for ``s > 0``. By Schwarz reflection a simple
  real zero stays real, so a root can leave the upper half plane only through a *double* real zero.
  For ``s > 0`` this needs ``f = g(s) = s^2 alpha / (2 - s^2 + 2 alpha beta)`` with a positive
  denominator, i.e. ``nu < 1/3`` and ``s^2 > s_*^2 = 4 gamma / (4 gamma - 1)``; ``g`` goes from
  ``+inf`` (at ``s_*``) through one minimum back to ``+inf``, so the double zero is at
  ``f_upper = min g``. For ``s < 0`` the corresponding function is monotone (no double zero).
(Unimodality of ``g`` and monotonicity for ``s < 0`` were checked numerically over ``nu``.)

Result: growing roots exist iff ``1 < f < f_upper(nu)`` with ``f_upper = min_{s > s_*} g(s)`` for
``0 < nu < 1/3`` and ``f_upper = inf`` for ``1/3 <= nu < 1/2``; none at ``nu = 0``
(``f_upper = 1 + 2 sqrt(nu) + O(nu)`` as ``nu -> 0``, from ``g ~ 1 / (1 - alpha - nu/alpha)``
near ``s = sqrt(2)``): a wedge in the (nu, f) plane with its tip at (0, 1), consistent with the
"wedge-zone" of Yastrebov (2016) Fig. 4a and with f = 1 as Renardy's limit. The growing root moves from ``sqrt(2) c_s`` (``f = 1``) to the supersonic
speed ``argmin g`` (``f = f_upper``); for ``nu > 1/3`` and ``f -> inf`` it tends to
``s = i sqrt(4 gamma / (1 - 4 gamma))`` (a non-propagating growing mode).

References
----------
M. Renardy (1992), Ill-posedness at the boundary for elastic solids sliding under Coulomb friction,
J. Elasticity 27, 281-287.
J.A.C. Martins, J. Guimaraes, L.O. Faria (1995), Dynamic surface solutions in linear elasticity and
viscoelasticity with frictional boundary conditions, J. Vib. Acoust. 117, 445-451.
G.G. Adams (1995), Self-excited oscillations of two elastic half-spaces sliding with a constant
coefficient of friction, J. Appl. Mech. 62, 867-872.
V.A. Yastrebov (2016), Sliding without slipping under Coulomb friction: opening waves and
inversion of frictional force, Tribol. Lett. 62, 1 (Fig. 4a, the flutter wedge).

All speeds are normalised by ``c_s``. Use this module for the rigid-flat case only: a deformable
counter-body (Adams 1995, Ranjith & Rice 2001) changes the secular equation.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.polynomial import polynomial as npoly
from scipy.optimize import minimize_scalar

__all__ = [
    "speed_ratio_squared",
    "secular_matrix",
    "secular_determinant",
    "growing_roots",
    "flutter_boundary",
    "inside_wedge",
    "boundary_speeds",
]

NU_MAX = 0.5
NU_WEDGE_OPEN = 1.0 / 3.0   # for nu >= 1/3 the instability extends to f = inf
THRESHOLD_F = 1.0           # Renardy (1992): the root crosses the real axis at f = 1 ...
THRESHOLD_SPEED = math.sqrt(2.0)  # ... at c = sqrt(2) c_s


def _check_nu(nu: float) -> float:
    nu = float(nu)
    if not (0.0 <= nu < NU_MAX):
        raise ValueError(f"nu = {nu!r} outside [0, 0.5)")
    return nu


def _check_f(f: float) -> float:
    f = float(f)
    if not math.isfinite(f):
        raise ValueError(f"f = {f!r} must be finite")
    return f


def speed_ratio_squared(nu: float) -> float:
    """gamma = c_s^2 / c_l^2 = (1 - 2 nu) / (2 (1 - nu)) for plane strain (dimensionless)."""
    nu = _check_nu(nu)
    return (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))


def _vertical_wavenumber(s, a: float):
    """q = sqrt(1 - s^2/a^2) on the physical sheet (Re q >= 0), real-axis values from Im s -> 0+.

    For Im s >= 0: q = -i sqrt(s/a - 1) sqrt(s/a + 1) (principal roots). For Im s < 0: principal.
    """
    s = np.asarray(s, dtype=complex)
    # +0.0 imaginary part on the real axis, so that the principal roots below take the upper limit.
    s = np.where(s.imag == 0.0, s.real + 0j, s)
    w = s / a
    upper = -1j * np.sqrt(w - 1.0) * np.sqrt(w + 1.0)
    lower = np.sqrt(1.0 - w * w)
    return np.where(s.imag >= 0.0, upper, lower)


def _wavenumbers(s, nu: float):
    gamma = speed_ratio_squared(nu)
    return _vertical_wavenumber(s, 1.0 / math.sqrt(gamma)), _vertical_wavenumber(s, 1.0)


def secular_matrix(c: complex, nu: float, f: float) -> np.ndarray:
    """The 2x2 matrix M of eq. (2) acting on the potential amplitudes (A, B).

    Row 0: u_y / (k E) at y = 0; row 1: (sigma_xy + f sigma_yy) / (mu k^2 E) at y = 0.

    Parameters
    ----------
    c : complex
        Phase speed normalised by c_s (scalar).
    nu : float
        Poisson's ratio, [0, 0.5).
    f : float
        Coulomb coefficient; f > 0 means the body slides in +x (f < 0: in -x).
    """
    nu, f = _check_nu(nu), _check_f(f)
    q_l, q_s = (complex(q) for q in _wavenumbers(complex(c), nu))
    return np.array(
        [[-q_l, -1j], [-2j * q_l + f * (1.0 + q_s**2), 1.0 + q_s**2 + 2j * f * q_s]], dtype=complex
    )


def secular_determinant(c, nu: float, f: float):
    """D(s; nu, f) = s^2 q_l + i f (2 - s^2 - 2 q_l q_s), s = c / c_s (dimensionless).

    Equals ``det secular_matrix``. Vectorised over ``c``. Branches as in the module docstring.
    ``D`` has a trivial double zero at ``c = 0`` (null field), which is not a mode.
    """
    nu, f = _check_nu(nu), _check_f(f)
    s = np.asarray(c, dtype=complex)
    q_l, q_s = _wavenumbers(s, nu)
    result = s * s * q_l + 1j * f * (2.0 - s * s - 2.0 * q_l * q_s)
    return result if result.ndim else complex(result)


def _rationalised_polynomial(nu: float, f: float) -> np.ndarray:
    """Coefficients (ascending, in z = s^2) of the polynomial whose roots contain every zero of D.

    D = 0  <=>  P - i z q_l = 2 f q_l q_s  with P = f (2 - z). Squaring twice removes both roots:
    (P^2 - z^2 a - 4 f^2 a b)^2 + 4 P^2 z^2 a = 0,  a = q_l^2 = 1 - gamma z,  b = q_s^2 = 1 - z.
    Degree 6; it also holds the zeros of the other sign choices of (q_l, q_s) and z = 0 (double).
    """
    gamma = speed_ratio_squared(nu)
    p = np.array([2.0 * f, -f])
    a = np.array([1.0, -gamma])
    b = np.array([1.0, -1.0])
    z2a = npoly.polymul([0.0, 0.0, 1.0], a)
    p2 = npoly.polymul(p, p)
    inner = npoly.polysub(npoly.polysub(p2, z2a), 4.0 * f * f * npoly.polymul(a, b))
    return npoly.polyadd(npoly.polymul(inner, inner), 4.0 * npoly.polymul(p2, z2a))


def _polish(s: complex, nu: float, f: float, max_iterations: int = 50) -> complex:
    """Newton on D; the Im s >= 0 formula continues analytically across the real cuts |s| > 1."""
    for _ in range(max_iterations):
        h = 1e-6 * max(1.0, abs(s))
        d0 = secular_determinant(s, nu, f)
        dd = (secular_determinant(s + h, nu, f) - secular_determinant(s - h, nu, f)) / (2.0 * h)
        if dd == 0:
            break
        step = d0 / dd
        s -= step
        if s.imag < 0.0:  # left the physical upper half plane: not a growing root
            break
        if abs(step) < 4.0 * np.finfo(float).eps * max(1.0, abs(s)):
            break
    return s


def growing_roots(nu: float, f: float, im_tol: float = 1e-9) -> np.ndarray:
    """Roots of D with Im c > 0 (growing, decaying into the body), speeds normalised by c_s.

    All zeros are taken from the rationalised degree-6 polynomial in s^2, mapped to Im s >= 0,
    polished by Newton on D and kept if D vanishes on the physical sheet.

    Parameters
    ----------
    nu : float
        Poisson's ratio, [0, 0.5).
    f : float
        Coulomb coefficient (finite; f < 0 means sliding in -x).
    im_tol : float
        Roots with Im c <= im_tol * max(1, |c|) count as neutral (real-axis, radiating) roots.

    Returns
    -------
    numpy.ndarray of complex
        Growing roots sorted by decreasing Im c (empty if none). Growth rate = k c_s Im(c) (1/s).
    """
    nu, f = _check_nu(nu), _check_f(f)
    if f == 0.0:
        return np.empty(0, dtype=complex)  # D = s^2 q_l: no zero off the real axis
    found: list[complex] = []
    for z in npoly.polyroots(_rationalised_polynomial(nu, f)):
        if abs(z) < 1e-8:  # the trivial double root s = 0 (null field)
            continue
        s = complex(np.sqrt(complex(z)))
        if s.imag < 0.0:
            s = -s
        s = _polish(s, nu, f)
        if abs(s) < 1e-4:  # Newton fell into the trivial zero; D / s^2 -> 1 + i f gamma != 0 there
            continue
        scale = 1.0 + abs(f) * (1.0 + abs(s) ** 2) + abs(s) ** 3
        if s.imag <= im_tol * max(1.0, abs(s)):
            continue
        if abs(secular_determinant(s, nu, f)) > 1e-10 * scale:
            continue  # a zero of another sign choice of (q_l, q_s): not on the physical sheet
        duplicates = [i for i, r in enumerate(found) if abs(s - r) <= 1e-8 * max(1.0, abs(s))]
        if not duplicates:
            found.append(s)
        elif abs(secular_determinant(s, nu, f)) < abs(secular_determinant(found[duplicates[0]], nu, f)):
            found[duplicates[0]] = s  # keep the better-converged copy
    return np.array(sorted(found, key=lambda r: -r.imag), dtype=complex)


def _edge_function_upper(nu: float):
    """(t_*, g(u)) with s^2 = t = t_* (1 + e^u), t_* = 4 gamma/(4 gamma - 1), for 0 < nu < 1/3.

    g = s^2 alpha / (2 - s^2 + 2 alpha beta) = alpha (t - 2 + 2 alpha beta) / ((4 gamma - 1)(t - t_*))
    (rationalised), alpha = sqrt(gamma t - 1), beta = sqrt(t - 1). Written without cancellation for
    nu -> 0, where gamma t_* - 1 = (1 - 2 gamma)^2 / (4 gamma - 1) = nu^2 / ((1 - nu)(1 - 3 nu)).
    """
    gamma = speed_ratio_squared(nu)
    four_gamma_minus_one = (1.0 - 3.0 * nu) / (1.0 - nu)
    t_star = 2.0 * (1.0 - 2.0 * nu) / (1.0 - 3.0 * nu)
    alpha2_at_t_star = nu * nu / ((1.0 - nu) * (1.0 - 3.0 * nu))

    def g(u):
        e_u = np.exp(u)
        t = t_star * (1.0 + e_u)
        alpha = np.sqrt(alpha2_at_t_star + gamma * t_star * e_u)
        beta = np.sqrt(t - 1.0)
        return alpha * (t - 2.0 + 2.0 * alpha * beta) / (four_gamma_minus_one * t_star * e_u)

    return t_star, g


def _upper_double_root(nu: float) -> tuple[float, float]:
    """(f_upper, s_upper): minimum of g over s > s_* and where it is attained (0 < nu < 1/3).

    g is unimodal there (+inf at both ends); a grid in u brackets the minimum, Brent refines it.
    """
    t_star, g = _edge_function_upper(nu)
    u = np.linspace(-80.0, 40.0, 1201)
    i = int(np.argmin(g(u)))
    lo, hi = u[max(i - 1, 0)], u[min(i + 1, u.size - 1)]
    res = minimize_scalar(g, bounds=(lo, hi), method="bounded", options={"xatol": 1e-12})
    if not res.success:
        raise RuntimeError(f"minimisation of the edge function failed for nu = {nu}: {res.message}")
    return float(res.fun), math.sqrt(t_star * (1.0 + math.exp(res.x)))


def flutter_boundary(nu: float) -> tuple[float, float]:
    """Range (f_lower, f_upper) of the Coulomb coefficient with growing surface roots.

    f_lower = 1 (exact; Renardy's threshold, root crossing at c = sqrt(2) c_s) for 0 < nu < 1/2;
    f_upper = min_{s > s_*} s^2 alpha / (2 - s^2 + 2 alpha beta) for 0 < nu < 1/3 (double
    supersonic neutral root), math.inf for 1/3 <= nu < 1/2. (nan, nan) at nu = 0: no instability.
    The open interval f_lower < f < f_upper is unstable; see the module docstring for the proof.
    """
    nu = _check_nu(nu)
    if nu == 0.0:
        return (math.nan, math.nan)
    if nu >= NU_WEDGE_OPEN:
        return (THRESHOLD_F, math.inf)
    return (THRESHOLD_F, _upper_double_root(nu)[0])


def inside_wedge(nu: float, f: float) -> bool:
    """Whether (nu, f) lies strictly inside the flutter wedge, f_lower < f < f_upper (False at
    nu = 0, where there is no instability)."""
    lower, upper = flutter_boundary(nu)
    return bool(math.isfinite(lower) and lower < f < upper)


def boundary_speeds(nu: float) -> tuple[float, float]:
    """Speeds c/c_s of the neutral root at (f_lower, f_upper): (sqrt(2), s_upper).

    s_upper > c_l/c_s (supersonic) for 0 < nu < 1/3; nan for nu >= 1/3 (root tends to i*y_inf);
    (nan, nan) at nu = 0.
    """
    nu = _check_nu(nu)
    if nu == 0.0:
        return (math.nan, math.nan)
    if nu >= NU_WEDGE_OPEN:
        return (THRESHOLD_SPEED, math.nan)
    return (THRESHOLD_SPEED, _upper_double_root(nu)[1])
