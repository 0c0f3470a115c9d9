"""A command-line config of the wrong type names the key and the expected type (study/config_overrides.py),
never a bare TypeError from Snakemake's merge."""

import pytest

from study.config_overrides import clashes

from .conftest import REPO, snakemake


def test_clashes_name_the_path_and_the_expected_type():
    study = {"model": {"E": 1000.0, "H": 25.0}, "sweeps": {"quick": {"points": []}}, "study": ["quick"]}
    assert clashes({"model": [1]}, study) == [
        "config key `model` must be a mapping (keys such as E, H), got a list: [1]"]
    assert clashes({"sweeps": {"quick": 3}}, study)[0].startswith("config key `sweeps.quick` must be a mapping")
    # Right types, new keys and non-mapping study values are the schema's business, not a clash.
    assert clashes({"model": {"E": 2.0}, "study": None, "sweeps": {"new": {"points": []}}}, study) == []


@pytest.mark.parametrize("override, key", [("sweeps=null", "sweeps"), ("model=[1]", "model"),
                                           ('sweeps={"quick": 3}', "sweeps.quick")])
def test_snakemake_reports_the_key_of_a_config_override_of_the_wrong_type(tmp_path, override, key):
    result = snakemake(tmp_path, "-n", "--config", override, check=False, timeout=300)
    assert result.returncode != 0
    assert f"config key `{key}` must be a mapping" in result.stderr + result.stdout
    assert "TypeError" not in result.stderr + result.stdout
    assert str(REPO / "study" / "config.yaml") in result.stderr + result.stdout
