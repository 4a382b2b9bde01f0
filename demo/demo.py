"""FairSplines headless demo: run by `make demo` as `freecadcmd demo/demo.py`.

Builds the csr paper's Fig. 2 situation, a half circle continued by an almost flat
parabola and sampled uniformly, and fits the samples with the csr-spline (as a
parametric CsrFit feature that follows its Points source) and with the baselines.
Writes into $FAIRSPLINES_OUT (default: out/demo):
  fairsplines_demo.FCStd   the document (open it in FreeCAD)
  fig2_curvature.png       curvature against arc length: csr-spline and classic interpolation
  fig2_curves.png          the curves with the samples and their curvature combs
  design_curvature.png     design with basic curves (Figs. 14 and 10): curvature plots
  monotone_curvature.png   a monotone-curvature blend against classic interpolation
  fair_blend_curvature.png a G2 fair blend of a line into an arc beside the quintic Bezier
                           that matches the same end derivatives
  blend_patches.png        a sphere zone blended C2 into a bicubic ring (blending paper)
  blend_join.png           basic shape to basic shape: a cylinder into a spherical dome and
                           two differently partitioned cones (Figs. 9-11)
  summary.txt              the measured figures
"""
import math
import os
import sys

import numpy as np

import FreeCAD
import Part
import Points

import freecad_workbench as fw
from freecad_workbench.features import (
    make_basic_curve,
    make_csr_fit,
    make_design_spline,
    make_fair_blend,
    make_monotone_blend,
    make_profile_test,
)
from freecad_workbench.gui.comb import comb_lines
from freecad_workbench.gui.plot import curvature_plot


def fig2_samples(per_half_circle=12, parabola_samples=19):
    h = math.pi / per_half_circle
    a = np.arange(per_half_circle + 1) * h
    s = np.arange(1, parabola_samples + 1) * h
    return np.r_[np.c_[np.cos(a), np.sin(a)], np.c_[-1.0 + 0.02 * s**2, -s]]


def add_shape(doc, name, shape, color):
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = shape
    if FreeCAD.GuiUp:
        obj.ViewObject.LineColor = color
    return obj


