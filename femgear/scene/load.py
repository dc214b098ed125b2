"""Loading a scene: TOML -> overrides -> validated :class:`Scene` (its own values only).

The checks that need the bound gear pair run once per run, where the pair is bound
(:func:`femgear.case.build_case`).

Every failure is a :class:`femgear.errors.SceneError` naming the key, so the CLI can
print one line.
"""

from __future__ import annotations

import tomllib
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from femgear.errors import SceneError
from femgear.scene.oils import fill_named_oil
from femgear.scene.plausibility import check_temperatures, log_warnings, scene_warnings
from femgear.scene.presets import expand_preset
from femgear.scene.ranges import check_input_ranges
from femgear.scene.schema import Scene


def parse_override(text: str) -> tuple[list[str], Any]:
    """Split ``a.b=value``; the value is read as a TOML value, else kept as a string."""
    if "=" not in text:
        raise SceneError(text, "an override must look like KEY=VALUE (e.g. operating.torque=150)")
    key, raw = (part.strip() for part in text.split("=", 1))
    if not key or any(not part for part in key.split(".")):
        raise SceneError(key or text, "empty key in override")
    try:
        value = tomllib.loads(f"v = {raw}")["v"]
    except tomllib.TOMLDecodeError:
        value = raw
    return key.split("."), value


def apply_overrides(data: Mapping[str, Any], overrides: Iterable[str]) -> dict[str, Any]:
    """Return a copy of the raw scene dictionary with ``--set`` overrides applied."""
    out: dict[str, Any] = _deep_copy(data)
    for text in overrides:
        path, value = parse_override(text)
        node = out
        for i, part in enumerate(path[:-1]):
            child = node.setdefault(part, {})
            if not isinstance(child, dict):
                raise SceneError(".".join(path[: i + 1]), "is a value, not a table; cannot set a key below it")
            node = child
        node[path[-1]] = value
    return out


def _deep_copy(data: Mapping[str, Any]) -> dict[str, Any]:
    return {k: _deep_copy(v) if isinstance(v, Mapping) else v for k, v in data.items()}


#: keys that earlier releases took, with what to do now (CHANGELOG.md)
REMOVED_KEYS = {
    "stiffness.n_slices": "removed: the pem and fe levels integrate every contact line over the face exactly, "
                          "without slices; delete the key",
}


def _problem(err: dict) -> tuple[str, str]:
    """(key, message) of one pydantic error: an unknown key with the closest key of its table."""
    own = err.get("ctx", {}).get("error")
    if isinstance(own, SceneError):          # a validator's check that names its own key (a cross-key check)
        return own.key, own.message
    key = ".".join(str(p) for p in err["loc"]) or "scene"
    if err["type"] == "extra_forbidden":
        return key, REMOVED_KEYS.get(key) or "unknown key" + _closest(err["loc"])
    message = err["msg"].removeprefix("Value error, ")
    if err["type"] != "missing" and "input" in err:
        message += f" (got {err['input']!r})"
    return key, message


def _closest(loc: tuple) -> str:
    """'; did you mean pinion.teeth?' for an unknown key ``loc`` close to a key of its table (else '')."""
    import difflib

    from femgear.scene.keys import scene_keys, scene_tables

    table = ".".join(str(p) for p in loc[:-1])
    names = [k.name for k in scene_keys() if k.table == table]
    names += [t.table.rpartition(".")[2] for t in scene_tables() if t.table.rpartition(".")[0] == table]
    close = difflib.get_close_matches(str(loc[-1]), names, n=1, cutoff=0.6)
    return f" (did you mean {table + '.' if table else ''}{close[0]}?)" if close else ""


def _first_error(exc: ValidationError) -> SceneError:
    """One :class:`SceneError` naming the first problem's key, its message listing every problem."""
    problems = [_problem(err) for err in exc.errors()]
    key, message = problems[0]
    if len(problems) > 1:
        message += f"; and {len(problems) - 1} more: " + "; ".join(f"{k}: {m}" for k, m in problems[1:])
    return SceneError(key, message)


def scene_from_dict(data: Mapping[str, Any], overrides: Iterable[str] = (), *, warn: bool = True) -> Scene:
    """Validate a raw scene dictionary (plus overrides): types, the inputs as typed and the temperatures.

    Impossible inputs raise :class:`SceneError`; implausible ones are logged as warnings, one line
    per key (``warn=False`` skips them).  The inputs as typed are checked in engineering terms
    (:mod:`femgear.scene.ranges`), before any derived geometry, so that a unit slip is blamed on the
    key the user typed.  The gear's feasibility and the checks of the operating point that need the
    pair run when the case is bound (:func:`femgear.case.build_case`).
    """
    raw = fill_named_oil(expand_preset(apply_overrides(data, overrides)))
    try:
        scene = Scene.model_validate(raw)
    except ValidationError as exc:
        raise _first_error(exc) from None
    range_warnings = check_input_ranges(scene)
    check_temperatures(scene)
    log_warnings(scene_warnings(scene, range_warnings), log_them=warn)
    return scene


MAX_TOML_BYTES = 1 << 20  # a scene or sweep file is a few kB


def read_toml(path: str | Path, what: str = "scene") -> dict[str, Any]:
    """Parse a TOML file; a missing or malformed file is a :class:`SceneError` naming it."""
    path = Path(path)
    if path.is_dir():
        raise SceneError(str(path), f"is a folder, not a {what} file")
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        raise SceneError(str(path), f"{what} file not found") from None
    except OSError as exc:
        raise SceneError(str(path), f"cannot read the {what} file: {exc.strerror or exc}") from None
    if len(data) > MAX_TOML_BYTES:
        raise SceneError(str(path), f"{len(data)} bytes is too large for a {what} file (limit {MAX_TOML_BYTES})")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise SceneError(str(path), f"not a text file (invalid UTF-8 at byte {exc.start})") from None
    if "\x00" in text:
        raise SceneError(str(path), "not a text file (it contains NUL bytes)")
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(str(path), f"not valid TOML: {exc}") from None


#: scene keys that name a file: a relative path is read from the scene file's folder
PATH_KEYS = (("housing", "frf_file"),)


def load_scene(path: str | Path, overrides: Iterable[str] = ()) -> Scene:
    """Read a TOML scene file, apply ``KEY=VALUE`` overrides and validate it (no geometry is built); the file
    keys of :data:`PATH_KEYS` given relative are taken from the scene file's folder."""
    data = apply_overrides(read_toml(path), overrides)
    for table, key in PATH_KEYS:
        node = data.get(table)
        if isinstance(node, dict) and isinstance(node.get(key), str) and not Path(node[key]).is_absolute():
            node[key] = str(Path(path).parent / node[key])
    return scene_from_dict(data)
