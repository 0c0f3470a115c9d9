"""The solver against interface-wave theory (issue 24 item 5; docs/substrate.md, "Checks against the theory").

Runs the configs of interface_mode_configs/ (H/64 with a period of H/2, a substrate of the layer's
thickness; about a second each) and measures them with analysis.metrics.interface_mode. Every assertion
is against the theory's number (analysis.theory.interface_wave, analysis.theory.bimaterial_stability),
never against a number read off a run:

* frictionless pair E_s / E = 1.2 (nu 0.2): the interface wave runs at c_gR within 1 % (both ways); the
  pair E_s / E = 3, which has no generalized Rayleigh wave, shows no peak below the slower shear speed;
* Coulomb sliding, f = 1, seeded at mode 1 (k = 2 pi / (H / 2)): the growing mode's phase speed within
  1 % of the theory's root and in the direction it gives (+x, the layer's slip direction, on the stiffer
  substrate E_s / E = 1.2; -x on the softer one, 1 / 1.2), its growth rate within 10 %; mode 2 grows
  twice as fast (10 %); identical materials: nothing slower than the shear speed grows.

Self-contained: the solver is $SLIDEWAVE_BIN or <repo>/build/slidewave (missing: a failure, not a skip).
"""

import json
import math
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest
from synthetic_run import paper_case

from analysis import cli
from analysis.core.io import load_run
from analysis.metrics.interface_mode import exponential_poles, interface_wave_speed, mode_growth
from analysis.theory.interface_wave import ElasticSolid, rayleigh_speed_ratio

REPO = Path(__file__).resolve().parents[3]
SOLVER = Path(os.environ.get("SLIDEWAVE_BIN", REPO / "build" / "slidewave"))
CONFIGS = Path(__file__).resolve().parent / "interface_mode_configs"

#: The interface-wave speed (issue 24: 1 %). Measured 0.09 % at H/64 (0.76 % at H/32, -0.08 % at H/128).
SPEED_TOLERANCE = 0.01
#: Phase speed of the growing mode: measured within 0.3 % (both directions, modes 1 and 2).
PHASE_TOLERANCE = 0.01
#: Growth rate: measured within 0.3 % (mode 1, +x and -x), 2.7 % (mode 2, 16 elements a wavelength);
#: the pole fit alone moves it by up to 3 % between windows and orders, and the mesh's dispersion acts
#: on Im c, a small part of c: 10 % holds all of these.
GROWTH_TOLERANCE = 0.10
#: Fit windows (s): from the seed's transient to before the mode's slip-rate swing reaches a few % of
#: V0 (mode 2 grows twice as fast: half the times).
WINDOW = {1: (100.0, 650.0), 2: (50.0, 325.0)}


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """Runs every config of interface_mode_configs/ once; name -> RunData."""
    assert SOLVER.is_file(), f"no solver binary at {SOLVER}: build it (scripts/build.sh) or set SLIDEWAVE_BIN"
    folder = tmp_path_factory.mktemp("interface_mode")
    loaded = {}
    for config in sorted(CONFIGS.glob("*.json")):
        output = folder / f"{config.stem}.h5"
        result = subprocess.run([str(SOLVER), "run", str(config), "-o", str(output)], capture_output=True,
                                text=True, timeout=600, cwd=folder)
        assert result.returncode == 0, f"{config.name}: exit {result.returncode}: {result.stderr}"
        loaded[config.stem] = load_run(output)
    return loaded


def growth(run, mode=1):
    return mode_growth(run, mode, "slip_velocity", *WINDOW[mode])


# --- the measurement on synthetic signals (its sign conventions) -------------------------------------

def test_mode_projection_and_poles_give_the_direction_and_growth_of_a_travelling_wave():
    """A wave cos(k (x - c t)) e^(g t) plus a faster neutral one running the other way: the pole fit
    returns (g, +c) and (0, -c'), whatever their amplitudes."""
    k, c, g, c_other = 2 * math.pi / 12.5, 0.6, 0.01, 1.7
    x = np.arange(32) * 12.5 / 32
    t = np.arange(0.0, 600.0, 0.77)
    field = (1e-3 * np.cos(k * (x[None, :] - c * t[:, None])) * np.exp(g * t)[:, None]
             + np.cos(k * (x[None, :] + c_other * t[:, None])))
    a = (2.0 / x.size) * (field @ np.exp(-1j * k * x))
    s, amplitude = exponential_poles(t, a, 4)
    speeds = -s.imag / k
    strong = np.abs(amplitude) > 1e-6
    found = sorted(zip(speeds[strong], s.real[strong]))
    assert found[0] == pytest.approx((-c_other, 0.0), abs=1e-9)
    assert found[1] == pytest.approx((c, g), abs=1e-9)


