"""Checks made before any case of a sweep runs.

:func:`check_cases` validates the scene of every case (the base scene with the case's
overrides) exactly as ``femgear run`` would: schema keys, types, units, ranges and the
gear's feasibility.  A typo in a grid key or an out-of-range value therefore stops the
sweep at once, with one line naming the key as the sweep file spells it
(``grid.operating.sped_rpm``, ``case[2].operating.torque``), instead of failing every
case after the others have run.

:func:`check_outputs` checks the outputs to draw against the result schema
(:mod:`femgear.edge.io.summary_schema`): each must be a numeric column of ``results.csv`` that some case of
the sweep writes, so that a pair (``safety_factors.S_H``), a text or a typo is refused before the first
case instead of after the last.

:func:`check_workers` asks each worker of a Dask cluster whether it can import femgear,
read the base scene and write the case folders at the paths the sweep sends it.
"""

from __future__ import annotations

import difflib
import logging
import os
from collections.abc import Sequence

from femgear.edge.sweep.spec import SweepSpec
from femgear.errors import ArgumentError, SceneError

log = logging.getLogger("femgear.edge.sweep")


def check_cases(spec: SweepSpec) -> None:
    """Raise :class:`SceneError` for the first case whose scene is invalid (nothing is computed).

    The key of the error is the override's key prefixed with where the sweep file set it (``grid.`` or
    ``case[i].``); a combination of valid values that makes an impossible gear names the scene key that
    refused it and the case's values.
    """
    from femgear.scene.load import read_toml, scene_from_dict

    data = read_toml(spec.base)
    for case in spec.cases:
        try:
            scene_from_dict(data, case.overrides, warn=False)
        except SceneError as exc:
            if exc.key in case.values:
                raise SceneError(f"{case.source}.{exc.key}", f"{exc.message} (checked before any case ran)") from None
            where = ", ".join(case.overrides) or "the base scene"
            raise SceneError(exc.key, f"{exc.message} (in the {case.source} case {where}; "
                                      "checked before any case ran)") from None
    log.info("sweep %s: %d cases checked", spec.name, len(spec.cases))


def check_outputs(spec: SweepSpec, requested: Sequence[str], argument: str = "outputs") -> None:
    """Raise :class:`ArgumentError` naming ``argument`` for an output of ``requested`` that no case's
    ``results.csv`` row will hold as a number: a key the result schema does not know (with the closest
    columns), a pair (its two columns ``.0`` and ``.1`` named), a list, text or flag, or a section that no
    case of the sweep computes (e.g. ``dynamics.*`` without a dynamics level).  Nothing is computed."""
    from femgear.edge.io import summary_schema as schema
    from femgear.scene.load import read_toml, scene_from_dict

    if not requested:
        return
    data = read_toml(spec.base)
    scenes = [scene_from_dict(data, case.overrides, warn=False) for case in spec.cases]
    for name in requested:
        if name == "seconds":
            continue
        problem = _output_problem(name, scenes, schema)
        if problem:
            raise ArgumentError(argument, f"{name!r} {problem} (checked before any case ran)")


def _output_problem(name: str, scenes: list, schema) -> str:
    """Why ``name`` is no numeric column any case of ``scenes`` writes ('' when it is one)."""
    base, _, half = name.rpartition(".")
    found = schema.kind_of(name)
    if found is None and half in ("0", "1") and (pair := schema.kind_of(base)) is not None and pair[1] == schema.PAIR:
        found = (pair[0], schema.NUMBER, pair[2])
    if found is None:
        close = difflib.get_close_matches(name, schema.columns(), n=3, cutoff=0.6)
        hint = f"; did you mean {', '.join(close)}?" if close else "; see docs/guide/outputs.md"
        return f"is no key of a run's results (femgear.edge.io.summary_schema){hint}"
    section, kind, _ = found
    if kind == schema.PAIR:
        return (f"is a pair (pinion and gear, or left and right helix), not one number: its columns are {name}.0 "
                f"and {name}.1")
    if kind != schema.NUMBER:
        return f"is {'a ' + kind if kind != schema.TEXT else 'text'} in results.json, not a numeric column"
    entry = schema.SECTIONS[section]
    if not any(entry.present(scene) for scene in scenes):
        return f"is written only {entry.when}, and no case of this sweep has that"
    return ""


def worker_probe(base: str, cases_dir: str) -> dict[str, object]:
    """Run on a worker: its working directory, femgear version and what it lacks to run the cases."""
    import femgear

    problems = []
    if not os.path.isfile(base):
        problems.append(f"cannot read the base scene {base}")
    if not os.path.isdir(cases_dir) or not os.access(cases_dir, os.W_OK):
        problems.append(f"cannot write in the case folder {cases_dir}")
    return {"cwd": os.getcwd(), "version": femgear.__version__, "problems": problems}


def check_workers(client, base: str, cases_dir: str, timeout: float = 60.0) -> int:
    """Check every worker of a Dask ``client`` (see :func:`worker_probe`); returns the number of workers.

    Raises :class:`ArgumentError` naming ``--scheduler`` when no worker joins within ``timeout`` seconds,
    when a worker cannot import femgear, or cannot see the base scene or the case folder (the
    filesystem is not shared at the same path, or the workers start in another folder while the
    paths are relative).  A worker with another femgear version, or with more than one thread (it
would run several cases at once in one process), is logged as a warning.
    """
    import femgear

    try:
        client.wait_for_workers(1, timeout=timeout)
    except TimeoutError:
        raise ArgumentError("--scheduler", f"no worker joined the scheduler within {timeout:g} s "
                                           "(start them with: dask worker ADDRESS)") from None
    try:
        answers = client.run(worker_probe, base, cases_dir)
    except (ImportError, AttributeError) as exc:
        raise ArgumentError("--scheduler", f"a worker cannot import femgear ({exc}); install femgear in the "
                                           "Python environment of every worker") from None
    for worker, answer in sorted(answers.items()):
        if answer["problems"]:
            raise ArgumentError("--scheduler", f"worker {worker} (working directory {answer['cwd']}): "
                                               f"{'; '.join(answer['problems'])}; share the filesystem at the same "
                                               "path on every worker")
        if answer["version"] != femgear.__version__:
            log.warning("worker %s runs femgear %s, this process %s", worker, answer["version"], femgear.__version__)
    threads = {w: info.get("nthreads", 1) for w, info in client.scheduler_info().get("workers", {}).items()}
    for worker, n in sorted(threads.items()):
        if n > 1:
            log.warning("worker %s has %d threads: it runs %d cases at once in one process (gmsh is not "
                        "thread-safe, BLAS threads compete); start workers with --nthreads 1", worker, n, n)
    return len(answers)


__all__ = ["check_cases", "check_outputs", "check_workers", "worker_probe"]
