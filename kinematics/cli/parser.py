"""The ``assur`` argument parser: every command and its options, the shared ones declared once.

Building the parser imports no kinematics solver and no matplotlib: of the project it
needs only the ``--explain`` formats and languages. A new command is one entry in
:data:`COMMANDS` (its name, its help line and the function that adds its arguments),
plus its runner in :data:`kinematics.cli.main.RUNNERS`.
"""

from __future__ import annotations

import argparse
import re
from collections.abc import Callable

from structure.explain.document import FORMATS, LANGUAGES
from structure.limits import memory_text
from structure.readwrite.formats import WRITE_SUFFIXES
from structure.readwrite.table import TABLE_FORMATS
from structure.readwrite.textfile import MAX_FILE_BYTES, MAX_FILE_OPTION

from .plotting import PLOT_FORMATS

__all__ = [
    "BATCH_FORMATS",
    "COMMANDS",
    "DRAWING_SUFFIXES",
    "SWEEP_SUFFIXES",
    "add_max_file_size",
    "build_parser",
    "file_size",
]

_DESCRIPTION = (
    "Planar mechanisms by Assur groups: structure, kinematics, forces, gear "
    "trains, figures and worked solutions."
)

_COORDINATES_FILE = "edge-list file with point coordinates and driver motion"


# ------------------------------------------------------------------ shared options
_SIZE_UNITS = {"": 1, "k": 10**3, "m": 10**6, "g": 10**9, "t": 10**12}
_SIZE = re.compile(r"\s*(\d+(?:\.\d*)?|\.\d+)\s*([kmgt]?)b?\s*", re.IGNORECASE)


def file_size(text: str) -> int:
    """A size in bytes as ``--max-file-size`` takes it: ``200MB``, ``1.5G``, ``64000000``.

    >>> file_size("200MB"), file_size("1.5g"), file_size("4096")
    (200000000, 1500000000, 4096)
    """
    found = _SIZE.fullmatch(text)
    size = int(float(found.group(1)) * _SIZE_UNITS[found.group(2).lower()]) if found else 0
    if size < 1:
        raise argparse.ArgumentTypeError(
            f"{text!r} is not a size: give bytes, or kB, MB, GB (e.g. 200MB)"
        )
    return size


def add_max_file_size(command: argparse.ArgumentParser) -> None:
    """``--max-file-size SIZE``: the largest file the command reads (every command that reads)."""
    command.add_argument(
        MAX_FILE_OPTION,
        type=file_size,
        default=MAX_FILE_BYTES,
        metavar="SIZE",
        help=f"read files of at most SIZE (default {memory_text(MAX_FILE_BYTES)}; e.g. 200MB); "
        "only regular files are read",
    )


def _add_file(command: argparse.ArgumentParser, holds: str) -> None:
    """The FILE argument: the mechanism to read (``holds`` says what it must hold); its limit."""
    command.add_argument("file", help=holds)
    add_max_file_size(command)


def _add_json(command: argparse.ArgumentParser) -> None:
    """``--json``: the answer as one JSON object."""
    command.add_argument("--json", action="store_true", help="print one JSON object")


def _add_exact(command: argparse.ArgumentParser) -> None:
    """``--exact``: exact values with sympy."""
    command.add_argument(
        "--exact", action="store_true", help="exact values (radicals, fractions) with sympy"
    )


def _add_plot(command: argparse.ArgumentParser, draws: str) -> None:
    """``--plot OUT``: save a figure of what ``draws`` says, in one of the plot formats."""
    command.add_argument("--plot", metavar="OUT", help=f"{draws} ({', '.join(PLOT_FORMATS)})")


def _add_explain(command: argparse.ArgumentParser) -> None:
    """``--explain [FORMAT]`` and ``--lang``: the worked solution instead of the plain answer."""
    command.add_argument(
        "--explain",
        nargs="?",
        const="text",
        choices=FORMATS,
        metavar="FORMAT",
        help="print the worked solution, step by step as the textbook writes it: "
        "text (default), markdown or latex",
    )
    command.add_argument(
        "--lang", choices=LANGUAGES, default="en", help="language of --explain (default en)"
    )


def _add_steps(command: argparse.ArgumentParser, default: int, counted: str) -> None:
    """``--steps N``: how many ``counted`` (poses, frames) per turn of the driver(s)."""
    command.add_argument(
        "--steps", type=int, default=default, help=f"{counted} per turn (default {default})"
    )


def _add_inputs(command: argparse.ArgumentParser, meaning: str) -> None:
    """``--inputs FILE``: the driver inputs to solve instead of one turn, as ``meaning`` says."""
    command.add_argument("--inputs", metavar="FILE", help=meaning)


#: the formats of a batch classification's table: a text table or a data file
BATCH_FORMATS = ("text", *TABLE_FORMATS)