# --- (a) the frictionless interface wave ---------------------------------------------------------------

def test_frictionless_interface_wave_runs_at_the_generalized_rayleigh_speed(runs):
    result = interface_wave_speed(runs["frictionless_wave"], 1, "slip")
    layer = ElasticSolid(1000.0, 0.2, 1000.0)
    # The check tells the pair from either body alone: c_gR is 4 % above the layer's Rayleigh speed.
    assert result["theory"] / (rayleigh_speed_ratio(0.2) * layer.c_s) - 1.0 > 0.04
    assert result["trapped"], result
    for speed in (result["speed_plus"], -result["speed_minus"]):
        assert speed / result["theory"] - 1.0 == pytest.approx(0.0, abs=SPEED_TOLERANCE), result


def test_pair_without_a_generalized_rayleigh_wave_traps_no_interface_wave(runs):
    result = interface_wave_speed(runs["frictionless_no_wave"], 1, "slip")
    assert result["theory"] is None
    assert not result["trapped"], result


# --- (b) the stability of steady Coulomb sliding -----------------------------------------------------

@pytest.mark.parametrize("name, direction", [("sliding_growth", +1), ("sliding_growth_mirror", -1)])
def test_growing_mode_has_the_theorys_speed_direction_and_growth(runs, name, direction):
    """E_s / E = 1.2: the layer is the more compliant body and the mode runs +x (its slip direction);
    E_s / E = 1 / 1.2: the substrate is, and the mode runs -x."""
    result = growth(runs[name])
    assert np.sign(result["theory_phase_speed"]) == direction
    assert result["phase_speed"] / result["theory_phase_speed"] - 1.0 == pytest.approx(0.0, abs=PHASE_TOLERANCE), \
        result
    assert result["growth_rate"] / result["theory_growth_rate"] - 1.0 == pytest.approx(0.0, abs=GROWTH_TOLERANCE), \
        result


def test_doubling_the_wavenumber_doubles_the_growth_rate(runs):
    one, two = growth(runs["sliding_growth"], 1), growth(runs["sliding_growth_mode2"], 2)
    assert two["k"] == pytest.approx(2.0 * one["k"])
    assert two["theory_growth_rate"] == pytest.approx(2.0 * one["theory_growth_rate"], rel=1e-9)
    assert two["growth_rate"] / one["growth_rate"] == pytest.approx(2.0, rel=GROWTH_TOLERANCE), (one, two)
    assert two["growth_rate"] / two["theory_growth_rate"] - 1.0 == pytest.approx(0.0, abs=GROWTH_TOLERANCE), two
    assert two["phase_speed"] / two["theory_phase_speed"] - 1.0 == pytest.approx(0.0, abs=PHASE_TOLERANCE), two


def test_identical_materials_grow_no_interface_mode(runs):
    """No coupling of slip and pressure: the theory has no growing root, and the run no growing pole
    slower than the shear speed (where the dissimilar pair's mode grows at rate `reference`). What
    grows at all is the grazing P wave (|c| ~ c_l), at a sixth of that rate (discretization)."""
    reference = growth(runs["sliding_growth"])["theory_growth_rate"]
    result = growth(runs["sliding_identical"])
    assert result["theory_growth_rate"] == 0.0 and result["theory_phase_speed"] is None
    c_s = runs["sliding_identical"].attr("c_s")
    slow = [p["growth_rate"] for p in result["poles"] if abs(p["phase_speed"]) < c_s and p["amplitude_at_end"] > 0.01]
    assert max(slow, default=-1.0) < 0.1 * reference, result["poles"]
    assert result["growth_rate"] < 0.25 * reference, result


def test_interface_mode_command_prints_the_measurement_and_the_theory(runs, tmp_path):
    path = runs["sliding_growth"].path
    result = subprocess.run(["/usr/bin/python3", "-m", "analysis", "interface-mode", str(path), "--start", "100",
                             "--end", "650"], capture_output=True, text=True, cwd=REPO, check=True)
    printed = json.loads(result.stdout)
    expected = growth(runs["sliding_growth"])
    assert printed["field"] == "slip_velocity"
    assert printed["growth_rate"] == pytest.approx(expected["growth_rate"], rel=1e-12)
    assert printed["theory_phase_speed"] == pytest.approx(expected["theory_phase_speed"], rel=1e-12)


def test_interface_mode_command_refuses_a_rigid_flat_run_and_a_mode_out_of_range(runs, run_file, capsys):
    assert cli.main(["interface-mode", str(run_file(paper_case()))]) == 2
    assert "no substrate" in capsys.readouterr().err
    assert cli.main(["interface-mode", str(runs["frictionless_wave"].path), "--mode", "16"]) == 2
    assert "--mode 16" in capsys.readouterr().err
