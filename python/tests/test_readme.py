"""The Python examples of the README and of the Python guide run as printed."""

from __future__ import annotations

import re
import subprocess
import sys

from conftest import ROOT


def run(code: str, cwd) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code], cwd=cwd,
                          capture_output=True, text=True)


def test_the_readme_one_liner_runs(tmp_path):
    readme = (ROOT / "README.md").read_text()
    line = re.search(r"\.venv/bin/python -c '(.*?)'\n", readme).group(1)
    result = run(line, tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("[[")


def test_the_python_guide_example_runs(tmp_path):
    guide = (ROOT / "docs" / "guide" / "python.md").read_text()
    example = re.search(r"```python\n(.*?)```", guide, re.S).group(1)
    result = run(example, tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("CD^2 ")
