"""Norm-preserving texture mapping (Lai & Cheng) on NumPy arrays: the types of the compiled
module norm_preserving (norm_preserving.cpp), for type checkers and editors. The docstrings of
the functions are the module's own: help(norm_preserving.texture)."""

import os
from typing import Callable, ClassVar, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
Faces = Union[npt.NDArray[np.integer], Sequence[Sequence[int]]]
FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]

class _Enum:
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...
    def __int__(self) -> int: ...

class ErrorCode(_Enum):
    """The package's error codes (CGAL's Error_code)."""
    OK: ClassVar[ErrorCode]
    ERROR_EMPTY_MESH: ClassVar[ErrorCode]
    ERROR_NON_TRIANGULAR_MESH: ClassVar[ErrorCode]
    ERROR_NO_TOPOLOGICAL_DISC: ClassVar[ErrorCode]
    ERROR_NO_TOPOLOGICAL_BALL: ClassVar[ErrorCode]
    ERROR_BORDER_TOO_SHORT: ClassVar[ErrorCode]
    ERROR_NON_CONVEX_BORDER: ClassVar[ErrorCode]
    ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: ClassVar[ErrorCode]
    ERROR_NO_1_TO_1_MAPPING: ClassVar[ErrorCode]
    ERROR_WRONG_PARAMETER: ClassVar[ErrorCode]

class SolverStatus(_Enum):
    """How the QP solver of a component ended."""
    CONVERGED: ClassVar[SolverStatus]
    ITERATION_LIMIT: ClassVar[SolverStatus]
    TIME_LIMIT: ClassVar[SolverStatus]
    PRECISION_LIMIT: ClassVar[SolverStatus]
    FAILED: ClassVar[SolverStatus]

class Progress:
    """Where a texture() call is, as its progress callback receives it."""
    components: int
    components_done: int
    fraction: float
    seconds: float

class SolveReport:
    """What the QP solve of one component did (C++ Norm_preserving_solve_report)."""
    status: SolverStatus
    method: str
    has_statistics: bool
    iterations: int
    kkt_residual: float
    optimality_gap: float
    assembly_seconds: float
    factorization_seconds: float
    iteration_seconds: float
    message: str
    interrupted: bool

class Timings:
    """Where the time of one component went, in seconds (the solve's own steps: SolveReport)."""
    extraction: float
    guess: float
    solve: float
    sign_refinement: float
    euclidean_refinement: float
    write_back: float

class ComponentReport:
    """What the map of one connected component did (C++ Norm_preserving_report)."""
    status: ErrorCode
    message: str
    vertices: int
    edges: int
    fixed_a: int
    fixed_b: int
    initial_objective: float
    objective: float
    max_constraint_violation: float
    active_constraints: int
    constraints: int
    solver: SolveReport
    sign_refinement_rounds: int
    sign_refinement_objectives: List[float]
    euclidean_iterations: int
    euclidean_stress: List[float]
    seconds: float
    timings: Timings

class Distortion:
    """Distortion of a uv map (C++ Parameterization_distortion)."""
    faces: int
    edges: int
    scale: float
    edge_length_error: float
    l1_edge_length_error: float
    l1_objective: float
    mean_angle_distortion: float
    max_angle_distortion: float
    area_distortion: float
    l2_stretch: float
    linf_stretch: float
    flipped_faces: int
    flipped_area_fraction: float
    degenerate_uv_faces: int

class Report:
    """What a texture() call did (C++ Texture_polygon_mesh_report), and its distortion."""
    status: ErrorCode
    message: str
    components: int
    isolated_vertices: int
    welded_vertices: int
    repeated_corners: int
    point_components: int
    objective: float
    optimality_gap: float
    reports: List[ComponentReport]
    seconds: float
    interrupted: bool
    distortion: Distortion

class CutReport:
    """What an lscm() or arap() call did."""
    method: str
    components: int
    seam_edges: int
    seam_length: float
    cut_seconds: float
    seconds: float
    distortion: Distortion

def texture(
    vertices: ArrayLike,
    faces: Faces,
    *,
    guess: str = "xy",
    fit: str = "uniform",
    tiles: Tuple[int, int] = (1, 1),
    fixed_pair: Optional[Tuple[int, int]] = None,
    keep_coincident: bool = False,
    refine_signs: bool = False,
    refine_euclidean: bool = False,
    quality: str = "default",
    tolerance: Optional[float] = None,
    time_limit: Optional[float] = None,
    progress: Optional[Callable[[Progress], Optional[bool]]] = None,
) -> Tuple[FloatArray, Report]:
    """Textures a polygon soup: one uv per vertex, no cut, no seam. Returns (uv, report)."""

def measure_distortion(vertices: ArrayLike, faces: Faces, uv: ArrayLike) -> Distortion:
    """Measures the distortion of a uv map (one uv per vertex) of a polygon soup."""

def lscm(vertices: ArrayLike, faces: Faces) -> Tuple[Union[FloatArray, List[FloatArray]], CutReport]:
    """CGAL's LSCM on the mesh cut to a disk. Returns (uv per face corner, report)."""

def arap(vertices: ArrayLike, faces: Faces) -> Tuple[Union[FloatArray, List[FloatArray]], CutReport]:
    """CGAL's ARAP on the mesh cut to a disk. Returns (uv per face corner, report)."""

def write_obj(basename: Union[str, os.PathLike], vertices: ArrayLike, faces: Faces, uv: ArrayLike) -> None:
    """Writes basename.obj (one vt per vertex), basename.mtl and a checkerboard basename.png, all
    three or none, as the command-line tool does; basename with or without .obj."""

def read_mesh(path: Union[str, os.PathLike]) -> Tuple[FloatArray, Union[IntArray, List[IntArray]]]:
    """Reads a mesh file as the command-line tool does. Returns (vertices, faces)."""
