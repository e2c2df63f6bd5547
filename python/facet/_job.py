"""Render jobs: what one item of a job is, and the per-item code that renders it and writes its
files. facet.dask spreads shards of a job over a Dask cluster with it; render_local runs the
same code in one process, so both write the same bytes.

An item's files are written whole or not at all: each is written into a folder of the writing
thread (OUT/.facet-partial/HOST-PID-THREAD/, removed when its shard ends) and renamed into place,
so a file that exists is complete, and an item whose files all exist is complete and is skipped.
A process killed mid-item leaves only its partial folder, which the next shard started on that
host removes (the process is gone), as does the end of the job where the driver sees the folder.
"""
import dataclasses
import importlib
import math
import os
import shutil
import socket
import threading
import time
from collections import OrderedDict

import numpy as np

from . import _facet as facet

PARTIAL_DIR = ".facet-partial"

# Outputs written as PNG; any other output is written with numpy.save as .npy, as rendered.
PNG_OUTPUTS = frozenset({"color"})

# The Renderer arguments an item does not set: the size is the item's, the render threads the job's.
_RENDERER_ARGUMENTS_OF_THE_JOB = frozenset({"width", "height", "threads"})


def _plain(value):
    """value with NumPy arrays and scalars as lists and floats, tuples for lists: a stable repr
    to key caches with, and a small pickle."""
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return tuple(_plain(v) for v in value)
    if isinstance(value, np.generic):
        return value.item()
    return value


@dataclasses.dataclass(frozen=True)
class CameraSpec:
    """A camera as the name of a facet.Camera constructor and its arguments, which pickles
    (facet.Camera does not) and is made on the worker: CameraSpec("look_at", (("eye", ...), ...))
    calls facet.Camera.look_at(eye=..., ...). Any constructor the module has can be named."""

    kind: str
    arguments: tuple = ()

    def make(self):
        constructor = getattr(facet.Camera, self.kind, None)
        if constructor is None or self.kind.startswith("_"):
            raise facet.Error(f"camera: facet.Camera has no constructor '{self.kind}'")
        return constructor(**dict(self.arguments))


def camera(kind="look_at", **arguments):
    """A picklable camera for a job item: camera("look_at", eye=(0, 1, 3), target=(0, 0, 0))
    stands for facet.Camera.look_at(eye=(0, 1, 3), target=(0, 0, 0)). The arguments are checked
    here, by making the camera once."""
    spec = CameraSpec(kind, tuple(sorted((k, _plain(v)) for k, v in arguments.items())))
    spec.make()
    return spec


def _camera_spec(value):
    """An item's camera as a CameraSpec (or None: the scene's own camera)."""
    if value is None or isinstance(value, CameraSpec):
        return value
    if isinstance(value, facet.Camera):
        # A perspective camera's fields are all attributes, and Camera.look_at stores them as
        # given, so the camera is remade exactly; the matrices are compared to make sure (a
        # camera of another kind differs from its look_at in its projection).
        spec = camera("look_at", eye=value.eye, target=value.target, up=value.up,
                      fov_y=value.fov_y, near=value.near, far=value.far)
        remade = spec.make()
        if not (np.array_equal(remade.view_matrix(), value.view_matrix())
                and np.array_equal(remade.projection_matrix(1.0), value.projection_matrix(1.0))):
            raise facet.Error(f"Item: camera {value!r} is not a look_at camera; give it as "
                              "facet.dask.camera(KIND, ...) with the constructor that made it")
        return spec
    raise facet.Error(f"Item: camera must be None, a facet.Camera or facet.dask.camera(...), "
                      f"got {type(value).__name__}")


@dataclasses.dataclass(frozen=True)
class Factory:
    """A scene made by a function, named "package.module:function" (importable on every worker)
    and called with args; scenes are cached per worker process by name and arguments."""

    name: str
    args: tuple = ()

    def __call__(self):
        module_name, _, function_name = self.name.partition(":")
        if not module_name or not function_name:
            raise facet.Error(f"factory: '{self.name}' is not 'module:function'")
        function = getattr(importlib.import_module(module_name), function_name, None)
        if function is None:
            raise facet.Error(f"factory: module {module_name} has no '{function_name}'")
        scene = function(*self.args)
        if not isinstance(scene, facet.Scene):
            raise facet.Error(f"factory: {self.name} returned {type(scene).__name__}, "
                              "not a facet.Scene")
        return scene


