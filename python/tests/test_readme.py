"""The README's Python example runs as written and does what its comments say."""

import pathlib
import re


def test_readme_python_example_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # the example writes energy.png where it runs
    readme = (pathlib.Path(__file__).parents[2] / "README.md").read_text()
    section = readme.split("## From Python", 1)[1]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    names = {}
    exec(compile(code, "README.md", "exec"), names)
    assert names["fine"].labeling.shape == (240, 320)
    assert names["fine"].energy == names["energy"].evaluate(names["fine"].labeling)
    assert names["flat"].reason == "converged"
    assert (tmp_path / "energy.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
