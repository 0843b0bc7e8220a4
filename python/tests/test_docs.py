"""The package's own examples run as written: the module docstring's doctests, and the
quickstart of python/README.md (in a scratch folder, reading the shipped scene)."""

import doctest
import os
import re

import pytest

import cga

HERE = os.path.dirname(__file__)
ROOT = os.path.join(HERE, "..", "..")


def test_the_module_doctests_pass():
    for module in (cga, cga.interop, cga.random, cga.pga, cga.sta, cga.cga2, cga.vga):
        result = doctest.testmod(module, verbose=False)
        assert result.attempted > 0 and result.failed == 0, module.__name__


def test_the_readme_quickstart_runs(tmp_path, monkeypatch):
    text = open(os.path.join(HERE, "..", "README.md")).read()
    block = re.search(r"```python\n(.*?)```", text, re.S).group(1)
    scene = os.path.abspath(os.path.join(ROOT, "cga-trace", "scenes", "primitives.toml"))
    if not os.path.exists(scene):
        return  # an installed package without the repository beside it
    monkeypatch.chdir(tmp_path)
    exec(compile(block.replace('"cga-trace/scenes/primitives.toml"', repr(scene)), "README.md", "exec"), {})
    assert (tmp_path / "primitives.png").exists() and (tmp_path / "row.png").exists()


def test_the_spelling_page_runs():
    # docs/PYTHON_SPELLINGS.md: its examples, with clifford and kingdon beside us.
    path = os.path.join(ROOT, "docs", "PYTHON_SPELLINGS.md")
    if not os.path.exists(path):
        return  # an installed package without the repository beside it
    pytest.importorskip("clifford")
    pytest.importorskip("kingdon")
    blocks = re.findall(r"```python\n(.*?)```", open(path).read(), re.S)
    test = doctest.DocTestParser().get_doctest("\n\n".join(blocks), {}, "PYTHON_SPELLINGS.md", path, 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.IGNORE_EXCEPTION_DETAIL)
    runner.run(test)
    assert runner.tries > 5 and runner.failures == 0
