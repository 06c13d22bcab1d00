"""Solvers that consume the structural report's Assur groups in solve order.

Positions, velocities, accelerations and forces are not implemented yet; this
package depends on :mod:`structure`, never the other way round.
"""
