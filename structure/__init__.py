"""Structural analysis of planar mechanisms (the ``assur`` project).

Text -> :class:`Mechanism` -> :class:`StructuralReport` (Assur groups in solve
order) -> the solvers of the ``kinematics`` package.
"""
