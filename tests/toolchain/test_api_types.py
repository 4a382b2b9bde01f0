"""Type hints on the public macro API (issue 14): every function of fw.__all__ and every
public method and constructor of the classes of fw.basic and fw.shapes annotates each
parameter and its return, and the annotations name things that exist (they resolve, with
FreeCAD and Part, which the modules import only for type checkers)."""
import inspect
import typing

import pytest

import FreeCAD
import Part
import freecad_workbench as fw


def _public_callables():
    for name in fw.__all__:
        obj = getattr(fw, name)
        if inspect.isfunction(obj):
            yield f"fw.{name}", obj
    for module in (fw.basic, fw.shapes):
        for name in module.__all__:
            obj = getattr(module, name)
            if inspect.isfunction(obj):
                yield f"{module.__name__}.{name}", obj
            elif inspect.isclass(obj):
                for cls in obj.__mro__:
                    if cls.__module__ != module.__name__:
                        continue
                    for attr, member in vars(cls).items():
                        if isinstance(member, property):
                            member = member.fget
                        if inspect.isfunction(member) and (attr == "__init__" or not attr.startswith("_")):
                            yield f"{cls.__name__}.{attr}", member


CALLABLES = dict(_public_callables())


def test_the_public_api_is_found():
    assert {"fw.csr_spline", "fw.blend_basic_shape", "fw.fair_blend", "CircleArc.__init__", "_Shape.set_control",
            "SphereZone.g2", "freecad_workbench.basic.from_edge"} <= set(CALLABLES)


@pytest.mark.parametrize("name", sorted(CALLABLES))
def test_every_parameter_and_the_return_are_annotated(name):
    function = CALLABLES[name]
    signature = inspect.signature(function)
    missing = [p.name for p in signature.parameters.values()
               if p.name != "self" and p.annotation is inspect.Parameter.empty]
    assert not missing, f"{name}: no type for {missing}"
    assert signature.return_annotation is not inspect.Signature.empty, f"{name}: no return type"
    hints = typing.get_type_hints(function, globalns={**function.__globals__, "FreeCAD": FreeCAD, "Part": Part})
    assert "return" in hints
