"""Full disk (issue 11, item 5): writes that fail (here with EFBIG under `ulimit -f`, SIGXFSZ ignored,
which needs no root) end the run with exit 4 and a message that names the file and the operating
system's reason; no RUN.h5 and no temporary file is left. Also: a corrupted dataset is reported by
h5py through the Fletcher32 checksum every dataset carries (item 13).

Runs the solver binary (build/slidewave, or $SLIDEWAVE_BIN: tests/support/solver_runs.py) in temporary
folders."""

import json
import subprocess

import h5py
import numpy as np
import pytest

from solver_runs import solver_or_skip

# H/16, ~5000 steps: over a megabyte of output, far above the 200 KiB file-size limit.
CONFIG = {
    "mesh": {"elements_per_H": 16},
    "time": {"t_end": 300.0, "dt_times_cs": 0.04},
    "output": {"interface_stride": 1, "snapshot_times": [0, 200], "progress": "never"},
}
SMALL = {"mesh": {"elements_per_H": 8}, "time": {"t_end": 60.0},
         "output": {"snapshot_times": [0, 30], "progress": "never"}}


def solver():
    return str(solver_or_skip())


def run_limited(folder, config, limit_kib):
    """`slidewave run` with files limited to limit_kib KiB; writes past it fail with EFBIG."""
    config_path = folder / "run.json"
    config_path.write_text(json.dumps(config))
    command = f'ulimit -f {limit_kib}; trap "" XFSZ; exec "$0" run "$1" -o "$2"'
    return subprocess.run(["bash", "-c", command, solver(), str(config_path), str(folder / "out" / "RUN.h5")],
                          capture_output=True, text=True, timeout=600)


def test_full_disk_exits_4_names_file_and_reason_and_leaves_nothing(tmp_path):
    (tmp_path / "out").mkdir()
    result = run_limited(tmp_path, CONFIG, 200)
    assert result.returncode == 4, (result.returncode, result.stderr)
    assert "File too large" in result.stderr, result.stderr
    assert str(tmp_path / "out" / "RUN") in result.stderr, result.stderr
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == [], "nothing left in the output folder"


def test_a_run_that_fits_is_unaffected_by_the_limit(tmp_path):
    (tmp_path / "out").mkdir()
    result = run_limited(tmp_path, SMALL, 200000)
    assert result.returncode == 0, result.stderr
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["RUN.h5", "RUN.interface.xdmf", "RUN.xdmf"]


def test_a_corrupted_dataset_is_reported_by_its_checksum(tmp_path):
    (tmp_path / "out").mkdir()
    result = run_limited(tmp_path, SMALL, 200000)
    assert result.returncode == 0, result.stderr
    path = tmp_path / "out" / "RUN.h5"
    with h5py.File(path, "r") as f:
        dataset = f["global/T"]
        assert dataset.fletcher32
        good = dataset[()]
        chunk = dataset.id.get_chunk_info(0)
    with open(path, "r+b") as stream:  # flip one byte inside the first chunk of /global/T
        stream.seek(chunk.byte_offset + 16)
        byte = stream.read(1)
        stream.seek(chunk.byte_offset + 16)
        stream.write(bytes([byte[0] ^ 0x5A]))
    with h5py.File(path, "r") as f:
        with pytest.raises(OSError, match="(?i)fletcher32|checksum"):
            f["global/T"][()]
        np.testing.assert_array_equal(f["global/N"][()].shape, good.shape)  # the rest stays readable
