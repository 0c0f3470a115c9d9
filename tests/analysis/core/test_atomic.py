"""analysis.core.atomic: files appear whole, and with the mode any file gets under the umask."""

import os
import stat

import pytest

from analysis.core.atomic import write_file, write_files


@pytest.fixture
def umask():
    """Function that sets the process umask for the test; the old one is restored."""
    old = os.umask(0o022)
    os.umask(old)
    yield os.umask
    os.umask(old)


@pytest.mark.parametrize("mask, mode", [(0o022, 0o644), (0o002, 0o664), (0o077, 0o600)])
def test_files_get_the_mode_of_the_umask(tmp_path, umask, mask, mode):
    umask(mask)
    write_files({tmp_path / "a.json": "{}\n", tmp_path / "sub" / "b.csv": "x\n"})
    for path in (tmp_path / "a.json", tmp_path / "sub" / "b.csv"):
        assert stat.S_IMODE(path.stat().st_mode) == mode
    # The same as a file opened the ordinary way.
    (tmp_path / "plain").write_text("")
    assert stat.S_IMODE((tmp_path / "plain").stat().st_mode) == mode


def test_nothing_is_left_when_a_write_fails(tmp_path):
    (tmp_path / "old.json").write_text("old\n")
    with pytest.raises(TypeError):
        write_files({tmp_path / "old.json": "new\n", tmp_path / "bad.json": 42})
    assert (tmp_path / "old.json").read_text() == "old\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["old.json"]
    write_file(tmp_path / "old.json", "new\n")
    assert (tmp_path / "old.json").read_text() == "new\n"
