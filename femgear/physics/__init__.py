"""Physics leaves: pure functions of arrays, numbers and typed objects.

Nothing here reads a scene, writes a file or imports a layer above (``system``,
``levels``, the driver, ``edge``); the allowed directions are data in
``tests/architecture/test_layers.py``.
"""
