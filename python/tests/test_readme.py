"""README.md's Python example runs as shown (every example a newcomer reads is run by a test)."""

import re

from conftest import REPO


def test_readme_python_blocks_run(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    text = (REPO / "README.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert blocks, "README has a Python example"
    for block in blocks:
        exec(compile(block, "README.md", "exec"), {})
    out = capsys.readouterr().out
    # the M8 aluminium joint: R_o beyond the bearing face, inside the 45° cone B + D
    r_o = float(re.search(r"R_o = ([0-9.]+)", out).group(1))
    assert 6.5 < r_o < 6.5 + 6.0, out
    assert "converged: True" in out, out
