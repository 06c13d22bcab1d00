"""Animation of a mechanism over a sweep: a GIF (Pillow) or an MP4 (ffmpeg).

The mechanism is drawn once (:func:`kinematics.figures.scene.draw_scene`'s
artists); each frame only moves those artists to the links' poses, so a
frame costs one Agg render. The axes are fixed to the whole motion, and the
paths of the moving points are traced faintly.

>>> import tempfile, pathlib
>>> from PIL import Image
>>> from structure import parse_edgelist
>>> from structure.report import analyze
>>> from kinematics.solvers.plan import make_plan
>>> m = parse_edgelist(["driver 1 omega=10", "0 1 R A", "1 2 R B", "2 3 R C", "3 0 R D",
...                     "point A 0 0", "point B 0.1 0", "point C 0.3 0.3", "point D 0.4 0"])
>>> report = analyze(m)
>>> plan = make_plan(report)
>>> with tempfile.TemporaryDirectory() as tmp:
...     out = animate(report, plan, np.linspace(0, 2 * np.pi, 4, endpoint=False),
...                   pathlib.Path(tmp) / "fourbar.gif", size=(3, 2.5), dpi=40)
...     Image.open(out).n_frames
4
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from matplotlib.animation import FFMpegWriter, PillowWriter
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.text import Text
from PIL import Image

from structure.errors import MechanismError
from structure.report import StructuralReport

from ..solvers.plan import SolvePlan
from ..solvers.solve import Motion, solve_poses
from ..solvers.sweep import Sweep
from ..solvers.travel import travel
from .scene import Scene, draw_scene
from .style import Poses, unit_text

__all__ = ["animate", "there_and_back", "turn_inputs"]


def turn_inputs(plan: SolvePlan, steps: int) -> np.ndarray:
    """Inputs (frames, drivers) for an animation of one cycle of the drivers.

    The cycle of :func:`kinematics.solvers.travel.travel`: one turn of a
    turning driver (several at the ratio of the speeds the file gives them),
    a sliding driver's stroke. A mechanism that cannot make the whole cycle
    goes over the stretch it reaches and back (:func:`there_and_back`), so
    that the animation loops without a jump.

    >>> from structure import parse_edgelist
    >>> from structure.report import analyze
    >>> from kinematics.solvers.plan import make_plan
    >>> plan = make_plan(analyze(parse_edgelist(["driver 1", "0 1 R A", "point A 0 0"])))
    >>> np.round(np.degrees(turn_inputs(plan, 4)[:, 0]), 6).tolist()
    [0.0, 90.0, 180.0, 270.0]
    """
    if steps < 1:
        raise ValueError(f"steps must be at least 1, got {steps}")
    way = travel(plan, steps)
    return way.inputs if way.complete else there_and_back(way.inputs)


def there_and_back(rows: np.ndarray) -> np.ndarray:
    """The rows, then back over them to the second (a loop without repeating either end).

    >>> there_and_back(np.array([[0.0], [1.0], [2.0], [3.0]])).ravel().tolist()
    [0.0, 1.0, 2.0, 3.0, 2.0, 1.0]
    """
    return np.concatenate([rows, rows[-2:0:-1]])


class _CanvasPillowWriter(PillowWriter):
    """A :class:`PillowWriter` that takes each frame from the Agg canvas as it stands.

    The frames are drawn by blitting (only the moving artists over a saved
    background), so no ``savefig`` (a full redraw) is needed per frame. The
    frames are kept in this class's own list and written with Pillow, as
    :class:`PillowWriter` does, so no private attribute of it is relied on.
    """

    def setup(self, fig, outfile, dpi=None) -> None:
        super().setup(fig, outfile, dpi=dpi)
        self.frames: list[Image.Image] = []
        self.palette: Image.Image | None = None

    def grab_frame(self, **savefig_kwargs) -> None:
        canvas = self.fig.canvas
        size = canvas.get_width_height(physical=True)
        rgb = Image.frombuffer("RGBA", size, canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
        rgb = rgb.convert("RGB")  # a copy: the canvas' buffer is reused
        if self.palette is None:  # every artist is in the first frame: its colours serve all
            self.palette = rgb.quantize(colors=256, method=Image.Quantize.FASTOCTREE)
        self.frames.append(rgb.quantize(palette=self.palette, dither=Image.Dither.NONE))

    def finish(self) -> None:
        self.frames[0].save(
            self.outfile, save_all=True, append_images=self.frames[1:],
            duration=int(1000 / self.fps), loop=0,
        )  # fmt: skip


def _writer(path: Path, fps: float):
    """The writer of ``path``'s format (a GIF blitted from the canvas, an MP4 by ffmpeg)."""
    suffix = path.suffix.lower()
    if suffix == ".gif":
        return _CanvasPillowWriter(fps=fps)
    if suffix == ".mp4":
        if not FFMpegWriter.isAvailable():
            raise MechanismError(
                f"cannot write {path.name}: an MP4 needs ffmpeg on the PATH and it was not "
                "found; install ffmpeg or write a .gif"
            )
        return FFMpegWriter(fps=fps)
    raise MechanismError(
        f"unsupported animation format {path.suffix or '(none)'!r} for {path.name}: "
        "use .gif (or .mp4 with ffmpeg)"
    )


