"""The summary figure of a sweep: chosen outputs against the swept keys (``summary.png``)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from femgear.edge.plot import pyplot

#: at most this many lines per panel get a legend entry (the others are drawn, unlabelled)
MAX_LEGEND = 12


def _number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def x_key(rows: Sequence[Mapping[str, Any]], keys: Sequence[str]) -> str:
    """The swept key on the x axis: the first numeric one with more than one value, else the first key."""
    for key in keys:
        values = [r.get(key) for r in rows]
        if all(_number(v) for v in values) and len(set(values)) > 1:
            return key
    return keys[0]


def plot_sweep_summary(rows: Sequence[Mapping[str, Any]], keys: Sequence[str], outputs: Sequence[str],
                       title: str = ""):
    """One panel per output against one swept key (x); one line per combination of the other swept keys
    that vary (the keys with one value are listed under the title).

    ``rows`` are the finished cases (a mapping per case holding the swept keys and the outputs); a case
    whose output is missing or not a number is left out of that panel.  A non-numeric x key is drawn at
    evenly spaced positions labelled with its values.
    """
    plt = pyplot()

    x = x_key(rows, keys)
    varied = [k for k in keys if len({repr(r.get(k)) for r in rows}) > 1]
    others = [k for k in varied if k != x]
    fixed = [f"{k} = {rows[0].get(k)}" for k in keys if k not in varied and k != x]
    numeric_x = all(_number(r.get(x)) for r in rows)
    labels = list(dict.fromkeys(repr(r.get(x)) for r in rows)) if not numeric_x else []
    groups: dict[tuple, list[Mapping[str, Any]]] = {}
    for row in rows:
        groups.setdefault(tuple(row.get(k) for k in others), []).append(row)
    fig, axes = plt.subplots(len(outputs), 1, figsize=(7.5, 2.6 * len(outputs) + 0.8), sharex=True, squeeze=False)
    for ax, name in zip(axes[:, 0], outputs):
        for i, (combo, members) in enumerate(groups.items()):
            pts = sorted((r[x] if numeric_x else labels.index(repr(r.get(x))), r[name])
                         for r in members if _number(r.get(name)))
            if not pts:
                continue
            label = ", ".join(f"{k} = {v}" for k, v in zip(others, combo)) if others and i < MAX_LEGEND else None
            ax.plot(*zip(*pts), "o-", ms=4, lw=1.2, label=label)
        ax.set_ylabel(name, fontsize=8)
        ax.grid(alpha=0.3)
    if others and len(groups) > 1:
        axes[0, 0].legend(fontsize=7, ncol=2 if len(groups) > 4 else 1)
    if not numeric_x:
        axes[-1, 0].set_xticks(range(len(labels)), labels)
    axes[-1, 0].set_xlabel(x)
    fig.suptitle((title or "sweep summary") + (f"\n{', '.join(fixed)}" if fixed else ""), fontsize=10)
    return fig


__all__ = ["plot_sweep_summary", "x_key"]
