"""Results files, written atomically (a file is either complete or absent).

- ``atomic``    atomic_write / write_text_atomic / write_bytes_atomic (temp file, fsync, rename, 0644)
- ``results``   JSON of numpy data (non-finite -> null)
- ``paths``     output folders checked writable before a computation; names kept inside their root
- ``paraview``  .pvd collections of .vtu files (meshio); ``paraview_run`` the main job's set
- ``run``, ``dynamics``  the results.json layout of a run and the dynamics files
- ``ltca``      ``femgear ltca``'s results.json and ParaView sets; the loaded-TE block of a run's results.json
"""

from femgear.edge.io.atomic import atomic_write, write_bytes_atomic, write_text_atomic
from femgear.edge.io.results import to_plain, write_json

__all__ = ["atomic_write", "to_plain", "write_bytes_atomic", "write_json", "write_text_atomic"]
