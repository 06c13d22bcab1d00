"""Kinematics of planar mechanisms, solved Assur group by Assur group.

The structural report (:mod:`structure`) gives the groups in solve order;
:func:`make_plan` turns them into equations, :func:`solve_pose`,
:func:`sweep` and :func:`solve_exact` solve them, :func:`solve_forces` gives
the joint reactions and the balancing moment. This package depends on
:mod:`structure`, never the other way round.

The public names below are imported from here; each is loaded on first use,
so ``import kinematics`` stays cheap (sympy and matplotlib come only with the
parts that need them).

>>> import structure, kinematics
>>> m = structure.read_edgelist("fixtures/ch2_2_4_fourbar.edges")
>>> state = kinematics.solve_pose(kinematics.make_plan(structure.analyze(m)))
>>> round(state.links["3"].omega, 9)
5.0
"""

from __future__ import annotations

import importlib
from typing import Any

from structure.deprecation import alias_moved_modules

#: the public names, by the module (below this package) that defines them
_PUBLIC_BY_MODULE = {
    "solvers.plan": ("DriverStep", "GroupStep", "SolvePlan", "make_plan"),
    "solvers.solve": (
        "AssemblyError",
        "KinematicState",
        "LinkState",
        "Motion",
        "PointState",
        "SingularPoseError",
        "assembly_modes",
        "solve_pose",
        "solve_poses",
    ),
    "solvers.sweep": ("Sweep", "parse_inputs", "read_inputs", "sweep", "transmission_angle"),
    "solvers.travel": ("Travel", "cycle_inputs", "travel"),
    "kinetostatics.forces": (
        "ForceSolution",
        "ForceSweep",
        "IndeterminateError",
        "Reaction",
        "forces_over",
        "solve_forces",
    ),
    "solvers.exact": (
        "EXACT_TIMEOUT",
        "ExactForces",
        "ExactState",
        "ExactTimeoutError",
        "forces_exact",
        "solve_exact",
    ),
    "dynamics.reduced": ("ReducedProperties", "reduced_inertia_over", "reduced_properties"),
    "dynamics.machine": ("ReducedMachine", "reduced_machine"),
    "dynamics.motion": ("Run", "SteadyRunning", "run_down", "start_up", "steady_running"),
    "dynamics.flywheel": ("Flywheel", "flywheel"),
    "dynamics.shaking": ("Shaking", "shaking"),
    "dynamics.balancing": ("Balanced", "Counterweight", "balance", "counterweight"),
    "dynamics.analysis": ("MachineDynamics", "machine_dynamics"),
    "kinetostatics.polygons": ("Term", "VectorEquation", "vector_equations"),
    "results.serialization": (
        "exact_forces_to_dict",
        "exact_to_dict",
        "forces_to_dict",
        "state_to_dict",
    ),
    "gears": (
        "DifferentialSplit",
        "Mesh",
        "TrainForces",
        "TrainLosses",
        "TrainRatios",
        "balancing_moment",
        "bevel_differential_split",
        "meshes",
        "reduced_inertia",
        "speed_ratios",
        "train_forces",
        "train_losses",
    ),
    "explain": ("explain_forces", "explain_kinematics"),
    "cams": (
        "CamDesign",
        "CamReport",
        "cam_geometry",
        "cam_mechanism",
        "cam_report",
        "cam_report_to_dict",
        "check_cam",
        "force_closure",
        "make_design",
        "smallest_base_circle",
        "write_profile",
    ),
}
_PUBLIC = {name: module for module, names in _PUBLIC_BY_MODULE.items() for name in names}

__all__ = sorted(_PUBLIC)


def __getattr__(name: str) -> Any:
    module = _PUBLIC.get(name)
    if module is None:
        raise AttributeError(f"module 'kinematics' has no attribute {name!r}")
    value = getattr(importlib.import_module(f".{module}", __name__), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_PUBLIC))


alias_moved_modules(
    {
        "kinematics.involute": "kinematics.gears.involute",
        "kinematics.differential": "kinematics.gears.differential",
        "kinematics.report": "kinematics.results.serialization",
        "kinematics.figure_style": "kinematics.figures.style",
        "kinematics.mechanism_figure": "kinematics.figures.mechanism",
        "kinematics.graph_figure": "kinematics.figures.graph",
        "kinematics.polygon_figures": "kinematics.figures.polygons",
        "kinematics.force_figures": "kinematics.figures.forces",
        "kinematics.sweep_figure": "kinematics.figures.sweep",
        "kinematics.animation": "kinematics.figures.animation",
        "kinematics.plan": "kinematics.solvers.plan",
        "kinematics.equations": "kinematics.solvers.equations",
        "kinematics.planar": "kinematics.solvers.planar",
        "kinematics.frames": "kinematics.solvers.frames",
        "kinematics.dyads": "kinematics.solvers.dyads",
        "kinematics.triads": "kinematics.solvers.triads",
        "kinematics.newton": "kinematics.solvers.newton",
        "kinematics.branches": "kinematics.solvers.branches",
        "kinematics.solve": "kinematics.solvers.solve",
        "kinematics.exact": "kinematics.solvers.exact",
        "kinematics.forces": "kinematics.kinetostatics.forces",
        "kinematics.polygons": "kinematics.kinetostatics.polygons",
        "kinematics.inertia": "kinematics.dynamics.reduced",
        "kinematics.kinetostatics.inertia": "kinematics.dynamics.reduced",
        "kinematics.state": "kinematics.results.state",
        "kinematics.serialization": "kinematics.results.serialization",
        "kinematics.export": "kinematics.results.export",
    }
)
