// The boundary rule for shapes (finite.hpp): a shape leaves the kernel only if OCCT's own
// checker, BRepCheck_Analyzer, calls it valid. Finite numbers are not enough: faces on
// surfaces far from the origin (1e12) or of denormal size (5e-324) have finite poles and
// still fail BRepCheck (edges off their surfaces by more than their tolerance, curves on
// surfaces that do not meet, degenerate boundaries), and FreeCAD would take them as success.
#include <BRepBndLib.hxx>
#include <BRepCheck.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Result.hxx>
#include <BRepCheck_Status.hxx>
#include <Bnd_Box.hxx>
#include <Standard_Failure.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "finite.hpp"

namespace fairsplines {

namespace {

const char* kindName(TopAbs_ShapeEnum kind) {
  switch (kind) {
    case TopAbs_COMPOUND:
      return "compound";
    case TopAbs_SHELL:
      return "shell";
    case TopAbs_FACE:
      return "face";
    case TopAbs_WIRE:
      return "wire";
    case TopAbs_EDGE:
      return "edge";
    case TopAbs_VERTEX:
      return "vertex";
    default:
      return "shape";
  }
}

/// The first status other than BRepCheck_NoError the analyzer recorded for sub-shape s.
BRepCheck_Status firstFault(const BRepCheck_Analyzer& analyzer, const TopoDS_Shape& s) {
  const Handle(BRepCheck_Result)& result = analyzer.Result(s);
  if (result.IsNull()) return BRepCheck_NoError;
  for (BRepCheck_ListIteratorOfListOfStatus it(result->Status()); it.More(); it.Next()) {
    if (it.Value() != BRepCheck_NoError) return it.Value();
  }
  return BRepCheck_NoError;
}

/// "face 3 (BRepCheck status 12)": the first face, edge or vertex the analyzer calls not
/// valid, numbered from 0 in the order TopExp_Explorer visits them.
std::string firstInvalid(const BRepCheck_Analyzer& analyzer, const TopoDS_Shape& shape) {
  for (TopAbs_ShapeEnum kind : {TopAbs_FACE, TopAbs_EDGE, TopAbs_VERTEX}) {
    int i = 0;
    for (TopExp_Explorer e(shape, kind); e.More(); e.Next(), ++i) {
      if (!analyzer.IsValid(e.Current())) {
        std::ostringstream os;
        os << kindName(kind) << " " << i << " (BRepCheck: ";
        BRepCheck::Print(firstFault(analyzer, e.Current()), os);
        os << ")";
        return os.str();
      }
    }
  }
  return std::string("the ") + kindName(shape.ShapeType());
}

}  // namespace

void requireValidShape(const TopoDS_Shape& shape, const std::string& what) {
  if (shape.IsNull()) throw InputError(what + ": no shape was built");
  try {
    const BRepCheck_Analyzer analyzer(shape);
    if (analyzer.IsValid()) return;
    Bnd_Box box;
    BRepBndLib::Add(shape, box);
    std::ostringstream os;
    os.precision(3);
    os << what << ": " << firstInvalid(analyzer, shape) << " is not a valid shape by OpenCASCADE's check";
    if (!box.IsVoid()) {
      double x0, y0, z0, x1, y1, z1;
      box.Get(x0, y0, z0, x1, y1, z1);
      const double extent = gp_Pnt(x0, y0, z0).Distance(gp_Pnt(x1, y1, z1));
      const double magnitude =
          std::max({std::abs(x0), std::abs(y0), std::abs(z0), std::abs(x1), std::abs(y1), std::abs(z1)});
      os << " (the shape is " << extent << " across, at coordinates up to " << magnitude
         << "; a size below about 1e-7 or coordinates above about 1e9 times its size leave too few digits for its "
            "edges to lie on its faces: scale or move the input nearer the origin)";
    }
    throw InputError(os.str());
  } catch (const Standard_Failure& failure) {
    throw InputError(what + ": OpenCASCADE could not check the shape (" + failure.GetMessageString() + ")");
  }
}

}  // namespace fairsplines
