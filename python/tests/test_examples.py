"""examples/python: dataset.py writes what it says, with cameras that agree with the images;
dataset_pyrender.py (not run: pyrender is not in Debian) at least compiles."""
import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

from scenes import icosphere, write_obj

EXAMPLES = pathlib.Path(
    os.environ.get("FACET_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2])
) / "examples" / "python"


def run_example(*arguments):
    return subprocess.run(
        [sys.executable, str(EXAMPLES / "dataset.py"), *map(str, arguments)],
        capture_output=True, text=True, timeout=120,
    )


def test_dataset_help():
    result = run_example("--help")
    assert result.returncode == 0, result.stderr
    assert "--views" in result.stdout and "--size" in result.stdout


def test_dataset_writes_images_depth_and_cameras(tmp_path):
    vertices, faces = icosphere(2)
    model = write_obj(tmp_path / "ball.obj", vertices * 2 + (1, 2, 3), faces)
    out = tmp_path / "out"
    result = run_example(model, out, "--views", 6, "--size", "64x48", "--workers", 2)
    assert result.returncode == 0, result.stderr
    assert "6 views" in result.stdout
    names = {p.name for p in out.iterdir()}
    for index in range(6):
        assert {f"color_{index:03d}.png", f"depth_{index:03d}.npy"} <= names
    cameras = np.load(out / "cameras.npz")
    assert cameras["world_to_camera"].shape == (6, 4, 4)
    assert cameras["intrinsics"].shape == (6, 3, 3)
    described = json.loads((out / "cameras.json").read_text())
    assert (described["width"], described["height"], len(described["views"])) == (64, 48, 6)

    sys.path.insert(0, str(EXAMPLES))
    try:
        import views
    finally:
        sys.path.remove(str(EXAMPLES))
    centre = np.array([1.0, 2.0, 3.0, 1.0])
    for index in range(6):
        view = described["views"][index]
        # facet's view matrix is the one views.look_at writes down.
        assert cameras["world_to_camera"][index] == pytest.approx(
            views.look_at(view["eye"], view["target"], view["up"]), abs=1e-5)
        # The ball's centre projects to the image centre, at its distance from the eye.
        in_camera = cameras["world_to_camera_opencv"][index] @ centre
        pixel = cameras["intrinsics"][index] @ in_camera[:3]
        assert pixel[:2] / pixel[2] == pytest.approx(((64 - 1) / 2, (48 - 1) / 2), abs=1e-3)
        depth = np.load(out / f"depth_{index:03d}.npy")
        assert depth.shape == (48, 64) and depth.dtype == np.float32
        # The ball's nearest point is 2 (its radius) nearer than its centre.
        assert depth[depth > 0].min() == pytest.approx(in_camera[2] - 2, rel=0.01)
        assert depth[0, 0] == 0


def test_dataset_reports_a_bad_model_in_one_line(tmp_path):
    result = run_example(tmp_path / "missing.glb", tmp_path / "out")
    assert result.returncode == 2
    assert result.stderr.strip() == f"dataset: {tmp_path / 'missing.glb'}: no such file"


def test_dataset_pyrender_compiles():
    source = (EXAMPLES / "dataset_pyrender.py").read_text()
    compile(source, "dataset_pyrender.py", "exec")