def factory(name, *args):
    """A scene made on the worker by calling the function name ("package.module:function")
    with args, for an item's scene."""
    return Factory(name, _plain(args))


def _check_stem(stem):
    if not isinstance(stem, str) or not stem:
        raise facet.Error(f"Item: stem must be a non-empty str, got {stem!r}")
    parts = stem.split("/")
    if os.path.isabs(stem) or "\\" in stem or any(p in ("", ".", "..") for p in parts) \
            or parts[0] == PARTIAL_DIR:
        raise facet.Error(f"Item: stem {stem!r} must be a relative path inside the output "
                          "folder, with '/' between its folders and no '.' or '..'")


@dataclasses.dataclass(frozen=True)
class Item:
    """One frame of a job and the files it writes, OUT/STEM_OUTPUT.png (color) and
    OUT/STEM_OUTPUT.npy (every other output, as rendered).

    stem: the files' name before _OUTPUT, relative to the output folder ("views/000" writes
          views/000_color.png); unique in a job.
    scene: a model file's path (facet.load; made absolute here) or facet.dask.factory(...).
    camera: None (the scene's camera), a facet.Camera made by look_at, or facet.dask.camera(...).
    outputs: names facet.Renderer.render accepts, passed through.
    size: (width, height).
    renderer: other facet.Renderer keyword arguments (background, exposure, ...).
    """

    stem: str
    scene: object
    camera: object = None
    outputs: tuple = ("color", "depth")
    size: tuple = (640, 480)
    renderer: tuple = ()

    def __post_init__(self):
        _check_stem(self.stem)
        scene = self.scene
        if isinstance(scene, (str, os.PathLike)):
            scene = os.path.abspath(os.fspath(scene))
        elif not isinstance(scene, Factory):
            raise facet.Error(f"Item {self.stem}: scene must be a model path or "
                              f"facet.dask.factory(...), got {type(scene).__name__}")
        outputs = (self.outputs,) if isinstance(self.outputs, str) else tuple(self.outputs)
        if not outputs or not all(isinstance(o, str) and o for o in outputs) \
                or len(set(outputs)) != len(outputs):
            raise facet.Error(f"Item {self.stem}: outputs must be distinct names, got {outputs!r}")
        size = tuple(int(s) for s in self.size)
        if len(size) != 2 or min(size) < 1:
            raise facet.Error(f"Item {self.stem}: size must be (width, height), got {self.size!r}")
        renderer = self.renderer.items() if isinstance(self.renderer, dict) else self.renderer
        renderer = tuple(sorted((str(k), _plain(v)) for k, v in renderer))
        for key, _ in renderer:
            if key in _RENDERER_ARGUMENTS_OF_THE_JOB:
                raise facet.Error(f"Item {self.stem}: renderer must not set '{key}' (the size "
                                  "is the item's, the render threads the job's)")
        object.__setattr__(self, "scene", scene)
        object.__setattr__(self, "camera", _camera_spec(self.camera))
        object.__setattr__(self, "outputs", outputs)
        object.__setattr__(self, "size", size)
        object.__setattr__(self, "renderer", renderer)

    def files(self):
        """{output: path relative to the output folder} of the files this item writes."""
        return {output: f"{self.stem}_{output}.{'png' if output in PNG_OUTPUTS else 'npy'}"
                for output in self.outputs}


def check_items(items):
    """items as a list of Item, with distinct stems and files."""
    items = list(items)
    stems, files = set(), set()
    for index, item in enumerate(items):
        if not isinstance(item, Item):
            raise facet.Error(f"items[{index}] is a {type(item).__name__}, not a facet.dask.Item")
        if item.stem in stems:
            raise facet.Error(f"items[{index}]: stem '{item.stem}' is used twice")
        stems.add(item.stem)
        for name in item.files().values():
            if name in files:
                raise facet.Error(f"items[{index}] ({item.stem}): another item writes {name} too")
            files.add(name)
    return items


