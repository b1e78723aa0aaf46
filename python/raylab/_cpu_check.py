"""Whether this CPU runs the compiled part of raylab: checked before the extension is imported,
so that a module built for a newer processor fails with an ImportError that names what is
missing, not with SIGILL in the middle of the import.
"""

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


def missing_features(arch, cpuinfo="/proc/cpuinfo"):
    """The features a build for `arch` needs that the CPU described by `cpuinfo` lacks (Linux x86);
    none when the file cannot be read, since then nothing is known to be missing."""
    needed = _NEEDED.get(arch, _V3)
    if not needed:
        return []
    try:
        with open(cpuinfo, encoding="ascii", errors="replace") as info:
            for line in info:
                if line.startswith("flags"):
                    flags = set(line.split(":", 1)[1].split())
                    return [f for f in needed if f not in flags]
    except OSError:
        pass
    return []


def require_cpu(arch, cpuinfo="/proc/cpuinfo"):
    """Raises ImportError naming the missing features when this CPU cannot run a build for `arch`."""
    missing = missing_features(arch, cpuinfo)
    if missing:
        raise ImportError(
            "raylab was built for " + arch + " and this CPU lacks " + ", ".join(missing)
            + "; rebuild with cmake -DRAYLAB_ARCH=x86-64 (or pip install . with"
            " RAYLAB_CMAKE_ARGS=-DRAYLAB_ARCH=x86-64)"
        )
