"""analysis/confidence/mesh_limit.py: the Richardson rule of docs/mesh-limit.md against hand-computed limits,
every status, the verdict's counts, and the CLI's outputs and errors."""

import csv
import json
import math

import pytest

from analysis import cli
from analysis.confidence import mesh_limit
from analysis.tables.reference import ReferenceCell

REFERENCE = [ReferenceCell(0.2, 1.5, 1.0), ReferenceCell(0.45, 1.0, -2.5), ReferenceCell(0.3, 1.1, 0.86)]


def run(nu, f, celerity, seed=1, reason="ok"):
    return {"nu": nu, "f": f, "seed": float(seed), "celerity": celerity, "celerity_reason": reason}


def test_limit_of_a_geometric_sequence_is_its_sum():
    # c_N = 1 - 0.08 (32/N)^1: differences 0.04, 0.02 -> r = 0.5, p = 1, limit 1.0.
    fit = mesh_limit.richardson([0.92, 0.96, 0.98])
    assert fit["status"] == "limit"
    assert fit["ratio"] == pytest.approx(0.5) and fit["order"] == pytest.approx(1.0)
    assert fit["limit"] == pytest.approx(1.0) and fit["step"] == pytest.approx(0.02)
    # Order 2: differences 0.04, 0.01 -> limit 0.95 + 0.01/3.
    fit = mesh_limit.richardson([0.9, 0.94, 0.95])
    assert fit["order"] == pytest.approx(2.0) and fit["limit"] == pytest.approx(0.95 + 0.01 / 3)


def test_only_the_finest_three_meshes_count():
    assert mesh_limit.richardson([5.0, 0.92, 0.96, 0.98])["limit"] == pytest.approx(1.0)


@pytest.mark.parametrize("values, status", [
    ([0.9, 0.95, 0.93], "not monotone"),
    ([0.9, 0.9, 0.93], "not monotone"),
    ([0.9, 0.92, 0.95], "not converging"),
    ([0.5, 0.75, 1.0], "not converging"),
    ([0.9, None, 0.94], "incomplete"),
    ([-0.9, 0.92, 0.94], "incomplete"),
    ([0.9, 0.92], "incomplete"),
])
def test_statuses_without_a_limit(values, status):
    fit = mesh_limit.richardson(values)
    assert fit["status"] == status and fit["limit"] is None


def tables():
    return {
        32: [run(0.2, 1.5, 0.92), run(0.45, 1.0, -2.7), run(0.3, 1.1, 0.90)],
        64: [run(0.2, 1.5, 0.96), run(0.2, 1.5, 0.5, seed=2), run(0.45, 1.0, -2.6), run(0.3, 1.1, 0.88)],
        128: [run(0.2, 1.5, 0.98), run(0.45, 1.0, -2.65), run(0.3, 1.1, math.nan, reason="no_major_front")],
    }


def test_rows_use_seed_one_and_compare_with_the_published_value():
    rows = mesh_limit.mesh_limit_rows(tables(), {n: f"h{n}" for n in (32, 64, 128)}, REFERENCE, 0.05)
    first, backward, missing = rows
    assert first["c_64"] == 0.96  # seed 2's 0.5 is ignored
    assert first["status"] == "limit" and first["limit"] == pytest.approx(1.0)
    assert first["dev_64"] == pytest.approx(-0.04) and first["dev_limit"] == pytest.approx(0.0, abs=1e-12)
    assert first["published_closer_than_64"] is True and first["within_limit"] is True
    assert backward["status"] == "not monotone" and backward["dev_64"] == pytest.approx(-0.04)
    assert missing["status"] == "incomplete" and missing["c_128"] is None
    summary = mesh_limit.summarize(rows, 0.05)
    assert summary["cells_with_limit"] == 1 and summary["within_limit"] == 1
    assert summary["within_64"] == 3 and summary["within_64_of_limit_cells"] == 1
    assert summary["published_at_limit"] is False  # 1 within at the limit is not more than 1 at H/64
    assert "do not sit" in summary["verdict"]


def test_verdict_says_converged_when_the_limit_brings_cells_in():
    t = tables()
    # 0.84, 0.90, 0.93: r = 0.5, limit 0.96 = published; H/64 is 6 % low.
    t[64][0]["celerity"] = 0.90
    t[32][0]["celerity"] = 0.84
    t[128][0]["celerity"] = 0.93
    rows = mesh_limit.mesh_limit_rows(t, {n: "x" for n in t}, [ReferenceCell(0.2, 1.5, 0.96)], 0.05)
    assert rows[0]["limit"] == pytest.approx(0.96) and rows[0]["within_64"] is False
    summary = mesh_limit.summarize(rows, 0.05)
    assert summary["published_at_limit"] is True and "sit at the converged" in summary["verdict"]


def test_a_cell_missing_at_a_mesh_has_fewer_meshes():
    t = tables()
    t[128] = [r for r in t[128] if r["nu"] != 0.2]
    rows = mesh_limit.mesh_limit_rows(t, {n: "x" for n in t}, REFERENCE, 0.05)
    assert rows[0]["status"] == "fewer meshes" and rows[0]["limit"] is None


def test_two_seed_one_runs_of_a_cell_are_an_error():
    t = tables()
    t[64].append(run(0.2, 1.5, 0.97))
    with pytest.raises(mesh_limit.InputError, match="h64: two seed-1 runs of the cell nu=0.2 f=1.5"):
        mesh_limit.mesh_limit_rows(t, {32: "h32", 64: "h64", 128: "h128"}, REFERENCE, 0.05)


def write_table(path, rows):
    with open(path, "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def test_cli_writes_every_file_or_none(tmp_path, capsys):
    reference = tmp_path / "ref.csv"
    reference.write_text("nu,f,celerity_m_per_s\n0.2,1.5,1.0\n0.45,1.0,-2.5\n")
    args = []
    for n, rows in tables().items():
        write_table(tmp_path / f"h{n}.csv", rows)
        args += ["--mesh", f"{n}={tmp_path / f'h{n}.csv'}"]
    out = tmp_path / "out"
    assert cli.main(["mesh-limit"] + args + ["--reference", str(reference), "-o", str(out)]) == 0
    assert sorted(p.name for p in out.iterdir()) == ["mesh_limit.csv", "mesh_limit.md", "mesh_limit.tex",
                                                     "mesh_limit_summary.json"]
    summary = json.loads((out / "mesh_limit_summary.json").read_text())
    assert summary["meshes"] == [32, 64, 128] and summary["cells"] == 2
    bad = tmp_path / "bad"
    assert cli.main(["mesh-limit"] + args[:4] + ["--reference", str(reference), "-o", str(bad)]) == 2
    assert "at least three meshes" in capsys.readouterr().err and not bad.exists()
    with pytest.raises(SystemExit):
        cli.main(["mesh-limit", "--mesh", "x=1", "-o", str(bad)])
