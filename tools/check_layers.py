#!/usr/bin/env python3
"""Checks that includes flow downward through facet's layers (run by ctest as LayerIncludes).

Each folder below may include only the folders and public headers its layer is allowed; the
allowed order is written down once, here. A quoted include ("x/y.hpp") names a folder of src/
(or of bench/ for the benchmark scenes) or a public header (facet/*.hpp). Prints every
violation as FILE:LINE: message and exits 1 if there is one.
"""
import pathlib
import re
import sys

# Public headers, by the layer that implements them.
PUBLIC = {
    "core": {"camera", "color", "error", "facet", "framebuffer", "image_io", "light", "material",
             "mesh", "mesh_tools", "overlay", "render_texture", "renderer", "scene", "texture",
             "version"},
    "import": {"import"},
    "worlds": {"worlds", "procedural", "teapot", "islands"},
    "sound": {"sound"},
    "gl": {"gl"},
}

# Layers from the bottom up: a folder may include the folders listed for it (internal headers)
# and the public headers of the layers listed for it.
CORE_PUBLIC = ["core"]
RULES = {
    # facet::core, inside: core types < shading < pipeline stages.
    "src/core": (["core"], CORE_PUBLIC),
    "src/shading": (["core", "shading"], CORE_PUBLIC),
    "src/pipeline": (["core", "shading", "pipeline"], CORE_PUBLIC),
    # The other layers see the core's public API only.
    "src/import": (["import"], ["core", "import"]),
    "src/worlds": (["worlds"], ["core", "worlds"]),
    "src/sound": (["sound"], ["core", "sound"]),
    # The OpenGL twin draws a Scene as the core's renderer does, through the public API.
    "src/gl": (["gl"], ["core", "gl"]),
    # Public headers: each layer's own and those below it.
    "include/facet:core": ([], ["core"]),
    "include/facet:import": ([], ["core", "import"]),
    "include/facet:worlds": ([], ["core", "worlds"]),
    "include/facet:sound": ([], ["sound"]),
    "include/facet:gl": ([], ["core", "gl"]),
    # The classic rasterizers, for learners: the core's types and nothing more.
    "src/classic": (["classic"], CORE_PUBLIC),
    # Their demo program draws built-in and imported scenes with them.
    "apps/classic": (["classic"], ["core", "import", "worlds"]),
    # The benchmark scenes plug shading models into the pipeline (record/custom_draw.hpp).
    "bench/scenes": (["core", "shading", "pipeline", "scenes"], ["core", "import", "worlds"]),
    # The program: public headers and the benchmark scenes, nothing internal.
    "apps/facet": (["scenes"], ["core", "import", "worlds", "sound", "gl"]),
    # The Python module: the public API of the layers it binds, nothing internal.
    "python/src": ([], ["core", "import"]),
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def rule_for(path: pathlib.Path, root: pathlib.Path):
    relative = path.relative_to(root).as_posix()
    if relative.startswith("include/facet/"):
        stem = path.stem
        for layer, headers in PUBLIC.items():
            if stem in headers:
                return "include/facet:" + layer
        return None
    for folder in RULES:
        if relative.startswith(folder + "/"):
            return folder
    return None


def check(root: pathlib.Path) -> list[str]:
    problems = []
    tops = ("src", "include", "bench", "apps", "python")
    files = [p for top in tops for p in (root / top).rglob("*") if p.suffix in (".cpp", ".hpp", ".h")]
    for path in sorted(files):
        rule = rule_for(path, root)
        where = path.relative_to(root).as_posix()
        if rule is None:
            problems.append(f"{where}:1: not in any layer (add its folder to tools/check_layers.py)")
            continue
        folders, public_layers = RULES[rule]
        allowed_public = set().union(*(PUBLIC[layer] for layer in public_layers))
        for number, line in enumerate(path.read_text().splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            target = match.group(1)
            if "/" not in target:
                continue  # a header beside it (apps/facet)
            folder, rest = target.split("/", 1)
            if folder == "facet":
                header = pathlib.PurePosixPath(rest).stem
                if header not in allowed_public:
                    problems.append(f"{where}:{number}: includes {target}, a public header of a "
                                    f"layer {rule} may not use")
            elif folder not in folders:
                problems.append(f"{where}:{number}: includes {target}: {rule} may include only "
                                f"{', '.join(folders) or 'public headers'}")
    return problems


def main() -> int:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    problems = check(root)
    for problem in problems:
        print(problem)
    if problems:
        print(f"check_layers: {len(problems)} include(s) against the layer order")
        return 1
    print("check_layers: every include flows downward")
    return 0


if __name__ == "__main__":
    sys.exit(main())
