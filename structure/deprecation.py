"""Old module paths that keep working for one release, with a DeprecationWarning.

The layout of the packages changed (``structure.edgelist`` is now
``structure.readwrite.edgelist``, and so on). An import of an old path gets
the new module itself, so every name, public or private, is still there, and
a :class:`DeprecationWarning` that names the new path.

>>> import warnings
>>> with warnings.catch_warnings(record=True) as caught:
...     warnings.simplefilter("always")
...     import structure.rank as old
>>> import structure.rigidity.rank as new
>>> old is new, caught[0].category.__name__
(True, 'DeprecationWarning')
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import sys
import warnings
from collections.abc import Mapping, Sequence
from types import ModuleType

__all__ = ["alias_moved_modules"]


class _MovedModuleFinder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds an old module path and loads it as the module now at the new path."""

    def __init__(self, moved: Mapping[str, str]) -> None:
        self.moved = dict(moved)

    def find_spec(
        self, fullname: str, path: Sequence[str] | None = None, target: ModuleType | None = None
    ) -> importlib.machinery.ModuleSpec | None:
        if fullname not in self.moved:
            return None
        return importlib.machinery.ModuleSpec(fullname, self)

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> ModuleType:
        new = self.moved[spec.name]
        warnings.warn(
            f"{spec.name} is deprecated and will be removed in the next release: "
            f"import {new} instead",
            DeprecationWarning,
            stacklevel=2,
        )
        return importlib.import_module(new)

    def exec_module(self, module: ModuleType) -> None:
        """The new module is already executed."""


def alias_moved_modules(moved: Mapping[str, str]) -> None:
    """Make each old module path (key) import the module at its new path (value)."""
    sys.meta_path.append(_MovedModuleFinder(moved))
