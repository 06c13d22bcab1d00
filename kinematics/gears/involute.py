"""Involute spur gear geometry: radii, centre distance, contact ratio, tooth thickness.

Small pure functions in SI units: lengths in metres (the module ``m`` too),
angles in radians. A pressure angle is always given in radians; write
``math.radians(20)`` for the standard 20°. Profile shift coefficients ``ξ``
(``shift``, ``x1``, ``x2``) are dimensionless, the shift itself being ``ξ·m``.

Internal gears follow the convention of the Soviet/Vietnamese textbooks
(ГОСТ 19274): a positive ``ξ`` moves the whole profile of the gear, internal
or external, away from its axis. So an external gear gets a thicker tooth and
a bigger tip circle, an internal gear a *thinner* tooth and a bigger (shorter
tooth) tip circle:

* external: ``r_a = r + m(h_a + ξ)``, ``r_f = r − m(h_f − ξ)``,
  ``S = m(π/2 + 2ξ tan α)``;
* internal: ``r_a = r − m(h_a − ξ)``, ``r_f = r + m(h_f + ξ)``,
  ``S = m(π/2 − 2ξ tan α)``.

In an internal pair gear 1 is the external pinion and gear 2 the internal
(ring) gear, ``z2 > z1``. No tip shortening is applied to shifted pairs.

>>> m, z = 0.004, 20
>>> round(pitch_radius(m, z), 6), round(base_radius(m, z), 7), round(tip_radius(m, z), 6)
(0.04, 0.0375877, 0.044)
>>> round(contact_ratio(m, 20, 40), 4)
1.6352
"""

from __future__ import annotations

import math
from numbers import Integral, Real

__all__ = [
    "MAX_SHIFT",
    "STANDARD_PRESSURE_ANGLE",
    "base_radius",
    "center_distance",
    "contact_ratio",
    "inverse_involute",
    "involute",
    "pitch_radius",
    "root_radius",
    "tip_radius",
    "tooth_thickness",
    "tooth_thickness_at",
    "working_center_distance",
    "working_pressure_angle",
]

STANDARD_PRESSURE_ANGLE: float = math.radians(20)
"""The standard pressure angle α = 20°, in radians."""

MAX_SHIFT: float = 2.0
"""Largest accepted ``|ξ|``; practical shifts lie well inside ±1.5."""


# --------------------------------------------------------------------------- validation


def _real(value: object, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, Real) or not math.isfinite(value):
        raise ValueError(f"{name} must be a finite real number, got {value!r}")
    return float(value)


def _module(module: object) -> float:
    m = _real(module, "module")
    if m <= 0:
        raise ValueError(f"module must be positive (metres), got {module!r}")
    return m


def _teeth(teeth: object, name: str = "teeth") -> int:
    if isinstance(teeth, bool) or not isinstance(teeth, Integral) or teeth < 1:
        raise ValueError(f"{name} must be an integer >= 1, got {teeth!r}")
    return int(teeth)


def _shift(shift: object, name: str = "shift") -> float:
    x = _real(shift, name)
    if abs(x) > MAX_SHIFT:
        raise ValueError(
            f"{name} (profile shift coefficient ξ) must satisfy |ξ| <= {MAX_SHIFT}, got {shift!r}"
        )
    return x


def _pressure_angle(alpha: object, name: str = "pressure_angle") -> float:
    a = _real(alpha, name)
    if not 0 < a < math.pi / 2:
        raise ValueError(
            f"{name} must be in radians with 0 < α < π/2 (e.g. math.radians(20)), got {alpha!r}"
        )
    return a


def _coefficient(value: object, name: str) -> float:
    c = _real(value, name)
    if c < 0:
        raise ValueError(f"{name} coefficient must be >= 0, got {value!r}")
    return c


def _pair(z1: object, z2: object, internal: bool) -> tuple[int, int]:
    n1, n2 = _teeth(z1, "z1"), _teeth(z2, "z2")
    if internal and n2 <= n1:
        raise ValueError(
            f"an internal pair needs the internal gear z2 larger than the pinion z1, "
            f"got z1={n1}, z2={n2}"
        )
    return n1, n2


