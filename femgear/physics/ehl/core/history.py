"""The convergence history every EHL solver keeps (FE Newton and FD multigrid alike) and reports
in :class:`femgear.physics.ehl.core.results.EHLResult` and in a ConvergenceError."""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass
class History:
    """Per Newton iteration: scaled residual norm, relative load error, step, Krylov its,
    level size, and the largest pressure component |dP| of the Newton direction before
    damping with the node where it occurs (``max_dp``, ``max_dp_at`` = [X, Y]): a solve
    whose steps are cut by the |dP| cap says there where its linear model fails. Multigrid
    cycles with spike elimination (:mod:`femgear.physics.ehl.fd.eliminate`) add ``eliminated``: the
    local residual |F_S| left by each elimination."""

    residual: list = field(default_factory=list)
    load_error: list = field(default_factory=list)
    step: list = field(default_factory=list)
    krylov: list = field(default_factory=list)
    level: list = field(default_factory=list)
    max_dp: list = field(default_factory=list)
    max_dp_at: list = field(default_factory=list)
    eliminated: list = field(default_factory=list)

    def as_dict(self) -> dict:
        return {k: list(v) for k, v in self.__dict__.items() if isinstance(v, list)}

    def extend(self, other: History) -> None:
        for k, v in other.as_dict().items():
            getattr(self, k).extend(v)

