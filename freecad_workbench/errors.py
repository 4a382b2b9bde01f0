"""Exceptions of the macro API. Bad input raises InputError, a ValueError."""
try:
    from ._kernel import InputError, NoMonotoneSolution
except ImportError as exc:  # pragma: no cover - only when the kernel is not built
    raise ImportError(
        "the FairSplines C++ kernel (freecad_workbench/_kernel*.so) is missing or was built for another "
        "Python: run 'make build' with /usr/bin/python3 (" + str(exc) + ")"
    ) from exc

InputError.__module__ = "freecad_workbench"
InputError.__doc__ = "Bad input: the message names the problem (a subclass of ValueError)."
NoMonotoneSolution.__module__ = "freecad_workbench"
NoMonotoneSolution.__doc__ = (
    "No monotone-curvature curve of the family meets the end conditions; the message says why "
    "(a subclass of InputError)."
)

__all__ = ["InputError", "NoMonotoneSolution"]