# --------------------------------------------------------------------------- involute function


def involute(alpha: float) -> float:
    """The involute function ``inv α = tan α − α``.

    Parameters
    ----------
    alpha : float
        Pressure angle, radians, ``0 <= α < π/2``.

    Returns
    -------
    float
        ``tan α − α``, radians.

    Examples
    --------
    >>> round(involute(math.radians(20)), 6)
    0.014904
    >>> involute(0.0)
    0.0
    """
    a = _real(alpha, "alpha")
    if not 0 <= a < math.pi / 2:
        raise ValueError(f"alpha must be in radians with 0 <= α < π/2, got {alpha!r}")
    return math.tan(a) - a


def inverse_involute(value: float, tol: float = 1e-15) -> float:
    """The angle ``α`` in ``[0, π/2)`` with ``inv α = value``, by Newton's method.

    ``inv`` is increasing and convex on ``[0, π/2)``, so Newton started to the
    right of the root (at ``min((3v)^(1/3), atan(v + π/2))``, both upper
    bounds) decreases monotonically onto it.

    Parameters
    ----------
    value : float
        ``inv α``, radians, ``>= 0``.
    tol : float
        Stop when the Newton step is below this, radians.

    Returns
    -------
    float
        ``α``, radians.

    Examples
    --------
    >>> round(math.degrees(inverse_involute(0.014904)), 3)
    20.0
    >>> round(math.degrees(inverse_involute(involute(math.radians(25)))), 12)
    25.0
    """
    v = _real(value, "value")
    if v < 0:
        raise ValueError(f"inv α must be >= 0 (α in [0, π/2)), got {value!r}")
    if v == 0:
        return 0.0
    a = min((3 * v) ** (1 / 3), math.atan(v + math.pi / 2))
    for _ in range(100):
        t = math.tan(a)
        step = (t - a - v) / (t * t)
        a -= step
        if abs(step) <= tol * max(1.0, a):
            return a
    return a  # pragma: no cover - monotone Newton converges in a handful of steps


# --------------------------------------------------------------------------- radii


def pitch_radius(module: float, teeth: int) -> float:
    """Pitch (reference) radius ``r = m·z/2``.

    Parameters
    ----------
    module : float
        Module ``m``, metres.
    teeth : int
        Number of teeth ``z``.

    Returns
    -------
    float
        ``r``, metres.

    Examples
    --------
    >>> round(pitch_radius(0.004, 20), 6)
    0.04
    """
    return _module(module) * _teeth(teeth) / 2


def base_radius(
    module: float, teeth: int, pressure_angle: float = STANDARD_PRESSURE_ANGLE
) -> float:
    """Base radius ``r_b = r·cos α``.

    Parameters
    ----------
    module : float
        Module ``m``, metres.
    teeth : int
        Number of teeth ``z``.
    pressure_angle : float
        ``α``, radians (default 20°).

    Returns
    -------
    float
        ``r_b``, metres.

    Examples
    --------
    >>> round(base_radius(0.004, 20, math.radians(20)), 7)
    0.0375877
    """
    return pitch_radius(module, teeth) * math.cos(_pressure_angle(pressure_angle))


def tip_radius(
    module: float,
    teeth: int,
    shift: float = 0.0,
    addendum: float = 1.0,
    internal: bool = False,
) -> float:
    """Tip (addendum) radius.

    External gear: ``r_a = r + m(h_a* + ξ)``; internal gear (``internal=True``):
    ``r_a = r − m(h_a* − ξ)``, the tips pointing inwards.

    Parameters
    ----------
    module : float
        Module ``m``, metres.
    teeth : int
        Number of teeth ``z``.
    shift : float
        Profile shift coefficient ``ξ``.
    addendum : float
        Addendum coefficient ``h_a*`` (1 for the standard rack).
    internal : bool
        The gear is internal (ring gear).

    Returns
    -------
    float
        ``r_a``, metres.

    Examples
    --------
    >>> round(tip_radius(0.004, 20), 6), round(tip_radius(0.004, 20, shift=0.5), 6)
    (0.044, 0.046)
    >>> round(tip_radius(0.004, 60, internal=True), 6)
    0.116
    """
    r = pitch_radius(module, teeth)
    m, x, ha = float(module), _shift(shift), _coefficient(addendum, "addendum")
    return r - m * (ha - x) if internal else r + m * (ha + x)


