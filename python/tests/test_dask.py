"""facet.dask: a job on a cluster of worker processes writes the files one process writes, byte
for byte; a worker killed mid-job costs time only (every file written once, whole); a finished
job run again renders nothing; a failing item fails alone."""
import json
import logging
import os
import pathlib
import signal
import subprocess
import sys
import time

import numpy as np
import pytest
from distributed import Client, LocalCluster
from distributed.diagnostics.plugin import WorkerPlugin

import facet
import facet.dask
from scenes import icosphere, write_obj

# distributed 2022.12 on Debian 12's tornado 6.2.
pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")

EXAMPLES = pathlib.Path(
    os.environ.get("FACET_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2])
) / "examples" / "python"


def start_cluster():
    """Two worker processes of one thread each, no fixed ports, warnings and below unsaid."""
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=":0", silence_logs=logging.ERROR)
    return cluster, Client(cluster)


@pytest.fixture(scope="module")
def client():
    cluster, client = start_cluster()
    yield client
    client.close()
    cluster.close()


@pytest.fixture(scope="module")
def ball(tmp_path_factory):
    vertices, faces = icosphere(2)
    return write_obj(tmp_path_factory.mktemp("model") / "ball.obj", vertices * 2 + (1, 2, 3), faces)


@pytest.fixture(scope="module")
def job(ball):
    """Frames of an orbit (every output the module has, in a subfolder), a scene made on the
    workers by a factory at two sizes, and a model seen from its own camera."""
    items = facet.dask.orbit(ball, 12, size=(96, 72), outputs=facet.OUTPUTS,
                             stem="orbit/frame_{:02d}")
    items += facet.dask.orbit(ball, 24, frames=range(3, 24, 4), size=(80, 60), outputs=("color",),
                              elevation=-30, renderer={"background": (0.2, 0.3, 0.4, 1)})
    made = facet.dask.factory("scenes:ball_on_a_floor")
    for index, eye in enumerate([(0, 2, 5), (4, 1, 3), (-3, 3, 3), (0, 6, 0.5)]):
        view = facet.Camera.look_at(eye, (0, 0, 0), fov_y=50, near=1, far=20)
        items.append(facet.dask.Item(f"made_{index}", made, view, ("depth", "color"), (120, 90)))
        items.append(facet.dask.Item(f"made_small_{index}", made,
                                     facet.dask.camera("look_at", eye=eye, target=(0, 0, 0)),
                                     ("color",), (33, 17), {"exposure": 1.0}))
    items.append(facet.dask.Item("own_camera", ball, None, ("color", "depth"), (64, 64)))
    return items


@pytest.fixture(scope="module")
def reference(job, tmp_path_factory):
    out = tmp_path_factory.mktemp("reference")
    index = facet.dask.render_local(job, out)
    assert index.rendered == [item.stem for item in job]
    return contents(out)


def contents(folder):
    """{relative path: bytes} of every file under folder, and None for every folder."""
    folder = pathlib.Path(folder)
    return {path.relative_to(folder).as_posix(): path.read_bytes() if path.is_file() else None
            for path in folder.rglob("*")}


def test_items_are_checked(ball):
    with pytest.raises(facet.Error, match="relative path"):
        facet.dask.Item("../up", ball)
    with pytest.raises(facet.Error, match="relative path"):
        facet.dask.Item(".facet-partial/x", ball)
    with pytest.raises(facet.Error, match="scene must be"):
        facet.dask.Item("x", facet.Scene())
    with pytest.raises(facet.Error, match="must not set 'threads'"):
        facet.dask.Item("x", ball, renderer={"threads": 2})
    with pytest.raises(facet.Error, match="used twice"):
        facet.dask.render_local([facet.dask.Item("x", ball), facet.dask.Item("x", ball)], "out")
    with pytest.raises(facet.Error, match="another item writes a_color_depth.npy"):
        facet.dask.render_local([facet.dask.Item("a", ball, outputs=("color_depth",)),
                                 facet.dask.Item("a_color", ball)], "out")
    with pytest.raises(facet.Error, match="no constructor"):
        facet.dask.camera("fisheye", eye=(0, 0, 1))
    with pytest.raises(facet.Error, match="Camera.look_at"):
        facet.dask.camera("look_at", eye=(0, 0, 1), target=(0, 0, 1))
    # A facet.Camera becomes a spec that makes the same camera.
    view = facet.Camera.look_at((0.1, 0.2, 3.3), (0, 0.01, 0), fov_y=37.7, near=0.3, far=9)
    remade = facet.dask.Item("x", ball, view).camera.make()
    assert np.array_equal(remade.view_matrix(), view.view_matrix())
    assert np.array_equal(remade.projection_matrix(1.5), view.projection_matrix(1.5))
    assert facet.dask.Item("x", ball).files() == {"color": "x_color.png", "depth": "x_depth.npy"}


