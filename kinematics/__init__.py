"""Kinematics of planar mechanisms, solved Assur group by Assur group.

The structural report (:mod:`structure`) gives the groups in solve order;
:func:`kinematics.plan.make_plan` turns them into equations and
:mod:`kinematics.solve`, :mod:`kinematics.sweep` and :mod:`kinematics.exact`
solve them. This package depends on :mod:`structure`, never the other way round.
"""
