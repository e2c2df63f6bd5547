"""facet: a CPU software rasterizer, for images and datasets of 3D scenes without a GPU.

    import facet
    scene = facet.load("model.glb")                  # or facet.Scene() and scene.add_mesh(...)
    camera = facet.Camera.look_at(eye=(2, 1, 3), target=(0, 0, 0))
    frame = facet.Renderer(640, 480).render(scene, camera)
    frame["color"]   # (480, 640, 4) uint8, sRGB
    frame["depth"]   # (480, 640) float32, distance along the camera axis; 0 where empty

Errors are facet.Error. `import facet.dask` spreads render jobs over a Dask cluster. docs/python.md
in facet's source tree has the whole story.
"""

from ._facet import (
    OUTPUTS,
    AnimatedModel,
    SHADING_MODELS,
    Camera,
    Error,
    Light,
    Material,
    Renderer,
    RenderTexture,
    Scene,
    Texture,
    __version__,
    load,
    write_png,
)

__all__ = [
    "OUTPUTS",
    "AnimatedModel",
    "SHADING_MODELS",
    "Camera",
    "Error",
    "Light",
    "Material",
    "Renderer",
    "RenderTexture",
    "Scene",
    "Texture",
    "__version__",
    "load",
    "write_png",
]
