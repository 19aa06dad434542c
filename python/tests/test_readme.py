"""The README's Python example runs as written (from the repository root) and computes what
its comments say."""

import os
import re

import numpy as np

from conftest import ROOT


def test_readme_python_blocks_run_as_written():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert blocks, "no python block in README.md"
    cwd = os.getcwd()
    os.chdir(ROOT)
    try:
        scope = {}
        for block in blocks:
            exec(compile(block, "README.md", "exec"), scope)
    finally:
        os.chdir(cwd)
    assert abs(scope["qdd"][2] + 9.81) < 1e-9
    assert scope["QDD"].shape == (10_000, scope["model"].nv)
    assert np.array_equal(scope["QDD"][0], scope["qdd"])
    assert abs(scope["d"].distance - 1.5) < 1e-12
    assert scope["summary"]["passed"] and scope["signals"]["t"][-1] == 0.5
    assert scope["limp"]["final_com_height"] < scope["summary"]["final_com_height"] - 0.05
    assert [len(r) for r in scope["sweep"]] == [2, 2, 2]
    assert "L_z" in scope["tables"]["minimization"] and scope["walked"]["violations"] == []
