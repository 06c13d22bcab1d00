"""pyslvs's example mechanisms and published positions, read from pyslvs's own sdist.

Nothing of pyslvs is kept in this repository. The tests take pyslvs's example
list (``pyslvs/example.py``) and the positions its tests check
(``test/test_core.py``) from the source distribution of pyslvs 22.7.0, found in
the directory ``$ASSUR_PYSLVS_SDIST_DIR`` (else ``.cache/pyslvs`` under the
repository root) or downloaded there once with ``pip download``. Both files are
read with :mod:`ast`: only literal nodes are evaluated, nothing is executed.
"""

from __future__ import annotations

import ast
import hashlib
import json
import os
import sys
import tarfile
import urllib.request
from dataclasses import dataclass
from pathlib import Path

__all__ = [
    "PYSLVS_VERSION",
    "SDIST_DIR_VARIABLE",
    "PublishedCheck",
    "PyslvsExample",
    "PyslvsSdist",
    "download_sdist",
    "read_sdist",
    "sdist_dir",
]

PYSLVS_VERSION = "22.7.0"
SDIST_DIR_VARIABLE = "ASSUR_PYSLVS_SDIST_DIR"
SDIST_NAME = f"pyslvs-{PYSLVS_VERSION}.tar.gz"
EXAMPLES_MEMBER = f"pyslvs-{PYSLVS_VERSION}/pyslvs/example.py"
TESTS_MEMBER = f"pyslvs-{PYSLVS_VERSION}/test/test_core.py"
#: the name of the example dictionary in pyslvs/example.py
EXAMPLES_NAME = "_example_list"
#: the sdist's sha256, as the package index lists it
SDIST_SHA256 = "0e92a67683f3627322be07f37e57d2ded2edd4dcf6773d52bcbe6e45948a5275"
#: seconds for the download (the file is about 1 MB)
DOWNLOAD_TIMEOUT = 300
ROOT = Path(__file__).resolve().parent.parent


@dataclass(frozen=True)
class PyslvsExample:
    """One example mechanism: its expression and its input pairs (base, driven joint)."""

    expression: str
    inputs: tuple[tuple[int, int], ...]


@dataclass(frozen=True)
class PublishedCheck:
    """A position pyslvs's tests check: ``x, y = <subject>`` and the numbers asserted."""

    subject: str
    xy: tuple[float, float]


@dataclass(frozen=True)
class PyslvsSdist:
    """What the tests take from the sdist.

    ``checks`` is keyed by (test function, number of the check in it, from 0).
    """

    path: Path
    examples: dict[str, PyslvsExample]
    checks: dict[tuple[str, int], PublishedCheck]


def sdist_dir() -> Path:
    """Where the sdist is looked for and downloaded to."""
    configured = os.environ.get(SDIST_DIR_VARIABLE)
    return Path(configured) if configured else ROOT / ".cache" / "pyslvs"


def download_sdist(directory: Path) -> tuple[Path | None, str]:
    """The sdist in ``directory``, downloaded from the package index when it is not there.

    The file is fetched as it is (nothing is built: ``pip download --no-binary`` would build
    Cython to read pyslvs's metadata), checked against :data:`SDIST_SHA256` and renamed into
    place only when whole.

    Returns
    -------
    tuple
        The path of the tarball and ``""``, or ``None`` and why it could not be had.
    """
    path = directory / SDIST_NAME
    if path.is_file():
        return path, ""
    try:
        url = _sdist_url()
        with urllib.request.urlopen(url, timeout=DOWNLOAD_TIMEOUT) as response:
            data = response.read()
    except (OSError, ValueError, KeyError) as exc:  # URLError is an OSError
        return None, f"the download of {SDIST_NAME} failed: {exc}"
    digest = hashlib.sha256(data).hexdigest()
    if digest != SDIST_SHA256:
        return None, f"{SDIST_NAME} from {url} has sha256 {digest}, not {SDIST_SHA256}"
    directory.mkdir(parents=True, exist_ok=True)
    partial = directory / f".{SDIST_NAME}.{os.getpid()}.part"
    partial.write_bytes(data)
    partial.replace(path)
    return path, ""


