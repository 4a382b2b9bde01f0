"""Exceptions of the macro API. Bad input raises InputError, a ValueError.

Both are the compiled kernel's exception classes (the binding raises them); kernel.py, the
one module that imports the kernel, names and documents them."""
from .kernel import InputError, NoMonotoneSolution

__all__ = ["InputError", "NoMonotoneSolution"]
