"""Every `python ...` command in the ```sh blocks of the guide's pages (docs/*.md) runs and exits
0, in a temporary directory, with this venv's Python (tests/cli/readme.rs runs the others and
leaves these to this test). `python -m pip install ./python` is the command `.ci/python` has just
run to build the package under test, so it is checked to be that command, not run again."""

import re
import subprocess
import sys

from conftest import REPO


def doc_commands():
    lines = []
    for page in sorted((REPO / "docs").glob("*.md")):
        for block in re.findall(r"```sh\n(.*?)```", page.read_text(), re.S):
            for line in block.splitlines():
                cmd = line.split(" #")[0].strip()
                if cmd.startswith("python"):
                    lines.append((page.name, cmd))
    return lines


def test_every_python_command_of_the_guide_runs(tmp_path):
    commands = doc_commands()
    assert commands, "no python command found in docs/*.md"
    ci = (REPO / ".ci" / "python").read_text()
    for page, cmd in commands:
        words = cmd.split()
        if words[1:] == ["-m", "pip", "install", "./python"]:
            assert "-m pip install" in ci and "./python" in ci, "%s: %s" % (page, cmd)
            continue
        # paths in the repository are given from its root; outputs land in tmp_path
        args = [sys.executable] + [str(REPO / w) if (REPO / w).exists() and "/" in w else w
                                   for w in words[1:]]
        out = subprocess.run(args, cwd=tmp_path, capture_output=True, text=True, check=False,
                             timeout=600)
        assert out.returncode == 0, "%s: %s\n%s" % (page, cmd, out.stderr[-2000:])
