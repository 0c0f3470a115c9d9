"""paper/make_claims.py on small hand-written sweep tables: a verdict per claim with its numbers, the
headline count with its tolerance and window sensitivity, "not testable here" for a table not built,
and an error for a table that lacks a column."""
import csv
import json

import pytest

from figure_support import PAPER, ROOT, command

CLAIMS = ROOT / "study" / "reference" / "claims.json"
TABLE1 = ("nu", "f", "celerity", "published", "deviation_rel", "sign_match", "regime_match", "category_match",
          "regime", "published_regime", "category", "celerity_window_sensitivity")


def write(path, rows):
    columns = list(dict.fromkeys(k for r in rows for k in r))
    with open(path, "w", newline="") as stream:
        writer = csv.DictWriter(stream, columns)
        writer.writeheader()
        writer.writerows(rows)
    return path


def table1_row(nu, f, celerity, published, sensitivity=0.0, regime="intersonic", published_regime="intersonic"):
    return {"nu": nu, "f": f, "celerity": celerity, "published": published,
            "deviation_rel": (celerity - published) / abs(published), "sign_match": "true",
            "regime_match": str(regime == published_regime).lower(), "category_match": "true",
            "regime": regime, "published_regime": published_regime, "category": "intersonic_opening_inversion",
            "celerity_window_sensitivity": sensitivity}


@pytest.fixture
def tables(tmp_path):
    """{name: path} of one table per name make_claims.py knows."""
    t = {}
    # Deviations +3.5, -4.5, +5.5, +0.5 %; the last with a window that reaches 6 %.
    t["table1"] = write(tmp_path / "table1.csv", [
        table1_row(0.2, 1.2, 1.035, 1.0), table1_row(0.2, 1.5, 0.955, 1.0), table1_row(0.3, 1.5, 1.055, 1.0),
        table1_row(0.1, 1.2, 1.005, 1.0, sensitivity=0.055),
        table1_row(0.0, 2.0, 0.9, 1.2, regime="intersonic", published_regime="supersonic")])
    grid = [{"nu": 0.2, "f": f, "category": "intersonic_opening_inversion", "celerity": c, "celerity_over_cs": c / 0.645,
             "below_sqrt2_cs": str(c / 0.645 < 2 ** 0.5).lower(), "opening": "true", "inversion": "true",
             "dissipative_friction_opening": 0.2 * f, "dissipative_friction_before_opening": 0.7 * f,
             "elements_per_H": 64} for f, c in ((1.2, 0.85), (1.5, 0.93))]
    t["grid"] = write(tmp_path / "grid.csv", grid)
    t["period"] = write(tmp_path / "period.csv", [{"lambda_over_H": p, "seed": 1, "pulse_count": n}
                                                  for p, n in ((2, 2), (4, 2), (6, 3))])
    t["mesh"] = write(tmp_path / "mesh.csv", [{"elements_per_H": n, "celerity": c, "category": "intersonic_opening",
                                              "pulse_count": 1} for n, c in ((32, 0.86), (64, 0.81), (128, 0.83))])
    t["timestep"] = write(tmp_path / "timestep.csv", [
        {"nu": 0.2, "f": 1.5, "dt_times_cs": d, "celerity": c, "category": "intersonic_opening"}
        for d, c in ((0.25, 0.826), (0.5, 0.811))])
    t["shear_rate"] = write(tmp_path / "shear.csv", [
        {"V0_over_cs": v, "inversion": "true", "min_T_over_N": -0.4, "first_drop_start_after_onset": s}
        for v, s in ((1e-6, 83.0), (1e-4, 96.0))])
    t["density"] = write(tmp_path / "density.csv", [{"rho": r, "celerity_over_cs": 1.25, "min_T_over_N": -0.3}
                                                    for r in (0.1, 1000)])
    t["long"] = write(tmp_path / "long.csv", [{"seed": 1, "n_drops": 3, "later_drops_start_T_over_N_median": 0.65}])
    return t


