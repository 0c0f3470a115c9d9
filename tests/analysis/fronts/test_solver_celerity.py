"""The direction and speed of the slip pulses of real runs, measured by the project's one cross-correlation
estimator (`analysis.fronts.xcorr`) on the slip-velocity map of every step: the smoke cases of
tests/solver/smoke_test.cpp (which checks the rest of those runs: slip, opening, T/N).

    nu = 0.2,  f = 1.5, H/16: pulses run in +x, intersonic (c_s < c < c_l);
    nu = 0.2,  f = 0.7, H/16: pulses run in +x, no opening;
    nu = 0.45, f = 1.0, H/32: pulses run in -x, supersonic (|c| > c_l) (H/16 does not resolve it).

The window is from the first slipping row to the end of the run. About 5 s with the Release solver."""
import json
import math
import subprocess

import numpy as np
import pytest

from analysis.core.io import load_run
from analysis.fronts.xcorr import celerity_by_xcorr
from solver_runs import solver_or_skip

SLIP = 2  # ContactState::slip in /interface/state


def run_case(folder, nu, f, elements_per_H, t_end):
    config = {"material": {"nu": nu}, "friction": {"f": f}, "mesh": {"elements_per_H": elements_per_H},
              "time": {"t_end": t_end}, "output": {"interface_stride": 1, "progress": "never"}}
    (folder / "config.json").write_text(json.dumps(config))
    subprocess.run([str(solver_or_skip()), "run", str(folder / "config.json"), "-o", str(folder / "run.h5")],
                   check=True, capture_output=True, timeout=600)
    return load_run(folder / "run.h5")


def measured_celerity(run):
    """xcorr celerity (m/s) over the rows from the first slip on."""
    interface = run.interface
    slipping = np.flatnonzero((interface.state == SLIP).any(axis=1))
    assert slipping.size > 0, "the interface must slip"
    window = (float(interface.t[slipping[0]]), float(interface.t[-1]))
    result = celerity_by_xcorr(interface.x, interface.t, interface.slip_velocity, window)
    assert math.isfinite(result.celerity)
    return result.celerity


@pytest.mark.parametrize("nu, f, elements_per_H, t_end, direction, speed", [
    (0.2, 1.5, 16, 1300.0, +1, "intersonic"),
    (0.2, 0.7, 16, 1360.0, +1, None),
    (0.45, 1.0, 32, 3340.0, -1, "supersonic"),
])
def test_pulses_run_as_the_regime_says(tmp_path, nu, f, elements_per_H, t_end, direction, speed):
    run = run_case(tmp_path, nu, f, elements_per_H, t_end)
    assert run.complete
    c, c_s, c_l = measured_celerity(run), run.attr("c_s"), run.attr("c_l")
    assert np.sign(c) == direction, f"celerity {c:.3f} m/s"
    if speed == "intersonic":
        assert c_s < abs(c) < c_l, f"celerity {c:.3f} m/s, c_s {c_s:.3f}, c_l {c_l:.3f}"
    if speed == "supersonic":
        assert abs(c) > c_l, f"celerity {c:.3f} m/s, c_l {c_l:.3f}"