def picture_of_curves(path, samples, curves):
    """Side by side, zoomed on the transition: each curve with its curvature comb drawn
    outside (teeth cross to the inside where the curvature changes sign)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(11, 6), dpi=100)
    FigureCanvasAgg(fig)
    for index, ((label, curve), color) in enumerate(zip(curves, ("black", "tab:red")), start=1):
        ax = fig.add_subplot(1, len(curves), index)
        comb = comb_lines(curve, scale=-0.6, n=600)
        for base, tip in zip(comb.base, comb.tip):
            ax.plot([base[0], tip[0]], [base[1], tip[1]], color="tab:blue", linewidth=0.4, alpha=0.6)
        ax.plot(comb.tip[:, 0], comb.tip[:, 1], color="tab:blue", linewidth=0.8)
        u = np.linspace(curve.FirstParameter, curve.LastParameter, 2000)
        points = np.array([tuple(curve.value(x)) for x in u])
        ax.plot(points[:, 0], points[:, 1], color=color, linewidth=1.8, label=label)
        ax.plot(samples[:, 0], samples[:, 1], "o", color="tab:green", markersize=4, label="samples")
        ax.set_xlim(-1.9, 0.1)
        ax.set_ylim(-2.2, 1.0)
        ax.set_aspect("equal")
        ax.set_title(f"{label}: {fw.curvature_sign_changes(curve)} curvature sign changes")
        ax.legend(loc="lower right")
    fig.suptitle("Fig. 2 data at the circle-parabola transition, with curvature combs")
    fig.tight_layout()
    fig.savefig(path)


def design_with_basic_curves(doc, out, lines):
    """Fig. 14 as parametric objects (BasicCurve pieces, a DesignSpline with marks, its
    ProfileTest surface of revolution), and Fig. 10 (semi-circle and semi-ellipse apart,
    joined by an edge) through the macro API."""
    quarter = make_basic_curve(doc, "Circle arc", name="QuarterCircle", Radius=1.0, StartAngle=0.0, EndAngle=90.0)
    line = make_basic_curve(doc, "Line segment", name="TouchingLine", Start=FreeCAD.Vector(0, 1, 0),
                            End=FreeCAD.Vector(-2, 1, 0))
    marks = [0.25, 0.5, 0.75]
    design = make_design_spline(doc, [(quarter, marks), (line, marks)], name="DesignSpline")
    profile = make_profile_test(doc, design, axis_point=FreeCAD.Vector(0, -1.5, 0),
                                axis_direction=FreeCAD.Vector(1, 0, 0), name="ProfileTest")
    doc.recompute()
    for obj in (quarter, line, design, profile):
        if obj.Status != "ok":
            raise SystemExit(f"demo: {obj.Label} failed: {obj.Status}")
    curve = design.Shape.Edges[0].Curve
    circle = fw.basic.CircleArc((0, 0, 0), 1.0, 0.0, math.pi / 2)
    details = fw.design_spline([(circle, marks), (fw.basic.LineSegment((0, 1, 0), (-2, 1, 0)), marks)], details=True)
    (t0, scale), u = details.ranges[0], details.marks[0]
    exact = max(abs(curve.value(t0 + scale * x).Length - 1.0) for x in np.linspace(0, u[-3], 200))

    semicircle = fw.basic.CircleArc((4, 0, 0), 1.0, -math.pi / 2, math.pi / 2)
    semiellipse = fw.basic.EllipseArc((3.4, 0, 0), 1.6, 1.0, math.pi / 2, 3 * math.pi / 2)
    fig10 = fw.design_spline([(semicircle, [0.2, 0.4, 0.6, 0.8]), (semiellipse, [0.2, 0.4, 0.6, 0.8])],
                             details=True)
    add_shape(doc, "CircleEllipseDesign", fig10.curve.toShape(), (0.0, 0.0, 0.0))

    lines += ["", "Design with basic curves (Fig. 14: quarter circle + touching line, 3 marks each)",
              f"  joins: {list(design.Joins)}, continuity {curve.Continuity}, "
              f"curvature sign changes {fw.curvature_sign_changes(curve)}",
              f"  circle piece kept exact: largest |radius - 1| up to its second last mark = {exact:.1e}",
              f"  profile test: exact surface of revolution, {profile.Shape.Faces[0].Surface.NbUPoles} x "
              f"{profile.Shape.Faces[0].Surface.NbVPoles} poles",
              f"  Fig. 10 circle + ellipse: joins {fig10.joins}, continuity {fig10.curve.Continuity}, "
              f"curvature sign changes {fw.curvature_sign_changes(fig10.curve)}"]
    curvature_plot(
        [(curve, "quarter circle + line, C2 design"), (fig10.curve, "semi-circle + semi-ellipse (Fig. 10)")],
        path=os.path.join(out, "design_curvature.png"),
        title="Design with basic curves: curvature against arc length",
    )


def monotone_blend(doc, out, lines):
    """Two line segments bridged by a cubic B-spline whose curvature is monotone
    (Algorithm 2, the fairest admissible curve), as a parametric Monotone blend; beside it
    classic interpolation of the same ends, whose curvature has an extremum."""
    a = doc.addObject("Part::Feature", "LeadIn")
    a.Shape = Part.makeLine(FreeCAD.Vector(-7, -0.7, 0), FreeCAD.Vector(3, 0.3, 0))
    b = doc.addObject("Part::Feature", "LeadOut")
    b.Shape = Part.makeLine(FreeCAD.Vector(7, 5.5, 0), FreeCAD.Vector(9, 10.5, 0))
    blend = make_monotone_blend(doc, (a, "Edge1"), (b, "Edge1"), start_end="last", end_end="first",
                                name="MonotoneBlend")
    doc.recompute()
    if blend.Status != "ok":
        raise SystemExit(f"demo: the monotone blend failed: {blend.Status}")
    curve = blend.Shape.Edges[0].Curve
    report = fw.check_monotone_curvature(curve)
    ends = [curve.value(curve.FirstParameter), curve.value(curve.LastParameter)]
    hermite = Part.BSplineCurve()
    hermite.interpolate([ends[0], FreeCAD.Vector(5.6, 1.9, 0), ends[1]],
                        InitialTangent=curve.tangent(curve.FirstParameter)[0],
                        FinalTangent=curve.tangent(curve.LastParameter)[0])
    lines += ["", "Monotone-curvature blend (Algorithm 2, fairest admissible curve)",
              f"  certificate: monotone={report.monotone}, increasing={report.increasing}, "
              f"decreasing={report.decreasing}; curvature extrema inside: {len(fw.curvature_extrema(curve))}",
              f"  classic interpolation through a middle point: {len(fw.curvature_extrema(hermite))} curvature extrema"]
    curvature_plot([(curve, "monotone blend"), (hermite, "classic interpolation, same ends")],
                   path=os.path.join(out, "monotone_curvature.png"),
                   title="Monotone-curvature blend: curvature against arc length")


def fair_blend(doc, out, lines):
    """A line into a circle arc (radius 10), G2: the Fair blend, whose curvature rises
    monotonically (certified) from the line's 0 to the arc's 1/10, beside the quintic Bezier
    with the same end points, tangents and curvatures (what derivative-matching blends
    build; here it happens to be monotone too, in 24.5% of the benchmark's ends)."""
    # The arc continues the clothoid kappa(s) = s / 200 (s in [0, 20]) from the origin, so a
    # monotone G2 blend exists (Simpson's rule for the clothoid's end).
    s = np.linspace(0.0, 20.0, 40001)
    theta = s**2 / 400.0
    w = np.ones_like(s)
    w[1:-1:2], w[2:-1:2] = 4.0, 2.0
    h = (s[1] - s[0]) / 3.0
    x0, y0 = 0.0, -14.0  # below the other demo curves
    end = FreeCAD.Vector(x0 + h * np.sum(w * np.cos(theta)), y0 + h * np.sum(w * np.sin(theta)), 0)
    centre = end + FreeCAD.Vector(-math.sin(1.0), math.cos(1.0), 0) * 10.0
    lead = doc.addObject("Part::Feature", "FairLeadIn")
    lead.Shape = Part.makeLine(FreeCAD.Vector(x0 - 10, y0, 0), FreeCAD.Vector(x0, y0, 0))
    arc = doc.addObject("Part::Feature", "FairArc")
    start = 1.0 - math.pi / 2
    arc.Shape = Part.ArcOfCircle(Part.Circle(centre, FreeCAD.Vector(0, 0, 1), 10), start, start + 2.0).toShape()
    blend = make_fair_blend(doc, (lead, "Edge1"), (arc, "Edge1"), name="FairBlend")
    doc.recompute()
    if blend.Status != "ok":
        raise SystemExit(f"demo: the fair blend failed: {blend.Status}")
    curve = blend.Shape.Edges[0].Curve
    report = fw.check_monotone_curvature(curve)
    # The quintic Bezier with the same 2-jets (speed = chord).
    p0, p1 = curve.value(curve.FirstParameter), curve.value(curve.LastParameter)
    r = (p1 - p0).Length
    t0, t1 = FreeCAD.Vector(1, 0, 0), FreeCAD.Vector(math.cos(1.0), math.sin(1.0), 0)
    n1 = FreeCAD.Vector(-t1.y, t1.x, 0)
    quintic = Part.BezierCurve()
    quintic.setPoles([p0, p0 + t0 * (r / 5), p0 + t0 * (2 * r / 5), p1 - t1 * (2 * r / 5) + n1 * (r * r * 0.1 / 20),
                      p1 - t1 * (r / 5), p1])
    lines += ["", "Fair blend, G2: a line into a circle arc (radius 10)",
              f"  certificate: monotone={report.monotone}, increasing={report.increasing}; "
              f"spans: {len(curve.getKnots()) - 1}; curvature extrema inside: {len(fw.curvature_extrema(curve))}",
              f"  end curvatures: {curve.curvature(curve.FirstParameter):.3g} and "
              f"{curve.curvature(curve.LastParameter):.6g}",
              f"  quintic Bezier with the same end derivatives: {len(fw.curvature_extrema(quintic))} curvature extrema"]
    curvature_plot([(curve, "fair blend (G2)"), (quintic, "quintic Bezier, same end derivatives")],
                   path=os.path.join(out, "fair_blend_curvature.png"),
                   title="G2 blend of a line into an arc: curvature against arc length")


def blended_sphere_zone(doc, out, lines):
    """A sphere zone of 8 x 4 non-uniform patches joined C2 to a bicubic ring by a (6,5)
    transition strip (blending paper, Section 4.2), against the naive Hermite strip."""
    longitudes = np.cumsum(np.r_[0.0, np.linspace(0.6, 1.0, 8)])
    longitudes = longitudes / longitudes[-1] * 2 * math.pi
    latitudes = np.radians([-40.0, -15.0, 5.0, 20.0, 40.0])
    zone = fw.shapes.SphereZone((0, 0, 12), 3.0, longitudes, latitudes)
    blended = fw.blend_basic_shape(zone)
    naive = fw.blend_naive(zone)
    c1 = fw.blend_basic_shape(zone, continuity="C1")  # Section 5: (4,2) strip to biquadratic NURBS
    obj = doc.addObject("Part::Feature", "BlendedSphereZone")
    obj.Shape = blended.shell
    roles = {}
    for role, _ in blended.patches:
        roles[role] = roles.get(role, 0) + 1
    lines += ["", "Sphere zone blended C2 into a bicubic ring (8 x 4 non-uniform patches)",
              f"  patches: {roles}, shell valid: {blended.shell.isValid()}, "
              f"single surface: {blended.surface.Continuity if blended.surface else None}",
              f"  naive baseline single surface: {naive.surface}",
              f"  C1 variant (Section 5): {len(c1.patches)} patches, shell valid: {c1.shell.isValid()}, "
              f"single surface: {c1.surface.Continuity if c1.surface else None}"]
    picture_of_blend(os.path.join(out, "blend_patches.png"), blended)


def joined_basic_shapes(doc, out, lines):
    """Basic shape to basic shape (blending paper, Figs. 9-11): a circular post under a
    spherical dome, and two cones partitioned differently around their axis; each joined by
    one C2 (6,5) transition row, both shapes kept exact."""
    around = np.radians([0.0, 50.0, 95.0, 160.0, 215.0, 290.0, 360.0])
    other = np.radians([10.0, 70.0, 100.0, 175.0, 240.0, 300.0, 370.0])
    post = fw.shapes.Cylinder((16, 0, 0), 2.0, around, [0.0, 2.0, 4.0])
    dome = fw.shapes.SphereZone((16, 0, 5.5), 2.0, around, np.radians([15.0, 50.0, 90.0]))
    lower = fw.shapes.Cone((24, 0, 0), 2.5, 0.15, around, [0.0, 1.5, 3.0])
    upper = fw.shapes.Cone((24, 0, 0), 3.6, -0.25, other, [4.5, 6.0, 7.5])
    pictures = []
    for name, (a, b) in (("PostAndDome", (post, dome)), ("TwoCones", (lower, upper))):
        joined = fw.join_basic_shapes(a, b)
        naive = fw.join_naive(a, b)
        obj = doc.addObject("Part::Feature", name)
        obj.Shape = joined.shell
        roles = {}
        for role, _ in joined.patches:
            roles[role] = roles.get(role, 0) + 1
        lines += ["", f"Basic shape to basic shape: {name}",
                  f"  patches: {roles}, shell valid: {joined.shell.isValid()}, "
                  f"single surface: {joined.surface.Continuity if joined.surface else None}, "
                  f"naive join single surface: {naive.surface}"]
        pictures.append(joined)
    picture_of_blend(os.path.join(out, "blend_join.png"), *pictures,
                     title="Cylinder into a dome, cone into cone: basic (blue), (6,5) transition (orange)")


def picture_of_blend(path, *blends, title="Sphere zone (blue), (6,5) transition (orange), bicubic ring (green)"):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7, 6), dpi=100)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(1, 1, 1, projection="3d")
    colors = {"basic": "tab:blue", "transition": "tab:orange", "freeform": "tab:green"}
    for blended in blends:
        for role, surface in blended.patches:
            u0, u1, v0, v1 = surface.bounds()
            grid = np.array([[tuple(surface.value(u, v)) for v in np.linspace(v0, v1, 6)]
                             for u in np.linspace(u0, u1, 6)])
            ax.plot_surface(grid[..., 0], grid[..., 1], grid[..., 2], color=colors.get(role, "grey"), alpha=0.8,
                            linewidth=0.2, edgecolor="k")
    ax.set_title(title)
    ax.set_box_aspect((1, 1, 0.8) if len(blends) == 1 else (2, 1, 1))
    fig.tight_layout()
    fig.savefig(path)