def test_files_are_those_of_one_process(client, job, reference, tmp_path):
    # Each item's renderer with one thread here, every core in render_local; shards of one,
    # then facet.dask's own size.
    for shard_size, threads in ((None, 1), (1, 2)):
        out = tmp_path / f"shards_{shard_size}_threads_{threads}"
        index = facet.dask.render(client, job, out, shard_size=shard_size, threads=threads,
                                  progress=False)
        assert index.rendered == [item.stem for item in job]
        assert len({entry["process"] for entry in index.values()}) == 2  # both workers drew
        assert contents(out) == reference
        assert index["orbit/frame_03"]["files"] == {
            output: f"orbit/frame_03_{output}.{'png' if output == 'color' else 'npy'}"
            for output in facet.OUTPUTS}


def test_a_finished_job_run_again_renders_nothing(client, job, reference, tmp_path):
    facet.dask.render(client, job, tmp_path, progress=False)
    before = {path: path.stat() for path in tmp_path.rglob("*")}
    reported = []
    index = facet.dask.render(client, job, tmp_path,
                              progress=lambda index, done, total: reported.append((done, total)))
    assert index.skipped == [item.stem for item in job]
    assert index.rendered == [] and index.failed == []
    assert reported[-1] == (len(job), len(job))
    after = {path: path.stat() for path in tmp_path.rglob("*")}
    assert {p: (s.st_ino, s.st_mtime_ns) for p, s in after.items()} == {
        p: (s.st_ino, s.st_mtime_ns) for p, s in before.items()}
    assert contents(tmp_path) == reference


def test_a_failing_item_fails_alone(client, ball, tmp_path):
    items = [facet.dask.Item("good", ball, size=(32, 24)),
             facet.dask.Item("missing", tmp_path / "missing.obj"),
             facet.dask.Item("unknown_output", ball, outputs=("color", "sparkle")),
             facet.dask.Item("no_factory", facet.dask.factory("scenes:no_such_scene"))]
    with pytest.raises(facet.Error, match="3 of 4 items failed: missing: .*no such file") as caught:
        facet.dask.render(client, items, tmp_path / "out", shard_size=4, progress=False)
    index = caught.value.index
    assert index.rendered == ["good"]
    assert index.failed == ["missing", "unknown_output", "no_factory"]
    assert "sparkle" in index["unknown_output"]["error"]
    assert "no_such_scene" in index["no_factory"]["error"]
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["good_color.png",
                                                                     "good_depth.npy"]


class SlowAndLogged(WorkerPlugin):
    """Makes each item of a worker process take delay seconds more, and logs to log each item it
    begins ("render STEM PID TIME") and each file it has written ("wrote PATH PID TIME"); also set
    up in a worker that replaces a killed one."""

    name = "facet-test-slow-and-logged"

    def __init__(self, delay, log):
        self.delay, self.log = delay, str(log)

    def setup(self, worker):
        from facet import _job

        render, write = _job._render_item, _job._write_output
        delay, log = self.delay, self.log

        def note(line):
            descriptor = os.open(log, os.O_WRONLY | os.O_APPEND | os.O_CREAT)
            try:
                os.write(descriptor, f"{line} {os.getpid()} {time.time()}\n".encode())
            finally:
                os.close(descriptor)

        def slow_render(item, threads):
            note(f"render {item.stem}")
            time.sleep(delay)
            return render(item, threads)

        def logged_write(path, output, array, partial):
            write(path, output, array, partial)
            note(f"wrote {path}")

        _job._render_item, _job._write_output = slow_render, logged_write


