"""The ``assur`` argument parser: every command and its options, the shared ones declared once.

Building the parser imports no kinematics solver and no matplotlib: of the project it
needs only the ``--explain`` formats and languages. A new command is one entry in
:data:`COMMANDS` (its name, its help line and the function that adds its arguments),
plus its runner in :data:`kinematics.cli.commands.RUNNERS`.
"""

from __future__ import annotations

import argparse
import math
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
    """``--exact``: exact values with sympy; ``--exact-timeout``: how long they may take."""
    command.add_argument(
        "--exact", action="store_true", help="exact values (radicals, fractions) with sympy"
    )
    command.add_argument(
        "--exact-timeout",
        type=_seconds,
        metavar="SECONDS",
        help="give up --exact after this many seconds (default 60)",
    )


def _seconds(text: str) -> float:
    """A time limit: a positive number of seconds, at most a day."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not 0 < value <= 86400:
        raise argparse.ArgumentTypeError(f"expected seconds in (0, 86400], not {text!r}")
    return value


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
        "text (default), markdown, latex or html (formulas in MathML)",
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
        help="assemble this group in another mode than the sketch's: 'II(2,3)' a dyad in "
        "its other one, 'III(4,5,6,7)' a triad or larger group in the next one found from "
        "the sketch's, 'III(4,5,6,7)=2' in mode 2 as --modes lists them (repeat for several)",
    )
    command.add_argument(
        "--modes",
        action="store_true",
        help="list each group's assembly modes at the sketch's inputs, for --flip GROUP=K",
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
        "the poses to solve instead of one turn: a line per pose, a column per driver, each "
        "the driver's rotation from the sketch in degrees (its displacement from the sketch in "
        "metres for a sliding driver); a first line 'drivers 4 1' sets the column order",
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
        help="assemble this group in another mode than the sketch's, as for "
        "'assur kinematics --flip'",
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


def _cam_arguments(command: argparse.ArgumentParser) -> None:
    """``cam SPEC [--json] [--plot OUT] [--profile OUT]... [-o OUT] [--samples N] [--explain]``."""
    command.add_argument(
        "file", metavar="SPEC", help="cam design: follower, base circle, program (JSON)"
    )
    _add_json(command)
    _add_plot(command, "draw the SVAJ diagrams beside the profile")
    command.add_argument(
        "--profile",
        action="append",
        metavar="OUT",
        help="write the profile: .dxf (a polyline on its own layer), .svg or .csv (repeat)",
    )
    command.add_argument(
        "-o",
        "--output",
        metavar="OUT",
        help="write the cam as a mechanism for the other commands: .json (the program inline) "
        "or .edges (the program beside it, OUT's name with .cam.json)",
    )
    command.add_argument(
        "--at",
        type=float,
        default=0.0,
        metavar="DEG",
        help="with -o: the program's angle the mechanism's sketch shows (default 0)",
    )
    command.add_argument(
        "--samples",
        type=int,
        default=360,
        metavar="N",
        help="cam angles the checks look at over a turn (default 360; extremes are refined)",
    )
    _add_explain(command)


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


def _dynamics_arguments(command: argparse.ArgumentParser) -> None:
    """``dynamics FILE [--delta D] [--drive LAW] [--omega W] [--steps N] [--json] ...``."""
    _add_file(command, "edge-list file with coordinates, masses, and the drive and loads")
    command.add_argument(
        "--delta",
        type=float,
        default=0.02,
        metavar="D",
        help="coefficient of speed fluctuation (ω_max − ω_min)/ω_m the flywheel is for "
        "(default 0.02)",
    )
    command.add_argument(
        "--drive",
        metavar="LAW",
        help="the drive instead of the file's: a torque (40), motor=M0,W0 (M0·(1 − ω/W0)), "
        "table=DEG:N·m,..., formula=EXPRESSION of phi and omega, or none",
    )
    _add_omega(command)
    _add_steps(command, 360, "poses")
    _add_json(command)
    _add_plot(command, "draw J_r(φ), M_r(φ), ω(φ), the energy–inertia diagram, the shaking")
    _add_explain(command)


def _add_omega(command: argparse.ArgumentParser) -> None:
    """``--omega W``: the mean running speed, where the file's ``omega=`` does not say it."""
    command.add_argument(
        "--omega",
        type=float,
        metavar="W",
        help="the mean speed, rad/s (default the driver's omega=)",
    )


def _balance_arguments(command: argparse.ArgumentParser) -> None:
    """``balance FILE [-o OUT] [--method M] [--radius R] [--fraction C] [--omega W] ...``."""
    _add_file(command, "edge-list file with coordinates and masses")
    command.add_argument(
        "-o",
        "--output",
        metavar="OUT",
        help="write the balanced mechanism (.edges or .json): counterweights as mass lines",
    )
    command.add_argument(
        "--method",
        choices=("auto", "complete", "primary", "static"),
        default="auto",
        help="complete (a four-bar, Berkof–Lowen), primary (a crank–slider), static (each "
        "link pinned to the frame); auto chooses (default)",
    )
    command.add_argument(
        "--radius",
        type=float,
        metavar="R",
        help="each counterweight's distance from its pivot, m (default the link's length)",
    )
    command.add_argument(
        "--fraction",
        type=float,
        default=0.5,
        metavar="C",
        help="primary: the part of the reciprocating mass the crank takes (default 0.5)",
    )
    _add_omega(command)
    _add_json(command)
    _add_plot(command, "draw the shaking force's polar plot before and after")


