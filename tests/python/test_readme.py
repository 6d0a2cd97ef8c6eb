"""README's Python section runs as written: its shell block starts the interpreter (from a folder
where build/release/python is this build's module) and its Python block is fed to it."""
import os
import re
import subprocess

import support

SOURCE = os.environ["TUMBLE_SOURCE_DIR"]
MODULE = os.path.join(os.path.dirname(support.TUMBLE), "..", "python")


def section():
    text = open(os.path.join(SOURCE, "README.md")).read()
    start = text.index("## From Python and in notebooks")
    end = text.index("\n## ", start + 1)
    return text[start:end]


def test_every_snippet_of_readmes_python_section_runs():
    blocks = re.findall(r"```(\w+)\n(.*?)```", section(), re.S)
    shell = [code for lang, code in blocks if lang == "sh"]
    python = [code for lang, code in blocks if lang == "python"]
    assert len(shell) == 1 and len(python) >= 1
    work = support.scratch("readme")
    os.makedirs(os.path.join(work, "build", "release"), exist_ok=True)
    link = os.path.join(work, "build", "release", "python")
    if not os.path.islink(link):
        os.symlink(os.path.realpath(MODULE), link)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    for code in python:
        proc = subprocess.run(["sh", "-c", shell[0].strip()], input=code, text=True, cwd=work,
                              env=env, capture_output=True, timeout=600)
        assert proc.returncode == 0, proc.stderr
        assert "Traceback" not in proc.stderr, proc.stderr
    # What the snippet says it makes, made: the CSV pair and the video.
    for name in ["flip.csv", "flip.diagnostics.csv", "flip.mp4"]:
        assert os.path.getsize(os.path.join(work, name)) > 0, name
    assert "unknown integrator" in proc.stdout and "(3, 360, 640, 3) uint8" in proc.stdout
