"""Machine dynamics of a one-degree-of-freedom mechanism over its cycle (driver angle φ).

- :mod:`~kinematics.dynamics.reduced`: the reduced inertia J_r(φ) and its slope;
- :mod:`~kinematics.dynamics.series`: periodic functions of φ from their samples;
- :mod:`~kinematics.dynamics.loads`: the drive and the loads over the cycle, reduced to
  the driver: M_r(φ, ω);
- :mod:`~kinematics.dynamics.machine`: the machine reduced to its driver, what the
  equation of motion needs;
- :mod:`~kinematics.dynamics.motion`: the equation of motion J_r·φ̈ + ½·J_r'·φ̇² = M_r:
  start-up, run-down, steady running (scipy);
- :mod:`~kinematics.dynamics.flywheel`: the flywheel for a coefficient of speed
  fluctuation, exactly (Wittenbauer) and approximately;
- :mod:`~kinematics.dynamics.shaking`: the shaking force and moment on the frame;
- :mod:`~kinematics.dynamics.balancing`: counterweights, the complete force balance of a
  four-bar (Berkof–Lowen), primary and secondary balance of a crank–slider.

The modules are imported one by one (this package imports none of them), so that scipy
comes only with the equation of motion. The public names are at :mod:`kinematics`.
"""