def orbit(scene, count, *, frames=None, stem="frame_{:04d}", size=(640, 480),
          outputs=("color", "depth"), elevation=20.0, fov_y=45.0, renderer=()):
    """Items of a frame range: the camera circles the scene's bounds about the y axis, frame i
    at angle 2*pi*i/count (from +z towards +x), elevation degrees above its centre, and frames
    (a range; default all count) picks which of them. The scene is loaded here once to frame it."""
    if count < 1:
        raise facet.Error(f"orbit: count must be at least 1, got {count}")
    frames = range(count) if frames is None else frames
    loaded = scene() if isinstance(scene, Factory) else facet.load(os.fspath(scene))
    if loaded.bounds is None:
        raise facet.Error(f"orbit: {scene} has nothing to frame")
    lower, upper = (np.array(corner, np.float64) for corner in loaded.bounds)
    center = (lower + upper) / 2.0
    radius = max(float(np.linalg.norm(upper - lower)) / 2.0, 1e-6)
    half = math.radians(fov_y) / 2.0
    aspect = size[0] / size[1]
    if aspect < 1.0:
        half = math.atan(math.tan(half) * aspect)  # the narrower side holds the sphere
    distance = 1.1 * radius / math.sin(half)
    near, far = max(distance - 1.05 * radius, distance * 1e-3), distance + 1.05 * radius
    up = math.radians(elevation)
    items = []
    for frame in frames:
        if not 0 <= frame < count:
            raise facet.Error(f"orbit: frame {frame} is outside 0..{count - 1}")
        angle = 2.0 * math.pi * frame / count
        direction = (math.cos(up) * math.sin(angle), math.sin(up), math.cos(up) * math.cos(angle))
        eye = center + distance * np.array(direction)
        view = camera("look_at", eye=eye, target=center, up=(0.0, 1.0, 0.0), fov_y=fov_y,
                      near=near, far=far)
        items.append(Item(stem.format(frame), scene, view, outputs, size, renderer))
    return items


# Per process: the scenes items name, loaded once (the most recently used few are kept), each
# as [lock, scene].
_SCENE_CACHE_SIZE = 4
_scenes = OrderedDict()
_scenes_lock = threading.Lock()
# Per thread: one renderer for each size and set of arguments, reused from item to item (the
# most recently used few).
_RENDERER_CACHE_SIZE = 4
_renderers = threading.local()


def _scene(spec):
    key = spec if isinstance(spec, str) else ("factory", spec.name, repr(spec.args))
    with _scenes_lock:
        entry = _scenes.get(key)
        if entry is None:
            entry = _scenes[key] = [threading.Lock(), None]
        _scenes.move_to_end(key)
        while len(_scenes) > _SCENE_CACHE_SIZE:
            _scenes.popitem(last=False)
    with entry[0]:  # threads wanting one scene load it once; other scenes are not held up
        if entry[1] is None:
            entry[1] = facet.load(spec) if isinstance(spec, str) else spec()
        return entry[1]


def _renderer(item, threads):
    cache = _renderers.__dict__.setdefault("by_key", OrderedDict())
    key = (item.size, threads, repr(item.renderer))
    if key in cache:
        cache.move_to_end(key)
    else:
        cache[key] = facet.Renderer(*item.size, threads, **dict(item.renderer))
        while len(cache) > _RENDERER_CACHE_SIZE:  # a job has one or a few sizes
            cache.popitem(last=False)
    return cache[key]


def _render_item(item, threads):
    """The item's frame: {output: array}."""
    scene = _scene(item.scene)
    view = item.camera.make() if item.camera is not None else None
    return _renderer(item, threads).render(scene, view, item.outputs)


def _process_name():
    return f"{socket.gethostname()}-{os.getpid()}"


def _partial_dir(out_dir):
    """This thread's folder for the files it is writing: OUT/.facet-partial/HOST-PID-THREAD."""
    return os.path.join(out_dir, PARTIAL_DIR, f"{_process_name()}-{threading.get_native_id()}")


