"""``femgear rexs``: gear data in from a REXS model, and a scene's pair out as one.

- ``femgear rexs FILE``: list the model's stages (cylindrical ones with teeth, module, helix angle,
  face width, centre distance and pair kind; planetary, bevel, worm stages marked as not supported);
- ``femgear rexs FILE --stage ID [-o scene.toml]``: the femgear scene of that stage, every value
  commented with its REXS component and attribute, the defaults used listed at the top (written
  atomically; without ``-o`` printed);
- ``femgear rexs --export scene.toml -o pair.rexs``: a REXS 1.4 model of the scene's pair (``.rexs``
  XML, ``.rexsj`` JSON, ``.rexsz`` zipped XML) that re-imports to the same scene.

``femgear info|run|dynamics FILE.rexs --stage ID`` read a stage through the same conversion.
"""

from __future__ import annotations

import argparse
import io
import logging
import zipfile
from pathlib import Path

from femgear.edge.cli.common import emit_json

log = logging.getLogger("femgear.edge.cli.rexs")


def register(sub) -> None:
    p = sub.add_parser("rexs", help="REXS gear models: list stages, convert a stage to a scene, export a scene")
    p.add_argument("file", nargs="?", metavar="FILE", help="REXS model (.rexs XML, .rexsj JSON, .rexsz zip)")
    p.add_argument("--stage", type=int, default=None, metavar="ID", help="convert this stage to a femgear scene")
    p.add_argument("--load-case", type=int, default=None, metavar="ID",
                   help="the model's load case for the operating point (default: its first)")
    p.add_argument("--export", type=Path, default=None, metavar="SCENE",
                   help="write the pair of this scene as a REXS 1.4 model (needs -o)")
    p.add_argument("--set", dest="overrides", action="append", default=[], metavar="KEY=VALUE",
                   help="override a scene key of the converted or exported scene (repeatable)")
    p.add_argument("-o", "--output", type=Path, default=None, metavar="PATH",
                   help="output file: scene.toml for --stage; pair.rexs/.rexsj/.rexsz for --export")
    p.add_argument("--json", action="store_true", help="list the stages as one JSON object (last line)")
    p.set_defaults(func=_rexs)


def _rexs(args: argparse.Namespace) -> int:
    from femgear.errors import ArgumentError

    if (args.file is None) == (args.export is None):
        raise ArgumentError("FILE", "give a REXS model FILE, or --export SCENE (not both)")
    if args.export is not None:
        if args.output is None:
            raise ArgumentError("-o", "--export needs an output file (-o pair.rexs, .rexsj or .rexsz)")
        return _export(args)
    if args.stage is None:
        if args.output is not None:
            raise ArgumentError("-o", "writing a scene needs --stage ID (femgear rexs FILE lists the stages)")
        return _list(args)
    return _convert(args)


def _list(args: argparse.Namespace) -> int:
    from femgear.rexs.read import read_model
    from femgear.rexs.stages import stage_rows

    model = read_model(args.file, args.load_case)
    rows = stage_rows(model)
    if args.json:
        emit_json({"file": str(args.file), "version": model.version, "application": model.application,
                   "stages": [row.__dict__ for row in rows]})
        return 0
    print(f"{model.source}: REXS {model.version} from {model.application or 'an unknown tool'}, "
          f"{len(rows)} stage{'s' if len(rows) != 1 else ''}")
    print(f"{'id':>6}  {'z1/z2':>9}  {'m_n mm':>7}  {'beta deg':>8}  {'b mm':>7}  {'a mm':>8}  name; kind")
    for r in rows:
        if not r.supported:
            print(f"{r.id:>6}  {'':>9}  {'':>7}  {'':>8}  {'':>7}  {'':>8}  {r.name}; {r.note}")
            continue
        print(f"{r.id:>6}  {f'{r.teeth[0]}/{r.teeth[1]}':>9}  {_mm(r.module):>7}  {_num(r.helix_deg):>8}  "
              f"{_mm(r.face_width):>7}  {_mm(r.centre_distance):>8}  {r.name}; {r.note}")
    return 0


def _mm(value: float | None) -> str:
    return "-" if value is None else f"{value * 1e3:.4g}"


def _num(value: float | None) -> str:
    return "-" if value is None else f"{value:.4g}"


def _convert(args: argparse.Namespace) -> int:
    from femgear.edge.cli.common import bind_rexs
    from femgear.edge.io.atomic import write_text_atomic
    from femgear.rexs.importer import read_stage, validate
    from femgear.rexs.scene_toml import scene_toml

    conv = read_stage(args.file, args.stage, args.load_case)
    for text in args.overrides:  # an override replaces the REXS value: its comment must not claim REXS
        key = text.split("=", 1)[0].strip()
        conv.sources.pop(key, None)
        conv.defaults.pop(key, None)
        conv.overridden.add(key)
    scene = validate(conv, args.overrides)
    bind_rexs(conv, scene)          # the gear's feasibility, in the model's terms
    if args.overrides:
        from femgear.scene.load import apply_overrides

        conv.data = apply_overrides(conv.data, args.overrides)
    text = scene_toml(conv, scene)
    if args.output is None:
        print(text, end="")
        return 0
    write_text_atomic(args.output, text)
    print(f"{args.output}: {conv.parts.kind} scene of stage {conv.stage.id} ({len(conv.defaults)} values not in the "
          "model, listed at the top)")
    return 0


def _export(args: argparse.Namespace) -> int:
    from femgear.case import build_case
    from femgear.edge.io.atomic import write_bytes_atomic
    from femgear.errors import ArgumentError
    from femgear.rexs.export import check_finite, export_scene
    from femgear.rexs.write import to_json, to_xml
    from femgear.scene import load_scene

    suffix = args.output.suffix.lower()
    if suffix not in (".rexs", ".rexsj", ".rexsz"):
        raise ArgumentError("-o", f"{args.output}: the REXS file must end in .rexs (XML), .rexsj (JSON) or .rexsz "
                                  "(zipped XML)")
    scene = load_scene(args.export, args.overrides)
    model, skipped = export_scene(scene, build_case(scene).pair, source=args.output.name)
    check_finite(model)
    version = _version()
    if suffix == ".rexsj":
        data = to_json(model, version).encode("utf-8")
    else:
        data = to_xml(model, version).encode("utf-8")
        if suffix == ".rexsz":
            buffer = io.BytesIO()
            with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
                archive.writestr(Path(args.output.name).with_suffix(".rexs").name, data)
            data = buffer.getvalue()
    for text in skipped:
        log.warning("not exported: %s", text)
    write_bytes_atomic(args.output, data)
    print(f"{args.output}: REXS 1.4 model of the {scene.pair.kind} pair of {args.export} "
          f"({len(model.components)} components)")
    return 0


def _version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("femgear")
    except PackageNotFoundError:
        return "unknown"