def _sdist_url() -> str:
    """The sdist's address, from the simple index's JSON page (PEP 691)."""
    index = os.environ.get("PIP_INDEX_URL", "https://pypi.org/simple").rstrip("/")
    request = urllib.request.Request(
        f"{index}/pyslvs/", headers={"Accept": "application/vnd.pypi.simple.v1+json"}
    )
    with urllib.request.urlopen(request, timeout=60) as response:
        page = json.load(response)
    for entry in page["files"]:
        if entry["filename"] == SDIST_NAME:
            return entry["url"]
    raise ValueError(f"the index {index} lists no {SDIST_NAME}")


def read_sdist(path: Path) -> PyslvsSdist:
    """The examples and the published checks of the sdist at ``path``."""
    with tarfile.open(path, "r:gz") as archive:
        examples = _source(archive, EXAMPLES_MEMBER)
        tests = _source(archive, TESTS_MEMBER)
    return PyslvsSdist(path, _examples(examples), _checks(tests))


def _source(archive: tarfile.TarFile, member: str) -> ast.Module:
    handle = archive.extractfile(member)
    if handle is None:
        raise ValueError(f"{archive.name}: {member} is not a file")
    with handle:
        return ast.parse(handle.read().decode("utf-8"), member)


def _examples(module: ast.Module) -> dict[str, PyslvsExample]:
    """pyslvs's example dictionary ``{name: (expression, ((base, driven), ...))}``."""
    for node in module.body:
        if isinstance(node, ast.Assign | ast.AnnAssign) and node.value is not None:
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            if any(isinstance(t, ast.Name) and t.id == EXAMPLES_NAME for t in targets):
                table = ast.literal_eval(node.value)
                return {
                    name: PyslvsExample(expression, tuple(map(tuple, inputs)))
                    for name, (expression, inputs) in table.items()
                }
    raise ValueError(f"{EXAMPLES_MEMBER}: no literal {EXAMPLES_NAME}")


def _checks(module: ast.Module) -> dict[tuple[str, int], PublishedCheck]:
    """Every ``x, y = <subject>`` followed by ``assertAlmostEqual(number, x|y, ...)``."""
    checks: dict[tuple[str, int], PublishedCheck] = {}
    for function in ast.walk(module):
        if isinstance(function, ast.FunctionDef):
            for number, check in enumerate(_function_checks(function.body)):
                checks[function.name, number] = check
    return checks


def _function_checks(body: list[ast.stmt]) -> list[PublishedCheck]:
    """The checks of one test function, in order."""
    found: list[tuple[str, dict[str, float]]] = []
    for statement in body:
        value = _pair_value(statement)
        if value is not None:
            found.append((ast.unparse(value), {}))
        elif found:
            found[-1][1].update(_asserted(statement))
    return [PublishedCheck(subject, (xy["x"], xy["y"])) for subject, xy in found if len(xy) == 2]


def _pair_value(statement: ast.stmt) -> ast.expr | None:
    """The value of ``x, y = value``, or None."""
    if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
        target = statement.targets[0]
        names = [e.id for e in getattr(target, "elts", []) if isinstance(e, ast.Name)]
        if isinstance(target, ast.Tuple) and names == ["x", "y"]:
            return statement.value
    return None


def _asserted(statement: ast.stmt) -> dict[str, float]:
    """``{"x": number}`` for ``self.assertAlmostEqual(number, x, ...)`` (either order)."""
    call = statement.value if isinstance(statement, ast.Expr) else None
    if not (isinstance(call, ast.Call) and getattr(call.func, "attr", "") == "assertAlmostEqual"):
        return {}
    if len(call.args) < 2:
        return {}
    first, second = call.args[:2]
    if isinstance(first, ast.Name):
        first, second = second, first
    if not (isinstance(second, ast.Name) and second.id in ("x", "y")):
        return {}
    try:
        return {second.id: float(ast.literal_eval(first))}
    except (TypeError, ValueError):  # not a literal number
        return {}


if __name__ == "__main__":  # .ci/run: fetch the sdist before the tests
    found, why = download_sdist(sdist_dir())
    print(why or f"pyslvs sdist: {found}", file=sys.stderr if why else sys.stdout)
    sys.exit(1 if why else 0)
