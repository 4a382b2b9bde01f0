"""The fair fit: a parametric fw.fair_fit of points taken from other objects (the same
sources as the csr fit: vertices, edges, Points objects, sketches; see csr_fit.py).
Headless; a view provider is attached only when FreeCAD.GuiUp.

    from freecad_workbench.features.fair_fit import make_fair_fit
    fit = make_fair_fit(doc, [scan_points], tolerance=0.05)
    fit.Status   # "ok: 42 poles, largest deviation 0.0093 mm, 0 curvature sign changes"

The curve stays within `Tolerance` of every point (checked by the kernel), with as few
poles as the fit finds and no more curvature sign changes than the data shows above its
`Noise` (0: estimated from the data). If the data is bad, or the tolerance cannot be met,
the feature keeps its last good shape and puts the message in `Status`.
"""
from ..errors import InputError
from ..fair_fit import fair_fit_report
from .base import FeatureProxy, attach_view_provider, set_if_changed
from .csr_fit import _describe, collect_points, normalize_sources, uses_edges
from .undo import undo_step

# (type, name, tooltip, default, editor mode); defaults are set only when a property is new.
_PROPERTIES = (
    ("App::PropertyLinkSubList", "Sources", "Vertices, edges, Points objects or sketches, in order", None, 0),
    ("App::PropertyLength", "Tolerance",
     "Largest distance allowed from any point to the curve. Every point is checked", 0.1, 0),
    ("App::PropertyLength", "Noise",
     "How much the points scatter about the shape they were measured from (standard deviation). "
     "0: estimated from the data (residuals of local quadratic fits)", 0.0, 0),
    ("App::PropertyBool", "Closed", "Fit a closed (periodic) curve", False, 0),
    ("App::PropertyInteger", "Samples", "Points taken from each source edge", 200, 0),
    ("App::PropertyEnumeration", "Corners",
     "Sharp corners of the points (a turn at one point, such as a trailing edge): Refuse (say where, fit nothing), "
     "Keep (one edge per stretch between corners, meeting at the corners), Smooth (one smooth curve through them)",
     "Refuse", 0),
    ("App::PropertyString", "Status",
     "'ok' with the number of poles, the largest deviation and the curvature sign changes, "
     "or why the last recompute failed", "ok", 1),
    ("App::PropertyInteger", "Version", "Version of this object's properties", 0, 2),
)


class FairFit(FeatureProxy):
    """Proxy of a Part::FeaturePython holding the fair fit of its Sources: the csr-spline
    (eq. (6)) of an adaptive subset of noise-smoothed points, within Tolerance of all."""

    Type = "FairFit"
    VERSION = 2  # 2: Corners (issue 25)
    GROUP = "Fair fit"
    PROPERTIES = _PROPERTIES
    ENUMERATIONS = {"Corners": ("Refuse", "Keep", "Smooth")}

    def build(self, obj):
        origins = []
        obj.setEditorMode("Samples", 0 if uses_edges(obj.Sources) else 2)
        tolerance = float(obj.Tolerance.Value)
        noise = float(obj.Noise.Value)
        if not tolerance > 0:
            raise InputError(f"Tolerance must be more than 0 mm, got {tolerance:g} mm")
        try:
            points, origins = collect_points(obj.Sources, obj.Samples, obj.Closed)
            curve, report = fair_fit_report(points, tolerance, closed=obj.Closed, noise=noise if noise > 0 else None,
                                            corners=str(obj.Corners).lower())
        except Exception as exc:
            raise InputError(_describe(exc, origins)) from exc
        self._status = report.status("mm")
        return curve if obj.Corners == "Keep" else curve.toShape()

    def execute(self, obj):
        self._status = "ok"
        super().execute(obj)  # raises on failure, keeping the last good shape
        set_if_changed(obj, "Status", self._status)


def make_fair_fit(doc, sources, tolerance=0.1, noise=None, closed=False, samples=200, corners="Refuse",
                  name="FairFit"):
    """Create a fair fit in `doc` and recompute, as one undoable step.

    sources: as make_csr_fit's (an object, ``(obj, "Vertex1")`` or ``(obj, ["Edge1", ...])``).
    tolerance in mm; noise in mm or None (estimated). Returns the new object; if the data is
    bad it exists with the message in its Status.
    """
    links = normalize_sources(sources)
    with undo_step(doc, "Create fair fit"):
        obj = doc.addObject("Part::FeaturePython", name)
        FairFit(obj)
        obj.Sources = links
        obj.Tolerance = float(tolerance)
        obj.Noise = 0.0 if noise is None else float(noise)
        obj.Closed = bool(closed)
        obj.Samples = int(samples)
        obj.Corners = corners
        attach_view_provider(obj, "ViewProviderFairFit")
        doc.recompute()
    return obj
