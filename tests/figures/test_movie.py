"""figures/movie.py: a short movie from a tiny real run, checked with ffprobe (frame count, frame
size, duration, file size); the GIF fallback without ffmpeg; bad input.

The tiny run (H/8, 60 s, a bulk snapshot every 3 s: 21 frames) takes a few seconds. Without the
solver binary or ffmpeg/ffprobe the tests that need them are skipped (a failure under CI=true).
"""
import json
import shutil
import subprocess

import pytest
from figure_support import ROOT, call, command

from solver_runs import missing, tiny_run as solver_run

FRAME_TIMES = [3.0 * k for k in range(21)]


@pytest.fixture(scope="module")
def tiny_run(tmp_path_factory):
    return solver_run(tmp_path_factory.mktemp("movie"),
                      {"interface_stride": 1, "snapshot_times": FRAME_TIMES, "progress": "never"})


def ffprobe(path):
    """{nb_read_frames, width, height, codec_name, duration} of the first video stream."""
    if not shutil.which("ffprobe"):
        missing("ffprobe not installed (Debian: apt-get install ffmpeg)")
    result = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                             "-show_entries", "stream=nb_read_frames,width,height,codec_name,duration",
                             "-of", "json", str(path)], check=True, capture_output=True, text=True)
    return json.loads(result.stdout)["streams"][0]


def test_mp4_has_one_frame_per_snapshot(tiny_run, tmp_path):
    if not shutil.which("ffmpeg"):
        missing("ffmpeg not installed (Debian: apt-get install ffmpeg)")
    out = tmp_path / "movie.mp4"
    result = command(ROOT / "figures" / "movie.py", tiny_run, "--out", out, "--fps", 10, "--dpi", 60)
    assert result.returncode == 0, result.stderr
    stream = ffprobe(out)
    assert stream["codec_name"] == "h264"
    assert int(stream["nb_read_frames"]) == len(FRAME_TIMES)
    assert (stream["width"], stream["height"]) == (480, 480)  # 8 x 8 in at 60 dpi
    assert float(stream["duration"]) == pytest.approx(len(FRAME_TIMES) / 10, abs=0.11)
    assert 5_000 < out.stat().st_size < 2_000_000
    # The log names the magnification, shows progress and the size.
    assert "magnified x" in result.stderr
    assert f"{len(FRAME_TIMES)}/{len(FRAME_TIMES)} frames" in result.stderr
    assert "MB" in result.stderr


def test_time_range_selects_frames(tiny_run, tmp_path):
    if not shutil.which("ffmpeg"):
        missing("ffmpeg not installed (Debian: apt-get install ffmpeg)")
    out = tmp_path / "part.mp4"
    assert call("movie", tiny_run, "--out", out, "--tmin", 10, "--tmax", 31, "--dpi", 40) == 0
    assert int(ffprobe(out)["nb_read_frames"]) == 7  # 12, 15, ..., 30 s


def test_gif_fallback_without_ffmpeg(tiny_run, tmp_path, monkeypatch, capsys):
    from matplotlib import animation
    from PIL import Image

    monkeypatch.setattr(animation.FFMpegWriter, "isAvailable", classmethod(lambda cls: False))
    assert call("movie", tiny_run, "--out", tmp_path / "movie.mp4", "--tmax", 12, "--dpi", 30) == 0
    assert "ffmpeg not found: writing the GIF" in capsys.readouterr().err
    assert not (tmp_path / "movie.mp4").exists()
    with Image.open(tmp_path / "movie.gif") as gif:
        assert gif.n_frames == 5  # 0, 3, 6, 9, 12 s


def test_a_run_without_snapshots_is_refused(data, tmp_path):
    result = command(ROOT / "figures" / "movie.py", data / "run_v1e-06.h5", "--out", tmp_path / "m.mp4")
    assert result.returncode == 2
    assert "snapshots" in result.stderr and not (tmp_path / "m.mp4").exists()


@pytest.mark.parametrize("option, value", [("--fps", 0), ("--scale", -1), ("--dpi", 5)])
def test_bad_options_name_the_option(data, tmp_path, option, value):
    result = command(ROOT / "figures" / "movie.py", data / "run.h5", "--out", tmp_path / "m.mp4", option, value)
    assert result.returncode == 2 and option in result.stderr
