"""The house is one-way: every import points down (issue 10's layout, STYLE.md §6).

Each module of ``structure`` and ``kinematics`` is read with :mod:`ast` (not
imported), so an import inside a function counts as much as one at the top.
Floors, from the bottom:

- ``structure``: the analysis (model, validation, rigidity, mobility,
  replacement, assur, report, chains, ...) < ``structure.readwrite`` and the
  many-mechanism jobs that read and write (``atlas``, ``batch``) < ``structure.explain``;
- ``kinematics``: the solvers (plan, solve, sweep, forces, gears, ...) <
  ``kinematics.explain`` and ``kinematics.figures`` < ``kinematics.html`` (the report page,
  beside the CLI on the top floor) and ``kinematics.cli``;
- ``structure`` < ``kinematics``: structure never imports kinematics;
- each package's ``__init__`` is the façade on top that re-exports its public API.
"""

from __future__ import annotations

import ast
from pathlib import Path

import networkx as nx
import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("structure", "kinematics")


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _modules() -> dict[str, Path]:
    return {
        _module_name(path): path
        for package in PACKAGES
        for path in sorted((ROOT / package).rglob("*.py"))
    }


MODULES = _modules()


def _imports(name: str, path: Path) -> list[tuple[str, tuple[str, ...], int, str]]:
    """``(target, imported names, line, where)`` for every import; where: top, typing, local."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    top_level = {id(node) for node in tree.body}
    # ``if TYPE_CHECKING:`` imports never run (annotations only): not local, not in the cycles
    typing_only = {
        id(inner)
        for node in tree.body
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test)
        for inner in node.body
    }
    found = []

    def where(node: ast.stmt) -> str:
        return "top" if id(node) in top_level else "typing" if id(node) in typing_only else "local"

    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                found.append((alias.name, (), node.lineno, where(node)))
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - node.level + 1]
                target = ".".join([*base, *([node.module] if node.module else [])])
            else:
                target = node.module or ""
            names = tuple(alias.name for alias in node.names)
            if node.module is None:  # ``from . import x``: each name is a module
                for alias in node.names:
                    found.append((f"{target}.{alias.name}", (), node.lineno, where(node)))
            else:
                found.append((target, names, node.lineno, where(node)))
    return found


def _floor(module: str) -> tuple[str, int]:
    """The package a module belongs to and its floor inside that package."""
    parts = module.split(".")
    package, sub = parts[0], parts[1] if len(parts) > 1 else ""
    if len(parts) == 1:  # the package root is the façade that re-exports the public API
        return package, 3
    if package == "structure":
        return package, {"readwrite": 1, "atlas": 1, "batch": 1, "explain": 2}.get(sub, 0)
    return package, {"explain": 1, "figures": 1, "html": 2, "cli": 2, "__main__": 2}.get(sub, 0)


def _project_imports():
    for name, path in MODULES.items():
        for target, names, line, top in _imports(name, path):
            if target.split(".")[0] in PACKAGES:
                yield name, path, target, names, line, top


def test_structure_never_imports_kinematics() -> None:
    back = [
        f"{path.relative_to(ROOT)}:{line} imports {target}"
        for name, path, target, _, line, _ in _project_imports()
        if name.startswith("structure") and target.startswith("kinematics")
    ]
    assert not back, "structure imports kinematics:\n" + "\n".join(back)


def test_every_import_points_down_inside_each_package() -> None:
    up = []
    for name, path, target, _, line, _ in _project_imports():
        (package, floor), (target_package, target_floor) = _floor(name), _floor(target)
        if target in ALLOWED_LOCAL_IMPORTS.get(name, {}):
            continue  # a documented exception, with its reason
        if package == target_package and target_floor > floor:
            up.append(f"{path.relative_to(ROOT)}:{line} imports {target} from a floor above")
    assert not up, "\n".join(up)


def test_no_module_imports_a_private_name_of_another() -> None:
    private = [
        f"{path.relative_to(ROOT)}:{line} imports {n} from {target}"
        for name, path, target, names, line, _ in _project_imports()
        for n in names
        if n.startswith("_") and not n.startswith("__") and target != name
    ]
    assert not private, "\n".join(private)


def test_the_top_level_import_graph_has_no_cycle() -> None:
    graph = nx.DiGraph()
    for name, _, target, names, _, where in _project_imports():
        if where != "top":
            continue
        # ``from package import module`` imports the module; otherwise the module named
        for module in [f"{target}.{n}" for n in names if f"{target}.{n}" in MODULES] or [target]:
            if module in MODULES and module != name and not name.startswith(f"{module}."):
                graph.add_edge(name, module)
    # a package's __init__ re-exporting its own modules is not a cycle of the house
    own = [(a, b) for a, b in graph.edges if b.startswith(f"{a}.")]
    graph.remove_edges_from(own)
    cycles = list(nx.simple_cycles(graph))
    assert not cycles, "import cycles:\n" + "\n".join(" -> ".join(c) for c in cycles[:10])


@pytest.mark.parametrize("module", sorted(MODULES))
def test_function_local_imports_are_the_documented_exceptions(module: str) -> None:
    """Lazy imports only for an optional extra, or where a module is listed with its reason."""
    local = [
        (target, line)
        for target, _, line, where in _imports(module, MODULES[module])
        if where == "local" and target.split(".")[0] not in OPTIONAL_EXTRAS
    ]
    allowed = ALLOWED_LOCAL_IMPORTS.get(module, {})
    unexpected = [f"{target} (line {line})" for target, line in local if target not in allowed]
    assert not unexpected, f"{module}: function-local imports " + ", ".join(unexpected)


#: optional extras: a module that uses one imports it when it is needed, so that the module
#: itself imports without it and a missing extra is a clear error, not an ImportError at start
OPTIONAL_EXTRAS = {
    "dask",
    "distributed",
    "ezdxf",
    "matplotlib",
    "pyarrow",
    "pynauty",
    "tqdm",
    "yaml",
}

#: module -> {project module it imports inside a function: why}
ALLOWED_LOCAL_IMPORTS: dict[str, dict[str, str]] = {
    "structure.model": {
        "networkx": "start-up: the kinematic graph is built on first use, so that classifying "
        "a mechanism does not pay for importing networkx (as long as the rest of assur classify)",
    },
    "structure.assur": {
        "networkx": "start-up: the group DAG as a networkx DiGraph is built when asked for",
    },
    "kinematics.dynamics.machine": {
        "kinematics.gears.trains": "start-up: a gear train without coordinates takes its ratios "
        "from sympy's exact Willis relations; every other machine's dynamics goes without sympy",
    },
    "structure.report": {
        "structure.readwrite": "the formatting's old path, kept for one release with a "
        "DeprecationWarning (a top-level import would be a cycle: reports reads the report)",
    },
}


def test_public_names_are_not_shadowed_by_submodules() -> None:
    """``kinematics.sweep`` is the function, even after its module is imported (issue 22, item 8).

    Importing a submodule sets it as an attribute of its package: a public name
    that is also a module's name would turn into the module.
    """
    import importlib
    import types

    import kinematics

    packages = sorted(
        name for name, path in MODULES.items() if path.name == "__init__.py"
    )  # every package, not only the two roots: ``kinematics.cli.main`` was once both
    roots = {name: importlib.import_module(name) for name in packages}
    public = {
        package: {
            name: getattr(root, name)
            for name in (root.__all__ if hasattr(root, "__all__") else dir(root))
            if not name.startswith("_")
            and hasattr(root, name)
            and not isinstance(getattr(root, name), types.ModuleType)
        }
        for package, root in roots.items()
    }
    for module in MODULES:
        if not module.endswith("__main__"):
            importlib.import_module(module)
    for package, names in public.items():
        changed = sorted(n for n, v in names.items() if getattr(roots[package], n) is not v)
        assert not changed, f"{package}: public names replaced by submodules: {changed}"
    assert kinematics.sweep.__name__ == "sweep" and callable(kinematics.sweep)
