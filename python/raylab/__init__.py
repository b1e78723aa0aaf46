"""raylab: ray tracing structures, batched ray queries and rendering, with numpy arrays in and out.

    import raylab
    scene = raylab.load("bunny.obj").build("bvh")
    rays = raylab.pinhole_rays(640, 480, eye=(0, 0.1, 0.3), at=(0, 0.1, 0), fov=40)
    hits = scene.intersect(rays)          # dict of arrays of shape (480, 640)
    depth = hits["t"]

See docs/python.md for the walk-through.
"""


from ._build import ARCH as _ARCH  # noqa: E402

# What each -march level needs beyond baseline x86-64, as /proc/cpuinfo names it. The default
# build (x86-64) needs nothing more and picks its wider kernels at run time; a "native" build
# is checked for at least what x86-64-v3 needs.
_V3 = ("sse4_2", "popcnt", "avx", "avx2", "fma", "bmi1", "bmi2", "f16c", "movbe")
_NEEDED = {
    "x86-64": (),
    "x86-64-v2": ("sse4_2", "popcnt"),
    "x86-64-v3": _V3,
    "x86-64-v4": _V3 + ("avx512f", "avx512vl", "avx512bw", "avx512dq", "avx512cd"),
}


def _missing_cpu_features():
    """The instruction-set features the compiled module needs that this CPU lacks (Linux x86)."""
    needed = _NEEDED.get(_ARCH, _V3)
    if not needed:
        return []
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
        "raylab was built for " + _ARCH + " and this CPU lacks "
        + ", ".join(_missing)
        + "; rebuild with cmake -DRAYLAB_ARCH=x86-64"
    )

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
