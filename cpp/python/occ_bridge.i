// A minimal SWIG module whose only job is to hand an OpenCASCADE TopoDS_Shape that the
// kernel built to FreeCAD without serialising it: FreeCAD's Part.__fromPythonOCC__
// accepts any SWIG-wrapped "TopoDS_Shape *" (the hook FreeCAD offers pythonocc).
// Both sides load the same Debian OCCT libraries, so the shape is shared as it is.
// The kernel hands the shape over in an owning capsule (shape_capsule.hpp): adopted
// exactly once, deleted if it never is.
%module occ_bridge

%{
#include <TopoDS_Shape.hxx>
#include "shape_capsule.hpp"
%}

// Only the type and its destructor are needed: the wrapper owns the shape and deletes it
// when Python collects it; FreeCAD keeps its own handle to the geometry.
class TopoDS_Shape {
public:
  ~TopoDS_Shape();
};

%exception adopt_shape {
  $action
  if (result == nullptr) SWIG_fail;  // adoptShapeCapsule set the TypeError
}

%newobject adopt_shape;
%inline %{
/// Takes ownership of the shape in a capsule from freecad_workbench._kernel (once).
TopoDS_Shape* adopt_shape(PyObject* capsule) {
  return fairsplines::python::adoptShapeCapsule(capsule);
}
%}
