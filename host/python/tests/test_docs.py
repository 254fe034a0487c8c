"""docs/python.md says what its examples print, and the map example runs."""

import contextlib
import io
import os
import re
import subprocess
import sys

import pytest

from conftest import ROOT

MARK = "<!-- python-example -->"


def examples():
    """(code, printed) of each example of docs/python.md: the python block
    after the mark and the text block after it."""
    with open(os.path.join(ROOT, "docs", "python.md")) as page:
        text = page.read()
    found = []
    for part in text.split(MARK)[1:]:
        code = re.search(r"```python\n(.*?)```", part, re.S)
        printed = re.search(r"```text\n(.*?)```", part, re.S)
        found.append((code.group(1), printed.group(1)))
    return found


@pytest.mark.parametrize("number", range(3))
def test_each_example_of_the_page_prints_what_the_page_says(number, monkeypatch):
    pages = examples()
    assert len(pages) == 3, "docs/python.md: expected 3 examples, found %d" % len(pages)
    code, printed = pages[number]
    monkeypatch.chdir(ROOT)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(code, "docs/python.md example %d" % (number + 1), "exec"), {})
    assert out.getvalue() == printed


@pytest.mark.slow
def test_the_map_example_draws_a_small_map(tmp_path):
    figure = tmp_path / "map.png"
    out = subprocess.run([sys.executable, os.path.join(ROOT, "host", "python", "examples", "map_example.py"),
                          "--small", "--jobs", "2", "--out", str(figure)],
                         check=True, stdout=subprocess.PIPE, text=True).stdout
    lines = out.splitlines()
    assert re.fullmatch(r"map: 4 points, 4 runs on 2 threads in \S+ s", lines[0])
    assert sum(int(re.fullmatch(r"outcome \w+: (\d+) points", line).group(1)) for line in lines[1:-1]) == 4
    assert lines[-1] == "figure: %s" % figure
    with open(figure, "rb") as png:
        assert png.read(8) == b"\x89PNG\r\n\x1a\n"
