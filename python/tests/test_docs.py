"""docs/python.md's Python blocks run as written (in order, in a scratch folder)."""
import os
import pathlib
import re

import numpy as np

DOCS = pathlib.Path(
    os.environ.get("FACET_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2])
) / "docs" / "python.md"


def test_the_python_blocks_of_the_docs_run(tmp_path, monkeypatch):
    blocks = re.findall(r"```python\n(.*?)```", DOCS.read_text(), re.DOTALL)
    assert len(blocks) >= 2
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in blocks:
        exec(compile(block, str(DOCS), "exec"), namespace)
    frame = namespace["frame"]
    assert frame["depth"][180, 320] > 0  # the cube is in the middle
    assert np.load("cube_depth.npy").shape == (360, 640)
    assert {"cube.png", "python.png", "cube_depth.npy", "monitor.png"} <= {
        p.name for p in tmp_path.iterdir()
    }
    # The render texture's second frame, shown on the screen in the middle of the view.
    monitor = namespace["monitor"].read_color()
    tv = namespace["tv"]
    assert tuple(tv[0, 0]) != (0, 0, 0, 255) and tv[180, 320, :3].max() > 0
    assert np.abs(tv[180, 320].astype(int) - monitor[90, 160]).max() <= 8
    # facet.dask's job wrote its 8 frames.
    assert namespace["index"].rendered == [f"frame_{i:04d}" for i in range(8)]
    assert len(list((tmp_path / "orbit").iterdir())) == 16