def read_log(log):
    return [line.split() for line in log.read_text().splitlines()] if log.exists() else []


def test_a_worker_killed_mid_job_costs_only_time(job, reference, tmp_path):
    log = tmp_path / "log"
    out = tmp_path / "out"
    cluster, client = start_cluster()
    try:
        delay = 0.25
        client.register_worker_plugin(SlowAndLogged(delay, log))
        shard_size = 4
        shard_of = {item.stem: position // shard_size for position, item in enumerate(job)}
        killed = []

        def kill_one(index, done, total):
            if killed:
                return
            # Kill a worker in the first half of its sleep in an item of a shard of which it has
            # written an item already: a shard cut short, to be run again from the start.
            deadline = time.monotonic() + 20
            while True:
                begun = {}
                for what, stem, pid, when in read_log(log):
                    if what == "render":
                        begun.setdefault(pid, []).append((stem, float(when)))
                cut = [int(pid) for pid, stems in begun.items()
                       if len(stems) >= 2 and shard_of[stems[-1][0]] == shard_of[stems[-2][0]]
                       and time.time() - stems[-1][1] < delay / 2]
                if cut:
                    break
                assert time.monotonic() < deadline, "no worker began a second item of a shard"
                time.sleep(0.005)
            os.kill(cut[0], signal.SIGKILL)
            killed.append((cut[0], done, total))

        index = facet.dask.render(client, job, out, shard_size=shard_size, progress=kill_one)
        client.wait_for_workers(2, timeout=60)  # the nanny started another
        assert killed[0][0] not in client.run(os.getpid).values()
    finally:
        client.close()
        cluster.close()

    victim, done, total = killed[0]
    assert done < total
    # Every file is there once, whole and the same as one process writes; nothing else is.
    assert contents(out) == reference
    # No file was written twice: what the killed worker finished was not redone.
    wrote = [line[1] for line in read_log(log) if line[0] == "wrote"]
    assert sorted(wrote) == sorted(str(out / path) for path, data in reference.items() if data)
    begun = [line[1] for line in read_log(log) if line[0] == "render" and int(line[2]) == victim]
    finished, cut_short = [s for s in begun[:-1] if shard_of[s] == shard_of[begun[-1]]], begun[-1]
    assert finished and set(finished) <= set(index.skipped)
    assert index[cut_short]["status"] == "rendered"
    assert index[cut_short]["process"].rpartition("-")[2] != str(victim)
    assert len(index.rendered) + len(index.skipped) == len(job)


def test_the_example_renders_a_dataset_and_then_nothing(ball, tmp_path):
    def run(out, *where):
        command = [sys.executable, EXAMPLES / "dask_dataset.py", ball, out, "--views", 3,
                   "--size", "64x48", "--quiet", *where]
        result = subprocess.run(list(map(str, command)), capture_output=True, text=True,
                                timeout=120)
        assert result.returncode == 0, result.stderr
        return result.stdout

    out = tmp_path / "out"
    assert "on 1 workers: 3 rendered, 0 skipped, 0 failed" in run(out, "--workers", 1)
    assert "on 1 workers: 0 rendered, 3 skipped, 0 failed" in run(out, "--workers", 1)
    index = json.loads((out / "index.json").read_text())
    assert [view["stem"] for view in index["views"]] == ["view_000", "view_001", "view_002"]
    assert index["views"][2]["files"] == {"color": "view_002_color.png",
                                          "depth": "view_002_depth.npy"}
    assert np.load(out / "view_001_depth.npy").shape == (48, 64)
    assert "in this process: 3 rendered" in run(tmp_path / "local", "--local")
    local, dask = contents(tmp_path / "local"), contents(out)
    assert local.pop("index.json") != dask.pop("index.json")  # "rendered" there, "skipped" here
    assert local == dask