def add_run_options(
    parser: argparse.ArgumentParser, formats: tuple[str, ...], default: str
) -> None:
    """``--format``, ``--output``, ``--jobs``, ``--scheduler``, ``--dask-local``."""
    parser.add_argument(
        "--format", choices=formats, default=default, help=f"table format (default {default})"
    )
    parser.add_argument(
        "--output", "-o", metavar="FILE", help="write the table to FILE instead of stdout"
    )
    parser.add_argument(
        "--jobs", "-j", type=int, default=1, metavar="N", help="local worker processes (default 1)"
    )
    parser.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="run on the Dask cluster of this scheduler, e.g. tcp://HOST:8786 (needs assur[dask])",
    )
    parser.add_argument(
        "--dask-local",
        type=int,
        default=0,
        metavar="N",
        help="run on a Dask LocalCluster of N worker processes started here (needs assur[dask])",
    )


# ------------------------------------------------------------------ the commands
def _classify_arguments(command: argparse.ArgumentParser) -> None:
    """``classify FILE [MORE ...] [--driver L]... [--all-drivers] [--json] [--plot OUT] ...``."""
    _add_file(
        command,
        "edge-list file (.edges) or its JSON form (.json); or a directory, a quoted glob, or - "
        "for JSON lines on stdin",
    )
    command.add_argument(
        "more",
        nargs="*",
        metavar="MORE",
        help="further inputs: several inputs are classified at once into one table",
    )
    command.add_argument(
        "--driver", action="append", metavar="L", help="driving link (repeat for several)"
    )
    command.add_argument(
        "--all-drivers",
        action="store_true",
        help="list the groups for every admissible driver choice",
    )
    _add_json(command)
    _add_plot(
        command,
        "draw the kinematic graph (and the mechanism, when the file has coordinates)",
    )
    _add_explain(command)
    add_run_options(command, BATCH_FORMATS, "text")


def _kinematics_arguments(command: argparse.ArgumentParser) -> None:
    """``kinematics FILE [--json] [--exact] [--plot OUT] [--flip GROUP]... [--explain]``."""
    _add_file(command, _COORDINATES_FILE)
    _add_json(command)
    _add_exact(command)
    _add_plot(command, "draw the mechanism and its velocity and acceleration polygons")
    command.add_argument(
        "--flip",
        action="append",
        metavar="GROUP",
        default=[],
        help="assemble this dyad (e.g. 'II(2,3)') in the other mode than the sketch's",
    )
    _add_explain(command)


def _forces_arguments(command: argparse.ArgumentParser) -> None:
    """``forces FILE [--json] [--exact] [--minimum-norm] [--plot OUT] [--explain]``."""
    _add_file(command, "edge-list file with coordinates, driver motion and loads")
    _add_json(command)
    _add_exact(command)
    command.add_argument(
        "--minimum-norm",
        action="store_true",
        help="for an over-constrained mechanism, give the minimum-norm reactions",
    )
    _add_plot(command, "draw the mechanism and the force polygon of each group and driver")
    _add_explain(command)


def _gears_arguments(command: argparse.ArgumentParser) -> None:
    """``gears FILE [--json] [--efficiency ETA]``."""
    _add_file(command, "edge-list file with 'a b H gear z=za,zb' meshes")
    _add_json(command)
    command.add_argument(
        "--efficiency",
        type=float,
        metavar="ETA",
        help="efficiency of each mesh (e.g. 0.98): losses, balancing moment with them",
    )


def _sweep_arguments(command: argparse.ArgumentParser) -> None:
    """``sweep FILE [--steps N] [--csv OUT] [--inputs FILE] [--plot OUT]``."""
    _add_file(command, _COORDINATES_FILE)
    _add_steps(command, 360, "poses")
    command.add_argument("--csv", metavar="OUT", help="write every pose to this CSV file")
    _add_inputs(
        command,
        "the poses to solve instead of one turn: a line per pose, a column per driver "
        "(degrees, or metres for a sliding driver); a first line 'drivers 4 1' sets the order",
    )
    _add_plot(command, "plot paths, ω, ε, |v|, |a|, transmission angle, balancing")


def _animate_arguments(command: argparse.ArgumentParser) -> None:
    """``animate FILE OUT [--steps N] [--fps FPS] [--inputs FILE]``."""
    _add_file(command, "edge-list file with point coordinates")
    command.add_argument("out", metavar="OUT", help="the animation: .gif (or .mp4 with ffmpeg)")
    _add_steps(command, 36, "frames")
    command.add_argument("--fps", type=float, default=12.0, help="frames per second (default 12)")
    _add_inputs(command, "the frames' driver inputs, as for 'assur sweep --inputs'")


#: drawings at one pose: matplotlib's formats and DXF
DRAWING_SUFFIXES = (".svg", ".png", ".pdf", ".dxf")
#: tables of a sweep
SWEEP_SUFFIXES = (".csv", ".parquet")


