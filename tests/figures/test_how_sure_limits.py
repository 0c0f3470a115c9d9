"""The limits subsections of paper/how_sure.tex: their figures (mesh limit, backward celerity against
dt and against f) and paper/make_how_sure_limits.py, from the made-up inputs of
how_sure_limits_inputs.py."""
import json
import re

import pytest

from figure_support import PAPER, ROOT, assert_figure, call, command
from how_sure_inputs import write_csv
from how_sure_limits_inputs import write_generated_limits, write_limits


@pytest.fixture(scope="module")
def limits(tmp_path_factory):
    return write_limits(tmp_path_factory.mktemp("limits"))


def test_mesh_limit_figure(limits, tmp_path):
    assert call("mesh_limit", limits / "mesh_limit.csv", "--tolerance", 0.05, "--out", tmp_path / "m") == 0
    assert_figure(tmp_path / "m")


def test_mesh_limit_figure_names_a_missing_column(tmp_path):
    broken = write_csv(tmp_path / "broken.csv", [{"nu": 0.2, "f": 1.5}])
    result = command(ROOT / "figures" / "mesh_limit.py", broken, "--tolerance", 0.05, "--out", tmp_path / "x")
    assert result.returncode != 0 and "status" in result.stderr and not (tmp_path / "x.png").exists()


def test_timestep_figure(limits, tmp_path):
    assert call("timestep_backward", limits / "timestep_limit.csv", "--out", tmp_path / "t") == 0
    assert_figure(tmp_path / "t")


def test_backward_celerity_refuses_an_unknown_table_folder(tmp_path):
    result = command(ROOT / "figures" / "backward_celerity.py", "--table", "nonsense=x.csv", "--out", tmp_path)
    assert result.returncode == 2 and "--table takes FOLDER=PATH" in result.stderr


def test_numbers_of_the_limits_subsections(limits, tmp_path):
    generated = tmp_path / "generated"
    generated.mkdir()
    write_generated_limits(limits, generated)
    macros = dict(re.findall(r"\\newcommand\{\\(\w+)\}\{(.*)\}", (generated / "how_sure_limits.tex").read_text()))
    # 0.84, 0.86, 0.87 -> 0.88 and -2.68, -2.66, -2.65 -> -2.64 (r = 0.5), both within 5 %;
    # 0.99, 1.01, 0.97 turns.
    assert macros["limMeshLimit"] == "2" and macros["limMeshWithinLimit"] == "2"
    assert macros["limMeshNotMonotone"] == "1"
    assert macros["limMeshList"] == "32, 64 and 128"
    # -2.40, -2.30, -2.25 with a seed range of 0.02: converging to -2.20.
    assert macros["limDtConverging"] == "1" and macros["limDtSmallest"] == "0.0625"
    assert macros["limTlOneOnsetMean"] == "744" and macros["limTlPaperOnset"] == "787"
    assert macros["limTlTwoLabel"] == "meshes"
    assert macros["limPulsePaperCounts"] == "1, 2 and 3" and macros["limPulsePaperPeriods"] == "$2$, $4$ and $6$"
    used = set(re.findall(r"\\(lim[A-Z]\w*)", (PAPER / "how_sure.tex").read_text()))
    assert used and used <= set(macros), sorted(used - set(macros))
    for name in ("mesh_limit", "timestep_backward", "backward_celerity"):
        assert (generated / f"{name}.pdf").exists()


def test_numbers_name_a_file_without_a_key(limits, tmp_path):
    summary = json.loads((limits / "mesh_limit_summary.json").read_text())
    del summary["verdict"]
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(summary))
    result = command(PAPER / "make_how_sure_limits.py", "--mesh", bad, "--timestep",
                     limits / "timestep_limit_summary.json", "--timeline", limits / "timeline_summary.json",
                     "--pulses", limits / "pulse_seeds_summary.json", "-o", tmp_path / "out.tex")
    assert result.returncode == 2 and "bad.json: no key 'verdict'" in result.stderr
    assert not (tmp_path / "out.tex").exists()
