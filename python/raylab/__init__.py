"""raylab: ray tracing structures, batched ray queries and rendering, with numpy arrays in and out.

    import raylab
    scene = raylab.load("bunny.obj").build("bvh")
    rays = raylab.pinhole_rays(640, 480, eye=(0, 0.1, 0.3), at=(0, 0.1, 0), fov=40)
    hits = scene.intersect(rays)          # dict of arrays of shape (480, 640)
    depth = hits["t"]

See docs/python.md for the walk-through.
"""


from ._build import ARCH as _ARCH  # noqa: E402
from ._cpu_check import require_cpu as _require_cpu  # noqa: E402

_require_cpu(_ARCH)

from ._raylab import (  # noqa: E402  (after the CPU check, on purpose)
    Mesh,
    Scene,
    SceneError,
    accelerators,
    compare,
    isa,
    load,
    pinhole_rays,
    quality,
    read_image,
    render,
    set_isa,
    usable_isas,
    write_image,
)
from ._raylab import __version__  # noqa: E402

__all__ = [
    "Mesh",
    "Scene",
    "SceneError",
    "accelerators",
    "compare",
    "isa",
    "load",
    "pinhole_rays",
    "quality",
    "read_image",
    "render",
    "set_isa",
    "usable_isas",
    "write_image",
    "__version__",
]
