#!/usr/bin/python3
"""Regenerates the key section of docs/contracts.md from the solver's key table.

The section between the markers is the output of `slidewave keys --markdown`; the test
ConfigKeys.ContractKeySectionIsTheTablesOutput fails while the committed text differs.

Usage: scripts/update_contract_keys.py [path/to/slidewave]   (default: build/slidewave)
"""
import pathlib
import subprocess
import sys

BEGIN = "<!-- BEGIN generated: slidewave keys --markdown"
END = "<!-- END generated: slidewave keys --markdown -->"


def main() -> int:
    root = pathlib.Path(__file__).resolve().parent.parent
    binary = sys.argv[1] if len(sys.argv) > 1 else str(root / "build" / "slidewave")
    section = subprocess.run([binary, "keys", "--markdown"], check=True, capture_output=True, text=True).stdout
    contracts = root / "docs" / "contracts.md"
    text = contracts.read_text()
    begin, end = text.find(BEGIN), text.find(END)
    if begin < 0 or end < begin:
        sys.exit(f"error: {contracts}: markers {BEGIN!r} ... {END!r} not found")
    body = text.index("\n", begin) + 1
    contracts.write_text(text[:body] + section + text[end:])
    return 0


if __name__ == "__main__":
    sys.exit(main())
