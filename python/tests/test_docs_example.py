"""docs/python.md's ten-line example runs as written and does what it says."""
import re

import numpy as np

from conftest import ROOT, run_docs_example


def test_the_ten_line_example_runs(tmp_path, capsys):
    block = re.search(r"## Ten lines.*?```python\n(.*?)```", (ROOT / "docs" / "python.md").read_text(), re.S).group(1)
    code_lines = [line for line in block.splitlines() if line.strip() and not line.startswith("import")]
    assert len(code_lines) <= 10
    scope = run_docs_example("## Ten lines", tmp_path)
    out = scope["out"]
    assert out.class_names == ["tree", "bush"]
    # 16x the area: about 16x the 60 elements, in both classes alike.
    counts = np.bincount(out.classes)
    assert 0.8 * 16 * 30 <= counts[0] <= 1.2 * 16 * 30
    assert 0.8 * 16 * 30 <= counts[1] <= 1.2 * 16 * 30
    usda = (tmp_path / "orchard.usda").read_text()
    assert usda.startswith("#usda 1.0")
    assert "PointInstancer" in usda
    assert "elements:" in capsys.readouterr().out
