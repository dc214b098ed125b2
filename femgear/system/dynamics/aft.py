"""Nonlinear harmonic balance with alternating frequency–time (AFT) and pseudo-arclength continuation.

For periodic responses where the mesh contact opens and closes (backlash), the mesh force is
no longer linear in the state.  The problem is posed on the m mesh coordinates y (the
structure condensed onto them by its receptance), with the mean mesh springs moved into the
structure (so that the receptance exists at zero frequency):

    r_k(Y; ω) = Y_k − Y⁰_k(ω) + R_k(ω) [N̂_k(Y) − (k̄ + i k ω c̄) Y_k] = 0,     k = 0 … H,

y(t) = Σ_{k=−H}^{H} Y_k e^{ikωt} (Y_{−k} = conj Y_k), R_k the receptance of the condensed
structure at kω, Y⁰ its response to the external forces, N(y, ẏ, t) the mesh law, evaluated in
the time domain on ``samples`` points per period and transformed back (AFT: Cameron & Griffin,
J. Appl. Mech. 56:149, 1989).  The unknowns are real: x = (Re Y_0, Re Y_1…H, Im Y_1…H) per
channel.  The Jacobian is exact for the sampled law (its derivatives dN/dy, dN/dẏ on the same
grid), so Newton converges in one step where the law is linear on every sample.

Continuation in the frequency ω: pseudo-arclength (Keller) with a secant-free tangent predictor,
the arclength in the scaled variables (x / x_scale, ω / ω_scale), step doubling and halving by
the corrector's iteration count; folds (turning points in ω, the jumps of a swept experiment)
are where the tangent's ω-component changes sign.  Stability (Floquet) is the caller's: a
function of the converged point (:func:`femgear.system.dynamics.sdof_hb.ks_stability` for the
single-DOF oscillator).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from femgear.errors import ConvergenceError

Receptance = Callable[[float], tuple[np.ndarray, np.ndarray]]
"""ω [rad/s] → (R (H+1, m, m), Y⁰ (H+1, m)): the condensed receptance and the forced response at k ω."""
MeshLaw = Callable[[np.ndarray, np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]
"""(y, ẏ (m, n_t), phase (n_t,) in periods) → (N, ∂N/∂y, ∂N/∂ẏ), each (m, n_t)."""


@dataclass(frozen=True)
class PeriodicProblem:
    """A periodic mesh-coordinate problem for :func:`solve` and :func:`continuation`."""

    channels: int                 #: m mesh coordinates [-]
    harmonics: int                #: H [-]
    samples: int                  #: AFT samples per period (≥ 2H + 1; a multiple of 4H resolves the kinks) [-]
    receptance: Receptance
    law: MeshLaw
    mean_stiffness: np.ndarray    #: (m,) k̄ moved into the structure [N/m]
    mean_damping: np.ndarray      #: (m,) c̄ moved into the structure [N s/m]

    def __post_init__(self):
        if self.samples < 2 * self.harmonics + 1:
            raise ValueError(f"samples ({self.samples}) must be at least 2H + 1 = {2 * self.harmonics + 1}")

    @property
    def size(self) -> int:
        return self.channels * (2 * self.harmonics + 1)


def harmonics_of(problem: PeriodicProblem, x: np.ndarray) -> np.ndarray:
    """(m, H+1) complex Y_k of the real unknowns x."""
    H = problem.harmonics
    xr = x.reshape(problem.channels, 2 * H + 1)
    Y = xr[:, :H + 1].astype(complex)
    Y[:, 1:] += 1j * xr[:, H + 1:]
    return Y


def unknowns_of(problem: PeriodicProblem, Y: np.ndarray) -> np.ndarray:
    """The real unknowns x of harmonics Y (m, H+1)."""
    return np.concatenate([Y.real, Y[:, 1:].imag], axis=1).ravel()


def time_signal(Y: np.ndarray, samples: int, omega: float = 1.0, derivative: bool = False) -> np.ndarray:
    """y(t_j) (or ẏ) at t_j = j T / samples of the harmonics Y (m, H+1) [unit of y]."""
    k = np.arange(Y.shape[-1])
    Z = Y * (1j * k * omega) if derivative else Y
    pad = np.zeros(Y.shape[:-1] + (samples // 2 + 1,), dtype=complex)
    pad[..., :Y.shape[-1]] = Z
    return np.fft.irfft(pad * samples, n=samples, axis=-1)


def _bases(H: int, n: int):
    """Real synthesis B (n, 2H+1): y_j = B x, and analysis E (2H+1, n): (Re N̂, Im N̂) = E N."""
    k = np.arange(1, H + 1)
    th = 2 * math.pi * np.outer(np.arange(n), k) / n
    B = np.hstack([np.ones((n, 1)), 2 * np.cos(th), -2 * np.sin(th)])
    Bd = np.hstack([np.zeros((n, 1)), -2 * k * np.sin(th), -2 * k * np.cos(th)])      # per unit ω
    E = np.vstack([np.ones((1, n)), np.cos(th).T, -np.sin(th).T]) / n
    return B, Bd, E


def _complex_operator(R: np.ndarray, H: int, m: int) -> np.ndarray:
    """The real matrix of u_k ↦ R_k u_k (R (H+1, m, m)) on the layout of the unknowns."""
    n = 2 * H + 1
    out = np.zeros((m, n, m, n))
    re, im = R.real, R.imag
    out[:, 0, :, 0] = re[0]
    k = np.arange(1, H + 1)
    out[:, k, :, k] = re[1:]
    out[:, k, :, H + k] = -im[1:]
    out[:, H + k, :, k] = im[1:]
    out[:, H + k, :, H + k] = re[1:]
    return out.reshape(m * n, m * n)


def residual(problem: PeriodicProblem, x: np.ndarray, omega: float, jacobian: bool = True):
    """(r, ∂r/∂x) of the harmonic-balance equations at the frequency ``omega`` [rad/s]."""
    H, m, n = problem.harmonics, problem.channels, problem.samples
    R, Y0 = problem.receptance(omega)
    Y = harmonics_of(problem, x)
    y = time_signal(Y, n)
    v = time_signal(Y, n, omega, derivative=True)
    N, dNy, dNv = problem.law(y, v, np.arange(n) / n)
    Nh = np.fft.rfft(N, axis=-1)[:, :H + 1] / n
    k = np.arange(H + 1)
    lin = (problem.mean_stiffness[:, None] + 1j * k * omega * problem.mean_damping[:, None]) * Y
    r = Y - Y0.T + np.einsum("kab,bk->ak", R, Nh - lin)
    r_real = unknowns_of(problem, r)
    if not jacobian:
        return r_real, None
    B, Bd, E = _bases(H, n)
    dN = np.zeros((m, 2 * H + 1, m, 2 * H + 1))
    for c in range(m):
        dN[c, :, c, :] = E @ (dNy[c][:, None] * B + omega * dNv[c][:, None] * Bd)
    klin = np.zeros((m, 2 * H + 1, m, 2 * H + 1))
    for c in range(m):
        kb, cb = problem.mean_stiffness[c], problem.mean_damping[c]
        klin[c, :, c, :] = np.diag(np.full(2 * H + 1, kb))
        kk = np.arange(1, H + 1)
        klin[c, kk, c, H + kk] = -kk * omega * cb
        klin[c, H + kk, c, kk] = kk * omega * cb
    Rop = _complex_operator(R, H, m)
    J = np.eye(problem.size) + Rop @ (dN - klin).reshape(problem.size, problem.size)
    return r_real, J


def _newton(problem, x, omega, tol, max_iter, constraint=None):
    """Newton on r(x, ω) = 0 (``constraint``: (g(x, ω), ∂g/∂x, ∂g/∂ω) adds ω as an unknown). Returns
    (x, ω, iterations) or raises ConvergenceError."""
    history = []
    scale = max(1.0, float(np.abs(x).max()))
    for it in range(1, max_iter + 1):
        r, J = residual(problem, x, omega)
        if constraint is None:
            dx = np.linalg.solve(J, -r)
            x = x + dx
            dom = 0.0
        else:
            g, gx, gw = constraint(x, omega)
            Jw = _omega_derivative(problem, x, omega)
            A = np.block([[J, Jw[:, None]], [gx[None, :], np.array([[gw]])]])
            d = np.linalg.solve(A, -np.concatenate([r, [g]]))
            x, omega, dom = x + d[:-1], omega + d[-1], d[-1]
            dx = d[:-1]
        step = float(np.abs(dx).max()) / scale
        history.append(step)
        if not np.all(np.isfinite(x)):
            break
        if step < tol and abs(dom) < tol * max(1.0, abs(omega)):
            return x, omega, it
    raise ConvergenceError("harmonic balance (Newton)", f"no convergence in {max_iter} iterations at ω = {omega:.6g}",
                           {"step": history})


def _omega_derivative(problem, x, omega, rel=1e-7):
    h = rel * max(abs(omega), 1e-12)
    rp, _ = residual(problem, x, omega + h, jacobian=False)
    rm, _ = residual(problem, x, omega - h, jacobian=False)
    return (rp - rm) / (2 * h)


def solve(problem: PeriodicProblem, omega: float, x0: np.ndarray, tol: float = 1e-10, max_iter: int = 50) -> np.ndarray:
    """The harmonic-balance solution at the fixed frequency ``omega`` from the guess ``x0``."""
    return _newton(problem, np.asarray(x0, dtype=float), float(omega), tol, max_iter)[0]


@dataclass(frozen=True)
class Branch:
    """A solution branch traced by :func:`continuation`."""

    omega: np.ndarray                 #: (P,) frequencies along the branch [rad/s]
    x: np.ndarray                     #: (P, size) real unknowns along the branch
    folds: tuple[int, ...]            #: indices of the points at which the branch turns back in ω [-]
    iterations: np.ndarray            #: (P,) Newton iterations of each point [-]
    stable: np.ndarray | None = None  #: (P,) Floquet-stable points (None: not computed) [-]
    info: dict = field(default_factory=dict, compare=False)


def continuation(problem: PeriodicProblem, omega0: float, omega1: float, x0: np.ndarray, *, ds: float = 0.02,
                 ds_min: float = 1e-5, ds_max: float = 0.1, x_scale: float = 1.0, max_points: int = 5000,
                 tol: float = 1e-10, stability: Callable[[np.ndarray, float], bool] | None = None,
                 omega_min: float | None = None) -> Branch:
    """Trace the branch from (x0, ``omega0``) towards ``omega1`` by pseudo-arclength continuation.

    The arclength is measured in (x / ``x_scale``, ω / |omega0|); ``ds`` the first step, adapted within
    [``ds_min``, ``ds_max``]; ends when ω passes ``omega1``, or when it turns back past ``omega_min`` (default
    ``omega0``: a branch that turns for good; lower lets a strongly bent resonance turn again below ``omega0``), or
    after ``max_points``.  Raises ConvergenceError when the step falls below ``ds_min``.
    """
    w_scale = abs(omega0)
    direction = 1.0 if omega1 > omega0 else -1.0
    omega_min = omega0 if omega_min is None else omega_min
    x, om, _ = _newton(problem, np.asarray(x0, float), float(omega0), tol, 50)
    xs, oms, its, folds = [x], [om], [0], []
    tangent = None
    history: list[float] = []
    while len(xs) < max_points:
        r, J = residual(problem, x, om)
        Jw = _omega_derivative(problem, x, om)
        # tangent: [J Jw] t = 0, oriented along the previous one (first: towards omega1)
        A = np.vstack([np.hstack([J, Jw[:, None]]),
                       np.concatenate([np.zeros(problem.size), [1.0]]) if tangent is None else tangent[None, :]])
        t = np.linalg.solve(A, np.concatenate([np.zeros(problem.size), [1.0]]))
        t = t * np.concatenate([np.full(problem.size, 1.0 / x_scale), [1.0 / w_scale]])
        t = t / np.linalg.norm(t)
        if tangent is None:
            t = t * direction * np.sign(t[-1] or 1.0)
        elif np.dot(t, tangent) < 0:
            t = -t
        if tangent is not None and np.sign(t[-1]) != np.sign(tangent[-1]) and t[-1] != 0:
            folds.append(len(xs) - 1)
        scale_vec = np.concatenate([np.full(problem.size, x_scale), [w_scale]])
        while True:
            pred = np.concatenate([x, [om]]) + ds * t * scale_vec
            x_p, om_p = pred[:-1], pred[-1]

            def arc(xx, ww, x_p=x_p, om_p=om_p, t=t):
                d = np.concatenate([(xx - x_p) / x_scale, [(ww - om_p) / w_scale]])
                return float(t @ d), t[:-1] / x_scale, float(t[-1] / w_scale)

            try:
                x_new, om_new, it = _newton(problem, x_p, om_p, tol, 12, constraint=arc)
                break
            except ConvergenceError:
                ds *= 0.5
                history.append(ds)
                if ds < ds_min:
                    raise ConvergenceError("harmonic balance (continuation)",
                                           f"step fell below {ds_min:g} at ω = {om:.6g}", {"ds": history}) from None
        tangent = t
        x, om = x_new, om_new
        xs.append(x)
        oms.append(om)
        its.append(it)
        ds = min(ds_max, ds * 1.5) if it <= 3 else (max(ds_min, ds * 0.5) if it > 6 else ds)
        if (om - omega1) * direction > 0 or (om - omega_min) * direction < -1e-9 * w_scale:
            break
    x_arr = np.array(xs)
    stable = None if stability is None else np.array([stability(xx, ww) for xx, ww in zip(x_arr, oms)])
    return Branch(omega=np.array(oms), x=x_arr, folds=tuple(folds), iterations=np.array(its), stable=stable)


def solutions_at(problem: PeriodicProblem, branch: Branch, omega: float, tol: float = 1e-10) -> list[np.ndarray]:
    """Every solution of ``branch`` at the frequency ``omega``: for each segment of the branch that brackets it, Newton at
    fixed ω from the segment's linear interpolation (the branch's points themselves lie at the continuation's ω)."""
    out = []
    w = branch.omega
    for i in range(w.size - 1):
        lo, hi = sorted((w[i], w[i + 1]))
        if not lo <= omega <= hi or hi == lo:
            continue
        s = (omega - w[i]) / (w[i + 1] - w[i])
        x = solve(problem, omega, (1 - s) * branch.x[i] + s * branch.x[i + 1], tol)
        if not any(np.allclose(x, y, rtol=1e-6, atol=1e-9 * max(1.0, float(np.abs(y).max()))) for y in out):
            out.append(x)
    return out
