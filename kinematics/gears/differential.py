"""Torque split of a bevel-gear differential with internal friction.

Steady state (no inertia terms), SI units: torques in N·m, forces in N,
radii in m, speeds in rad/s. The differential case is driven by a torque
``M_case`` about the axle; ``n`` planets on the cross-shaft mesh with the two
side gears (left, right) at the side-gear radius ``r_s`` from the axle; each
planet has radius ``r_p`` at the mesh. One side turns faster than the case,
the other as much slower (``ω_fast + ω_slow = 2 ω_case``), so every planet
spins on its pin at ``ω_p = (ω_fast − ω_case)·r_s/r_p`` and each side gear
slides on its back face against the case.

Equations (the moment balances of Lê Hoàng Anh et al. 2016, eqs. (2)-(3),
(20)-(24), for the LIFAN LF3070G1 light-truck differential, generalised to
``n`` planets sharing the load equally):

* cross-shaft force on all planets together, ``F_t2 = M_case / r_s``;
* planet, forces along the case tangent: ``F_slow,i + F_fast,i = F_t2 / n``;
* planet, moments about its own axis: ``(F_slow,i − F_fast,i)·r_p = M_p``,
  where ``M_p`` (= planet/cross-shaft + planet/thrust-washer friction, the
  paper's ``M3ms``) opposes the planet's spin, hence
  ``F_slow = F_t2/2 + n·M_p/(2 r_p)`` and ``F_fast = F_t2/2 − n·M_p/(2 r_p)``
  (totals over the planets; paper eq. (21), ``F_t3``/``F_t4``, with ``n = 1``);
* side gears, moments about the axle, with the back-face friction ``M_sc``
  (the paper's ``M4ms = M5ms``) and an optional resistance torque ``M_C``:

  - ``side_friction_model="relative"`` (default): the friction opposes each
    side gear's rotation *relative to the case*: the faster side is braked,
    the slower one dragged forward,
    ``T_fast = F_fast·r_s − M_sc − M_C,fast``,
    ``T_slow = F_slow·r_s + M_sc − M_C,slow``;
  - ``side_friction_model="paper"``: eq. (24) of the paper subtracts it on
    both sides, ``T = F·r_s − M_sc − M_C``.

Sum of the half-shaft torques: ``T_left + T_right = M_case − M_C,left −
M_C,right`` in the relative model (all friction is internal, and the planet
friction acts about the planet axes, perpendicular to the axle), but
``M_case − 2 M_sc − M_C,left − M_C,right`` in the paper's model.
Power: in the relative model ``M_case·ω_case = Σ(T + M_C)·ω + n·M_p·ω_p +
2·M_sc·(ω_fast − ω_case)``; the paper's model instead dissipates
``2·M_sc·ω_case`` in the side-gear contacts, i.e. it treats them as if they
rubbed on a fixed housing, and loses ``2 M_sc`` of torque even when driving
straight, where those contacts do not slide.

Inputs inferred for the paper's worked example (the paper prints neither
the case torque nor any radius used in eqs. (21)-(24)):

* ``r_s`` from the sum of the printed half-shaft torques,
  ``r_s = (M4 + M5 + 2·M_C + 2·M4ms)/F_t2 = 1637.7208/14000 = 0.11698006 m``,
  which fixes the case torque ``M_case = F_t2·r_s = 1637.7208 N·m``;
  the difference ``(M5 − M4)/(F_t3 − F_t4) = 23.279/199 = 0.1169799 m``
  agrees to the printed precision;
* ``r_p`` from the difference, ``r_p = M3ms·r_s/(M5 − M4)
  = 7·0.11698006/23.279 = 0.03517593 m`` (the numbers only fix
  ``M3ms/r_p = F_t3 − F_t4 = 199 N``; the paper uses the rounded ``M3ms = 7``
  although 1.3 + 5.6132 = 6.9132 N·m);
* ``n = 1``: the paper puts the whole cross-shaft force ``F_t2 = 14 kN`` and
  the friction computed from it on one planet, though the LF3070G1 has four;
  since Coulomb friction grows with the load, four planets at ``7/4 N·m``
  each give the same split;
* the pinion torque ``M1 = 784.7202 N·m`` is *not* the case torque: the paper
  goes ``F_t1 = M1/r1 = 9895.6 N`` (so ``r1 ≈ 0.0793 m``) and
  ``F_t2 = F_t1·r2/r_tr = 14000 N`` (so ``r2/r_tr ≈ 1.4148``) without printing
  ``r1``, ``r2`` or ``r_tr``; with ``r_tr = r_s`` the case torque is
  ``1637.7208 ≈ 2.087·M1``;
* the rolling-resistance moments ``M_Ctr = M_Cph = 191.25`` are
  ``G·f = 1275 kg · 10 m/s² · 0.015`` in newtons; the paper omits the wheel
  radius ``r_b`` of eq. (22) (``r_b = 1 m`` in effect) and subtracts them from
  the half-shaft torques as in its eqs. (2)-(3).

Without friction the split is even, with it the slower side gets more:

>>> s = bevel_differential_split(1000.0, side_radius=0.05, planet_radius=0.025,
...                              planet_friction=0.0, side_friction=0.0, faster="left")
>>> s.torque_left, s.torque_right, s.bias_ratio
(500.0, 500.0, 1.0)
>>> s = bevel_differential_split(1000.0, side_radius=0.05, planet_radius=0.025,
...                              planet_friction=2.0, side_friction=10.0,
...                              faster="left", n_planets=2)
>>> round(s.force_left, 6), round(s.force_right, 6)
(9920.0, 10080.0)
>>> round(s.torque_left, 6), round(s.torque_right, 6), round(s.bias_ratio, 6)
(486.0, 514.0, 1.057613)

The paper's worked example, with the inputs inferred above:

>>> r_s = 1637.7208 / 14000          # inferred side-gear radius, m
>>> r_p = 7.0 * r_s / 23.279         # inferred planet radius, m
>>> s = bevel_differential_split(1637.7208, side_radius=r_s, planet_radius=r_p,
...                              planet_friction=7.0,  # M3ms as printed
...                              side_friction=35.2304, faster="left",
...                              resistance_torques=(191.25, 191.25),
...                              side_friction_model="paper")
>>> round(s.cross_shaft_force, 1), round(s.force_right, 1), round(s.force_left, 1)
(14000.0, 7099.5, 6900.5)
>>> round(s.torque_left, 4), round(s.torque_right, 4), round(s.bias_ratio, 4)
(580.7405, 604.0195, 1.0401)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from numbers import Integral, Real
from typing import Literal

__all__ = ["DifferentialSplit", "bevel_differential_split"]

Side = Literal["left", "right"]
SideFrictionModel = Literal["relative", "paper"]
_MODELS = ("relative", "paper")


@dataclass(frozen=True)
class DifferentialSplit:
    """Forces and torques of a bevel differential in steady relative rotation.

    Attributes
    ----------
    cross_shaft_force : float
        ``F_t2 = M_case / r_s``, tangential force of the cross-shaft on all
        planets together, N.
    force_left, force_right : float
        Tangential mesh force on each side gear, summed over the planets, N
        (the paper's ``F_t4`` and ``F_t3``).
    torque_left, torque_right : float
        Half-shaft torques, N·m, less the resistance torques if any were
        given (the paper's ``M4`` and ``M5``).
    bias_ratio : float
        Torque bias ratio ``T_slow / T_fast`` (``inf`` if ``T_fast == 0``);
        meaningful when both torques are positive (drive).
    faster : {"left", "right"}
        The side that turns faster than the case.
    """

    cross_shaft_force: float
    force_left: float
    force_right: float
    torque_left: float
    torque_right: float
    bias_ratio: float
    faster: Side

    @property
    def torque_fast(self) -> float:
        """Half-shaft torque of the faster side, N·m."""
        return self.torque_left if self.faster == "left" else self.torque_right

    @property
    def torque_slow(self) -> float:
        """Half-shaft torque of the slower side, N·m."""
        return self.torque_right if self.faster == "left" else self.torque_left


def _finite(name: str, value: object) -> float:
    if isinstance(value, bool) or not isinstance(value, Real) or not math.isfinite(value):
        raise ValueError(f"{name} must be a finite real number, got {value!r}")
    return float(value)


def _positive(name: str, value: object) -> float:
    v = _finite(name, value)
    if v <= 0:
        raise ValueError(f"{name} must be positive, got {value!r}")
    return v


def _non_negative(name: str, value: object) -> float:
    v = _finite(name, value)
    if v < 0:
        raise ValueError(f"{name} must be >= 0 (a friction moment magnitude), got {value!r}")
    return v


def bevel_differential_split(
    case_torque: float,
    *,
    side_radius: float,
    planet_radius: float,
    planet_friction: float,
    side_friction: float,
    faster: Side,
    n_planets: int = 1,
    resistance_torques: tuple[float, float] = (0.0, 0.0),
    side_friction_model: SideFrictionModel = "relative",
) -> DifferentialSplit:
    """Split the case torque of a bevel differential between the half-shafts.

    Parameters
    ----------
    case_torque : float
        Torque driving the differential case about the axle, N·m (the ring
        gear torque, not the pinion torque). May be negative (coasting).
    side_radius : float
        Side-gear radius at the mesh = distance of the planet mesh point and
        of the cross-shaft force from the axle, ``r_s``, m.
    planet_radius : float
        Planet radius at the mesh, ``r_p``, m.
    planet_friction : float
        Friction moment on *each* planet about its own axis,
        ``M_p = M_planet/cross-shaft + M_planet/thrust washer``, N·m (>= 0).
    side_friction : float
        Friction moment between *each* side gear and the case, ``M_sc``,
        N·m (>= 0).
    faster : {"left", "right"}
        The side that turns faster than the case (the outer wheel in a turn).
        Friction moments oppose the relative rotations, so they are fixed by
        this, not by the sign of the torque.
    n_planets : int, optional
        Number of planets sharing the cross-shaft force equally (default 1,
        as in the paper's lumped calculation).
    resistance_torques : (float, float), optional
        Torques ``(M_C,left, M_C,right)`` subtracted from the half-shaft
        torques, N·m, as the paper does with the wheels' rolling-resistance
        moments; default none.
    side_friction_model : {"relative", "paper"}, optional
        ``"relative"`` (default): the side-gear/case friction brakes the
        faster and drives the slower side gear. ``"paper"``: subtracted on
        both sides, as in eq. (24) of the paper.

    Returns
    -------
    DifferentialSplit
        Cross-shaft force, side-gear tangential forces, half-shaft torques and
        the torque bias ratio ``T_slow/T_fast``.

    Raises
    ------
    ValueError
        On non-finite inputs, non-positive radii, negative friction moments,
        ``n_planets < 1`` or an unknown ``faster``/``side_friction_model``.

    Examples
    --------
    In the module's docstring: an even split without friction, more torque to
    the slower side with it, and the paper's worked example.
    """
    given = _Given(
        case_torque=_finite("case_torque", case_torque),
        side_radius=_positive("side_radius", side_radius),
        planet_radius=_positive("planet_radius", planet_radius),
        planet_friction=_non_negative("planet_friction", planet_friction),
        side_friction=_non_negative("side_friction", side_friction),
        n_planets=_planets(n_planets),
        faster=_choice("faster", faster, ("left", "right")),
        side_friction_model=_choice("side_friction_model", side_friction_model, _MODELS),
        resistance_torques=_resistance(resistance_torques),
    )
    return _split(given)


@dataclass(frozen=True)
class _Given:
    """The inputs of :func:`bevel_differential_split`, checked and converted."""

    case_torque: float
    side_radius: float
    planet_radius: float
    planet_friction: float
    side_friction: float
    n_planets: int
    faster: Side
    side_friction_model: SideFrictionModel
    resistance_torques: tuple[float, float]


def _planets(n_planets: object) -> int:
    if isinstance(n_planets, bool) or not isinstance(n_planets, Integral) or n_planets < 1:
        raise ValueError(f"n_planets must be an integer >= 1, got {n_planets!r}")
    return int(n_planets)


def _resistance(resistance_torques: tuple[float, float]) -> tuple[float, float]:
    if len(resistance_torques) != 2:
        raise ValueError(f"resistance_torques must be a pair, got {resistance_torques!r}")
    return (
        _finite("resistance_torques[0]", resistance_torques[0]),
        _finite("resistance_torques[1]", resistance_torques[1]),
    )


def _choice(name: str, value: str, options: tuple[str, ...]) -> str:
    if value not in options:
        raise ValueError(f"{name} must be {' or '.join(map(repr, options))}, got {value!r}")
    return value


def _split(given: _Given) -> DifferentialSplit:
    """The moment balances of the planets and the side gears (see the module's equations)."""
    r_s, m_sc = given.side_radius, given.side_friction
    f_t2 = given.case_torque / r_s
    # planet moment balance: (F_slow - F_fast)·r_p = M_p on each of the n planets
    shift = given.n_planets * given.planet_friction / (2.0 * given.planet_radius)
    f_fast = f_t2 / 2.0 - shift
    f_slow = f_t2 / 2.0 + shift
    # side gears about the axle; the case brakes the faster side gear
    m_sc_slow = m_sc if given.side_friction_model == "relative" else -m_sc
    mc_left, mc_right = given.resistance_torques
    mc_fast, mc_slow = (mc_left, mc_right) if given.faster == "left" else (mc_right, mc_left)
    t_fast = f_fast * r_s - m_sc - mc_fast
    t_slow = f_slow * r_s + m_sc_slow - mc_slow
    bias = t_slow / t_fast if t_fast != 0 else math.inf

    if given.faster == "left":
        f_left, f_right, t_left, t_right = f_fast, f_slow, t_fast, t_slow
    else:
        f_left, f_right, t_left, t_right = f_slow, f_fast, t_slow, t_fast
    return DifferentialSplit(
        cross_shaft_force=f_t2,
        force_left=f_left,
        force_right=f_right,
        torque_left=t_left,
        torque_right=t_right,
        bias_ratio=bias,
        faster=given.faster,
    )
