<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1">
<context>
    <name>FairSplines</name>
    <message>
        <location filename="../freecad_workbench/gui/panels/edit_polygon.py"/>
        <source>  (moved)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>  gap {} mm, angle {}°, jump {} %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>(a ring)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>1 piece per arc (σ)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>1: the longest tooth a quarter of the curves&apos; size and short of its centre of curvature. Negative: the comb on the other side.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/comb.py"/>
        <source>1: the longest tooth is at most a quarter of the curve&apos;s size, and every tooth ends short of its centre of curvature (at most 90% of the way), so the teeth of an arc do not cross. Above 1 teeth may reach past their centres. Negative: the comb on the other side.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>3 pieces per arc (ρ)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>A B-spline face, bicubic and periodic around the axis (any knots), its first row near the interface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>A B-spline face, bicubic and periodic around the axis, its first row near the start of the profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>A sketch, a Design spline or edges, in a plane through the shape&apos;s axis and off the axis; revolved around the axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>Add a mark in the middle of the widest gap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>Add mark</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/monotone_design.py"/>
        <source>Add vector</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/monotone_design.py"/>
        <source>Algorithm 1 of the monotone-curvature paper: V0 is the first control vector, dV_i = V_(i+1) - V_i; each dV_i is kept where the second-derivative control point C2_i lies in its fair location (Theorem 2), so the curvature is monotone.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Angles (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Angles around the torus&apos; axis, in degrees, where the arcs meet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Angles around the tube, in degrees, where the profile&apos;s arcs meet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Angles between the surface normal and the light, in degrees, separated by commas</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/basic_curve.py"/>
        <source>Archimedean spiral</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Arcs around</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Around the axis (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Around the tube (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>At face A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>At face B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>At the end: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>At the start: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/blend_shape.py"/>
        <source>Auto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/curvature_map.py"/>
        <source>Automatic range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Basic curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Black and white stripe pairs around the reflected sky</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Black and white stripe pairs the zebra shading of blends and of new profile tests reflects. An existing profile test keeps its own: its Stripes view property.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Blend basic shape</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/face_blend.py"/>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Blend faces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/curvature_map.py"/>
        <source>Blue from here down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/blend_shape.py"/>
        <source>Both ends</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/continuity.py"/>
        <source>Boundary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>Build the kernel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>Building...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>C2: (6,5) strip to bicubic NURBS (Section 4.2); C1: (4,2) double strip to biquadratic NURBS (Section 5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>Check again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Check continuity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/basic_curve.py"/>
        <source>Circle arc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/basic_curve.py"/>
        <source>Circle involute</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Circles as</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>Combs on isolines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/blend_shape.py"/>
        <source>Cone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Continuous in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>Copy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Curvature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Curvature (C2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Curvature (G2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Curvature below this, relative to one over the size of the data, counts as straight (eq. (6) of the csr paper). Used by new splines through points (csr fits); an existing one keeps its CurvatureTolerance.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/comb.py"/>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Curvature comb</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Curvature jumps smaller than this, in % of the largest curvature along the edge: G2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/curvature_map.py"/>
        <source>Curvature map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Curvature plot samples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>Curves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>Curves per face and direction, evenly spaced</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/blend_shape.py"/>
        <source>Cylinder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Default parabola</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Default parabola (no profile picked)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Default ring</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Default ring (continues the shape)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Default ring at the start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Depth A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Depth B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Design spline join tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Dimensions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/edit_polygon.py"/>
        <source>Drag a control point in the 3D view, or pick it in the list and type its position. A moved point changes the curve only near it (on the four spans it supports).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Edit basic curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Edit blend basic shape</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/edit_polygon.py"/>
        <source>Edit control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Edit face blend</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/edit_polygon.py"/>
        <source>Edit polygon</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/view_providers.py"/>
        <source>Edit {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/basic_curve.py"/>
        <source>Ellipse arc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/blend_shape.py"/>
        <source>End</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>End angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>End parameter t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>End point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>End points of consecutive pieces closer than this are averaged into one point; farther apart they are joined by a line. Used by new design splines.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>End y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Exact: the blend&apos;s boundary rows from the face&apos;s homogeneous poles. Gap, angle and curvature jump (across the edge and at 45°, in % of the curvature scale): measured by OCCT at 101 points of each edge (fw.blend_errors). Monotone: the exact certificate of monotone curvature of each cross section (rational Bezier)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Faces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Faces farther apart than this: a gap. 0: twice the edge&apos;s own tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/form.py"/>
        <source>Failed: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Fair (automatic)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>FairSplines computes its curves and surfaces in a compiled kernel. It is not built for this FreeCAD yet. It can be built here, into your own FreeCAD folder: a few minutes on a recent computer, up to a quarter of an hour on a slow one. No administrator rights are needed for the build itself.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>FairSplines: build the geometry kernel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Fitting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Flip direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Focal distance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Free-form side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>From</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/curvature_map.py"/>
        <source>From the 2nd to the 98th percentile of the values, so that a few extreme points do not wash out the colours of the rest.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/continuity.py"/>
        <source>G0: kink</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/continuity.py"/>
        <source>G1: tangent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/continuity.py"/>
        <source>G2: curvature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>G2: the blend meets this face in position, tangent plane and normal curvature in every direction; G1: in position and tangent plane only. Exact where the edge is an isoparametric boundary (the face&apos;s homogeneous poles), else fitted within the tolerances. Across, the blend is a quintic (G2 at both faces), a quartic (G2 at one) or a cubic (G1 at both)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/continuity.py"/>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Gap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Gap, G0 (a kink), G1 (tangent), G2 (curvature continuous) or boundary (one face only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/curvature_map.py"/>
        <source>Gaussian curvature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/curvature_map.py"/>
        <source>Gaussian: k1 k2 (1/mm²), negative on saddles. Mean: (k1 + k2) / 2. Largest |curvature|: max(|k1|, |k2|). Minimum and maximum: the principal curvatures k2 and k1. Radius: 1 / largest |curvature|. Convex is positive, seen from the face&apos;s outside.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>General</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Heights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/curvature_map.py"/>
        <source>Highest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Horizontal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>How far the blend runs along this face before turning: the cross-boundary derivative magnitude alpha, {} to {} times the default (mean chord over mean cross-boundary speed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>How many</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>How many teeth a comb has on each edge, at least. More show finer detail, fewer redraw faster.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>How much the radius grows per unit of height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>How the circles of the shape are reparametrised so that they join C2 (Section 3): ρ, three rational pieces per arc (Appendix 7.1); σ, one sextic per arc (eqs. (7)-(8)); mixed, ρ only where neighbouring arcs differ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/basic_curve.py"/>
        <source>Hyperbola arc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>Isolines: the face&apos;s own parameter lines. Sections: cuts by evenly spaced planes across the faces&apos; box, normal to that axis.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Isophotes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Join</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Join another Blend basic shape instead of a ring (Figs. 9-12): this profile&apos;s end to the start of its profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Join at</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Joined to {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Joins: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Jump</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Largest angle between the faces&apos; normals, degrees</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Largest gap between the faces, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Largest jump of curvature across the edge, % of the largest curvature along it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/curvature_map.py"/>
        <source>Largest |curvature|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Latitudes (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Length of the teeth. At 1 the longest tooth is at most a quarter of the curve&apos;s size and no tooth reaches its centre of curvature; 2 doubles them. Negative: the comb on the other side of the curve.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Light from the view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/basic_curve.py"/>
        <source>Line segment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Longitudes (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/curvature_map.py"/>
        <source>Lowest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Major radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>Mark points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>Mark {} of this piece (its parameter u in 0..1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/curvature_map.py"/>
        <source>Maximum curvature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/curvature_map.py"/>
        <source>Mean curvature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/curvature_map.py"/>
        <source>Minimum curvature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Minor radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Mixed (ρ where arcs differ)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/monotone_design.py"/>
        <source>Monotone design</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/common.py"/>
        <source>More in FairSplines&apos; documentation, section “{}”:
{}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Most curvature extrema: {} (section {})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/curvature_map.py"/>
        <source>Move the cursor over the map to read its value.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/monotone_design.py"/>
        <source>Moved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/monotone_design.py"/>
        <source>No step needed moving: the curvature is monotone.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Normals closer than this: tangent (G1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/continuity.py"/>
        <source>Not judged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/view_providers.py"/>
        <source>Number of black and white stripe pairs reflected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/comb.py"/>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>On: every comb shown is drawn to one scale, the smallest any of them would get on its own, so tooth lengths compare between curves. Off: each comb is sized to its own curve.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/comb.py"/>
        <source>One scale for all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/face_blend.py"/>
        <source>Open a document first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Or join to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Pair the start of the first edge with the end of the second (for a twisted blend, try this)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/basic_curve.py"/>
        <source>Parabola arc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Patches: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>Piece {}: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Pieces along the profile (its arcs or segments)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>Pieces {} and {}: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Pitch (per turn)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Plain join</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Plots</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Points at which a curvature plot evaluates each curve.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Poles and weights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Profile fractions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Profile from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Profile not taken: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Profile pieces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Profile to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Radius at height 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/curvature_map.py"/>
        <source>Radius of curvature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/basic_curve.py"/>
        <source>Rational cubic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/curvature_map.py"/>
        <source>Red from here up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Reflected stripes on the two faces too: across a G2 join they run on smoothly, across G1 they bend, across G0 they break</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/monotone_design.py"/>
        <source>Remove last</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/curvature_map.py"/>
        <source>Remove the map and show the object as before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Remove the shading and show the object as before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>Remove this mark</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/edit_polygon.py"/>
        <source>Reset all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/edit_polygon.py"/>
        <source>Reset pole</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>Reversed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/blend_shape.py"/>
        <source>Revolution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>Run this in a terminal (it asks for your password), then press Check again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>Run this piece from its end to its start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Same scale for all combs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/comb.py"/>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>Scale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Scale factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>Sections across X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>Sections across Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>Sections across Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Sections with monotone curvature (certified): {} of {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Select a sketch, a Design spline or edges first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/face_blend.py"/>
        <source>Select two edges, each on the face to blend from (Ctrl+click)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/curvature_map.py"/>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Show</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/view_providers.py"/>
        <source>Show the control polygon of the curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/comb.py"/>
        <source>Show the curvature comb of this object&apos;s edges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Side {}: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>Slide the marks along each basic curve. A conic stays exact from its second to its second-last mark; the joins are rounded off in between.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Slope</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/comb.py"/>
        <source>Space curves also get a comb of their torsion, in orange, along the binormal. Its teeth change sides where the curve&apos;s twist changes direction (a torsion sign change). Planar curves have none.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/blend_shape.py"/>
        <source>Sphere zone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Spline through points: tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/blend_shape.py"/>
        <location filename="../freecad_workbench/gui/panels/monotone_design.py"/>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Start angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Start parameter t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Start point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Start y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/monotone_design.py"/>
        <source>Step {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/monotone_design.py"/>
        <source>Steps moved to keep the curvature monotone: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Stripe pairs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Stripes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Tangent (C1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Tangent (G1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/comb.py"/>
        <source>Teeth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Teeth per edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/comb.py"/>
        <source>Teeth per edge (at least)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>The OpenCASCADE headers are not the version FreeCAD runs ({version}): the kernel will hand shapes over as arrays (slower, as exact).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>The build failed. The last lines of the compiler&apos;s output are below; the full log is {log}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/monotone_design.py"/>
        <source>The curve&apos;s control points, as where it starts and the step to each next one. A step that would make the curvature change direction is moved at once to the nearest one that keeps it rising (or falling); the last column says how far.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>The derivative magnitude alpha across the edge chosen for fair cross sections: fewest curvature extrema, then least scale-free curvature variation L³∫(dκ/ds)²ds, by a grid and pattern search over the 13 sections</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>The edges of the blend and its two faces, in one shell, coloured by their measured continuity (gap, G0, G1, G2; fw.edge_continuity)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>The faces that meet at the edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>The kernel is built ({seconds} s). FairSplines is ready: close this window.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>The kernel is built ({seconds} s). Restart FreeCAD to use it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>The kernel is built for this FreeCAD.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>The light shines along the current view direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>This part of the curve is the csr-spline of the samples (curvature-sensitive spline, Section 4 of the paper): close to every sample, without added curvature wiggles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>To</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>To compare: the paper&apos;s naive blend (Fig. 2a), the shape and the ring joined without the transition strip; its seams show</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/comb.py"/>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Torsion comb too</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/features/blend_shape.py"/>
        <source>Torus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/curvature_map.py"/>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Turn off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>U and V isolines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>U isolines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Uniform partitions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Use selected face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Use selected face at the start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Use selected profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/iso_combs.py"/>
        <source>V isolines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/continuity.py"/>
        <source>Verdict</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Vertical</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/form.py"/>
        <source>Warning: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Weight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>What the build needs:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Where the blend ends along each edge, in % of its length in parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Where the blend starts along each edge, in % of its length in parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>Where the curve&apos;s own origin lies (its Placement)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>Which end of the profile joins the free-form side; Auto: the end, or the start where the end is a pole; Both ends: free-form on both sides, as for a ball joint&apos;s band. Joined to another shape: Start adds free-form below this shape, End beyond the other one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/monotone_design.py"/>
        <source>X (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/monotone_design.py"/>
        <source>Y (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <location filename="../freecad_workbench/gui/preferences.py"/>
        <source>Zebra</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>Zebra on the faces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Zebra stripes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/zebra_shape.py"/>
        <source>Zebra: the faces reflect black and white stripes; kinks in the stripes show G1 joins, breaks show G0. Isophotes: lines where the surface meets the light at the same angle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>ends a little apart, averaged into one point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>ends apart, joined by a straight edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>exact (face&apos;s poles)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>fitted ({} spans)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>found: {name}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>meet end to start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>missing (optional): {name}, package {package}: {why}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>missing: {name}, package {package}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>none found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/basic_curve.py"/>
        <source>other</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/blend_shape.py"/>
        <source>select a B-spline face of another object first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/curvature_map.py"/>
        <source>{label}: {quantity} {value} {unit} at ({x}, {y}, {z}) mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/edit_polygon.py"/>
        <source>{} control points, {} moved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>{} mark(s) added to keep the weights positive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/face_blend.py"/>
        <source>{} of {} bounds no face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/face_blend.py"/>
        <source>{} of {} bounds {}: select the face to blend from too (Ctrl+click)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/mark_points.py"/>
        <source>{} samples, no marks: the curve follows them closely here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/panels/face_blend.py"/>
        <source>{}: {}, {} of {}</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_AnalysisGroup</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Curvature analysis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Curvature comb, curvature plot, monotonicity check, curvature map,
continuity check, zebra, combs on isolines, zebra profile test</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_ArchimedeanSpiral</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>An Archimedean spiral (followed to about 1e-8 of its size in a design)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Archimedean spiral</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_BasicCurves</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Basic curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Create a basic curve: line, conic arc, spiral, involute, rational cubic</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_BlendBasicShape</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/blend.py"/>
        <source>A sphere zone, cylinder, cone or torus kept exact and joined smoothly (C2, or C1) to a
free-form ring, a selected B-spline face or another basic shape.
Set it up in the panel; zebra stripes show the seams.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/blend.py"/>
        <source>Blend basic shape</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_BlendFaces</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/face_blend.py"/>
        <source>A smooth surface from an edge of one face to an edge of another: it meets both faces
in curvature (G2) or in tangent (G1), exactly where the edge is a boundary of its face.
Its cross sections are chosen for fair, monotone curvature (certified).
Select two edges in the 3D view, with the face of each where an edge bounds two.
Exact boundary derivatives from the face&apos;s poles; shows with zebra stripes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/face_blend.py"/>
        <source>Blend faces</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_BlendGroup</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/__init__.py"/>
        <source>Blends</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/__init__.py"/>
        <source>Fair blend between two curves, monotone design, blend basic shape, blend faces</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_BuildKernel</name>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>Build FairSplines&apos; compiled kernel for this FreeCAD, into your own FreeCAD folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../fairsplines_setup/dialog.py"/>
        <source>Build the kernel...</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_CheckContinuity</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Check continuity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>How smoothly the faces of the selected shape (or the selected faces) meet at each edge:
gap, G0 (a kink), G1 (tangent) or G2 (curvature continuous), drawn in colour on the edges
and listed in a table with the gap, angle and curvature jump. Click a row to find the edge.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_CheckMonotone</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Check curvature monotonicity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Prove whether the curvature of the selected planar edges only rises or only falls
(an exact check, span by span): a report in the report view and a curvature plot
with any extremum marked.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_CircleArc</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>A circle arc (kept exact in a design)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Circle arc</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_CircleInvolute</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>An involute of a circle (followed closely in a design)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Circle involute</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_CsrFit</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/csr.py"/>
        <source>A smooth C2 spline through the selected vertices, Points object, sketch points or edges
(the csr-spline: conics stay exact, no curvature wiggles). Select points in order;
edges are sampled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/csr.py"/>
        <source>Spline through points</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_CurvatureComb</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Curvature comb</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Show or hide the curvature comb of the selected edges.
With nothing selected, hide all combs.
A whole object&apos;s comb is its view property Curvature Comb, saved with the document.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_CurvatureMap</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Colour the selected shapes or faces by their curvature (Gaussian, mean, largest,
minimum, maximum or radius), with a colour bar, an automatic or manual range, and
the value under the cursor. Again on a mapped object: turn its map off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Curvature map</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_CurvaturePlot</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Curvature plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Plot curvature against arc length of the selected edges, one line each,
in a tab of the main window, with the curvature extrema marked.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_DesignSpline</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Design spline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>One smooth (C2) spline through the selected basic curves, in pick order: edges of
sketches or Part objects (lines, arcs, conics) or Basic curve objects; a Points object or a
sketch of points is a sampled piece (its csr-spline). Then mark points on them.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_EditPolygon</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Edit control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Move control points of the selected spline (a Design spline, a spline through points or any
B-spline edge). The edited curve follows the design; a moved point changes the curve only
near it (the four spans it supports).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_EllipseArc</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>An ellipse arc (kept exact in a design)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Ellipse arc</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_FairFit</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/csr.py"/>
        <source>A fair C2 spline with few control points within a tolerance (mm) of the selected
vertices, Points object, sketch points or edges: scan noise is smoothed away and the
curvature changes sign only where the data does (the csr-spline of chosen points).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/csr.py"/>
        <source>Fair fit</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_FitGroup</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/__init__.py"/>
        <source>Fit points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/__init__.py"/>
        <source>Spline through points (csr fit), fair fit within a tolerance</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_HyperbolaArc</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>A hyperbola arc (kept exact in a design)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Hyperbola arc</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_IsoCombs</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Combs on isolines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Curvature combs on the U and V isolines, or on planar cross sections, of the selected
faces or shapes: how the curvature runs across a surface, not only along its edges.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_LineSegment</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>A line segment, to join to curved pieces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Line segment</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_MarkPoints</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Mark points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Move, add and remove the points marked on the pieces of the selected Design spline,
with sliders (live preview)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_MonotoneBlend</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/fair_blend.py"/>
        <source>Bridge two selected edges, at the ends you clicked near, with a curve whose curvature
only rises or only falls, proved exactly. Matches the edges&apos; tangents and curvatures
(G2); set Continuity to G1 for tangents only. Or select two vertices and set the
directions in the blend&apos;s properties.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/fair_blend.py"/>
        <source>Fair blend</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_MonotoneDesign</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/fair_blend.py"/>
        <source>Design a cubic spline whose curvature only rises or only falls, from the steps between
its control points. Edits the selected Monotone design, or creates one. A step that
would break the monotone curvature is moved back to the nearest one that keeps it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/fair_blend.py"/>
        <source>Monotone design</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_ParabolaArc</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>A parabola arc (kept exact in a design)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Parabola arc</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_ProfileTest</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Profile test</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Revolve the selected profile curve into its exact surface of revolution, with zebra shading:
kinks or wobbles of the stripes show curvature flaws of the profile. Axis: the sketch&apos;s
vertical axis, or Z (change AxisPoint / AxisDirection).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_RationalCubic</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>A rational Bezier curve of degree at most 3 (kept exact in a design)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/design.py"/>
        <source>Rational cubic</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FairSplines_Zebra</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Show the selected shapes reflecting black and white stripes (zebra), or with isophotes:
stripes that kink or break show where faces meet only tangent or with a kink.
Again on a shaded object: turn it off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../freecad_workbench/gui/commands/analysis.py"/>
        <source>Zebra</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Workbench</name>
    <message>
        <location filename="../freecad_workbench/gui/commands/__init__.py"/>
        <source>Basic curve</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
