// G1 and G2 blends between two faces along their edges (issue 29; src/face_blend.cpp,
// face_blend_fitted.cpp, docs/FACE_BLENDS.md).
#pragma once
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>
#include <string>
#include <vector>

namespace fairsplines {

struct FaceBlendOptions {
  int continuity = 2;             ///< 1: G1, 2: G2 along edge A, and along edge B unless continuityB is set
  int continuityB = 0;            ///< G1 (1) or G2 (2) along edge B when it differs (0: continuity). Across, the
                                  ///< blend has degree continuity + continuityB + 1: 5 (G2, G2), 4 (G2, G1), 3 (G1, G1)
  bool flip = false;              ///< pair the start of edge A with the end of edge B
  double start = 0.0, end = 1.0;  ///< the part of each edge covered, as fractions of its parameter range
  int sections = 13;              ///< cross sections the fairness search and the report judge
  /// > 0: fixed multiples of each side's default derivative magnitude (no search for that side's
  /// magnitude; its second-order term is then 0). 0: chosen for fairness.
  double scaleA = 0.0, scaleB = 0.0;
};

/// How one side was matched: v(s) = v0 - alpha s + beta s^2 / 2 carries the face's cross-boundary
/// parameter into the blend's (docs/FACE_BLENDS.md section 2).
struct FaceBlendSide {
  std::string method;         ///< "exact": an isoparametric boundary, its derivatives taken from the poles;
                              ///< "fitted": sampled from the face and fitted until the tolerances hold
  std::string reason;         ///< why the side is fitted ("" when exact)
  std::string surfaceType;    ///< the face's surface before conversion ("BSplineSurface", "CylindricalSurface", ...)
  std::string isoparametric;  ///< "u" or "v": the face parameter that is constant along the edge; "line": a plane
  double alpha = 0.0, beta = 0.0;
  double scale = 0.0;  ///< alpha over the default magnitude (mean chord over mean cross-boundary speed)
  double bend = 0.0;   ///< beta / alpha
  bool rational = false;
  bool closed = false;  ///< the edge is closed (a rim circle): the blend closes in u
  int continuity = 2;   ///< 1: G1, 2: G2 along this side's edge
  /// Fitted sides: the fit's spans, its rounds of halving spans, the face samples, and its worst
  /// misfit between the samples (gap over the size of both edges' box, angle in degrees,
  /// normal curvature over the curvature scale; G1: curvature not fitted, 0).
  int spans = 0, refinements = 0, samples = 0;
  double fitGap = 0.0, fitAngle = 0.0, fitCurvature = 0.0;
};

/// One cross section s -> blend(u, s), judged twice: the exact certificate (certifySpaceCurvature)
/// and dense sampling.
struct FaceBlendSection {
  double u = 0.0;  ///< the blend's parameter along the edges, in [0, 1]
  bool monotone = false;
  int curvatureExtrema = 0;  ///< from the certificate
  int sampledExtrema = 0;    ///< sign changes of dkappa/ds at 96 samples
  double kappaMin = 0.0, kappaMax = 0.0;
  double variation = 0.0;  ///< L^3 int (dkappa/ds)^2 ds, sampled
  std::string reason;
};

struct FaceBlend {
  Handle(Geom_BSplineSurface) surface;  ///< u along the edges in [0, 1], s in [0, 1] from edge A to edge B
  FaceBlendSide sides[2];
  std::vector<FaceBlendSection> sections;
  int evaluations = 0;  ///< candidate magnitudes judged by the fairness search
  double size = 0.0;    ///< the diagonal of the blend's pole box
};

/// The blend between faceA along its edge number edgeA (1-based, TopExp::MapShapes order, as
/// FreeCAD's Face.Edges) and faceB along edgeB. Where an edge is an isoparametric boundary of its
/// face (or a straight edge of a plane) on a surface converted exactly to a B-spline (GeomConvert),
/// the blend matches its position and first (G1) and second (G2) cross-boundary derivatives in
/// homogeneous coordinates, exactly to rounding along the whole edge ("exact"). Elsewhere (trimmed
/// edges, seams, isolines inside the face, other surfaces) the face's position, normal and normal
/// curvature are sampled along the edge and fitted, refined until a tenth of the issue's
/// tolerances holds between the samples ("fitted"; face_blend_fitted.cpp).
/// Throws InputError for an edge index out of range, a degenerate edge, a fitted edge whose fit
/// spends its budget or whose face is singular along it, faces that touch, non-positive weights,
/// and a blend that would cross itself (a folded or self-approaching cross section).
FaceBlend blendFaces(const TopoDS_Face& faceA, int edgeA, const TopoDS_Face& faceB, int edgeB,
                     const FaceBlendOptions& options = {});

}  // namespace fairsplines
