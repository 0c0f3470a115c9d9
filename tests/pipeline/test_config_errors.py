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


# Issue 21 items 3, 6 and 9b: a value that would reach a run's name, a file name or a command, or the
# solver out of its range, is refused before anything runs, on one line naming the key (or the file,
# row and column) and the allowed values; no traceback, nothing left in the work directory.

def refused(workdir, *args):
    """stderr of a Snakemake call that must stop on the config; checks the common promises."""
    result = snakemake(workdir, "-c1", *args, env={"SLIDEWAVE_BIN": "/bin/false"}, check=False, timeout=300)
    output = result.stdout + result.stderr
    assert result.returncode != 0, output
    assert "Traceback" not in output and 'File "' not in output, output
    assert not (workdir / "PWNED").exists() and not (workdir / "results").exists(), output
    return result.stderr


def test_a_hostile_csv_row_is_refused_naming_file_row_and_column(tmp_path):
    work, rows, extra = tmp_path / "work", tmp_path / "points.csv", tmp_path / "evil.yaml"
    work.mkdir()
    rows.write_text("nu,f,integration\n0.2,1.5,reduced\n0.2,1.5,reduced;touch PWNED;#\n")
    extra.write_text(f"sweeps:\n  evil:\n    points_from_csv: {rows}\n    products: []\n")
    err = refused(work, "evil", "--until", "simulate", "--configfile", str(extra))
    assert (f"error: config key `sweeps.evil`: {rows}, row 3, column integration: 'reduced;touch PWNED;#' is "
            "not allowed; allowed: one of reduced, full, reduced_pure") in err


@pytest.mark.parametrize("override, message", [
    ("point={f: 1e999}", "config key `point.f` = inf: inf is greater than the maximum of 10; "
                         "allowed: a number in [0, 10]"),
    ("point={seed: 1e19}", "config key `point.seed` = 1e+19: 1e+19 is greater than the maximum of "
                           "9007199254740991; allowed: an integer in [0, 9007199254740991]"),
    ('paper={tables: {mesh: {sets: {"": mesh}, columns: ["celerity;touch PWNED"]}}}',
     "config key `paper.tables.mesh.columns[0]` = 'celerity;touch PWNED'"),
    ('paper={figures: {"f;touch PWNED": {sweep: mesh, figure: convergence}}}',
     "config key `paper.figures` = 'f;touch PWNED'"),
    ("reference={table: 'x;touch PWNED'}", "config key `reference.table` = 'x;touch PWNED'"),
    ("study=[unknown]", "config key `study[0]` = 'unknown': not a declared sweep; allowed: table1, shear_rate"),
])
def test_an_impossible_or_hostile_value_names_the_key_and_the_allowed_values(tmp_path, override, message):
    work = tmp_path / "work"
    work.mkdir()
    err = refused(work, "explore" if override.startswith("point") else "all", "--config", override)
    assert f"error: {message}" in err, err
