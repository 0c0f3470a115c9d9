"""One wavenumber of the interface, measured from a run and placed against interface-wave theory.

The runs of the checks (issue 24 item 5, docs/substrate.md "Checks against the theory") seed one mode
of wavenumber ``k = 2 pi m / lambda`` (config group ``mode_seed``). Projecting an interface field on
``exp(-i k x)`` gives the complex amplitude ``a(t)`` of that wavenumber; a wave ``cos(k (x - c t))``
contributes ``exp(-i k c t) / 2``, so

* a **frictionless** pair (``interface_wave_speed``): the spectrum of ``a(t)`` over the phase speed
  ``c = -omega / k`` has a peak at ``+-c_gR`` (the seed is a standing pattern: both directions) when the
  pair carries a generalized Rayleigh wave, and none below the slower shear speed when it does not (a
  trapped interface wave is the only wave slower than both shear speeds; the layers' guided modes are
  faster). The peak is located on a Hann-windowed, zero-padded spectrum, refined by a parabola through
  the logarithm of its three highest samples.
* **Coulomb sliding** (``mode_growth``): each mode of the pair at wavenumber k contributes
  ``exp(-i k c t)`` with complex ``c``: a pole ``s = -i k c`` of a(t), whose real part ``k Im c`` is the
  growth rate (1/s) and whose imaginary part gives the phase speed ``Re c`` (+ = +x = the layer's slip
  direction). The poles are found by the matrix pencil method, so that the growing interface mode is
  measured even where the finite bodies' other modes at the same k are as large.

Theory alongside: ``analysis.theory.interface_wave`` (c_gR), ``analysis.theory.bimaterial_stability``
(growing roots), from the run's own constants (``/setup``).
"""

from __future__ import annotations

import math

import numpy as np

from analysis.core.errors import InputError
from analysis.core.io import RunData

__all__ = ["mode_amplitude", "phase_speed_spectrum", "interface_wave_speed", "exponential_poles", "mode_growth",
           "run_solids", "TRAPPED_RATIO", "POLE_ORDER", "SIGNIFICANT"]

#: A peak below the slower shear speed is a trapped wave when it is at least this fraction of the
#: spectrum's maximum (the Hann window's side lobes are below 0.03).
TRAPPED_RATIO = 0.1
#: Zero padding of the spectrum (a sample every main-lobe width / 128).
_PADDING = 64
#: Exponentials fitted to a sliding run's mode amplitude: enough for the finite bodies' fast guided modes
#: besides the interface mode (the checks move by < 0.3 % between 16 and 32 at hht_alpha 0.1; at
#: hht_alpha 0, which damps those modes less, 10 and 16 are too few there, 24 and 32 agree).
POLE_ORDER = 24
#: A pole counts when its amplitude at the end of the window is at least this fraction of the largest.
SIGNIFICANT = 0.01


def run_solids(run: RunData):
    """(layer, substrate) as ``ElasticSolid`` from the run's constants; InputError without a substrate."""
    from analysis.theory.interface_wave import ElasticSolid

    if not run.has_substrate:
        raise InputError(f"{run.path}: no substrate (format_version 2): the interface-mode check needs one")
    return (ElasticSolid(run.attr("E"), run.attr("nu"), run.attr("rho")),
            ElasticSolid(run.attr("substrate_E"), run.attr("substrate_nu"), run.attr("substrate_rho")))


def mode_amplitude(run: RunData, mode: int, field: str) -> tuple[np.ndarray, np.ndarray, float]:
    """(t, a(t), k): the complex amplitude of wavenumber k = 2 pi mode / lambda in an interface field,
    a(t) = (2 / n_c) sum_x field(t, x) exp(-i k x) (s, field units, 1/m)."""
    values = getattr(run.interface, field, None)
    if field == "state" or values is None:
        raise InputError(f"--field {field!r}: not an interface field of numbers (slip_velocity, slip, opening, "
                         "normal_traction, tangential_traction)")
    n_c = run.interface.x.size
    if not 1 <= mode < n_c / 2:
        raise InputError(f"--mode {mode}: allowed an integer in [1, {math.ceil(n_c / 2) - 1}] for {n_c} nodes")
    k = 2.0 * math.pi * mode / run.attr("lambda")
    phase = np.exp(-1j * k * run.interface.x)
    return run.interface.t, (2.0 / n_c) * (np.asarray(values, dtype=float) @ phase), k


