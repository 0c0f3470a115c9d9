"""paper/make_table1.py marks every quality flag, every sign flip across meshes and every outcome
other than the published one, on small hand-written tables (one row per case)."""
import csv

from figure_support import PAPER, command

COLUMNS = ("nu", "f", "celerity", "published", "deviation_rel", "within_tol", "sign_match", "regime_match",
           "category_match", "reproduced", "celerity_quality", "celerity_window_sensitivity", "regime",
           "category", "end_reason")


def row(nu, f, celerity, published, quality="ok", reproduced=True, category="intersonic_opening",
        category_match=True):
    measured = celerity != ""
    return {"nu": nu, "f": f, "celerity": celerity, "published": published,
            "deviation_rel": (celerity - published) / abs(published) if measured else "",
            "within_tol": "true" if reproduced else "false", "sign_match": "true" if measured else "",
            "regime_match": "true" if measured else "", "category_match": str(category_match).lower(),
            "reproduced": str(reproduced and measured).lower(), "celerity_quality": quality if measured else "",
            "celerity_window_sensitivity": 0.01 if measured else "", "regime": "intersonic" if measured else "",
            "category": category, "end_reason": ""}


def write(path, rows):
    with open(path, "w", newline="") as stream:
        writer = csv.DictWriter(stream, COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    return path


def table_row(text, nu, f):
    """The LaTeX row of cell (nu, f)."""
    start = f"{nu:g} & {f:g} & "
    return next(line for line in text.splitlines() if line.startswith(start))


def render(tmp_path, rows, *other):
    table = write(tmp_path / "table1.csv", rows)
    out = tmp_path / "table1.tex"
    extra = []
    for label, other_rows in other:
        extra.append(f"--other-mesh={label}={write(tmp_path / f'{label[2:]}.csv', other_rows)}")
    result = command(PAPER / "make_table1.py", table, *extra, "-o", out)
    assert result.returncode == 0, result.stderr
    return out.read_text()


def test_every_flag_of_a_flag_list_is_marked_and_explained(tmp_path):
    text = render(tmp_path, [row(0.1, 1.1, 0.866, 0.829, quality="estimates_disagree;unsteady"),
                             row(0.49, 1.2, -5.8, -5.085, quality="aliasing_risk", reproduced=False),
                             row(0.2, 1.2, 0.84, 0.875, quality="ok"),
                             row(0.3, 1.5, 0.77, 0.774, quality="some_new_flag")])
    assert r"\textsuperscript{(e,u)}" in table_row(text, 0.1, 1.1)
    assert r"\textsuperscript{(a)}" in table_row(text, 0.49, 1.2)
    assert "textsuperscript" not in table_row(text, 0.2, 1.2)
    assert r"\textsuperscript{(some\_new\_flag)}" in table_row(text, 0.3, 1.5)  # unknown: by its name
    notes = text.split(r"\end{tabular}")[1]
    assert "(e) " in notes and "(u) " in notes and "(a) aliasing risk" in notes


def test_a_sign_flip_at_another_mesh_is_marked_and_not_bold(tmp_path):
    cells = [row(0.49, 1.5, -5.6, -5.399), row(0.2, 1.5, 0.85, 0.882)]
    text = render(tmp_path, cells,
                  ("H/32", [row(0.49, 1.5, 0.7, -5.399), row(0.2, 1.5, 0.86, 0.882)]),
                  ("H/128", [row(0.49, 1.5, 0.71, -5.399), row(0.2, 1.5, "", 0.882)]))
    flipped = table_row(text, 0.49, 1.5)
    assert r"\textsuperscript{(m)}" in flipped and r"\mathbf" not in flipped
    kept = table_row(text, 0.2, 1.5)
    assert r"\mathbf" in kept and "(m)" not in kept  # no front at H/128 is not a sign flip
    notes = text.split(r"\end{tabular}")[1]
    assert "(0.49, 1.5) at H/32 and H/128 (1 cells bold; reproduced at this mesh alone: 2)" in notes


def test_without_other_meshes_the_reproduced_cell_is_bold(tmp_path):
    text = render(tmp_path, [row(0.49, 1.5, -5.6, -5.399)])
    assert r"\mathbf{-3.7}" in table_row(text, 0.49, 1.5)


def test_a_row_without_opening_carries_its_section_mark(tmp_path):
    text = render(tmp_path, [row(0.0, 1.1, "", 0.861, category="no_opening", category_match=False),
                             row(0.49, 1.05, "", -5.248, category="opening_without_front",
                                 category_match=False)])
    assert r"--$^\S$" in table_row(text, 0.0, 1.1)
    assert r"--$^\S$" in table_row(text, 0.49, 1.05)


def test_an_unreadable_other_mesh_is_an_error(tmp_path):
    table = write(tmp_path / "table1.csv", [row(0.2, 1.5, 0.85, 0.882)])
    result = command(PAPER / "make_table1.py", table, "--other-mesh", f"H/32={tmp_path / 'absent.csv'}",
                     "-o", tmp_path / "out.tex")
    assert result.returncode == 2 and "absent.csv" in result.stderr
    result = command(PAPER / "make_table1.py", table, "--other-mesh", "no-label", "-o", tmp_path / "out.tex")
    assert result.returncode == 2 and "LABEL=TABLE1_CSV" in result.stderr
