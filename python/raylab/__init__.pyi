"""Type stub of the raylab module, for editors and type checkers (the module itself is compiled)."""

import os
from typing import Any, Sequence, TypedDict

import numpy as np
import numpy.typing as npt

__version__: str

_Path = str | os.PathLike[str]
_Floats = npt.ArrayLike
_Vec3 = tuple[float, float, float] | Sequence[float]

class Hits(TypedDict, total=False):
    """What Scene.intersect returns, each array of the rays' leading shape."""

    t: npt.NDArray[np.float32]
    """Distance in units of the direction; inf on a miss."""
    prim_id: npt.NDArray[np.int32]
    """Primitive hit (for a Mesh, the triangle's row); -1 on a miss."""
    object_id: npt.NDArray[np.int32]
    """Object of that primitive; -1 on a miss."""
    uv: npt.NDArray[np.float32]
    """(..., 2) barycentric weights of the triangle's vertices 1 and 2."""
    normal: npt.NDArray[np.float32]
    """(..., 3) unit geometric normal as the primitive is wound; 0 on a miss."""

class SceneError(ValueError):
    """A broken scene file, with the position of the error."""

    file: str
    line: int
    """1-based; 0 when not known."""
    column: int
    """1-based; 0 when not known."""

class Scene:
    """Primitives and the acceleration structure built over them (see raylab.load, raylab.Mesh)."""

    def build(self, accel: str = "bvh", *, threads: int | None = None, **config: Any) -> Scene:
        """Builds (or rebuilds) the structure named `accel` with its parameters; returns the scene."""
    def intersect(
        self,
        origins: _Floats,
        directions: _Floats | None = None,
        *,
        tmin: float | _Floats = 0.0,
        tmax: float | _Floats = float("inf"),
        threads: int | None = None,
        fields: Sequence[str] | None = None,
    ) -> Hits:
        """Closest hit of every ray: origins and directions (..., 3), or rays (..., 6)."""
    def occluded(
        self,
        origins: _Floats,
        directions: _Floats | None = None,
        *,
        tmin: float | _Floats = 0.0,
        tmax: float | _Floats = float("inf"),
        threads: int | None = None,
    ) -> npt.NDArray[np.bool_]:
        """Whether anything lies on each ray in [tmin, tmax)."""
    def count_intersections(
        self,
        origins: _Floats,
        directions: _Floats | None = None,
        *,
        tmin: float | _Floats = 0.0,
        tmax: float | _Floats = float("inf"),
        threads: int | None = None,
    ) -> npt.NDArray[np.uint32]:
        """How many primitives each ray crosses (shared edges and vertices count once)."""
    def contains(self, points: _Floats, *, threads: int | None = None) -> npt.NDArray[np.bool_]:
        """Whether each point (..., 3) lies inside the scene's closed surfaces."""
    @property
    def accel(self) -> str:
        """Name of the structure queries use."""
    @property
    def info(self) -> dict[str, Any]:
        """Build time, memory, node, leaf and primitive counts of the structure."""
    @property
    def primitive_count(self) -> int:
        """Number of primitives."""
    @property
    def bounds(self) -> npt.NDArray[np.float32]:
        """(2, 3): minimum row, maximum row."""
    @property
    def vertices(self) -> Any:
        """The vertex array a Mesh was made from, as given (None for a loaded scene)."""
    @property
    def triangles(self) -> Any:
        """The triangle array a Mesh was made from, as given (None for a loaded scene)."""

def Mesh(vertices: _Floats, triangles: npt.ArrayLike) -> Scene:
    """A triangle mesh from (N, 3) vertices and (M, 3) vertex indices."""

def load(path: _Path, *, allow_outside_paths: bool = False) -> Scene:
    """A scene file, mesh file, built-in scene ("demo") or SPD generator ("spd:balls")."""

def accelerators() -> list[str]:
    """Names of the structures this build has."""

def isa() -> str:
    """The instruction set of the kernels structures built from now on run: 'baseline', 'avx2' or 'avx512'."""

def set_isa(isa: str) -> None:
    """Makes `isa` the instruction set of structures built from now on; ValueError if this CPU cannot run it."""

def usable_isas() -> list[str]:
    """The instruction sets this build has and this CPU can run, narrowest first."""

def pinhole_rays(
    width: int, height: int, eye: _Vec3, at: _Vec3, up: _Vec3 = (0.0, 1.0, 0.0), fov: float = 45.0
) -> npt.NDArray[np.float32]:
    """(height, width, 6) rays through the pixel centres of a pinhole camera."""

def render(
    scene: Scene | _Path,
    *,
    width: int | None = None,
    height: int | None = None,
    spp: int | None = None,
    sampler: str | None = None,
    integrator: str | None = None,
    max_depth: int | None = None,
    env: str | os.PathLike[str] | None = None,
    env_rotate: float | None = None,
    accel: str = "bvh",
    threads: int | None = None,
) -> npt.NDArray[np.float32]:
    """Linear (H, W, 3) radiance image of the scene (integrator "whitted" or "path")."""

def read_image(path: _Path) -> npt.NDArray[np.float32]:
    """Reads a PNG (decoded to linear), EXR or PFM file as a linear (H, W, 3) array."""

def write_image(path: _Path, image: _Floats) -> None:
    """Writes an (H, W, 3) linear image as PNG, EXR or PFM by the extension."""

def compare(
    scene: Scene | _Path,
    *,
    accels: Sequence[str] | None = None,
    width: int = 256,
    height: int = 256,
    repeat: int = 3,
    threads: int | None = None,
) -> dict[str, Any]:
    """The figures of `raylab compare --json` for the scene."""


def quality(
    scene: Scene | _Path,
    *,
    samplers: Sequence[str] | None = None,
    budgets: Sequence[int] = (1, 4, 16, 64),
    seeds: int = 5,
    reference: _Path | _Floats | None = None,
    reference_spp: int = 1024,
    width: int | None = None,
    height: int | None = None,
    threads: int | None = None,
) -> dict[str, Any]:
    """The figures of `raylab quality --json`: samplers at budgets against a reference image."""
