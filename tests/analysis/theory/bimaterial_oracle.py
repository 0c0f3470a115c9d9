"""The matrix form of the sliding interface problem of analysis.theory.bimaterial_stability, built
from the potentials: the tests' independent oracle of its dispersion relation (eq. (3) there; its
roots make the 4x4 determinant vanish) and of the surface compliance (eq. (2)). Not production code:
the analysis uses the reduced scalar form.
"""

import numpy as np

from analysis.theory.bimaterial_stability import _check_f, _reduced_coupling
from analysis.theory.interface_wave import _as_solid, _q, reduced_rayleigh_function


def surface_compliance(c, solid, side: int) -> np.ndarray:
    """The 2x2 matrix C of eq. (2), mu k (u_x, u_y) = C (sigma_xy, sigma_yy) at y = 0 (dimensionless).

    Parameters
    ----------
    c : complex      phase speed (m/s), not a Rayleigh zero of the solid
    solid : ElasticSolid or (E, nu, rho)
    side : int       +1 for a body in y > 0, -1 for a body in y < 0
    """
    solid = _as_solid(solid)
    if side not in (1, -1):
        raise ValueError(f"side = {side!r} outside the allowed range {{+1, -1}}")
    s = complex(c) / solid.c_s
    q_l, q_s = (complex(q) for q in _q(s, solid.gamma))
    r = complex(reduced_rayleigh_function(s, solid.gamma))
    n = complex(_reduced_coupling(s, solid.gamma))
    return np.array([[side * q_s, -1j * n], [1j * n, side * q_l]], dtype=complex) / r


def boundary_matrix(c, solid, side: int, k: float = 1.0) -> np.ndarray:
    """Rows (u_x, u_y, sigma_xy, sigma_yy) at y = 0 per unit potential amplitudes (A, B) (4x2).

    phi = A exp(i k (x - c t) - side k q_l y), psi = B exp(i k (x - c t) - side k q_s y), with
    u_x = phi_x + psi_y, u_y = phi_y - psi_x and Hooke's law (lambda = mu (1/gamma - 2)):

        u_x = k (i A - side q_s B),                u_y = -k (side q_l A + i B),
        sigma_xy = mu k^2 (-2 i side q_l A + (2 - s^2) B),
        sigma_yy = mu k^2 ((2 - s^2) A + 2 i side q_s B).

    Units: u in m per (m^2 of A, B), sigma in Pa per m^2; k in 1/m, c in m/s.
    """
    solid = _as_solid(solid)
    s = complex(c) / solid.c_s
    q_l, q_s = (complex(q) for q in _q(s, solid.gamma))
    mu_k2 = solid.shear_modulus * k * k
    b = 2.0 - s * s
    return np.array([
        [1j * k, -side * k * q_s],
        [-side * k * q_l, -1j * k],
        [-2j * side * q_l * mu_k2, b * mu_k2],
        [b * mu_k2, 2j * side * q_s * mu_k2],
    ], dtype=complex)


def interface_matrix(c, upper, lower, f: float, k: float = 1.0) -> np.ndarray:
    """4x4 matrix of conditions (1) on the amplitudes (A_1, B_1, A_2, B_2) (m^2).

    Rows, all of the form k^2 x (amplitude), dimensionless: k (u_y(1) - u_y(2));
    (sigma_yy(1) - sigma_yy(2)) / (mu_1 k); (sigma_xy(1) - sigma_xy(2)) / (mu_1 k);
    (sigma_xy(1) + f sigma_yy(1)) / (mu_1 k). With f = 0 it is the frictionless problem of
    ``analysis.theory.interface_wave``. An independent oracle of eq. (3): det = 0 at its roots.
    """
    upper, lower = _as_solid(upper), _as_solid(lower)
    f = _check_f(f)
    one, two = boundary_matrix(c, upper, +1, k), boundary_matrix(c, lower, -1, k)
    zero = np.zeros(2, dtype=complex)
    scale = 1.0 / (upper.shear_modulus * k)
    return np.array([
        np.concatenate([k * one[1], -k * two[1]]),
        np.concatenate([scale * one[3], -scale * two[3]]),
        np.concatenate([scale * one[2], -scale * two[2]]),
        np.concatenate([scale * (one[2] + f * one[3]), zero]),
    ])
