"""raylab: ray tracing structures, batched ray queries and rendering, with numpy arrays in and out.

    import raylab
    scene = raylab.load("bunny.obj").build("bvh")
    rays = raylab.pinhole_rays(640, 480, eye=(0, 0.1, 0.3), at=(0, 0.1, 0), fov=40)
    hits = scene.intersect(rays)          # dict of arrays of shape (480, 640)
    depth = hits["t"]

See docs/python.md for the walk-through.
"""


def _missing_cpu_features():
    """The instruction-set features the compiled module needs that this CPU lacks (Linux x86)."""
    needed = ("avx2", "fma", "bmi2")
    try:
        with open("/proc/cpuinfo", encoding="ascii", errors="replace") as info:
            for line in info:
                if line.startswith("flags"):
                    flags = set(line.split(":", 1)[1].split())
                    return [f for f in needed if f not in flags]
    except OSError:
        pass
    return []


_missing = _missing_cpu_features()
if _missing:
    # Importing the extension would end in SIGILL: say why instead.
    raise ImportError(
        "raylab was built for x86-64-v3 (AVX2, FMA) and this CPU lacks "
        + ", ".join(_missing)
        + "; rebuild with cmake -DRAYLAB_ARCH=x86-64"
    )

from ._raylab import (  # noqa: E402  (after the CPU check, on purpose)
    Mesh,
    Scene,
    SceneError,
    accelerators,
    compare,
    load,
    pinhole_rays,
    quality,
    read_image,
    render,
    write_image,
)
from ._raylab import __version__  # noqa: E402

__all__ = [
    "Mesh",
    "Scene",
    "SceneError",
    "accelerators",
    "compare",
    "load",
    "pinhole_rays",
    "quality",
    "read_image",
    "render",
    "write_image",
    "__version__",
]