def _window(t: np.ndarray, start: float | None, end: float | None) -> np.ndarray:
    chosen = np.ones(t.size, dtype=bool)
    if start is not None:
        chosen &= t >= start
    if end is not None:
        chosen &= t <= end
    return chosen


def phase_speed_spectrum(t: np.ndarray, a: np.ndarray, k: float) -> tuple[np.ndarray, np.ndarray, float]:
    """(c, |A(c)|, lobe): Hann-windowed spectrum of a(t) on uniform t as a function of the phase speed
    c = -omega / k (m/s, increasing), normalized to max 1, and the half-width of the window's main lobe
    in c (m/s; two frequency bins)."""
    dt = float(np.median(np.diff(t)))
    if not np.allclose(np.diff(t), dt, rtol=1e-6):
        raise InputError("the interface output is not uniformly spaced in time")
    n = t.size
    window = np.hanning(n)
    spectrum = np.abs(np.fft.fftshift(np.fft.fft((a - a.mean()) * window, n * _PADDING)))
    omega = 2.0 * math.pi * np.fft.fftshift(np.fft.fftfreq(n * _PADDING, dt))
    c = -omega[::-1] / k
    lobe = 2.0 * (2.0 * math.pi / (n * dt)) / k
    return c, spectrum[::-1] / spectrum.max(), lobe


def _refined_peak(c: np.ndarray, amplitude: np.ndarray, i: int) -> float:
    """Vertex of the parabola through log amplitude at i - 1, i, i + 1."""
    y0, y1, y2 = np.log(amplitude[i - 1:i + 2])
    curvature = y0 - 2.0 * y1 + y2
    shift = 0.5 * (y0 - y2) / curvature if curvature < 0.0 else 0.0
    return float(c[i] + shift * (c[1] - c[0]))


def interface_wave_speed(run: RunData, mode: int = 1, field: str = "slip",
                         start: float | None = None, end: float | None = None) -> dict:
    """The interface wave of a frictionless run, measured, with the theory's speed.

    Returns a dict: ``k`` (1/m); ``c_min`` (m/s, the slower shear speed); ``band_edge`` (m/s: a trapped peak
    lies below it, c_min less one and a half main-lobe half-widths); ``trapped`` (bool: the highest local
    maximum of the spectrum with |c| < band_edge reaches ``TRAPPED_RATIO`` of the maximum);
    ``trapped_ratio`` (its height, 0 without one); ``speed_plus``, ``speed_minus`` (m/s, the highest
    peak of each sign below band_edge, None without one or when nothing is trapped; their mean magnitude
    is ``speed``); ``theory`` (c_gR in m/s, None without a generalized Rayleigh wave) and
    ``relative_error`` (speed / theory - 1).
    """
    from analysis.theory.interface_wave import generalized_rayleigh_speed

    if run.attr("f") != 0.0:
        raise InputError(f"{run.path}: friction.f = {run.attr('f'):g}; the interface-wave check needs f = 0")
    layer, substrate = run_solids(run)
    t, a, k = mode_amplitude(run, mode, field)
    chosen = _window(t, start, end)
    if chosen.sum() < 16:
        raise InputError(f"{run.path}: {int(chosen.sum())} output times in the window; at least 16 needed")
    c, amplitude, lobe = phase_speed_spectrum(t[chosen], a[chosen], k)
    c_min = min(layer.c_s, substrate.c_s)
    band_edge = c_min - 1.5 * lobe
    peaks = np.flatnonzero((amplitude[1:-1] > amplitude[:-2]) & (amplitude[1:-1] >= amplitude[2:])) + 1
    speeds = {}
    for sign in (+1, -1):
        inside = [i for i in peaks if 0.0 < sign * c[i] < band_edge]
        speeds[sign] = max(inside, key=lambda i: amplitude[i]) if inside else None
    found = [i for i in speeds.values() if i is not None]
    ratio = float(max(amplitude[i] for i in found)) if found else 0.0
    if ratio < TRAPPED_RATIO:  # side lobes, not a wave
        speeds = {+1: None, -1: None}
    speed_plus = _refined_peak(c, amplitude, speeds[+1]) if speeds[+1] is not None else None
    speed_minus = _refined_peak(c, amplitude, speeds[-1]) if speeds[-1] is not None else None
    magnitudes = [abs(s) for s in (speed_plus, speed_minus) if s is not None]
    speed = float(np.mean(magnitudes)) if magnitudes else None
    theory = generalized_rayleigh_speed(layer, substrate)
    return {"k": k, "c_min": c_min, "band_edge": band_edge, "trapped": ratio >= TRAPPED_RATIO,
            "trapped_ratio": ratio, "speed_plus": speed_plus, "speed_minus": speed_minus, "speed": speed,
            "theory": theory,
            "relative_error": None if speed is None or theory is None else speed / theory - 1.0}


