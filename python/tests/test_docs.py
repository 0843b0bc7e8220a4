"""The package's own examples run as written: the module docstring's doctests, and the
quickstart of python/README.md (in a scratch folder, reading the shipped scene)."""

import doctest
import os
import re

import cga

HERE = os.path.dirname(__file__)
ROOT = os.path.join(HERE, "..", "..")


def test_the_module_doctests_pass():
    result = doctest.testmod(cga, verbose=False)
    assert result.attempted > 0 and result.failed == 0


def test_the_readme_quickstart_runs(tmp_path, monkeypatch):
    text = open(os.path.join(HERE, "..", "README.md")).read()
    block = re.search(r"```python\n(.*?)```", text, re.S).group(1)
    scene = os.path.abspath(os.path.join(ROOT, "cga-trace", "scenes", "primitives.toml"))
    if not os.path.exists(scene):
        return  # an installed package without the repository beside it
    monkeypatch.chdir(tmp_path)
    exec(compile(block.replace('"cga-trace/scenes/primitives.toml"', repr(scene)), "README.md", "exec"), {})
    assert (tmp_path / "primitives.png").exists()