def root_radius(
    module: float,
    teeth: int,
    shift: float = 0.0,
    dedendum: float = 1.25,
    internal: bool = False,
) -> float:
    """Root (dedendum) radius.

    External gear: ``r_f = r − m(h_f* − ξ)``; internal gear:
    ``r_f = r + m(h_f* + ξ)``.

    Parameters
    ----------
    module : float
        Module ``m``, metres.
    teeth : int
        Number of teeth ``z``.
    shift : float
        Profile shift coefficient ``ξ``.
    dedendum : float
        Dedendum coefficient ``h_f* = h_a* + c*`` (1.25 for the standard rack).
    internal : bool
        The gear is internal (ring gear).

    Returns
    -------
    float
        ``r_f``, metres.

    Examples
    --------
    >>> round(root_radius(0.004, 20), 6), round(root_radius(0.004, 60, internal=True), 6)
    (0.035, 0.125)
    """
    r = pitch_radius(module, teeth)
    m, x, hf = float(module), _shift(shift), _coefficient(dedendum, "dedendum")
    return r + m * (hf + x) if internal else r - m * (hf - x)


# --------------------------------------------------------------------------- pairs


def center_distance(module: float, z1: int, z2: int, internal: bool = False) -> float:
    """Standard centre distance (no shift) ``a = m(z1 ± z2)/2``.

    External pair: ``m(z1 + z2)/2``; internal pair: ``m(z2 − z1)/2`` with
    ``z2`` the internal gear.

    Parameters
    ----------
    module : float
        Module ``m``, metres.
    z1, z2 : int
        Teeth of the pinion and of the gear (internal gear when ``internal``).
    internal : bool
        Gear 2 is internal.

    Returns
    -------
    float
        ``a``, metres.

    Examples
    --------
    >>> round(center_distance(0.004, 20, 40), 6), round(center_distance(0.004, 20, 60, True), 6)
    (0.12, 0.08)
    """
    m = _module(module)
    n1, n2 = _pair(z1, z2, internal)
    return m * ((n2 - n1) if internal else (n1 + n2)) / 2


def working_pressure_angle(
    z1: int,
    z2: int,
    x1: float = 0.0,
    x2: float = 0.0,
    alpha: float = STANDARD_PRESSURE_ANGLE,
    internal: bool = False,
) -> float:
    """Working pressure angle ``α_w`` of a shifted pair meshing without backlash.

    External: ``inv α_w = inv α + 2 tan α (x1 + x2)/(z1 + z2)``;
    internal: ``inv α_w = inv α + 2 tan α (x2 − x1)/(z2 − z1)``.
    ``inv`` is inverted by Newton (:func:`inverse_involute`).

    Parameters
    ----------
    z1, z2 : int
        Teeth of the pinion and of the gear (internal gear when ``internal``).
    x1, x2 : float
        Profile shift coefficients.
    alpha : float
        Pressure angle of the rack ``α``, radians.
    internal : bool
        Gear 2 is internal.

    Returns
    -------
    float
        ``α_w``, radians.

    Examples
    --------
    >>> a = math.radians(20)
    >>> working_pressure_angle(20, 40, 0.3, -0.3, a) == a
    True
    >>> round(math.degrees(working_pressure_angle(20, 40, 0.5, 0.5, a)), 3)
    24.197
    """
    n1, n2 = _pair(z1, z2, internal)
    s1, s2 = _shift(x1, "x1"), _shift(x2, "x2")
    a = _pressure_angle(alpha, "alpha")
    sum_x, sum_z = ((s2 - s1), (n2 - n1)) if internal else ((s1 + s2), (n1 + n2))
    if sum_x == 0:
        return a
    target = involute(a) + 2 * math.tan(a) * sum_x / sum_z
    if target <= 0:
        raise ValueError(
            f"the shifts x1={x1!r}, x2={x2!r} give inv α_w = {target:.6g} <= 0: no working "
            "pressure angle; the negative shifts are too large for these teeth"
        )
    return inverse_involute(target)


