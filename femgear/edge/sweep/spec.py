"""Sweep files: a base scene plus a grid and/or a list of overrides.

```toml
base = "paper_baseline.toml"          # relative to the sweep file
name = "rig15"                        # output folder out/sweeps/<name> (default: file stem)
outputs = ["friction.mu_mean"]        # columns of results.csv drawn in summary.png (optional)

[grid]                                # full factorial over these keys
"operating.speed_rpm" = [100, 200, 300, 400, 500]
"operating.torque" = [100, 150, 200]

[[case]]                              # extra cases, each a table of overrides
"operating.torque" = 0.0              # (an impossible case is reported, not fatal)
```

Every case is a tuple of ``KEY=VALUE`` overrides with a stable identifier derived
from them, so that a rerun recognises cases it has already finished.  The file is
checked here (its own keys); every case's scene is checked before any case runs by
:func:`femgear.edge.sweep.check.check_cases`.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import re
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

from femgear.errors import SceneError
from femgear.scene.load import parse_override, read_toml


@dataclass(frozen=True)
class Case:
    """One load case of a sweep."""

    overrides: tuple[str, ...]
    #: where the case was written in the sweep file (``grid`` or ``case[i]``), for messages
    source: str = field(default="grid", compare=False)

    @cached_property
    def values(self) -> dict[str, object]:
        """The overridden values by key, as TOML reads them (numbers stay numbers); read once."""
        out = {}
        for text in self.overrides:
            path, value = parse_override(text)
            out[".".join(path)] = value
        return out

    @property
    def case_id(self) -> str:
        """Readable and stable: the overridden values plus a short hash of the overrides."""
        values = "_".join(o.split("=", 1)[1] for o in self.overrides)
        slug = re.sub(r"[^A-Za-z0-9.+-]+", "-", values).strip("-")[:60] or "base"
        digest = hashlib.sha1("\n".join(self.overrides).encode()).hexdigest()[:8]
        return f"{slug}-{digest}"


@dataclass(frozen=True)
class SweepSpec:
    """A parsed sweep file."""

    name: str
    base: Path
    cases: tuple[Case, ...]
    #: the swept keys, grid keys first, then those of the ``[[case]]`` tables, in the file's order
    keys: tuple[str, ...] = ()
    #: columns of ``results.csv`` to draw in ``summary.png`` (empty: a default set)
    outputs: tuple[str, ...] = ()


def _as_override(key: str, value, where: str) -> str:
    return f"{key}={json.dumps(value) if isinstance(value, str) else _toml_value(value, f'{where}.{key}')}"


def _toml_value(value, where: str) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    raise SceneError(where, f"a swept value must be a number, a string or a boolean (got {value!r})")


def parse_sweep(path: str | Path) -> SweepSpec:
    """Read a sweep file; errors name the offending key."""
    path = Path(path)
    data = read_toml(path, "sweep")
    unknown = set(data) - {"base", "name", "grid", "case", "outputs"}
    if unknown:
        raise SceneError(sorted(unknown)[0], "unknown key in sweep file (use base, name, grid, case, outputs)")
    if "base" not in data:
        raise SceneError("base", "the sweep file must name its base scene")
    base = (path.parent / data["base"]).resolve()
    if not base.exists():
        raise SceneError("base", f"base scene {base} not found")
    grid = data.get("grid", {})
    for key, values in grid.items():
        if not isinstance(values, list) or not values:
            raise SceneError(f"grid.{key}", "a grid entry must be a non-empty list of values")
    cases = [
        Case(tuple(_as_override(k, v, "grid") for k, v in zip(grid, combo)))
        for combo in itertools.product(*grid.values())
    ] if grid else []
    for i, table in enumerate(data.get("case", [])):
        if not isinstance(table, dict):
            raise SceneError(f"case[{i}]", "each [[case]] must be a table of overrides")
        cases.append(Case(tuple(_as_override(k, v, f"case[{i}]") for k, v in table.items()), source=f"case[{i}]"))
    if not cases:
        raise SceneError("grid", "the sweep has no cases (add a [grid] or [[case]] tables)")
    ids = [c.case_id for c in cases]
    if len(set(ids)) != len(ids):
        raise SceneError("grid", "the sweep lists the same case twice")
    keys = tuple(dict.fromkeys(k for c in cases for k in c.values))
    return SweepSpec(name=data.get("name", path.stem), base=base, cases=tuple(cases), keys=keys,
                     outputs=_outputs(data.get("outputs", [])))


def _outputs(value) -> tuple[str, ...]:
    if not isinstance(value, list) or not all(isinstance(v, str) and v for v in value):
        raise SceneError("outputs", 'must be a list of results.csv column names, e.g. ["friction.mu_mean"]')
    return tuple(value)
