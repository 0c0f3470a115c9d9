"""No Python source file of the project over 400 lines (issue 22): a file that grows past it is split
by concern, as bimaterial_stability.py (complex_roots.py) and make_claims.py (claims.py) were."""
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
FOLDERS = ("analysis", "figures", "paper", "study", "scripts", "tests", "bench")
MAX_LINES = 400


@pytest.mark.parametrize("folder", FOLDERS)
def test_no_python_file_is_longer_than_the_limit(folder):
    long = {str(p.relative_to(ROOT)): n for p in sorted((ROOT / folder).rglob("*.py"))
            if "results" not in p.parts and (n := len(p.read_text().splitlines())) > MAX_LINES}
    assert not long, f"over {MAX_LINES} lines: {long}"