def _synthesize_arguments(command: argparse.ArgumentParser) -> None:
    """``synthesize path|function|motion ...``: a design from targets, as a mechanism file."""
    kinds = command.add_subparsers(dest="kind", required=True)

    def common(sub: argparse.ArgumentParser, draws: str) -> None:
        sub.add_argument(
            "-o", "--output", metavar="OUT", help="write the design here (.edges or .json)"
        )
        _add_json(sub)
        _add_plot(sub, draws)

    path = kinds.add_parser("path", help="a coupler point through N targets")
    path.add_argument(
        "targets", metavar="TARGETS", help="CSV rows x,y (x,y,crank_deg with --timing)"
    )
    path.add_argument(
        "--linkage", choices=("fourbar", "watt1", "watt2", "stephenson3"), default="fourbar"
    )
    path.add_argument(
        "--timing", action="store_true", help="the third column is the crank angle (degrees)"
    )
    path.add_argument("--seed", type=int, default=0, help="the search's seed (default 0)")
    path.add_argument(
        "--transmission", type=float, default=30.0, metavar="DEG",
        help="least transmission angle over the motion (default 30)",
    )
    path.add_argument(
        "--ratio", type=float, default=10.0, metavar="R",
        help="largest ratio of the longest link to the shortest (default 10)",
    )
    path.add_argument(
        "--allow-rocker", action="store_true",
        help="with --timing, let the input rock over the targets' range instead of turning",
    )
    path.add_argument("--generations", type=int, default=600, help="per search (default 600)")
    path.add_argument(
        "--population", type=int, default=15, help="candidates per parameter (default 15)"
    )
    path.add_argument(
        "--restarts", type=int, default=4, help="independent searches, seeds N, N+1, ... (4)"
    )
    path.add_argument(
        "--jobs", "-j", type=int, default=1, metavar="N", help="local worker processes (default 1)"
    )
    path.add_argument(
        "--scheduler", metavar="ADDRESS", help="run the searches on this Dask cluster"
    )
    path.add_argument(
        "--dask-local", type=int, default=0, metavar="N", help="on a Dask LocalCluster of N workers"
    )
    common(path, "draw the targets over the coupler curve")

    function = kinds.add_parser("function", help="a four-bar or crank–slider for y = f(x)")
    function.add_argument("--expr", required=True, help="f(x), e.g. 'log10(x)' (never evaluated)")
    function.add_argument("--x", nargs=2, type=float, required=True, metavar=("X0", "X1"))
    function.add_argument("--input-range", type=float, required=True, metavar="DEG")
    function.add_argument(
        "--output-range", type=float, required=True, metavar="DEG_OR_M",
        help="the output's swing: degrees (four-bar) or metres (crank-slider)",
    )
    function.add_argument("--points", type=int, default=3, help="precision points (default 3)")
    function.add_argument("--linkage", choices=("fourbar", "crank-slider"), default="fourbar")
    function.add_argument(
        "--input-start", type=float, default=45.0, metavar="DEG", help="crank angle at x0 (45)"
    )
    function.add_argument(
        "--output-start", type=float, metavar="DEG_OR_M",
        help="output at x0 (default 135° or twice the slider's range)",
    )
    function.add_argument("--spacing", choices=("chebyshev", "even"), default="chebyshev")
    function.add_argument(
        "--size", type=float, default=1.0, metavar="M", help="the four-bar's ground link (1 m)"
    )
    common(function, "plot the structural error over the range")

    motion = kinds.add_parser("motion", help="a four-bar carrying a body through 2 to 5 poses")
    motion.add_argument("poses", metavar="POSES", help="CSV rows x,y,angle_deg")
    motion.add_argument(
        "--check", type=int, default=12, help="designs run through the solvers (default 12)"
    )
    motion.add_argument("--designs", type=int, default=10, help="designs listed (default 10)")
    common(motion, "draw the poses over the coupler curve")


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
        "cam",
        "a disc cam from its follower's motion: SVAJ, profile, pressure angle, curvature, "
        "undercut, force closure; DXF/SVG/CSV, and the mechanism",
        _cam_arguments,
    ),
    (
        "report",
        "one self-contained HTML page: drawing, structure, kinematics, forces, cycle, gears, "
        "worked solution",
        _report_arguments,
    ),
    (
        "dynamics",
        "reduced inertia and moment, steady running, flywheel, start-up, run-down, shaking",
        _dynamics_arguments,
    ),
    ("balance", "counterweights that balance the shaking force", _balance_arguments),
    (
        "synthesize",
        "dimensional synthesis: path, function or motion generation, as a mechanism file",
        _synthesize_arguments,
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
