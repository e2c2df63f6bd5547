"""facet.dask: a render job spread over a Dask cluster (Debian: python3-distributed).

    import distributed, facet.dask
    client = distributed.Client("tcp://scheduler:8786")      # or distributed.LocalCluster()
    items = facet.dask.orbit("model.glb", 100, size=(640, 480))   # or a list of facet.dask.Item
    index = facet.dask.render(client, items, "/shared/out")

Each task renders a shard of the items and writes their files into the output folder (which
every worker must see at the same path); the driver shows progress and returns an Index of what
was written. Files are written whole or not at all and complete items are skipped, so a shard
run again after its worker died, or a job run again, renders only what is missing. The files
are byte-identical to render_local's, whatever the number of workers and threads: each item is
rendered on its own by the same code (facet's frames do not depend on the thread count).
"""
import math
import os
import sys
import time
import uuid

from . import _facet
from . import _job
from ._job import PNG_OUTPUTS, CameraSpec, Factory, Index, Item, camera, factory, orbit

__all__ = [
    "PNG_OUTPUTS",
    "CameraSpec",
    "Factory",
    "Index",
    "Item",
    "camera",
    "factory",
    "orbit",
    "render",
    "render_local",
]

# Shards: at least this many per worker thread, so the threads finish together (the last shards
# are short), and at most this many items each, so progress and the work left on a lost worker
# stay small. A task costs the scheduler a few milliseconds, an item tens.
_SHARDS_PER_THREAD = 4
_MAX_SHARD_SIZE = 8


def render(client, items, out_dir, *, shard_size=None, threads=1, progress=True,
           raise_errors=True):
    """Renders items (facet.dask.Item) on client's workers into out_dir; returns the Index.

    shard_size: items per task (default: enough shards for 4 per worker thread, at most 8 items
        each). threads: render threads of each item's renderer (default 1: the workers' threads
        render items side by side). progress: True draws a bar on stderr, False nothing, a
        callable is called as progress(index, done, total) after each shard.
    A failed item (a missing model, an unknown output, a shard whose workers kept dying) does not
    stop the others; at the end raise_errors raises facet.Error naming the failures, with the
    Index as its .index. Run one job into a folder at a time.
    """
    from distributed import as_completed

    items = _job.check_items(items)
    out_dir = os.path.abspath(out_dir)
    os.makedirs(out_dir, exist_ok=True)
    if shard_size is None:
        worker_threads = max(1, sum(client.nthreads().values()))
        shard_size = min(_MAX_SHARD_SIZE,
                         max(1, len(items) // (_SHARDS_PER_THREAD * worker_threads)))
    if shard_size < 1:
        raise _facet.Error(f"render: shard_size must be at least 1, got {shard_size}")
    job = uuid.uuid4().hex[:12]
    batches = [items[first:first + shard_size] for first in range(0, len(items), shard_size)]
    futures = client.map(_job.run_shard, batches, [out_dir] * len(batches),
                         [threads] * len(batches),
                         key=[f"facet-render-{job}-{number}" for number in range(len(batches))])
    shards = dict(zip(futures, batches))

    index = Index(out_dir, items)
    report = _reporter(progress, len(items))
    done = 0
    try:
        for future in as_completed(shards):
            shard = shards.pop(future)
            if future.status == "finished":
                index.record(future.result())
            else:  # the shard raised outside its items, or the workers running it kept dying
                error = future.exception()
                message = f"{type(error).__name__}: {error}"
                index.record([{"stem": item.stem, "files": item.files(), "status": "failed",
                               "error": message, "seconds": 0.0, "process": ""}
                              for item in shard])
            future.release()
            done += len(shard)
            report(index, done, len(items))
    finally:
        for future in shards:  # only after an interruption
            future.cancel()
        report(index, done, len(items), final=True)
    _job.remove_partials(out_dir)
    return _finish(index, raise_errors)


def render_local(items, out_dir, *, threads=0, progress=False, raise_errors=True):
    """Renders items in this process, one after another, with the code a Dask task runs: the
    same files as render(). threads: each frame's render threads (default 0: every core)."""
    items = _job.check_items(items)
    out_dir = os.path.abspath(out_dir)
    os.makedirs(out_dir, exist_ok=True)
    index = Index(out_dir, items)
    report = _reporter(progress, len(items))
    done = 0
    try:
        for item in items:
            index.record(_job.run_shard([item], out_dir, threads))
            done += 1
            report(index, done, len(items))
    finally:
        report(index, done, len(items), final=True)
    _job.remove_partials(out_dir)
    return _finish(index, raise_errors)


def _finish(index, raise_errors):
    if raise_errors:
        try:
            index.raise_failures()
        except _facet.Error as error:
            error.index = index
            raise
    return index


def _reporter(progress, total):
    if callable(progress):
        return lambda index, done, total, final=False: None if final else progress(index, done,
                                                                                   total)
    if not progress:
        return lambda index, done, total, final=False: None
    return _Bar(sys.stderr, total)


class _Bar:
    """A progress line on stream: redrawn in place on a terminal (at most 10 times a second),
    else a line every 10 seconds; always a last line."""

    def __init__(self, stream, total):
        self.stream = stream
        self.terminal = stream.isatty()
        self.interval = 0.1 if self.terminal else 10.0
        self.start = self.shown = time.monotonic()
        self.closed = False

    def __call__(self, index, done, total, final=False):
        if self.closed:
            return
        now = time.monotonic()
        if not final and now - self.shown < self.interval:
            return
        self.shown = now
        seconds = now - self.start
        width = 24
        filled = width * done // total if total else width
        rate = done / seconds if seconds > 0 else 0.0
        left = f", {_duration((total - done) / rate)} left" if rate > 0 and done < total else ""
        line = (f"facet.dask: [{'#' * filled}{'.' * (width - filled)}] {done}/{total} items "
                f"({index.summary()}), {rate:.1f} items/s, {_duration(seconds)}{left}")
        if self.terminal:
            self.stream.write(f"\r{line}\033[K" + ("\n" if final else ""))
        else:
            self.stream.write(line + "\n")
        self.stream.flush()
        self.closed = final


def _duration(seconds):
    if seconds < 60:
        return f"{seconds:.1f} s"
    seconds = int(math.ceil(seconds))
    return f"{seconds // 3600}:{seconds // 60 % 60:02d}:{seconds % 60:02d}"
