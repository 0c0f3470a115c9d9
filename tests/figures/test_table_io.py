"""paper/table_io.py: atomic writes that leave a file readable as the umask allows (not the
temporary file's 0600), and nothing behind on failure."""
import os
import stat
import sys

import pytest

from figure_support import PAPER

sys.path.insert(0, str(PAPER))
from table_io import write_atomically  # noqa: E402


@pytest.fixture
def umask():
    """Sets a umask for the test and restores the previous one."""
    saved = os.umask(0o022)
    yield os.umask
    os.umask(saved)


@pytest.mark.parametrize("mask, mode", [(0o022, 0o644), (0o002, 0o664), (0o077, 0o600)])
def test_written_tables_take_their_mode_from_the_umask(tmp_path, umask, mask, mode):
    umask(mask)
    path = tmp_path / "generated" / "table.tex"
    write_atomically(str(path), "x\n")
    assert stat.S_IMODE(path.stat().st_mode) == mode
    assert path.read_text() == "x\n"


def test_a_failed_write_leaves_no_temporary_file(tmp_path):
    with pytest.raises(TypeError):
        write_atomically(str(tmp_path / "table.tex"), None)
    assert list(tmp_path.iterdir()) == []
