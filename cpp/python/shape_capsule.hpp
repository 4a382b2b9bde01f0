// The hand-over of a kernel-built TopoDS_Shape to FreeCAD (issue 13): an owning capsule,
// not an integer address. The pybind11 module makes the capsule; occ_bridge.adopt_shape
// takes the shape out of it exactly once (renaming the capsule), and a capsule that is
// never adopted deletes its shape when Python collects it. Shared by both modules.
#pragma once
#include <Python.h>
#include <TopoDS_Shape.hxx>

namespace fairsplines::python {

inline constexpr const char* kShapeCapsule = "fairsplines.TopoDS_Shape";
inline constexpr const char* kAdoptedCapsule = "fairsplines.TopoDS_Shape.adopted";

/// Deletes the shape unless it was adopted (then its new owner deletes it).
inline void destroyShapeCapsule(PyObject* capsule) {
  if (PyCapsule_IsValid(capsule, kShapeCapsule)) {
    delete static_cast<TopoDS_Shape*>(PyCapsule_GetPointer(capsule, kShapeCapsule));
  }
}

/// A new reference to a capsule owning `shape` (which must come from new).
inline PyObject* newShapeCapsule(TopoDS_Shape* shape) {
  PyObject* capsule = PyCapsule_New(shape, kShapeCapsule, &destroyShapeCapsule);
  if (capsule == nullptr) delete shape;
  return capsule;
}

/// The shape of an unadopted capsule, now owned by the caller, or nullptr (with a Python
/// TypeError set) for anything else: another object, or a capsule adopted already.
inline TopoDS_Shape* adoptShapeCapsule(PyObject* capsule) {
  if (!PyCapsule_IsValid(capsule, kShapeCapsule)) {
    PyErr_SetString(PyExc_TypeError, PyCapsule_IsValid(capsule, kAdoptedCapsule)
                                         ? "this shape was adopted already: a capsule hands its shape over once"
                                         : "adopt_shape takes a shape capsule made by freecad_workbench._kernel");
    return nullptr;
  }
  auto* shape = static_cast<TopoDS_Shape*>(PyCapsule_GetPointer(capsule, kShapeCapsule));
  PyCapsule_SetName(capsule, kAdoptedCapsule);  // the destructor leaves it alone from now on
  return shape;
}

}  // namespace fairsplines::python
