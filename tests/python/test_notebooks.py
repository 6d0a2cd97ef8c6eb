"""The notebooks of examples/notebooks execute (nbclient, an IPython kernel on Debian's Python)
without an error, and show what they say they show, with numbers the physics expects."""
import os
import re

import nbformat
import pytest
from nbclient import NotebookClient

import support

NOTEBOOKS = os.path.join(os.environ["TUMBLE_SOURCE_DIR"], "examples", "notebooks")


def run(name):
    nb = nbformat.read(os.path.join(NOTEBOOKS, name), as_version=4)
    work = support.scratch("notebook_" + name.split(".")[0])
    NotebookClient(nb, timeout=600, kernel_name="python3",
                   resources={"metadata": {"path": work}}).execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    shown = [o.data for o in outputs if o.output_type in ("display_data", "execute_result")]
    return text, shown, work


def test_the_intermediate_axis_flip_notebook():
    text, shown, _ = run("intermediate_axis.ipynb")
    assert sum("image/png" in d for d in shown) == 2  # w(t) and Poinsot's picture
    # The book flips again and again, at a steady half-period (torque-free motion is periodic).
    flips = [float(x) for x in re.search(r"flips at t = \[([^\]]*)\]", text).group(1).split()]
    assert len(flips) >= 3
    halves = [float(x) for x in re.search(r"half-periods: \[([^\]]*)\]", text).group(1).split()]
    assert max(halves) - min(halves) < 0.05
    # splitting keeps world L to round-off and the energy's error small and bounded.
    assert float(re.search(r"\|L - L0\| / \|L0\|: (\S+)", text).group(1)) < 1e-12
    assert float(re.search(r"energy drift: +(\S+)", text).group(1)) < 1e-3
    assert "(360, 640, 3) uint8" in text


def test_the_integrators_compared_notebook():
    text, shown, work = run("integrators_compared.ipynb")
    assert any("image/png" in d for d in shown)
    assert any("<video" in d.get("text/html", "") for d in shown)
    assert os.path.getsize(os.path.join(work, "integrators_compared.mp4")) > 0
    drift = {m: float(v) for m, v in re.findall(r"(\w+) +max energy drift (\S+)", text)}
    # Explicit Euler gains energy every step; exact keeps it to round-off; rk4 between.
    assert drift["euler"] > 1e-2
    assert drift["exact"] < 1e-12
    assert drift["exact"] < drift["rk4"] < drift["euler"]