def exponential_poles(t: np.ndarray, a: np.ndarray, order: int) -> tuple[np.ndarray, np.ndarray]:
    """(s, amplitude): a(t) ~ sum_j amplitude_j exp(s_j (t - t_0)) on uniform t, by the matrix pencil method
    (Hua & Sarkar 1990): the Hankel matrix of a, its rank-`order` signal subspace, the poles z_j = exp(s_j dt)
    as the eigenvalues of the shifted subspace, the amplitudes by least squares. s in 1/s (complex)."""
    dt = float(t[1] - t[0])
    if not np.allclose(np.diff(t), dt, rtol=1e-6):
        raise InputError("the interface output is not uniformly spaced in time")
    n = a.size
    width = n // 3
    hankel = np.lib.stride_tricks.sliding_window_view(a, width + 1)
    row_space = np.linalg.svd(hankel, full_matrices=False)[2][:order].T  # rows of hankel = combinations of these
    z = np.linalg.eigvals(np.linalg.pinv(row_space[:-1]) @ row_space[1:])
    s = np.log(z) / dt
    amplitude = np.linalg.lstsq(np.exp(np.outer(t - t[0], s)), a, rcond=None)[0]
    return s, amplitude


def mode_growth(run: RunData, mode: int = 1, field: str = "slip_velocity", start: float | None = None,
                end: float | None = None, order: int = POLE_ORDER) -> dict:
    """Growth rate and phase speed of the growing interface mode of a sliding run, with the theory's root.

    a(t) on the window [start, end] (s) is decomposed into ``order`` exponentials (``exponential_poles``);
    each pole s = -i k c gives a phase speed Re c = -Im(s) / k (m/s, + = +x, the layer's slip direction) and
    a growth rate Re s (1/s). The interface mode is the fastest-growing pole slower than both P waves
    (|Re c| < min(c_l1, c_l2)) whose amplitude at the end of the window is at least ``SIGNIFICANT`` of the
    largest: the finite bodies' guided modes, faster than that, are no part of the half-space theory.

    Returns a dict: ``k`` (1/m), ``f``, ``growth_rate`` (1/s) and ``phase_speed`` (m/s) of that pole
    (None without one), ``growth_per_k`` (growth_rate / k, m/s, to compare with Im c), ``poles`` (every pole:
    growth_rate, phase_speed, relative amplitude at the window's end), and the theory's growing roots
    below the same speed: ``theory_growth_rate`` (k Im c of the fastest, 1/s; 0 without one) and
    ``theory_phase_speed`` (its Re c, m/s; None without one).
    """
    from analysis.theory.bimaterial_stability import growing_roots

    layer, substrate = run_solids(run)
    t, a, k = mode_amplitude(run, mode, field)
    chosen = _window(t, start, end)
    if chosen.sum() < 3 * order + 3:
        raise InputError(f"{run.path}: {int(chosen.sum())} output times in the window; at least "
                         f"{3 * order + 3} needed for {order} poles")
    t, a = t[chosen], a[chosen]
    s, amplitude = exponential_poles(t, a, order)
    at_end = np.abs(amplitude * np.exp(s.real * (t[-1] - t[0])))
    at_end = at_end / at_end.max()
    subsonic = min(layer.c_l, substrate.c_l)
    speeds = -s.imag / k
    candidates = [j for j in range(s.size) if abs(speeds[j]) < subsonic and at_end[j] >= SIGNIFICANT]
    best = max(candidates, key=lambda j: s[j].real) if candidates else None
    roots = [c for c in growing_roots(layer, substrate, run.attr("f")) if abs(c.real) < subsonic]
    top = max(roots, key=lambda c: c.imag) if roots else None
    order_of_growth = np.argsort(-s.real)
    return {"k": k, "f": run.attr("f"),
            "growth_rate": None if best is None else float(s[best].real),
            "phase_speed": None if best is None else float(speeds[best]),
            "growth_per_k": None if best is None else float(s[best].real / k),
            "poles": [{"growth_rate": float(s[j].real), "phase_speed": float(speeds[j]),
                       "amplitude_at_end": float(at_end[j])} for j in order_of_growth],
            "theory_growth_rate": 0.0 if top is None else float(k * top.imag),
            "theory_phase_speed": None if top is None else float(top.real)}
