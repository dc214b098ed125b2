"""Scenes: TOML files validated into frozen models.

- ``schema``  the models, every key documented with its unit.
- ``levels``  fidelity levels per sub-model and which exist today.
- ``presets`` named fidelity presets (fast, balanced, accurate).
- ``load``    reading, ``--set`` overrides, error messages naming the key.
"""

from femgear.scene.load import load_scene, scene_from_dict
from femgear.scene.schema import Scene

__all__ = ["Scene", "load_scene", "scene_from_dict"]