def animate(
    report: StructuralReport,
    plan: SolvePlan,
    source: Sweep | np.ndarray,
    path: str | Path,
    fps: float = 12.0,
    *,
    dpi: float = 80.0,
    size: tuple[float, float] = (6.0, 5.0),
) -> Path:
    """Write an animation of the mechanism over the inputs of ``source``.

    Parameters
    ----------
    report : StructuralReport
        The structural analysis (group colours, drivers, replacements).
    plan : SolvePlan
        Its solve plan.
    source : Sweep or array_like
        A sweep (its ``inputs`` are used) or the inputs themselves, shape
        (frames,) or (frames, drivers): driver rotations (rad) or
        displacements (m) from the sketch.
    path : str or Path
        ``.gif`` (Pillow) or ``.mp4`` (needs ffmpeg).
    fps : float
        Frames per second.
    dpi, size : float, (float, float)
        Resolution and size (inches) of each frame.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    MechanismError
        An unsupported extension, an MP4 without ffmpeg, or a pose the
        mechanism cannot take (an :class:`~kinematics.solvers.solve.AssemblyError`,
        or any pose but the sketch for a mechanism with higher pairs).
    ValueError
        No frames, or ``fps`` not positive.
    """
    path = Path(path)
    if not fps > 0:
        raise ValueError(f"fps must be positive, got {fps}")
    writer = _writer(path, fps)
    inputs = _frame_inputs(source)
    motion = solve_poses(plan, inputs)
    poses = [{link: q[k] for link, q in motion.q.items()} for k in range(len(inputs))]

    name = plan.mechanism.name or "mechanism"
    fig, scene, title, moving = _first_frame(report, plan, motion, poses[0], name, size, dpi)
    ax = title.axes
    blit = isinstance(writer, _CanvasPillowWriter)
    canvas = fig.canvas
    background = _draw_still_parts(fig, moving) if blit else None
    try:
        with writer.saving(fig, str(path), dpi):
            for pose, values in zip(poses, inputs, strict=True):
                scene.update(pose)
                title.set_text(_frame_title(name, plan, values))
                if blit:
                    canvas.restore_region(background)
                    for artist in moving:
                        ax.draw_artist(artist)
                writer.grab_frame()
    except FileNotFoundError as exc:
        raise MechanismError(f"cannot write {path}: {exc.strerror or exc}") from exc
    return path