def _write_output(path, output, array, partial):
    """Writes one output's file: into the thread's partial folder, then renamed into place."""
    temporary = os.path.join(partial, os.path.basename(path))
    try:
        if output in PNG_OUTPUTS:
            facet.write_png(temporary, array)
        else:
            with open(temporary, "wb") as file:
                np.save(file, array)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.remove(temporary)
        raise


def _run_item(item, out_dir, threads):
    start = time.perf_counter()
    files = item.files()
    result = {"stem": item.stem, "files": files, "process": _process_name()}
    missing = [o for o, name in files.items() if not os.path.exists(os.path.join(out_dir, name))]
    if not missing:
        return {**result, "status": "skipped", "seconds": time.perf_counter() - start}
    try:
        frame = _render_item(item, threads)
        partial = _partial_dir(out_dir)
        os.makedirs(os.path.dirname(os.path.join(out_dir, item.stem)), exist_ok=True)
        os.makedirs(partial, exist_ok=True)
        # Only the missing files: a file of an item that was cut short is already whole.
        for output in missing:
            _write_output(os.path.join(out_dir, files[output]), output, frame[output], partial)
    except Exception as error:  # the item fails, the shard goes on
        message = error if isinstance(error, facet.Error) else f"{type(error).__name__}: {error}"
        return {**result, "status": "failed", "error": str(message),
                "seconds": time.perf_counter() - start}
    return {**result, "status": "rendered", "seconds": time.perf_counter() - start}


def _process_alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def remove_dead_partials(out_dir):
    """Removes the partial folders of this host's processes that are gone (killed mid-write)."""
    folder = os.path.join(out_dir, PARTIAL_DIR)
    host = socket.gethostname()
    try:
        names = os.listdir(folder)
    except FileNotFoundError:
        return
    for name in names:
        owner, pid, _ = (name.rsplit("-", 2) + ["", ""])[:3]
        if owner == host and pid.isdigit() and not _process_alive(int(pid)):
            shutil.rmtree(os.path.join(folder, name), ignore_errors=True)


def remove_partials(out_dir):
    """Removes OUT/.facet-partial once no shard of the job runs: what is left in it are pieces
    of files whose writers died."""
    shutil.rmtree(os.path.join(out_dir, PARTIAL_DIR), ignore_errors=True)


def run_shard(items, out_dir, threads):
    """Renders the items that are not complete and writes their files; one result per item:
    {"stem", "files", "status": "rendered" | "skipped" | "failed", "seconds", "process",
    "error" (when failed)}."""
    remove_dead_partials(out_dir)
    try:
        return [_run_item(item, out_dir, threads) for item in items]
    finally:
        try:
            os.rmdir(_partial_dir(out_dir))
        except OSError:  # never made (nothing written), or not empty (a failed removal)
            pass


class Index(dict):
    """What a job wrote: {stem: {"files": {output: path relative to out_dir}, "status":
    "rendered" | "skipped" | "failed", "seconds", "process": "HOST-PID", "error" (failed)}},
    in the job's order; out_dir is the folder the paths are in."""

    def __init__(self, out_dir, items):
        super().__init__((item.stem, None) for item in items)
        self.out_dir = out_dir

    def _with(self, status):
        return [stem for stem, entry in self.items() if entry and entry["status"] == status]

    @property
    def rendered(self):
        return self._with("rendered")

    @property
    def skipped(self):
        return self._with("skipped")

    @property
    def failed(self):
        return self._with("failed")

    def record(self, results):
        for result in results:
            self[result.pop("stem")] = result

    def summary(self):
        return (f"{len(self.rendered)} rendered, {len(self.skipped)} skipped, "
                f"{len(self.failed)} failed")

    def raise_failures(self):
        failed = self.failed
        if failed:
            shown = "; ".join(f"{stem}: {self[stem]['error']}" for stem in failed[:3])
            more = f" (and {len(failed) - 3} more)" if len(failed) > 3 else ""
            raise facet.Error(f"{len(failed)} of {len(self)} items failed: {shown}{more}")
