"""analysis/theory/contrast_theory.py: the theory at the points of a contrast sweep (cheap contrasts only:
a near-rigid substrate's threshold takes ~30 s)."""
import math

import pytest

from analysis.theory import flutter
from analysis.theory.contrast_theory import COLUMNS, contrast_theory_rows


def test_rigid_flat_identical_bodies_and_a_generalized_rayleigh_pair():
    rows = contrast_theory_rows([(0.2, None, 1.5), (0.2, 1.0, 1.5), (0.2, 1.5, 0.5), (0.2, 1.5, 1.0)])
    assert all(set(row) <= set(COLUMNS) for row in rows)
    rigid, identical, rayleigh, rayleigh_f1 = rows
    # Rigid flat: the flutter wedge (1, f_upper), no backward family.
    assert rigid["f_threshold_forward"] == 1.0 and rigid["f_upper"] == pytest.approx(flutter.flutter_boundary(0.2)[1])
    assert rigid["f_threshold_backward"] == math.inf and rigid["unstable"] is True
    # Identical bodies: stable at every f (docs/bimaterial-theory.md section 5).
    assert identical["f_threshold"] == math.inf and identical["unstable"] is False
    assert identical["c_gR_over_cs1"] == pytest.approx(0.910996, abs=1e-6)
    # E_s/E = 1.5: a generalized Rayleigh wave, unstable for every f > 0; its mode runs at ~0.985 c_s1 in +x.
    assert rayleigh["f_threshold_forward"] == 0.0 and rayleigh["f_threshold_backward"] == pytest.approx(2.06, abs=0.01)
    assert rayleigh["family"] == "forward" and rayleigh["phase_speed_over_cs1"] == pytest.approx(0.9854, abs=1e-3)
    assert rayleigh_f1["growth_rate_per_k_over_cs1"] == pytest.approx(0.0530, abs=1e-3)


@pytest.mark.parametrize("point", [(0.5, 1.0, 1.0), (0.2, 0.0, 1.0), (0.2, 1.0, 0.0), (0.2, -3.0, 1.0)])
def test_bad_points_are_refused(point):
    with pytest.raises(ValueError, match="allowed range"):
        contrast_theory_rows([point])
