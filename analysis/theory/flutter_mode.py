"""The surface solution (mode) of the flutter problem for a root of the secular equation.

The problem, the potentials and eq. (2) are stated in `analysis.theory.flutter`; this module builds the
complex displacement, velocity and stress fields of one root, e.g. to draw the unstable mode or to
check that it satisfies the sliding conditions (1).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from analysis.theory.flutter import _check_f, _check_nu, _wavenumbers, secular_determinant, speed_ratio_squared

__all__ = ["SurfaceMode", "reconstruct_field"]


@dataclass(frozen=True)
class SurfaceMode:
    """One surface solution of eq. (2): complex fields in SI units.

    Fields are complex; their real parts are solutions too (the Navier equations and conditions (1)
    have real coefficients).
    Arrays x, y, t broadcast; y >= 0 is the body.

    Attributes
    ----------
    c : complex            phase speed (m/s); growth rate k Im(c) (1/s)
    k : float              wavenumber (1/m), > 0
    q_l, q_s : complex     decay factors, Re > 0
    amplitude_p, amplitude_s : complex   potential amplitudes A, B (m^2)
    shear_modulus, lame_lambda : float   (Pa)
    density : float        (kg/m^3)
    """

    c: complex
    k: float
    q_l: complex
    q_s: complex
    amplitude_p: complex
    amplitude_s: complex
    shear_modulus: float
    lame_lambda: float
    density: float

    @property
    def growth_rate(self) -> float:
        """k Im(c) (1/s)."""
        return self.k * self.c.imag

    def _exponentials(self, x, y, t):
        x, y, t = (np.asarray(v, dtype=float) for v in (x, y, t))
        phase = 1j * self.k * (x - self.c * t)
        return np.exp(phase - self.k * self.q_l * y), np.exp(phase - self.k * self.q_s * y)

    def displacement(self, x, y, t) -> np.ndarray:
        """(u_x, u_y) (m), shape (2, *broadcast)."""
        e_l, e_s = self._exponentials(x, y, t)
        a, b, k = self.amplitude_p, self.amplitude_s, self.k
        return np.array([k * (1j * a * e_l - self.q_s * b * e_s), -k * (self.q_l * a * e_l + 1j * b * e_s)])

    def velocity(self, x, y, t) -> np.ndarray:
        """du/dt = -i k c u (m/s), shape (2, *broadcast)."""
        return -1j * self.k * self.c * self.displacement(x, y, t)

    def stress(self, x, y, t) -> np.ndarray:
        """(sigma_xx, sigma_yy, sigma_xy) (Pa), shape (3, *broadcast)."""
        e_l, e_s = self._exponentials(x, y, t)
        a, b, q_l, q_s = self.amplitude_p, self.amplitude_s, self.q_l, self.q_s
        mu_k2 = self.shear_modulus * self.k**2
        return mu_k2 * np.array([
            (q_s**2 - 1.0 - 2.0 * q_l**2) * a * e_l - 2j * q_s * b * e_s,
            (1.0 + q_s**2) * a * e_l + 2j * q_s * b * e_s,
            -2j * q_l * a * e_l + (1.0 + q_s**2) * b * e_s,
        ])


def reconstruct_field(
    root: complex,
    nu: float,
    f: float,
    *,
    wavenumber: float = 1.0,
    shear_modulus: float = 1.0,
    shear_speed: float = 1.0,
    slip_amplitude: float = 1.0,
) -> SurfaceMode:
    """The surface solution for a root of D (speed normalised by c_s).

    B = i q_l A (u_y = 0); A is scaled so that u_x(0, 0, 0) = slip_amplitude (m).

    Parameters
    ----------
    root : complex       c / c_s, a zero of D (checked: relative residual <= 1e-8)
    nu, f : float        Poisson's ratio [0, 0.5), Coulomb coefficient
    wavenumber : float   k (1/m), > 0
    shear_modulus : float  mu (Pa), > 0
    shear_speed : float  c_s (m/s), > 0; density = mu / c_s^2
    slip_amplitude : float  (m)

    Raises
    ------
    ValueError if ``root`` is not a zero of D, is the trivial zero c = 0, or does not decay.
    """
    nu, f = _check_nu(nu), _check_f(f)
    for name, value in (("wavenumber", wavenumber), ("shear_modulus", shear_modulus), ("shear_speed", shear_speed)):
        if not (math.isfinite(value) and value > 0.0):
            raise ValueError(f"{name} = {value!r} must be finite and > 0")
    s = complex(root)
    if abs(s) < 1e-6:
        raise ValueError("c = 0 is the trivial zero of D (null field), not a mode")
    residual = abs(secular_determinant(s, nu, f)) / (1.0 + abs(f) * (1.0 + abs(s) ** 2) + abs(s) ** 3)
    if residual > 1e-8:
        raise ValueError(f"c/c_s = {s} is not a root of D (relative residual {residual:.2e})")
    q_l, q_s = (complex(q) for q in _wavenumbers(s, nu))
    if q_l.real <= 0.0 or q_s.real <= 0.0:
        raise ValueError(f"c/c_s = {s} is a neutral (radiating) root: Re q = 0, no decay")
    gamma = speed_ratio_squared(nu)
    amplitude_p = slip_amplitude / (1j * wavenumber * (1.0 - q_l * q_s))
    density = shear_modulus / shear_speed**2
    return SurfaceMode(
        c=s * shear_speed,
        k=float(wavenumber),
        q_l=q_l,
        q_s=q_s,
        amplitude_p=amplitude_p,
        amplitude_s=1j * q_l * amplitude_p,
        shear_modulus=float(shear_modulus),
        lame_lambda=shear_modulus * (1.0 / gamma - 2.0),
        density=density,
    )
