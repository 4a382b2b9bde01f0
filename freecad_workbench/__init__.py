"""FairSplines: fair curves and surfaces for FreeCAD.

The macro API. Everything here works headless (``freecadcmd`` or plain
``/usr/bin/python3``); nothing imports the GUI.

    import freecad_workbench as fw
    curve = fw.csr_spline(points)            # Part.BSplineCurve, cubic, C2
    fw.curvature_sign_changes(curve)         # 0 for convex data
"""
from ._freecad import ensure_freecad_path as _ensure_freecad_path

_ensure_freecad_path()

from .errors import InputError, NoMonotoneSolution  # noqa: E402
from .csr import (  # noqa: E402
    csr_spline,
    interpolate_classic,
    quasi_interpolant,
    control_point_spline,
    quadratic_design,
)
from . import basic  # noqa: E402
from .design import ApproximationError, DesignResult, approximation_error, design_spline, revolve_profile  # noqa: E402
from . import shapes  # noqa: E402
from .blend import (  # noqa: E402
    BlendResult,
    blend_basic_shape,
    blend_chain,
    blend_naive,
    freeform_knots,
    join_basic_shapes,
    join_naive,
)
from .analysis import (  # noqa: E402
    CurvatureProfile,
    curvature_profile,
    curvature_sign_changes,
    curvature_extrema,
    max_distance,
)
from .monotone import (  # noqa: E402
    monotone_curvature_solution,
    monotone_curvature_design,
    monotone_end_conditions,
    clamp_to_fair_locations,
    check_monotone_curvature,
    curvature_variation,
    derivative_polygons,
)
from .fair_blend import (  # noqa: E402
    FairBlendReport,
    fair_blend,
    fair_blend_solution,
    fair_blend_space_solution,
    monotone_curvature_spline,
)
from .surface_analysis import (  # noqa: E402
    CurvatureMap,
    EdgeContinuity,
    SurfaceCurvature,
    curvature_map,
    edge_continuity,
    surface_curvature,
)
from .face_blend import FaceBlendReport, blend_errors, blend_faces  # noqa: E402
from .fair_fit import FairFitReport, fair_edge, fair_edge_report, fair_fit, fair_fit_report  # noqa: E402

__all__ = [
    "InputError",
    "csr_spline",
    "interpolate_classic",
    "quasi_interpolant",
    "control_point_spline",
    "quadratic_design",
    "basic",
    "design_spline",
    "DesignResult",
    "revolve_profile",
    "approximation_error",
    "ApproximationError",
    "CurvatureProfile",
    "curvature_profile",
    "curvature_sign_changes",
    "curvature_extrema",
    "max_distance",
    "shapes",
    "BlendResult",
    "blend_basic_shape",
    "blend_chain",
    "blend_naive",
    "join_basic_shapes",
    "join_naive",
    "freeform_knots",
    "NoMonotoneSolution",
    "fair_blend",
    "fair_blend_solution",
    "fair_blend_space_solution",
    "FairBlendReport",
    "monotone_curvature_spline",
    "monotone_curvature_solution",
    "monotone_curvature_design",
    "monotone_end_conditions",
    "clamp_to_fair_locations",
    "check_monotone_curvature",
    "curvature_variation",
    "derivative_polygons",
    "fair_fit",
    "fair_fit_report",
    "fair_edge",
    "fair_edge_report",
    "FairFitReport",
    "SurfaceCurvature",
    "surface_curvature",
    "EdgeContinuity",
    "edge_continuity",
    "CurvatureMap",
    "curvature_map",
    "FaceBlendReport",
    "blend_faces",
    "blend_errors",
]
__version__ = "0.1.0"