def run(tmp_path, tables, *extra):
    args = [f"--table={name}={path}" for name, path in tables.items()]
    out = tmp_path / "out"
    result = command(PAPER / "make_claims.py", "--claims", CLAIMS, "--tolerance", "0.05", *args, *extra,
                     "-o", out / "claims.tex", "--conclusions", out / "conclusions.tex", "--json", out / "claims.json")
    return result, out


def verdicts(out):
    return {c["claim"]: c for c in json.loads((out / "claims.json").read_text())["claims"]}


def test_every_claim_gets_a_verdict_with_its_numbers(tmp_path, tables):
    result, out = run(tmp_path, tables)
    assert result.returncode == 0, result.stderr
    v = verdicts(out)
    assert set(v) == set(json.loads(CLAIMS.read_text())["claims"])
    assert v["nu0_f2"]["verdict"] == "not reproduced" and "intersonic" in v["nu0_f2"]["reason"]
    assert v["density"]["verdict"] == "not testable here" and "by construction" in v["density"]["reason"]
    assert v["pulses"]["verdict"] == "not reproduced"  # 2 pulses at lambda/H = 2 against the paper's 1
    assert v["long"]["verdict"] == "partly" and "paper $1$" in v["long"]["reason"]
    assert v["timestep"]["verdict"] == "reproduced"
    table = (out / "claims.tex").read_text()
    assert table.count(r"\addlinespace") == len(v) and r"\label{tab:claims}" in table
    conclusions = (out / "conclusions.tex").read_text()
    assert "Where the numbers contradict the paper" in conclusions and r"\ref{tab:claims}" in conclusions


def test_the_headline_count_comes_with_its_sensitivity(tmp_path, tables):
    result, out = run(tmp_path, tables)
    assert result.returncode == 0, result.stderr
    head = json.loads((out / "claims.json").read_text())["headline"]
    # |deviation| 3.5, 4.5, 5.5, 0.5 and 25 %: within 4 % two, 5 % three, 6 % four.
    assert head["within"] == {"0.04": 2, "0.05": 3, "0.06": 4}
    # The +0.5 % cell's window reaches +-5.6 %: it straddles; 3.5 % and -4.5 % are inside (no window).
    assert head["window"] == {"inside": 2, "straddles": 1, "outside": 2, "unknown": 0}
    assert "18 at" not in (out / "conclusions.tex").read_text()
    assert "2 at $4$\\,\\%, 3 at $5$\\,\\%, 4 at $6$\\,\\%" in (out / "conclusions.tex").read_text()


def test_a_table_not_built_makes_its_claims_not_testable(tmp_path, tables):
    del tables["period"]
    tables["long"] = tmp_path / "absent" / "all_metrics.csv"
    result, out = run(tmp_path, tables)
    assert result.returncode == 0, result.stderr
    v = verdicts(out)
    for claim, table in (("pulses", "period"), ("long", "long")):
        assert v[claim]["verdict"] == "not testable here"
        assert v[claim]["reason"].startswith(f"table \\texttt{{{table}}} not built")
    assert "absent/all" in v["long"]["reason"]


def test_a_sign_flip_at_another_mesh_is_no_reproduction(tmp_path, tables):
    rows = list(csv.DictReader(open(tables["table1"])))
    flipped = [dict(r, celerity=-float(r["celerity"])) if r["nu"] == "0.2" and r["f"] == "1.2" else r for r in rows]
    mesh = write(tmp_path / "h32.csv", flipped)
    result, out = run(tmp_path, tables, f"--mesh-table=H/32={mesh}")
    assert result.returncode == 0, result.stderr
    head = json.loads((out / "claims.json").read_text())["headline"]
    assert head["reproduced"]["0.05"] == 3 and head["reproduced_sign_stable"] == 2


def test_a_table_without_a_needed_column_is_an_error(tmp_path, tables):
    tables["mesh"] = write(tmp_path / "bad.csv", [{"elements_per_H": 32, "celerity": 0.8}])
    result, _ = run(tmp_path, tables)
    assert result.returncode == 2 and "bad.csv" in result.stderr and "category" in result.stderr
    result, _ = run(tmp_path, {"nonsense": tables["grid"]})
    assert result.returncode == 2 and "unknown table name" in result.stderr