def main():
    out = os.environ.get("FAIRSPLINES_OUT", os.path.join(os.getcwd(), "out", "demo"))
    os.makedirs(out, exist_ok=True)
    samples = fig2_samples()

    doc = FreeCAD.newDocument("FairSplinesDemo")
    cloud = doc.addObject("Points::Feature", "Fig2Samples")
    cloud.Points = Points.Points([FreeCAD.Vector(x, y, 0) for x, y in samples])
    fit = make_csr_fit(doc, [cloud], name="CsrSpline")

    classic = fw.interpolate_classic(samples)
    curves = {
        "csr-spline": fit,
        "classic C2 interpolation": add_shape(doc, "ClassicInterpolation", classic.toShape(), (0.8, 0.1, 0.1)),
        "quasi-interpolant": add_shape(doc, "QuasiInterpolant", fw.quasi_interpolant(samples).toShape(), (1, 0.6, 0)),
        "data as control points": add_shape(
            doc, "ControlPointSpline", fw.control_point_spline(samples).toShape(), (0.5, 0.5, 0.5)
        ),
    }
    sparse = samples[::4]
    add_shape(doc, "QuadraticDesign", fw.quadratic_design(sparse).toShape(), (0.1, 0.6, 0.1))
    theta = np.linspace(0, 2 * math.pi, 24, endpoint=False)
    ellipse = np.c_[3 + 1.5 * np.cos(theta), 0.6 * np.sin(theta)]
    closed_cloud = doc.addObject("Points::Feature", "EllipseSamples")
    closed_cloud.Points = Points.Points([FreeCAD.Vector(x, y, 0) for x, y in ellipse])
    make_csr_fit(doc, [closed_cloud], closed=True, name="ClosedCsrSpline")
    doc.recompute()
    if fit.Status != "ok":
        raise SystemExit(f"demo: the csr fit failed: {fit.Status}")

    edges = {label: obj.Shape.Edges[0] for label, obj in curves.items()}
    csr_curve = edges["csr-spline"].Curve
    lines = ["FairSplines demo: Fig. 2 of the csr paper (half circle + flat parabola, "
             f"{len(samples)} uniform samples)", ""]
    lines.append(f"{'curve':<28}{'curvature sign changes':>24}{'max distance to data':>22}")
    for label, edge in edges.items():
        lines.append(f"{label:<28}{fw.curvature_sign_changes(edge):>24d}{fw.max_distance(edge, samples):>22.2e}")
    lines += ["", f"csr-spline continuity: {csr_curve.Continuity}, poles: {csr_curve.NbPoles}"]

    design_with_basic_curves(doc, out, lines)
    monotone_blend(doc, out, lines)
    fair_blend(doc, out, lines)
    blended_sphere_zone(doc, out, lines)
    joined_basic_shapes(doc, out, lines)
    doc.recompute()

    path_doc = os.path.join(out, "fairsplines_demo.FCStd")
    doc.saveAs(path_doc)
    curvature_plot(
        [(edges["csr-spline"], "csr-spline"), (edges["classic C2 interpolation"], "classic C2 interpolation")],
        path=os.path.join(out, "fig2_curvature.png"),
        title="Fig. 2 data: signed curvature against arc length",
    )
    picture_of_curves(
        os.path.join(out, "fig2_curves.png"),
        samples,
        [("csr-spline", csr_curve), ("classic C2 interpolation", classic)],
    )
    with open(os.path.join(out, "summary.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    print(f"\nwrote {path_doc}, fig2_curvature.png, fig2_curves.png, design_curvature.png, monotone_curvature.png, "
          f"fair_blend_curvature.png, blend_patches.png, blend_join.png and summary.txt in {out}")
    FreeCAD.closeDocument(doc.Name)


try:
    main()
except Exception:  # report, and make freecadcmd's exit status say so
    import traceback

    traceback.print_exc()
    sys.stdout.flush()
    os._exit(1)