def working_center_distance(
    module: float,
    z1: int,
    z2: int,
    x1: float = 0.0,
    x2: float = 0.0,
    pressure_angle: float = STANDARD_PRESSURE_ANGLE,
    internal: bool = False,
) -> float:
    """Working centre distance ``a_w = a·cos α / cos α_w`` of a shifted pair.

    Parameters
    ----------
    module : float
        Module ``m``, metres.
    z1, z2 : int
        Teeth of the pinion and of the gear (internal gear when ``internal``).
    x1, x2 : float
        Profile shift coefficients.
    pressure_angle : float
        ``α``, radians.
    internal : bool
        Gear 2 is internal.

    Returns
    -------
    float
        ``a_w``, metres; equals :func:`center_distance` when the shifts cancel.

    Examples
    --------
    >>> round(working_center_distance(0.004, 20, 40), 6)
    0.12
    >>> round(working_center_distance(0.004, 20, 40, 0.5, 0.5), 6)
    0.123624
    """
    a = center_distance(module, z1, z2, internal)
    alpha = _pressure_angle(pressure_angle)
    alpha_w = working_pressure_angle(z1, z2, x1, x2, alpha, internal)
    return a * math.cos(alpha) / math.cos(alpha_w)


def contact_ratio(
    module: float,
    z1: int,
    z2: int,
    shift1: float = 0.0,
    shift2: float = 0.0,
    pressure_angle: float = STANDARD_PRESSURE_ANGLE,
    internal: bool = False,
) -> float:
    """Transverse contact ratio ``ε`` of a spur pair.

    External pair::

        ε = (√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a_w sin α_w) / (π m cos α)

    Internal pair (gear 2 internal, ``a_w`` from ``z2 − z1``): the base-circle
    tangent points lie on the same side of the pitch point, so the ring's term
    enters with a minus and ``a_w sin α_w`` with a plus::

        ε = (√(r_a1² − r_b1²) − √(r_a2² − r_b2²) + a_w sin α_w) / (π m cos α)

    Tip radii are :func:`tip_radius` with the shifts and ``h_a* = 1``; no tip
    shortening. Interference (the path of contact leaving the segment between
    the tangent points) is not checked.

    Parameters
    ----------
    module : float
        Module ``m``, metres.
    z1, z2 : int
        Teeth of the pinion and of the gear (internal gear when ``internal``).
    shift1, shift2 : float
        Profile shift coefficients.
    pressure_angle : float
        ``α``, radians.
    internal : bool
        Gear 2 is internal.

    Returns
    -------
    float
        ``ε`` (dimensionless).

    Examples
    --------
    >>> round(contact_ratio(0.004, 20, 40), 4)
    1.6352
    >>> round(contact_ratio(0.004, 20, 60, internal=True), 4)
    1.9497
    """
    m = _module(module)
    n1, n2 = _pair(z1, z2, internal)
    alpha = _pressure_angle(pressure_angle)
    alpha_w = working_pressure_angle(n1, n2, shift1, shift2, alpha, internal)
    a_w = center_distance(m, n1, n2, internal) * math.cos(alpha) / math.cos(alpha_w)
    ra1, rb1 = tip_radius(m, n1, shift1), base_radius(m, n1, alpha)
    ra2, rb2 = tip_radius(m, n2, shift2, internal=internal), base_radius(m, n2, alpha)
    if ra2 <= rb2:
        raise ValueError(
            f"the tip circle of gear 2 (r_a = {ra2:.6g} m) lies inside its base circle "
            f"(r_b = {rb2:.6g} m): no involute there"
        )
    g1 = math.sqrt(ra1 * ra1 - rb1 * rb1)
    g2 = math.sqrt(ra2 * ra2 - rb2 * rb2)
    g = a_w * math.sin(alpha_w)
    path = g1 - g2 + g if internal else g1 + g2 - g
    return path / (math.pi * m * math.cos(alpha))