def _convert_arguments(parser: argparse.ArgumentParser) -> None:
    """``convert IN OUT [--driver L] [--pose X ...] [--flip GROUP] [--steps N] [--inputs FILE]``."""
    parser.add_argument(
        "file", metavar="IN", help="mechanism: .edges, .json (ours or pylinkage's), .pyslvs"
    )
    add_max_file_size(parser)
    parser.add_argument(
        "out",
        metavar="OUT",
        help="by extension: " + ", ".join((*WRITE_SUFFIXES, *DRAWING_SUFFIXES, *SWEEP_SUFFIXES)),
    )
    parser.add_argument(
        "--driver", action="append", metavar="L", help="driving link (repeat for several)"
    )
    parser.add_argument(
        "--pose",
        nargs="+",
        metavar="X",
        help="draw at this input of each driver from the sketch: degrees, or metres for a "
        "sliding driver (default: the sketch)",
    )
    parser.add_argument(
        "--flip",
        action="append",
        metavar="GROUP",
        default=[],
        help="assemble this dyad (e.g. 'II(2,3)') in the other mode than the sketch's",
    )
    parser.add_argument("--steps", type=int, default=360, help="poses per turn (default 360)")
    parser.add_argument(
        "--inputs", metavar="FILE", help="the sweep's poses, as for 'assur sweep --inputs'"
    )


def _atlas_arguments(parser: argparse.ArgumentParser) -> None:
    """``atlas --links N [--dof F] [--labelled] [--summary] ...``: the options of the atlas."""
    parser.add_argument(
        "--links",
        required=True,
        metavar="N",
        help="number of links: N, a range 4-10 or a list 4,6,8 (counts with no chain are skipped "
        "in a range)",
    )
    parser.add_argument("--dof", type=int, default=1, metavar="F", help="degrees of freedom (1)")
    parser.add_argument(
        "--labelled",
        action="store_true",
        help="one row per labelled ground and driver choice (multiplicity 1) instead of one per "
        "choice distinct up to the chain's symmetry",
    )
    parser.add_argument(
        "--degenerate",
        action="store_true",
        help="keep the chains with a rigid subchain (left out and counted apart by default)",
    )
    parser.add_argument(
        "--no-fractionated",
        action="store_true",
        help="leave out the chains that one link cuts in two (with --degenerate: pyslvs's atlas)",
    )
    parser.add_argument(
        "--summary",
        action="store_true",
        help="print the table of chains and mechanisms per link count and Assur class instead "
        "of the rows (the rows still go to --output)",
    )
    parser.add_argument(
        "--count", action="store_true", help="print the chain counts only (no classification)"
    )
    parser.add_argument(
        "--write-edgelists",
        metavar="DIR",
        help="write the edge list of every mechanism into DIR (the row's 'edgelist' names it)",
    )
    parser.add_argument(
        "--resume",
        action="store_true",
        help="keep the chains already complete in --output and classify the rest",
    )
    add_run_options(parser, TABLE_FORMATS, "jsonl")


def _report_arguments(command: argparse.ArgumentParser) -> None:
    """``report FILE [-o OUT] [--lang en|vi] [--steps N]``."""
    _add_file(command, "edge-list file (coordinates, loads and gears where it has them)")
    command.add_argument(
        "-o",
        "--output",
        metavar="OUT",
        help="the HTML file to write (default: the file's name with .html, here)",
    )
    command.add_argument(
        "--lang", choices=LANGUAGES, default="en", help="language of the page (default en)"
    )
    _add_steps(command, 120, "poses of the animation and the plots")


#: every command, in the order ``assur --help`` lists them: name, help line, its arguments
COMMANDS: tuple[tuple[str, str, Callable[[argparse.ArgumentParser], None]], ...] = (
    (
        "classify",
        "mobility, higher-pair replacement, Assur groups, class and structural formula",
        _classify_arguments,
    ),
    (
        "kinematics",
        "positions, velocities and accelerations at the sketch pose, group by group",
        _kinematics_arguments,
    ),
    ("forces", "joint reactions and balancing moment, farthest group first", _forces_arguments),
    (
        "gears",
        "gear train: meshes, carriers, DOF, exact speed ratios, balancing moment",
        _gears_arguments,
    ),
    ("sweep", "the kinematics over a whole turn of the driver(s)", _sweep_arguments),
    ("animate", "an animation of the mechanism over one turn of the driver(s)", _animate_arguments),
    (
        "convert",
        "a mechanism into another format (edge list, JSON, pyslvs), its drawing (SVG, DXF, ...) "
        "or its sweep (CSV, Parquet)",
        _convert_arguments,
    ),
    (
        "atlas",
        "every kinematic chain of N links and F DOF, every mechanism of it classified",
        _atlas_arguments,
    ),
    (
        "report",
        "one self-contained HTML page: drawing, structure, kinematics, forces, cycle, gears, "
        "worked solution",
        _report_arguments,
    ),
)


def build_parser() -> argparse.ArgumentParser:
    """The ``assur`` parser: one sub-command per entry of :data:`COMMANDS`.

    >>> build_parser().parse_args(["sweep", "m.edges"]).steps
    360
    """
    parser = argparse.ArgumentParser(prog="assur", description=_DESCRIPTION)
    sub = parser.add_subparsers(dest="command", required=True)
    for name, summary, add_arguments in COMMANDS:
        add_arguments(sub.add_parser(name, help=summary))
    return parser
