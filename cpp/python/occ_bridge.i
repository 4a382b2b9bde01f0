// A minimal SWIG module whose only job is to hand an OpenCASCADE TopoDS_Shape that the
// kernel built to FreeCAD without serialising it: FreeCAD's Part.__fromPythonOCC__
// accepts any SWIG-wrapped "TopoDS_Shape *" (the hook FreeCAD offers pythonocc).
// Both sides load the same Debian OCCT libraries, so the shape is shared as it is.
%module occ_bridge

%{
#include <TopoDS_Shape.hxx>
%}

// Only the type and its destructor are needed: the wrapper owns the shape and deletes it
// when Python collects it; FreeCAD keeps its own handle to the geometry.
class TopoDS_Shape {
public:
  ~TopoDS_Shape();
};

%newobject adopt_shape;
%inline %{
/// Takes ownership of a heap TopoDS_Shape created by the kernel (its address as an int).
TopoDS_Shape* adopt_shape(unsigned long long address) {
  return reinterpret_cast<TopoDS_Shape*>(static_cast<uintptr_t>(address));
}
%}