# --------------------------------------------------------------------------- tooth thickness


def tooth_thickness(
    module: float,
    shift: float = 0.0,
    pressure_angle: float = STANDARD_PRESSURE_ANGLE,
    internal: bool = False,
) -> float:
    """Arc tooth thickness on the pitch circle of a gear cut by a rack with shift ``ξ``.

    The generating rack rolls without backlash on the blank's pitch circle, so
    the tooth there is as thick as the rack's space on its rolling line:
    ``S = πm/2 + 2ξm tan α = m(π/2 + 2ξ tan α)``. It does not depend on the
    number of teeth. For an internal gear ``S = m(π/2 − 2ξ tan α)``.

    Parameters
    ----------
    module : float
        Module ``m``, metres.
    shift : float
        Profile shift coefficient ``ξ``.
    pressure_angle : float
        ``α``, radians.
    internal : bool
        The gear is internal.

    Returns
    -------
    float
        ``S``, metres (arc length).

    Examples
    --------
    >>> round(tooth_thickness(0.004), 7)
    0.0062832
    >>> round(tooth_thickness(0.004, 0.5, math.radians(20)), 7)
    0.0077391
    """
    m, x = _module(module), _shift(shift)
    t = math.tan(_pressure_angle(pressure_angle))
    return m * (math.pi / 2 + (-2 if internal else 2) * x * t)


def tooth_thickness_at(
    radius: float,
    module: float,
    teeth: int,
    shift: float = 0.0,
    pressure_angle: float = STANDARD_PRESSURE_ANGLE,
    internal: bool = False,
) -> float:
    """Arc tooth thickness on the circle of radius ``r_y``.

    ``s_y = r_y (S/r − 2(inv α_y − inv α))`` with ``cos α_y = r_b/r_y`` and ``S``
    from :func:`tooth_thickness`. For an internal gear the tooth is the space
    of an external one, so the sign flips: ``s_y = r_y (S/r + 2(inv α_y − inv α))``.
    On the base circle this is ``s_b = r_b (S/r ± 2 inv α)``.

    Parameters
    ----------
    radius : float
        ``r_y``, metres, at least the base radius.
    module : float
        Module ``m``, metres.
    teeth : int
        Number of teeth ``z``.
    shift : float
        Profile shift coefficient ``ξ``.
    pressure_angle : float
        ``α``, radians.
    internal : bool
        The gear is internal.

    Returns
    -------
    float
        ``s_y``, metres (arc length). Zero or negative beyond the radius where
        an external tooth comes to a point.

    Examples
    --------
    >>> m, z, a = 0.004, 20, math.radians(20)
    >>> round(tooth_thickness_at(pitch_radius(m, z), m, z, 0.0, a), 7)
    0.0062832
    >>> round(tooth_thickness_at(base_radius(m, z, a), m, z, 0.0, a), 7)
    0.0070247
    """
    ry = _real(radius, "radius")
    alpha = _pressure_angle(pressure_angle)
    r = pitch_radius(module, teeth)
    rb = r * math.cos(alpha)
    if ry <= 0 or ry < rb * (1 - 1e-12):
        raise ValueError(
            f"radius must be at least the base radius r_b = {rb:.6g} m "
            f"(no involute inside the base circle), got {radius!r}"
        )
    alpha_y = math.acos(min(1.0, rb / ry))
    s = tooth_thickness(module, shift, alpha, internal)
    d_inv = involute(alpha_y) - involute(alpha)
    return ry * (s / r + (2 if internal else -2) * d_inv)