def _first_frame(
    report: StructuralReport,
    plan: SolvePlan,
    motion: Motion,
    pose: Poses,
    name: str,
    size: tuple[float, float],
    dpi: float,
) -> tuple[Figure, Scene, Text, list]:
    """The figure at the first pose, laid out once for every frame.

    Returns the figure, its scene, its title, and the artists that move
    (those of the scene still shown, and the title), in drawing order.
    """
    fig = Figure(figsize=size, dpi=dpi)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    scene, handles = draw_scene(report, plan, ax, pose)
    hidden = _hide_absent_virtual_links(scene, motion)
    _fit_to_motion(ax, scene, plan, motion)
    ax.legend(  # below the axes, where no link passes over it
        handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, fontsize=7
    )
    ax.set_xlabel(f"x ({unit_text(scene.unit)})")
    ax.set_ylabel(f"y ({unit_text(scene.unit)})")
    title = ax.set_title(name, fontsize=9)
    fig.tight_layout()
    fig.set_layout_engine(None)  # laid out once: no layout pass (and second draw) per frame
    shown = [a for a in scene.artists if not any(a is h for h in hidden)]
    moving = sorted([*shown, title], key=lambda a: a.get_zorder())
    return fig, scene, title, moving


def _frame_inputs(source: Sweep | np.ndarray) -> np.ndarray:
    """The inputs (frames, drivers) of a sweep or of an array (a 1-D one: one driver).

    Raises
    ------
    ValueError
        No frames.
    """
    inputs = np.asarray(source.inputs if isinstance(source, Sweep) else source, dtype=float)
    if inputs.ndim == 1:
        inputs = inputs[:, None]
    if len(inputs) == 0:
        raise ValueError("no frames to animate: the inputs are empty")
    return inputs


def _draw_still_parts(fig: Figure, moving: list):
    """Draw the figure without the ``moving`` artists, once; returns that background to blit on."""
    for artist in moving:
        artist.set_animated(True)
    fig.canvas.draw()
    return fig.canvas.copy_from_bbox(fig.bbox)


def _hide_absent_virtual_links(scene: Scene, motion: Motion) -> list:
    """Hide the virtual links a rolling gear mesh does without away from the sketch.

    Returns the hidden artists.
    """
    hidden = []
    for link, artists in scene.virtual.items():
        if link not in motion.q:
            hidden.extend(artists)
            for artist in artists:
                artist.set_visible(False)
    return hidden


def _fit_to_motion(ax: Axes, scene: Scene, plan: SolvePlan, motion: Motion) -> None:
    """Fix the limits to the whole motion, and trace the paths of the moving points faintly.

    The scene draws in its unit (``scene.unit`` metres): the motion is divided by it.
    """
    reach = []
    for link, sketch in scene.anchors:
        q = motion.q.get(link)
        if q is None:
            continue
        cos, sin = np.cos(q[:, 2])[:, None], np.sin(q[:, 2])[:, None]
        x = q[:, 0:1] / scene.unit + cos * sketch[None, :, 0] - sin * sketch[None, :, 1]
        y = q[:, 1:2] / scene.unit + sin * sketch[None, :, 0] + cos * sketch[None, :, 1]
        reach.append(np.column_stack([x.ravel(), y.ravel()]))
    for name, (link, c) in plan.points.items():
        if link not in motion.q:
            continue
        xy, _, _ = motion.point(link, np.asarray(c, dtype=float))
        xy = xy / scene.unit
        reach.append(xy)
        if float(np.ptp(xy, axis=0).max()) > 1e-9 * scene.size:
            ax.plot(xy[:, 0], xy[:, 1], lw=0.8, color="0.6", alpha=0.6, gid=f"trace:{name}")
    every = np.vstack(reach)
    lo, hi = every.min(axis=0), every.max(axis=0)
    pad = 0.12 * max(float((hi - lo).max()), scene.size)
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.set_autoscale_on(False)


def _frame_title(name: str, plan: SolvePlan, values: np.ndarray) -> str:
    """The mechanism's name over the drivers' inputs: ``φ1 = 90°``, ``s1 = 0.02 m``."""
    state = ", ".join(
        f"φ{d.link} = {math.degrees(v):.0f}°" if d.kind == "R" else f"s{d.link} = {v:.4g} m"
        for d, v in zip(plan.drivers, values, strict=True)
    )
    return f"{name}\n{state}" if state else name
