"""Dimensional synthesis: function, motion and path generation, every answer checked by the solvers.

Function generation (:mod:`.function`) by Freudenstein's equation, motion
generation (:mod:`.motion`) by poles and Burmester's curves, path generation
(:mod:`.path`) by differential evolution polished by least squares. A design
is a :class:`~structure.model.Mechanism` with its coupler point as the marker
``P`` and its targets kept; before it is returned it is run through the
group-by-group solvers (:mod:`.defects`), so that an answer that does not
assemble, changes branch or meets a dead point between its targets is never
given.
"""
