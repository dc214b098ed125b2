"""Surface roughness as a film term of the EHL solvers: H = H0 + G + D - R(X, Y, T).

Convention: R is the height of the rough surface towards the other one (a peak, R > 0,
thins the film), in the solver's Hertzian units (heights H = h R_x / a^2, lengths
X = x / a; line contacts: b in place of a). The paper (seed paper sec. 3.1.2, eq. 23)
*adds* its R_r(x, y) to h; with its eq. 22 (R_r >= 0) that is a dent, not the "peak"
its text names, so femgear follows the text: pass a negative amplitude for the literal
eq. 23 sign.

Features (all functions of X, or of (X, Y) broadcasting, in Hertzian units):

* :func:`paper_peak` - the seed paper's single roughness peak (eq. 22):
  R = (A_b/2) [1 + cos(pi (X - x0) / l_b)] for |X - x0| <= l_b, 0 elsewhere
  (a transverse ridge: independent of Y; cosine period 2 l_b, support 2 l_b).
* :func:`harmonic` - waviness A cos(2 pi (X - x0) / lambda) (Venner, Couhier, Lubrecht &
  Greenwood 1997, the amplitude-reduction studies).
* :func:`random_surface` - a Gaussian random field with given Rq and exponential or
  Gaussian autocorrelation, by FFT filtering of seeded white noise (Hu & Tonder 1992,
  Int. J. Mach. Tools Manuf. 32:83; the filter is the square root of the spectrum of
  the target ACF).

Moving roughness: a feature carried by a surface of speed u_s moves through the contact
as R(X - c T) with c = u_s / u_m and T = t u_m / a (:func:`surface_speed`).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import scipy.fft as sfft

from femgear.errors import ArgumentError

SurfaceLike = Callable | np.ndarray


def paper_peak(X, Y=None, *, amplitude: float, half_width: float, x0: float = 0.0):
    """The seed paper's single roughness peak, eq. 22 (Hertzian units):
    0.5 A_b [1 + cos(pi (X - x0) / l_b)] on |X - x0| <= l_b, else 0. ``half_width`` is the
    paper's "wavelength" l_b (the cosine's half period, the half base of the peak)."""
    if not half_width > 0:
        raise ArgumentError("half_width", f"the peak's l_b must be > 0, got {half_width!r}")
    s = (np.asarray(X, dtype=float) - x0) / half_width
    R = np.where(np.abs(s) <= 1.0, 0.5 * amplitude * (1.0 + np.cos(np.pi * s)), 0.0)
    return R if Y is None else np.broadcast_to(R, np.broadcast(R, Y).shape).copy()


def harmonic(X, Y=None, *, amplitude: float, wavelength: float, x0: float = 0.0):
    """Transverse waviness A cos(2 pi (X - x0) / lambda) (Hertzian units)."""
    if not wavelength > 0:
        raise ArgumentError("wavelength", f"must be > 0, got {wavelength!r}")
    R = amplitude * np.cos(2.0 * np.pi * (np.asarray(X, dtype=float) - x0) / wavelength)
    return R if Y is None else np.broadcast_to(R, np.broadcast(R, Y).shape).copy()


def surface_speed(srr: float, member: str) -> float:
    """c = u_s / u_m of the surface that carries the roughness, for the slide-to-roll
    ratio SRR = (u1 - u2) / u_m: member 1 (``"pinion"``, the faster one for SRR > 0)
    moves at 1 + SRR/2, member 2 (``"gear"``) at 1 - SRR/2 (u_m = (u1 + u2)/2)."""
    if not -2.0 <= srr <= 2.0:
        raise ArgumentError("srr", f"slide-to-roll ratio must lie in [-2, 2], got {srr!r}")
    if member not in ("pinion", "gear"):
        raise ArgumentError("member", f"must be 'pinion' or 'gear', got {member!r}")
    return 1.0 + 0.5 * srr if member == "pinion" else 1.0 - 0.5 * srr


def hertz_height(h_m: float, R: float, a: float) -> float:
    """A height in metres in Hertzian units: h R / a^2 (a: Hertz half width b for a line
    contact, radius for a point contact; R the reduced radius along the rolling)."""
    return h_m * R / a**2


def evaluate(surface: SurfaceLike | None, X: np.ndarray, Y: np.ndarray | None = None,
             fine_x: np.ndarray | None = None) -> np.ndarray | None:
    """Nodal values of ``surface`` on nodes X (Y for point contacts): a callable is called
    as f(X) (line) or f(X, Y) (point); an array is taken as nodal values on the finest
    grid ``fine_x`` (line; interpolated linearly onto coarser nodes) or as a point grid
    of the same size as X (point)."""
    if surface is None:
        return None
    if callable(surface):
        R = surface(X) if Y is None else surface(X, Y)
        R = np.asarray(R, dtype=float)
        R = np.broadcast_to(R, np.shape(X)).ravel() if R.size != np.size(X) else R.ravel()
    else:
        R = np.asarray(surface, dtype=float)
        if Y is None and fine_x is not None and R.ndim == 1 and R.size == fine_x.size:
            R = np.interp(X, fine_x, R)
        elif R.size == np.size(X):
            R = R.ravel()
        else:
            raise ArgumentError("surface", f"array of {R.size} values does not match the "
                                f"grid ({np.size(X)} nodes); pass a callable f(X[, Y]) instead")
    if not np.all(np.isfinite(R)):
        raise ArgumentError("surface", "non-finite roughness heights")
    return R


def apply_surface(level, R: np.ndarray | None, smooth: np.ndarray | None = None) -> None:
    """Subtract the roughness R (nodal, Hertzian units) from a Level's undeformed gap:
    H = H0 + G - R + D[P]. ``smooth`` is the smooth gap G (default: the level's current
    one); with R None nothing changes (the smooth solve is bit-identical)."""
    if R is None:
        return
    G = level.geometry if smooth is None else smooth
    level.geometry = G - np.asarray(R, dtype=float).reshape(G.shape)


def random_surface(shape: int | tuple[int, int], h: float, *, rq: float, corr_length: float,
                   acf: str = "exponential", seed: int = 0) -> np.ndarray:
    """Seeded Gaussian random heights on a uniform grid of spacing ``h`` (any length unit),
    RMS ``rq`` and autocorrelation C(r) = rq^2 exp(-r/beta) ('exponential') or
    rq^2 exp(-(r/beta)^2) ('gaussian'), beta = ``corr_length`` (C(beta) = rq^2/e).

    FFT filtering (Hu & Tonder 1992): z = IFFT(sqrt(FFT(C)) FFT(w)) with unit white noise
    w on a periodic grid padded by 6 beta (so that the wrap-around does not correlate the
    two ends), cropped to ``shape``; isotropic in 2-D. The heights are a sample: their Rq
    and correlation length scatter about the targets (tested)."""
    dims = (shape,) if isinstance(shape, (int, np.integer)) else tuple(shape)
    if not all(int(n) >= 2 for n in dims) or len(dims) > 2:
        raise ArgumentError("shape", f"need 1 or 2 dimensions of >= 2 nodes, got {shape!r}")
    for name, v in (("h", h), ("rq", rq), ("corr_length", corr_length)):
        if not (np.isfinite(v) and v > 0):
            raise ArgumentError(name, f"must be > 0, got {v!r}")
    if acf not in ("exponential", "gaussian"):
        raise ArgumentError("acf", f"must be 'exponential' or 'gaussian', got {acf!r}")
    pad = int(np.ceil(6.0 * corr_length / h))
    full = [sfft.next_fast_len(int(n) + pad) for n in dims]
    axes = [np.minimum(np.arange(N), N - np.arange(N)) * h for N in full]  # periodic distance
    r = np.sqrt(sum(g**2 for g in np.meshgrid(*axes, indexing="ij")))
    C = rq**2 * (np.exp(-r / corr_length) if acf == "exponential" else np.exp(-(r / corr_length) ** 2))
    spectrum = np.maximum(sfft.fftn(C).real, 0.0)
    noise = np.random.default_rng(seed).standard_normal(full)
    z = sfft.ifftn(np.sqrt(spectrum) * sfft.fftn(noise)).real
    return z[tuple(slice(0, int(n)) for n in dims)]


def correlation_length(z: np.ndarray, h: float, axis: int = -1) -> float:
    """The lag at which the sample autocorrelation of ``z`` along ``axis`` (mean removed,
    averaged over the other axis) first falls to 1/e, linearly interpolated [length]."""
    z = np.moveaxis(np.atleast_2d(np.asarray(z, dtype=float)), axis, -1)
    z = z - z.mean()
    n = z.shape[-1]
    F = sfft.rfft(z, 2 * n, axis=-1)
    c = sfft.irfft(np.abs(F) ** 2, 2 * n, axis=-1)[..., :n].mean(axis=0)
    c = c / c[0]
    k = int(np.argmax(c < np.exp(-1.0)))
    if k == 0:
        raise ArgumentError("z", "the autocorrelation never falls to 1/e: sample too short")
    return float(h * (k - 1 + (c[k - 1] - np.exp(-1.0)) / (c[k - 1] - c[k])))


def peak_feature(peak, R: float, a: float) -> Callable:
    """The scene's ``[roughness.peak]`` (metres: amplitude, wavelength l_b, x0) as a
    Hertzian-unit profile f(X) for a contact of reduced radius ``R`` and Hertz half width
    (line) or radius (point) ``a`` [m]: heights h R / a^2, lengths x / a."""
    A, lb, x0 = hertz_height(peak.amplitude, R, a), peak.wavelength / a, peak.x0 / a

    def feature(X, Y=None):
        return paper_peak(X, Y, amplitude=A, half_width=lb, x0=x0)

    return feature


def synthetic_feature(synthetic, R: float, a: float, *, extent: tuple[float, float],
                      h: float) -> Callable:
    """The scene's ``[roughness.synthetic]`` as a Hertzian-unit profile f(X) on
    [extent[0], extent[1]] (Hertzian X) sampled every ``h`` (Hertzian; the solver's node
    spacing, so a moving surface shifts by whole samples), linear in between and held
    constant beyond: a transverse profile (1-D, the line contact's roughness; a point
    contact sees it as ridges). Same seed, same surface."""
    lo, hi = extent
    n = int(np.ceil((hi - lo) / h)) + 1
    z = random_surface(n, h * a, rq=synthetic.rq, corr_length=synthetic.correlation_length,
                       acf=synthetic.acf, seed=synthetic.seed)
    xs, Z = lo + h * np.arange(n), hertz_height(1.0, R, a) * z

    def feature(X, Y=None):
        Rx = np.interp(np.asarray(X, dtype=float), xs, Z)
        return Rx if Y is None else np.broadcast_to(Rx, np.broadcast(Rx, Y).shape).copy()

    return feature


def scene_features(roughness, R: float, a: float, *, extent: tuple[float, float],
                   h: float) -> list[tuple[Callable, str, bool]]:
    """The deterministic roughness of a scene's ``[roughness]`` table at one contact
    (reduced radius ``R``, Hertz half width or radius ``a`` [m]) as a list of
    (Hertzian profile f(X[, Y]), member carrying it, moving): the single peak and the
    synthetic surface when present, empty for smooth flanks. A stationary one enters
    ``solve_line``/``solve_point`` as ``surface=f``; a moving one enters the transient
    solvers with c = :func:`surface_speed`(SRR, member). ``extent``/``h``: the sampled
    range and spacing (Hertzian X) of a synthetic surface."""
    out: list[tuple[Callable, str, bool]] = []
    if roughness.peak is not None:
        out.append((peak_feature(roughness.peak, R, a), roughness.peak.member, roughness.peak.moving))
    if roughness.synthetic is not None:
        s = roughness.synthetic
        out.append((synthetic_feature(s, R, a, extent=extent, h=h), s.member, s.moving))
    return out
