"""Periodic functions of the driver angle, known at equally spaced poses, anywhere in the turn.

The reduced inertia and the velocity ratios of a mechanism that turns its
driver through whole turns are smooth periodic functions of φ. Known at N
equally spaced angles, each is interpolated by its trigonometric polynomial
(the discrete Fourier series of its samples), which converges faster than any
power of 1/N for a smooth function: a few hundred poses give them to rounding,
and their slope with them. The equation of motion reads them at any φ its
integrator asks for; the slope of J_r it uses is the series' own, so that the
integrated motion keeps ½·J_r·ω² exactly where no load acts.

>>> phi = np.linspace(0, 2 * np.pi, 8, endpoint=False)
>>> s = PeriodicSeries.from_samples(np.vstack([2 + np.cos(phi), np.sin(2 * phi)]))
>>> v, d = s.at(0.3)
>>> np.allclose(v, [2 + np.cos(0.3), np.sin(0.6)]), np.allclose(d, [-np.sin(0.3), 2 * np.cos(0.6)])
(True, True)
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["PeriodicSeries"]

#: complex exponentials formed at once when a series is read at many angles
_BLOCK = 200_000


@dataclass(frozen=True)
class PeriodicSeries:
    """Rows of 2π-periodic functions as trigonometric polynomials.

    Row ``i`` is ``f_i(φ) = Re Σ_k c[i, k]·exp(i·k·φ)`` over the harmonics
    ``k = 0 … K−1``; build it with :meth:`from_samples`.
    """

    coefficients: np.ndarray  # complex, (rows, K)
    _k: np.ndarray = field(init=False, repr=False, compare=False)
    _stacked: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        c = self.coefficients
        k = np.arange(c.shape[1], dtype=float)
        a, b = c.real, c.imag
        # Re(c·e^{ikφ}) = a·cos kφ − b·sin kφ; its slope −k·(a·sin kφ + b·cos kφ): the values'
        # and the slopes' real coefficients in one matrix, so that one product reads both
        # (real products: complex ones are far slower in some BLAS builds)
        stacked = np.block([[a, -b], [-k * b, -k * a]])
        object.__setattr__(self, "_k", k)
        object.__setattr__(self, "_stacked", np.ascontiguousarray(stacked))

    @classmethod
    def from_samples(cls, samples: np.ndarray, tolerance: float = 1e-15) -> PeriodicSeries:
        """The trigonometric interpolant of ``samples`` (rows, N) at φ_j = 2πj/N.

        Harmonics whose coefficients are all below ``tolerance`` times the
        rows' largest value are left out (they are rounding), so that the series is
        read quickly.
        """
        samples = np.atleast_2d(np.asarray(samples, dtype=float))
        n = samples.shape[1]
        c = np.fft.rfft(samples, axis=1) / n
        c[:, 1:] *= 2.0
        if n % 2 == 0:
            c[:, -1] /= 2.0  # the Nyquist term is counted once (a cosine)
        scale = float(np.max(np.abs(samples))) if samples.size else 0.0
        significant = np.nonzero(np.max(np.abs(c), axis=0) > tolerance * max(scale, 1e-300))[0]
        kept = int(significant[-1]) + 1 if significant.size else 1
        return cls(np.ascontiguousarray(c[:, :kept]))

    @property
    def harmonics(self) -> int:
        """How many harmonics are kept (the constant term included)."""
        return self.coefficients.shape[1]

    @property
    def mean(self) -> np.ndarray:
        """Each row's mean over the turn."""
        return self.coefficients[:, 0].real.copy()

    def at(self, phi: float) -> tuple[np.ndarray, np.ndarray]:
        """Each row's value and slope d/dφ at one angle (rad)."""
        angles = self._k * phi
        both = self._stacked @ np.concatenate([np.cos(angles), np.sin(angles)])
        rows = self.coefficients.shape[0]
        return both[:rows], both[rows:]

    def over(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each row's values and slopes at many angles: two arrays (rows, len(phi))."""
        phi = np.asarray(phi, dtype=float).reshape(-1)
        rows = self.coefficients.shape[0]
        values, slopes = np.empty((rows, len(phi))), np.empty((rows, len(phi)))
        block = max(1, _BLOCK // self.harmonics)  # a few MB of cosines at a time
        for start in range(0, len(phi), block):
            angles = np.outer(self._k, phi[start : start + block])
            both = self._stacked @ np.vstack([np.cos(angles), np.sin(angles)])
            values[:, start : start + block] = both[:rows]
            slopes[:, start : start + block] = both[rows:]
        return values, slopes
