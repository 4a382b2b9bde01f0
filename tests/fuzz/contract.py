"""The contract every public callable of the macro API keeps, whatever it is given: it
raises fw.InputError (a ValueError) with a message, or returns finite, valid geometry,
within a hang limit. check_call is the one function the fuzz tests use."""
import dataclasses
import math
import numbers
import time

import numpy as np

import freecad_workbench as fw

# A hang detector, not a speed test (speed is measured in bench/): a call that takes this
# long has no bound on its work. Generous on purpose (calls take milliseconds to about a
# second; a loaded machine or a sanitized build may be ten times slower), so that it never
# fails on a slow machine. The kernel cannot be interrupted: measured, not enforced.
TIME_BOUND = 60.0  # seconds per call


class ContractError(AssertionError):
    pass


def _fail(what, func, args, kwargs, detail):
    name = getattr(func, "__qualname__", repr(func))
    raise ContractError(f"{what} in {name}(*{args!r}, **{kwargs!r}): {detail}")


CALLS = {"refused": 0, "returned": 0}  # how the examples came out (for tuning the strategies)


def check_call(func, *args, time_bound=TIME_BOUND, **kwargs):
    """Call func(*args, **kwargs) and check the contract. Returns the result, or None when an
    InputError was raised. Any other exception, a non-finite number in the result, invalid
    geometry or a call over time_bound raises ContractError naming the arguments."""
    start = time.monotonic()
    try:
        result = func(*args, **kwargs)
    except fw.InputError as exc:
        elapsed = time.monotonic() - start
        if elapsed > time_bound:
            _fail("slow refusal", func, args, kwargs, f"{elapsed:.2f} s > {time_bound} s")
        if not str(exc).strip():
            _fail("InputError without a message", func, args, kwargs, repr(exc))
        CALLS["refused"] += 1
        return None
    except Exception as exc:  # noqa: BLE001  (the contract: nothing else may escape)
        _fail(f"{type(exc).__name__} escaped", func, args, kwargs, str(exc))
    elapsed = time.monotonic() - start
    if elapsed > time_bound:
        _fail("slow call", func, args, kwargs, f"{elapsed:.2f} s > {time_bound} s")
    try:
        check_value(result)
    except ContractError as exc:
        _fail("invalid result", func, args, kwargs, str(exc))
    CALLS["returned"] += 1
    return result


def _finite_numbers(values, what):
    a = np.asarray(values, dtype=float)
    if not np.all(np.isfinite(a)):
        raise ContractError(f"{what} not finite: {a!r}")


def _vector(v, what):
    _finite_numbers((v.x, v.y, v.z), what)


def _check_part(value, path):
    import FreeCAD
    import Part

    if isinstance(value, FreeCAD.Vector):
        _vector(value, path)
    elif isinstance(value, Part.Shape):
        if value.isNull():
            raise ContractError(f"{path}: a null shape")
        if not value.isValid():
            raise ContractError(f"{path}: shape not valid (isValid() is False)")
        box = value.BoundBox
        _finite_numbers((box.XMin, box.YMin, box.ZMin, box.XMax, box.YMax, box.ZMax), f"{path} bounding box")
        for i, face in enumerate(value.Faces):
            if isinstance(face.Surface, Part.BSplineSurface):
                _check_part(face.Surface, f"{path}.Faces[{i}].Surface")
        for i, edge in enumerate(value.Edges):  # degenerated edges (at a dome's pole) have no curve
            if not edge.Degenerated and isinstance(edge.Curve, Part.BSplineCurve):
                _check_part(edge.Curve, f"{path}.Edges[{i}].Curve")
    elif isinstance(value, Part.BSplineCurve):
        _finite_numbers([tuple(p) for p in value.getPoles()], f"{path} poles")
        _finite_numbers(value.getWeights(), f"{path} weights")
        _finite_numbers(value.getKnots(), f"{path} knots")
        if min(value.getWeights()) <= 0:
            raise ContractError(f"{path}: non-positive weight")
    elif isinstance(value, Part.BSplineSurface):
        _finite_numbers([[tuple(p) for p in row] for row in value.getPoles()], f"{path} poles")
        _finite_numbers(value.getWeights(), f"{path} weights")
        _finite_numbers(value.getUKnots(), f"{path} u knots")
        _finite_numbers(value.getVKnots(), f"{path} v knots")
        if path.count("[") <= 1 and "." not in path:  # a surface returned (or in a returned list)
            _check_face_of(value, path)
    elif hasattr(value, "toShape") and hasattr(value, "FirstParameter"):  # lines, conics, their arcs
        if True:
            _finite_numbers((value.FirstParameter, value.LastParameter), f"{path} parameters")
            _vector(value.value(value.FirstParameter), f"{path} start")
            _vector(value.value(value.LastParameter), f"{path} end")
            if not value.toShape().isValid():
                raise ContractError(f"{path}: its edge is not valid")
    else:
        return False
    return True


def _check_face_of(surface, path):
    """Issue 26: a surface the API returns makes a face BRepCheck calls valid, with edges at
    Precision::Confusion() or, far from the origin, at about 100 rounding units of its largest
    coordinate (the kernel's rule for the faces it hands over: 1e-7 is below what coordinates
    of 1e12 tell apart)."""
    face = surface.toShape()
    if face.isValid():
        return
    box = face.BoundBox
    magnitude = max(abs(box.XMin), abs(box.YMin), abs(box.ZMin), abs(box.XMax), abs(box.YMax), abs(box.ZMax))
    face.fixTolerance(max(1e-7, 1e-14 * magnitude))
    if not face.isValid():
        raise ContractError(f"{path}: its face is not valid (BRepCheck), even with edges at 1e-14 of its coordinates")


def check_value(value, path="result", depth=0):
    """Recursively: numbers finite, arrays finite, Part geometry finite and valid."""
    if depth > 6:
        return
    if value is None or isinstance(value, (bool, str, bytes)):
        return
    if isinstance(value, numbers.Number):
        if isinstance(value, numbers.Real) and not math.isfinite(value):
            raise ContractError(f"{path} = {value}")
        return
    if isinstance(value, np.ndarray):
        if value.dtype.kind in "fc" and not np.all(np.isfinite(value)):
            raise ContractError(f"{path} not finite: {value!r}")
        if value.dtype == object:
            for i, v in enumerate(value.ravel()):
                check_value(v, f"{path}[{i}]", depth + 1)
        return
    if _check_part(value, path):
        return
    if isinstance(value, dict):
        for k, v in value.items():
            check_value(v, f"{path}[{k!r}]", depth + 1)
        return
    if isinstance(value, (tuple, list)):
        for i, v in enumerate(value):
            check_value(v, f"{path}[{i}]", depth + 1)
        return
    if dataclasses.is_dataclass(value):
        for field in dataclasses.fields(value):
            check_value(getattr(value, field.name), f"{path}.{field.name}", depth + 1)
        return
    if isinstance(value, fw.basic.BasicCurve):
        _finite_numbers(value.size(), f"{path}.size()")
        for u in (0.0, 0.5, 1.0):
            try:  # a user function (ParametricCurve) is evaluated lazily: InputError then is fine
                _vector(value.value(u), f"{path}.value({u})")
            except fw.InputError:
                pass
    if hasattr(value, "__dict__"):  # API objects (basic curves, shapes): their public attributes
        for k, v in vars(value).items():
            if not k.startswith("_"):
                check_value(v, f"{path}.{k}", depth + 1)
