"""REXS import and export: gear data in from the tools engineers use (KISSsoft, MASTA, FVA-Workbench,
Bearinx, ...) and back out.

REXS (Reusable Engineering EXchange Standard, FVA e.V.) versions 1.0–1.4, as XML ``.rexs``, JSON
``.rexsj`` or zipped ``.rexsz``.  Modules, in data-flow order:

- :mod:`~femgear.rexs.database`: the REXS 1.4 ids and units femgear maps (a small derived table),
  renames between versions, femgear's custom attributes;
- :mod:`~femgear.rexs.units`: declared unit → scene unit, checked against the database unit;
- :mod:`~femgear.rexs.model`: the model in memory and :class:`RexsError`;
- :mod:`~femgear.rexs.read`: file → model (defusedxml, size caps, zip member, load case);
- :mod:`~femgear.rexs.stages`: stage listing, pair kind (double-helical halves), refusals;
- :mod:`~femgear.rexs.lookup`: following relations (flanks, tools, materials, bearings, ...);
- :mod:`~femgear.rexs.convert`, :mod:`~femgear.rexs.tables`, :mod:`~femgear.rexs.modifications`:
  stage → scene dictionary with the REXS source of every value;
- :mod:`~femgear.rexs.viscosity`: ν40/ν100 → viscosity and its temperature slope (ASTM D341);
- :mod:`~femgear.rexs.importer`: file → validated scene, scene errors named by REXS component;
- :mod:`~femgear.rexs.scene_toml`: the commented scene file;
- :mod:`~femgear.rexs.export`, :mod:`~femgear.rexs.write`: scene → REXS 1.4 model → XML/JSON text.
"""

from femgear.rexs.model import RexsError
from femgear.rexs.read import is_rexs_path, read_model

__all__ = ["RexsError", "is_rexs_path", "read_model"]
