#!/usr/bin/python3
"""Write generated/table1.tex: Table 1 as analysis.tables.table1_tex renders it, with the sign flips at
the other meshes marked.

    paper/make_table1.py table1.csv [--other-mesh H/32=table1_h32.csv ...] -o paper/generated/table1.tex

table1.csv is `python3 -m analysis aggregate`'s (columns: analysis.tables.table1_tex.REQUIRED). Only
selection and formatting happen here.
"""
import argparse
import sys

from analysis.core.atomic import write_file
from analysis.tables.table1_tex import REQUIRED, cell_key, render
from table_io import InputError, labelled_paths, read_rows


def read_other_mesh(path):
    """{(nu, f): celerity} of another mesh's table1.csv."""
    return {cell_key(r): r["celerity"] for r in read_rows(path, ("nu", "f", "celerity"))}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("table", help="table1.csv of `python3 -m analysis aggregate`")
    parser.add_argument("--other-mesh", action="append", default=[], metavar="LABEL=TABLE1_CSV",
                        help="table1.csv of the same cells at another mesh (sign flips are marked)")
    parser.add_argument("-o", "--output", required=True, help="table1.tex to write")
    args = parser.parse_args(argv)
    try:
        rows = read_rows(args.table, REQUIRED)
        if not rows:
            raise InputError(f"{args.table}: no data rows")
        other_meshes = [(mesh, read_other_mesh(path))
                        for mesh, path in labelled_paths(args.other_mesh, "TABLE1_CSV")]
    except (InputError, ValueError) as err:
        print(f"make_table1.py: error: {err}", file=sys.stderr)
        return 2
    write_file(args.output, render(rows, other_meshes, generator="paper/make_table1.py"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
