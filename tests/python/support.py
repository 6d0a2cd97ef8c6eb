"""What the Python module's tests share: the `tumble` command they compare against, a scratch
folder, and the command line's CSV read back as exact doubles (it prints %.17g, which reads back
as the same double)."""
import csv
import os
import subprocess
import tempfile

import numpy as np

TUMBLE = os.environ["TUMBLE_EXE"]
ARTIFACTS = os.environ.get("TUMBLE_TEST_ARTIFACTS", tempfile.gettempdir())


def scratch(name):
    """A fresh folder for one test under the build's test artifacts."""
    path = os.path.join(ARTIFACTS, "python", name)
    os.makedirs(path, exist_ok=True)
    for f in os.listdir(path):
        full = os.path.join(path, f)
        if os.path.isfile(full):
            os.remove(full)
    return path


def tumble(*args, check=True):
    """Runs the command line; returns the finished process (stdout and stderr as text)."""
    proc = subprocess.run([TUMBLE, *map(str, args)], capture_output=True, text=True)
    if check and proc.returncode != 0:
        raise AssertionError("tumble %s: exit %d\n%s" % (" ".join(map(str, args)),
                                                         proc.returncode, proc.stderr))
    return proc


def read_states(path):
    """`tumble simulate`'s states CSV as {name: column}, the body names as a list of rows'.
    Lines starting with '#' (the scene record on the first line) are not rows."""
    with open(path, newline="") as f:
        reader = csv.reader(line for line in f if not line.startswith("#"))
        header = next(reader)
        rows = list(reader)
    cols = {h: [r[i] for r in rows] for i, h in enumerate(header)}
    out = {h: np.array([float(v) for v in cols[h]]) for h in header if h != "name"}
    out["name"] = cols["name"]
    return out


def read_table(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
        rows = [[float(v) if v else float("nan") for v in line.rstrip("\n").split(",")]
                for line in f]
    data = np.array(rows)
    return {h: data[:, i] for i, h in enumerate(header)}


def decode_png(path):
    """A PNG decoded by FFmpeg (an independent decoder) as uint8 (H, W, 3)."""
    probe = subprocess.run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-show_entries",
                            "stream=width,height", "-of", "csv=p=0", path],
                           capture_output=True, text=True, check=True)
    width, height = map(int, probe.stdout.strip().split(","))
    raw = subprocess.run(["ffmpeg", "-v", "error", "-i", path, "-f", "rawvideo", "-pix_fmt",
                          "rgb24", "-"], capture_output=True, check=True).stdout
    return np.frombuffer(raw, dtype=np.uint8).reshape(height, width, 3)
